//! The radially averaged power spectral density (SURFACES.md §6b).
//!
//! For a map: the areal PSD with a Hann window in both directions, in Persson's convention
//! over the angular wavenumber q = 2π/λ: C(q) in m⁴ with ∫ C d²q = ⟨h²⟩, i.e.
//! 2π ∫ q C(q) dq = m0 for an isotropic surface. On the discrete grid
//! C(q_k) = |Σ w h e^{−i q_k·x}|² Δx Δy / (N (2π)² ⟨w²⟩), so that Σ_k C(q_k) δq_x δq_y is the
//! mean square of the windowed heights divided by the mean square of the window (≈ m0).
//! The 2-D values are then averaged over logarithmic rings of |q|.
//!
//! For a profile: the one-sided line PSD C1(q) in m³ with ∫₀^∞ C1 dq = m0.
//!
//! Missing points are set to 0 (after levelling their mean is 0); [`Psd::filled`] says how
//! many.

use rayon::prelude::*;
use rustfft::num_complex::Complex;
use rustfft::FftPlanner;
use serde::Serialize;

use super::HeightMap;

/// Which spectrum a [`Psd`] holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum PsdKind {
    /// Areal, radially averaged, m⁴: 2π ∫ q C dq = m0.
    Areal,
    /// One-sided line PSD of a profile, m³: ∫ C dq = m0.
    Profile,
}

/// A radially averaged PSD on logarithmic bins.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Psd {
    /// Areal or profile.
    pub kind: PsdKind,
    /// Mean |q| of each bin, rad/m (increasing).
    pub q: Vec<f64>,
    /// Mean C of each bin (m⁴ areal, m³ profile).
    pub c: Vec<f64>,
    /// Wavevectors averaged in each bin.
    pub count: Vec<usize>,
    /// Grid spacing of q along x and y, rad/m (δq_y = 0 for a profile).
    pub dq: (f64, f64),
    /// Missing points set to 0 for the transform.
    pub filled: usize,
}

/// Bins per decade of q.
pub const BINS_PER_DECADE: f64 = 10.0;

/// Symmetric Hann window of n points (all ones for n < 2).
fn hann(n: usize) -> Vec<f64> {
    if n < 2 {
        return vec![1.0; n];
    }
    (0..n)
        .map(|i| 0.5 * (1.0 - (2.0 * std::f64::consts::PI * i as f64 / (n - 1) as f64).cos()))
        .collect()
}

/// Signed frequency index of FFT bin k of n.
fn signed(k: usize, n: usize) -> f64 {
    if k <= n / 2 {
        k as f64
    } else {
        k as f64 - n as f64
    }
}

/// Accumulates (q, C) pairs in logarithmic bins starting at `q1`.
struct Bins {
    q1: f64,
    sum_q: Vec<f64>,
    sum_c: Vec<f64>,
    count: Vec<usize>,
}

impl Bins {
    fn new(q1: f64, q_max: f64) -> Self {
        let n = ((q_max / q1).log10() * BINS_PER_DECADE).floor() as usize + 1;
        Bins {
            q1,
            sum_q: vec![0.0; n],
            sum_c: vec![0.0; n],
            count: vec![0; n],
        }
    }
    fn index(&self, q: f64) -> usize {
        let b = ((q / self.q1).log10() * BINS_PER_DECADE).floor().max(0.0) as usize;
        b.min(self.count.len() - 1)
    }
    fn add(&mut self, q: f64, c: f64) {
        let b = self.index(q);
        self.sum_q[b] += q;
        self.sum_c[b] += c;
        self.count[b] += 1;
    }
    fn merge(mut self, o: &Bins) -> Self {
        for b in 0..self.count.len() {
            self.sum_q[b] += o.sum_q[b];
            self.sum_c[b] += o.sum_c[b];
            self.count[b] += o.count[b];
        }
        self
    }
    fn finish(self, kind: PsdKind, dq: (f64, f64), filled: usize) -> Psd {
        let mut psd = Psd {
            kind,
            q: Vec::new(),
            c: Vec::new(),
            count: Vec::new(),
            dq,
            filled,
        };
        for b in 0..self.count.len() {
            if self.count[b] > 0 {
                let n = self.count[b] as f64;
                psd.q.push(self.sum_q[b] / n);
                psd.c.push(self.sum_c[b] / n);
                psd.count.push(self.count[b]);
            }
        }
        psd
    }
}

impl Psd {
    /// The PSD of a levelled map (see the module documentation).
    pub fn of(map: &HeightMap) -> Psd {
        if map.is_profile() {
            Self::profile(map)
        } else {
            Self::areal(map)
        }
    }

