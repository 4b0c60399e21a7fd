//! Form removal (SURFACES.md §2): subtract the least-squares polynomial of the valid points.

use nalgebra::{DMatrix, DVector};
use rayon::prelude::*;
use serde::Serialize;

use super::{HeightMap, SurfaceError};

/// Which polynomial is fitted to the valid points and subtracted.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Levelling {
    /// The mean only.
    None,
    /// a + b x + c y (the default).
    Plane,
    /// The full second-order polynomial (curved samples, spherical tips).
    Quadratic,
}

impl Levelling {
    /// The name used on the command line and in problem files.
    pub fn as_str(self) -> &'static str {
        match self {
            Levelling::None => "none",
            Levelling::Plane => "plane",
            Levelling::Quadratic => "quadratic",
        }
    }
    /// Every name, for messages.
    pub const NAMES: [&'static str; 3] = ["none", "plane", "quadratic"];
    /// By name.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "none" => Some(Levelling::None),
            "plane" => Some(Levelling::Plane),
            "quadratic" => Some(Levelling::Quadratic),
            _ => None,
        }
    }
}

/// Powers (a, b) of u^a v^b in the basis.
fn basis(level: Levelling, profile: bool) -> &'static [(u32, u32)] {
    match (level, profile) {
        (Levelling::None, _) => &[(0, 0)],
        (Levelling::Plane, false) => &[(0, 0), (1, 0), (0, 1)],
        (Levelling::Plane, true) => &[(0, 0), (1, 0)],
        (Levelling::Quadratic, false) => &[(0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2)],
        (Levelling::Quadratic, true) => &[(0, 0), (1, 0), (2, 0)],
    }
}

/// Centred, scaled coordinate of index k of n: in [-1, 1] (0 when n = 1).
fn scaled(k: usize, n: usize) -> f64 {
    if n <= 1 {
        0.0
    } else {
        let half = (n - 1) as f64 / 2.0;
        (k as f64 - half) / half
    }
}

/// Per-row sums over valid points: Σ u^a (a = 0..4) and Σ h u^a (a = 0..2).
#[derive(Clone, Copy, Default)]
struct RowSums {
    s: [f64; 5],
    t: [f64; 3],
}

/// The map minus its least-squares polynomial (fitted with the physical aspect ratio
/// irrelevant: the polynomial space is the same in scaled coordinates). Missing points stay
/// missing. Deterministic: row sums are combined in row order.
pub fn level(map: &HeightMap, level: Levelling) -> Result<HeightMap, SurfaceError> {
    let (nx, ny) = (map.nx(), map.ny());
    let terms = basis(level, map.is_profile());
    let rows: Vec<RowSums> = (0..ny)
        .into_par_iter()
        .map(|j| {
            let mut r = RowSums::default();
            for (i, &h) in map.row(j).iter().enumerate() {
                if h.is_nan() {
                    continue;
                }
                let u = scaled(i, nx);
                let u2 = u * u;
                r.s[0] += 1.0;
                r.s[1] += u;
                r.s[2] += u2;
                r.s[3] += u2 * u;
                r.s[4] += u2 * u2;
                r.t[0] += h;
                r.t[1] += h * u;
                r.t[2] += h * u2;
            }
            r
        })
        .collect();
    let k = terms.len();
    let mut a = DMatrix::<f64>::zeros(k, k);
    let mut b = DVector::<f64>::zeros(k);
    for (j, r) in rows.iter().enumerate() {
        let v = scaled(j, ny);
        let vp = [1.0, v, v * v, v * v * v, v * v * v * v];
        for (p, &(ap, bp)) in terms.iter().enumerate() {
            b[p] += vp[bp as usize] * r.t[ap as usize];
            for (q, &(aq, bq)) in terms.iter().enumerate() {
                a[(p, q)] += vp[(bp + bq) as usize] * r.s[(ap + aq) as usize];
            }
        }
    }
    if a[(0, 0)] == 0.0 {
        let total = nx * ny;
        return Err(SurfaceError::TooManyMissing { valid: 0, total });
    }
    let coef = a
        .clone()
        .svd(true, true)
        .solve(&b, 1e-12 * a.amax())
        .unwrap_or_else(|_| DVector::zeros(k));
    let coef: Vec<f64> = coef.iter().copied().collect();
    // The fit on row j is a polynomial in u alone: Σ_a row[a] u^a with
    // row[a] = Σ over terms (a, b) of c · v_j^b.
    let us: Vec<f64> = (0..nx).map(|i| scaled(i, nx)).collect();
    let mut out = vec![f64::NAN; nx * ny];
    out.par_chunks_mut(nx).enumerate().for_each(|(j, row)| {
        let v = scaled(j, ny);
        let mut poly = [0.0f64; 3];
        for (c, &(ap, bp)) in coef.iter().zip(terms) {
            poly[ap as usize] += c * v.powi(bp as i32);
        }
        for ((cell, &h), &u) in row.iter_mut().zip(map.row(j)).zip(&us) {
            if !h.is_nan() {
                *cell = h - (poly[0] + u * (poly[1] + u * poly[2]));
            }
        }
    });
    Ok(map.with_heights(out))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn removes_exact_polynomials() {
        // h = 3 + 2x − y + 0.5 x² − 0.25 xy + y² sampled on a 7 × 5 grid: quadratic levelling
        // leaves zeros, plane levelling leaves the quadratic part minus its own plane fit.
        let (nx, ny) = (7, 5);
        let mut h = Vec::new();
        for j in 0..ny {
            for i in 0..nx {
                let (x, y) = (i as f64 * 0.1, j as f64 * 0.2);
                h.push(3.0 + 2.0 * x - y + 0.5 * x * x - 0.25 * x * y + y * y);
            }
        }
        let map = HeightMap::new(nx, ny, 0.1, 0.2, h).unwrap();
        let q = level(&map, Levelling::Quadratic).unwrap();
        assert!(q.heights().iter().all(|r| r.abs() < 1e-12));
        let p = level(&map, Levelling::Plane).unwrap();
        let mean: f64 = p.heights().iter().sum::<f64>() / 35.0;
        assert!(mean.abs() < 1e-12);
        assert!(p.heights().iter().any(|r| r.abs() > 1e-3));
    }

    #[test]
    fn plane_of_valid_points_only() {
        // A plane with one outlier marked missing: the plane is removed exactly.
        let (nx, ny) = (4, 3);
        let mut h: Vec<f64> = (0..12)
            .map(|k| 1.0 + 0.5 * (k % 4) as f64 - 2.0 * (k / 4) as f64)
            .collect();
        h[5] = f64::NAN;
        let map = HeightMap::new(nx, ny, 1.0, 1.0, h).unwrap();
        let l = level(&map, Levelling::Plane).unwrap();
        assert!(l.at(1, 1).is_nan());
        for (k, r) in l.heights().iter().enumerate() {
            if k != 5 {
                assert!(r.abs() < 1e-12, "{k}: {r}");
            }
        }
    }
}
