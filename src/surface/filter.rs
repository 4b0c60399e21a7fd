//! The short-wavelength cut-off: the areal Gaussian filter of ISO 16610-61 (SURFACES.md §3).
//!
//! Weights s(x, y) = exp(−π (x² + y²) / (α λs)²), α = √(ln 2 / π), over the truncated kernel
//! |x|, |y| ≤ λs, applied by direct convolution. The kernel is a product of one weight along x
//! and one along y and so is its truncation, so the sums Σ s h and Σ s over the valid points
//! are two one-dimensional passes each: exactly the areal sums, in O(n (kx + ky)) instead of
//! O(n kx ky).

use rayon::prelude::*;

use super::{HeightMap, SurfaceError};

/// α = √(ln 2 / π) of ISO 16610-61: the filter passes 50 % amplitude at wavelength λs.
pub fn iso_alpha() -> f64 {
    (std::f64::consts::LN_2 / std::f64::consts::PI).sqrt()
}

/// A filtered map, cropped to the points at least the edge band away from every edge.
#[derive(Debug, Clone, PartialEq)]
pub struct Filtered {
    /// The kept points, filtered (not yet levelled again).
    pub map: HeightMap,
    /// Pixels dropped at each edge along x and y: ⌈λs/Δ⌉ (0 along y for a profile).
    pub edge_band: (usize, usize),
}

/// λs/Δ, snapped to the nearest integer when it is one up to rounding (so that a cut-off
/// of exactly 5 pixels is 5, not 5.000000000000001).
fn ratio(cutoff: f64, pixel: f64) -> f64 {
    let r = cutoff / pixel;
    if (r - r.round()).abs() <= 1e-9 * r.max(1.0) {
        r.round()
    } else {
        r
    }
}

/// The one-dimensional weights exp(−π (kΔ)² / (α λs)²) for k = −K..=K, K = ⌊λs/Δ⌋.
pub fn weights(cutoff: f64, pixel: f64) -> Vec<f64> {
    let half = ratio(cutoff, pixel).floor() as usize;
    let a = iso_alpha() * cutoff;
    (0..=2 * half)
        .map(|m| {
            let x = (m as f64 - half as f64) * pixel;
            (-std::f64::consts::PI * (x / a) * (x / a)).exp()
        })
        .collect()
}

/// Filters `map` with cut-off `cutoff` (metres) and drops the edge band. The kernel is
/// renormalised over the valid points it covers; a point whose valid weight is below half
/// the full kernel weight becomes missing.
pub fn gaussian_cutoff(map: &HeightMap, cutoff: f64) -> Result<Filtered, SurfaceError> {
    if !(cutoff.is_finite() && cutoff > 0.0) {
        return Err(SurfaceError::BadCutoff { value: cutoff });
    }
    let (nx, ny) = (map.nx(), map.ny());
    let (dx, dy) = (map.pixel_size_x(), map.pixel_size_y());
    let profile = map.is_profile();
    let rx = ratio(cutoff, dx);
    let ry = ratio(cutoff, dy);
    let band_x = rx.ceil().min(nx as f64) as usize;
    let band_y = if profile {
        0
    } else {
        ry.ceil().min(ny as f64) as usize
    };
    let kept_nx = nx.saturating_sub(2 * band_x);
    let kept_ny = ny.saturating_sub(2 * band_y);
    if kept_nx < 3 || (!profile && kept_ny < 3) {
        let largest_x = ((nx.saturating_sub(3)) / 2) as f64 * dx;
        let largest_y = ((ny.saturating_sub(3)) / 2) as f64 * dy;
        return Err(SurfaceError::CutoffTooLarge {
            cutoff,
            band_x,
            band_y,
            kept_nx,
            kept_ny,
            nx,
            ny,
            largest: if profile {
                largest_x
            } else {
                largest_x.min(largest_y)
            },
        });
    }
    let wx = weights(cutoff, dx);
    let wy = if profile {
        vec![1.0]
    } else {
        weights(cutoff, dy)
    };
    let (hx, hy) = ((wx.len() - 1) / 2, (wy.len() - 1) / 2);
    let full: f64 = wx.iter().sum::<f64>() * wy.iter().sum::<f64>();

    // Pass along x on every row the y pass reads: Σ w h and Σ w over valid points, at the
    // kept columns only.
    let rows_needed = (band_y - hy)..(ny - band_y + hy);
    let first_row = rows_needed.start;
    let pass_x: Vec<(Vec<f64>, Vec<f64>)> = rows_needed
        .into_par_iter()
        .map(|j| {
            let row = map.row(j);
            let mut num = vec![0.0; kept_nx];
            let mut den = vec![0.0; kept_nx];
            for (c, (n, d)) in num.iter_mut().zip(den.iter_mut()).enumerate() {
                let i = band_x + c;
                let window = &row[i - hx..=i + hx];
                for (w, &h) in wx.iter().zip(window) {
                    if !h.is_nan() {
                        *n += w * h;
                        *d += w;
                    }
                }
            }
            (num, den)
        })
        .collect();

    let mut out = vec![f64::NAN; kept_nx * kept_ny];
    out.par_chunks_mut(kept_nx)
        .enumerate()
        .for_each(|(r, out_row)| {
            let j = band_y + r;
            for (c, cell) in out_row.iter_mut().enumerate() {
                let mut n = 0.0;
                let mut d = 0.0;
                for (l, w) in wy.iter().enumerate() {
                    let (pn, pd) = &pass_x[j - hy + l - first_row];
                    n += w * pn[c];
                    d += w * pd[c];
                }
                if d >= 0.5 * full && d > 0.0 {
                    *cell = n / d;
                }
            }
        });
    let map = HeightMap::new(kept_nx, kept_ny, dx, dy, out)?;
    Ok(Filtered {
        map,
        edge_band: (band_x, band_y),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fifty_percent_at_the_cutoff_wavelength() {
        // ISO 16610-61: the continuous filter transmits exp(−π α² λs²/λ²) of a sine of
        // wavelength λ, 50 % at λ = λs. With 40 samples per λs the truncated sampled kernel
        // is within 1e-3 of that.
        let n = 400;
        let d = 1.0;
        let cutoff = 40.0;
        let lambda = cutoff;
        let k = 2.0 * std::f64::consts::PI / lambda;
        let h: Vec<f64> = (0..n).map(|i| (k * i as f64 * d).sin()).collect();
        let map = HeightMap::new(n, 1, d, d, h).unwrap();
        let f = gaussian_cutoff(&map, cutoff).unwrap();
        assert_eq!(f.edge_band, (40, 0));
        let amp = f.map.heights().iter().fold(0.0f64, |m, x| m.max(x.abs()));
        assert!((amp - 0.5).abs() < 1e-3, "{amp}");
    }

    #[test]
    fn edge_band_and_too_large() {
        let map = HeightMap::new(10, 10, 1.0, 1.0, vec![0.0; 100]).unwrap();
        let f = gaussian_cutoff(&map, 3.0).unwrap();
        assert_eq!(f.edge_band, (3, 3));
        assert_eq!((f.map.nx(), f.map.ny()), (4, 4));
        assert!(matches!(
            gaussian_cutoff(&map, 4.0),
            Err(SurfaceError::CutoffTooLarge { .. })
        ));
        assert!(gaussian_cutoff(&map, -1.0).is_err());
    }
}