    fn profile(map: &HeightMap) -> Psd {
        let n = map.nx();
        let dx = map.pixel_size_x();
        let w = hann(n);
        let w2 = w.iter().map(|x| x * x).sum::<f64>() / n as f64;
        let mut filled = 0;
        let mut buf: Vec<Complex<f64>> = map
            .row(0)
            .iter()
            .zip(&w)
            .map(|(&h, &wi)| {
                if h.is_nan() {
                    filled += 1;
                    Complex::new(0.0, 0.0)
                } else {
                    Complex::new(h * wi, 0.0)
                }
            })
            .collect();
        FftPlanner::new().plan_fft_forward(n).process(&mut buf);
        let two_pi = 2.0 * std::f64::consts::PI;
        let dq = two_pi / (n as f64 * dx);
        let mut bins = Bins::new(dq, dq * (n / 2).max(1) as f64);
        for (k, z) in buf.iter().enumerate().take(n / 2 + 1).skip(1) {
            // One-sided: the negative frequency −k carries the same power (except Nyquist).
            let sides = if 2 * k == n { 1.0 } else { 2.0 };
            let c = sides * z.norm_sqr() * dx / (n as f64 * two_pi * w2);
            bins.add(k as f64 * dq, c);
        }
        bins.finish(PsdKind::Profile, (dq, 0.0), filled)
    }

    fn areal(map: &HeightMap) -> Psd {
        let (nx, ny) = (map.nx(), map.ny());
        let (dx, dy) = (map.pixel_size_x(), map.pixel_size_y());
        let (wx, wy) = (hann(nx), hann(ny));
        let w2 = wx.iter().map(|x| x * x).sum::<f64>() / nx as f64
            * (wy.iter().map(|x| x * x).sum::<f64>() / ny as f64);
        let filled = map.heights().len() - map.valid_count();
        let mut planner = FftPlanner::<f64>::new();
        let fft_x = planner.plan_fft_forward(nx);
        let fft_y = planner.plan_fft_forward(ny);
        // Rows: window and transform along x.
        let mut grid: Vec<Complex<f64>> = vec![Complex::new(0.0, 0.0); nx * ny];
        grid.par_chunks_mut(nx).enumerate().for_each(|(j, row)| {
            for (i, cell) in row.iter_mut().enumerate() {
                let h = map.at(i, j);
                if !h.is_nan() {
                    *cell = Complex::new(h * wx[i] * wy[j], 0.0);
                }
            }
            fft_x.process(row);
        });
        // Columns: transpose, transform along y.
        let mut cols: Vec<Complex<f64>> = vec![Complex::new(0.0, 0.0); nx * ny];
        cols.par_chunks_mut(ny).enumerate().for_each(|(i, col)| {
            for (j, cell) in col.iter_mut().enumerate() {
                *cell = grid[j * nx + i];
            }
            fft_y.process(col);
        });
        let two_pi = 2.0 * std::f64::consts::PI;
        let (dqx, dqy) = (two_pi / (nx as f64 * dx), two_pi / (ny as f64 * dy));
        let scale = dx * dy / ((nx * ny) as f64 * two_pi * two_pi * w2);
        let q1 = dqx.min(dqy);
        let q_max = ((nx / 2) as f64 * dqx).hypot((ny / 2) as f64 * dqy);
        let bins = cols
            .par_chunks(ny)
            .enumerate()
            .map(|(i, col)| {
                let mut b = Bins::new(q1, q_max);
                let qx = signed(i, nx) * dqx;
                for (j, z) in col.iter().enumerate() {
                    if i == 0 && j == 0 {
                        continue;
                    }
                    let q = qx.hypot(signed(j, ny) * dqy);
                    b.add(q, z.norm_sqr() * scale);
                }
                b
            })
            .collect::<Vec<_>>()
            .into_iter()
            .fold(Bins::new(q1, q_max), |acc, b| acc.merge(&b));
        bins.finish(PsdKind::Areal, (dqx, dqy), filled)
    }

    /// The discrete integral of the spectrum: Σ count C δq_x δq_y (areal) or Σ count C δq
    /// (profile). Equals the mean square of the windowed heights over that of the window,
    /// ≈ m0.
    pub fn integral(&self) -> f64 {
        let cell = match self.kind {
            PsdKind::Areal => self.dq.0 * self.dq.1,
            PsdKind::Profile => self.dq.0,
        };
        self.c
            .iter()
            .zip(&self.count)
            .map(|(c, &n)| c * n as f64 * cell)
            .sum()
    }
}
