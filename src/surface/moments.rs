//! Spectral moments by finite differences (SURFACES.md §4).

use rayon::prelude::*;
use serde::Serialize;

use super::HeightMap;

/// Nayak's profile moments of a levelled map, per direction and combined. SI: m0 in m²,
/// m2 dimensionless, m4 in m⁻².
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Moments {
    /// Mean of h² over the valid points.
    pub m0: f64,
    /// ½ (m2_x + m2_y); m2_x for a profile.
    pub m2: f64,
    /// ½ (m4_x + m4_y); m4_x for a profile.
    pub m4: f64,
    /// Mean of h_x² over the valid forward-difference pairs along x.
    pub m2_x: f64,
    /// Mean of h_y² over the valid pairs along y (None for a profile).
    pub m2_y: Option<f64>,
    /// Mean of h_xx² over the valid triples along x.
    pub m4_x: f64,
    /// Mean of h_yy² over the valid triples along y (None for a profile).
    pub m4_y: Option<f64>,
    /// On a map with no valid pair (or triple) along one direction, the other
    /// direction, whose moments alone make m2 and m4 (`"x"` or `"y"`); None when
    /// both directions count.
    pub only_along: Option<&'static str>,
}

/// Sums and counts of one row's contributions.
#[derive(Clone, Copy, Default)]
struct Sums {
    h2: f64,
    n0: usize,
    hx2: f64,
    nx2: usize,
    hy2: f64,
    ny2: usize,
    hxx2: f64,
    nxx: usize,
    hyy2: f64,
    nyy: usize,
}

impl Sums {
    fn add(mut self, o: &Sums) -> Sums {
        self.h2 += o.h2;
        self.n0 += o.n0;
        self.hx2 += o.hx2;
        self.nx2 += o.nx2;
        self.hy2 += o.hy2;
        self.ny2 += o.ny2;
        self.hxx2 += o.hxx2;
        self.nxx += o.nxx;
        self.hyy2 += o.hyy2;
        self.nyy += o.nyy;
        self
    }
}

fn mean(sum: f64, n: usize) -> f64 {
    if n == 0 {
        0.0
    } else {
        sum / n as f64
    }
}

impl Moments {
    /// The moments of `map`, which should be levelled (m0 is the mean of h², not the
    /// variance). Each mean is over its own valid set; a difference touching a missing
    /// point is left out. Rows are summed in parallel and combined in row order, so the
    /// result does not depend on the number of threads.
    pub fn of(map: &HeightMap) -> Moments {
        let (nx, ny) = (map.nx(), map.ny());
        let (dx, dy) = (map.pixel_size_x(), map.pixel_size_y());
        let rows: Vec<Sums> = (0..ny)
            .into_par_iter()
            .map(|j| {
                let mut s = Sums::default();
                let row = map.row(j);
                for &h in row {
                    if !h.is_nan() {
                        s.h2 += h * h;
                        s.n0 += 1;
                    }
                }
                for w in row.windows(2) {
                    let d = (w[1] - w[0]) / dx;
                    if !d.is_nan() {
                        s.hx2 += d * d;
                        s.nx2 += 1;
                    }
                }
                for w in row.windows(3) {
                    let d = (w[2] - 2.0 * w[1] + w[0]) / (dx * dx);
                    if !d.is_nan() {
                        s.hxx2 += d * d;
                        s.nxx += 1;
                    }
                }
                if j + 1 < ny {
                    for (a, b) in row.iter().zip(map.row(j + 1)) {
                        let d = (b - a) / dy;
                        if !d.is_nan() {
                            s.hy2 += d * d;
                            s.ny2 += 1;
                        }
                    }
                }
                if j >= 1 && j + 1 < ny {
                    let (up, down) = (map.row(j - 1), map.row(j + 1));
                    for i in 0..nx {
                        let d = (down[i] - 2.0 * row[i] + up[i]) / (dy * dy);
                        if !d.is_nan() {
                            s.hyy2 += d * d;
                            s.nyy += 1;
                        }
                    }
                }
                s
            })
            .collect();
        let t = rows.iter().fold(Sums::default(), |acc, r| acc.add(r));
        let m0 = mean(t.h2, t.n0);
        let m2_x = mean(t.hx2, t.nx2);
        let m4_x = mean(t.hxx2, t.nxx);
        if map.is_profile() {
            Moments {
                m0,
                m2: m2_x,
                m4: m4_x,
                m2_x,
                m2_y: None,
                m4_x,
                m4_y: None,
                only_along: None,
            }
        } else {
            let m2_y = mean(t.hy2, t.ny2);
            let m4_y = mean(t.hyy2, t.nyy);
            // A direction without a single valid pair or triple has no moments:
            // averaging its 0 in would halve m2 and m4 (R off by √2); the other
            // direction stands for both (isotropy assumed, and said).
            let x_counts = t.nx2 > 0 && t.nxx > 0;
            let y_counts = t.ny2 > 0 && t.nyy > 0;
            let (m2, m4, only_along) = match (x_counts, y_counts) {
                (true, false) => (m2_x, m4_x, Some("x")),
                (false, true) => (m2_y, m4_y, Some("y")),
                _ => (0.5 * (m2_x + m2_y), 0.5 * (m4_x + m4_y), None),
            };
            Moments {
                m0,
                m2,
                m4,
                m2_x,
                m2_y: Some(m2_y),
                m4_x,
                m4_y: Some(m4_y),
                only_along,
            }
        }
    }

    /// Larger / smaller of m2_x and m2_y (1 for a profile or when one direction has
    /// no moments; infinite when one is 0).
    pub fn anisotropy_ratio(&self) -> f64 {
        if self.only_along.is_some() {
            return 1.0;
        }
        match self.m2_y {
            None => 1.0,
            Some(y) => {
                let (lo, hi) = if y < self.m2_x {
                    (y, self.m2_x)
                } else {
                    (self.m2_x, y)
                };
                if hi == 0.0 {
                    1.0
                } else {
                    hi / lo
                }
            }
        }
    }
}
