//! Contact mechanics on a measured map: a periodic FFT boundary-element solver
//! (docs/contact.md).
//!
//! A rigid rough surface — the levelled height map, repeated periodically — is
//! pressed against a flat elastic half-space of composite modulus E* at a given
//! mean pressure. The surface compliance is Westergaard's, applied by FFT
//! ([`fft::Compliance`]); the pressures are found by the constrained
//! conjugate-gradient scheme of Polonsky & Keer (Wear 231, 1999), with an
//! optional cap at the hardness H (a perfectly plastic pixel carries H and may
//! interpenetrate, as in Almqvist et al. 2007 and Tamaas's saturated solver).
//! No I/O, no printing: the outcome is a [`Solution`].

pub mod adhesion;
pub mod fft;
pub mod patches;

use fft::Compliance;

/// Iterations without a new best residual after which the capped conjugate
/// scheme is taken to cycle.
const STALL: usize = 100;

/// The smallest map side the solver accepts (points along x and along y).
pub const MIN_SIDE: usize = 8;

/// How a solve is asked for.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    /// The cap on the contact pressure (Pa), the hardness H; `f64::INFINITY` for
    /// a purely elastic contact.
    pub hardness: f64,
    /// The residual (see [`Solution::residual`]) at which the solve stops.
    pub tolerance: f64,
    /// The most conjugate-gradient iterations per mean pressure.
    pub max_iterations: usize,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            hardness: f64::INFINITY,
            tolerance: DEFAULT_TOLERANCE,
            max_iterations: 5_000,
        }
    }
}

/// The residual a solve meets unless told otherwise.
pub const DEFAULT_TOLERANCE: f64 = 1e-10;

/// Why a contact problem cannot be solved: faults of the input, never outcomes.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ContactError {
    /// Fewer than [`MIN_SIDE`] points along a side.
    #[error(
        "the map is {nx} × {ny} points; the contact solver needs at least {MIN_SIDE} × {MIN_SIDE}"
    )]
    TooSmall {
        /// Points along x.
        nx: usize,
        /// Points along y.
        ny: usize,
    },
    /// The map has missing (NaN) or infinite points.
    #[error("{missing} of {total} points are missing or not finite; the contact solver needs a complete map (fill or crop the scan first)")]
    Missing {
        /// Points that are not finite.
        missing: usize,
        /// All points.
        total: usize,
    },
    /// A non-positive or non-finite modulus.
    #[error("the modulus is {0} Pa; it must be positive and finite")]
    Modulus(f64),
    /// A non-positive or non-finite mean pressure.
    #[error("the mean pressure is {0} Pa; it must be positive and finite")]
    Pressure(f64),
    /// A hardness that is not positive.
    #[error("the hardness is {0} Pa; it must be positive (or infinite: no cap)")]
    Hardness(f64),
    /// A mean pressure the hardness cannot carry.
    #[error("the mean pressure {pressure} Pa is not below the hardness {hardness} Pa: the whole map would flow")]
    AboveHardness {
        /// The mean pressure asked for.
        pressure: f64,
        /// The hardness.
        hardness: f64,
    },
    /// A non-positive or non-finite adhesion parameter.
    #[error("the {what} is {value} {unit}; it must be positive and finite")]
    Adhesion {
        /// Which parameter.
        what: &'static str,
        /// Its value.
        value: f64,
        /// Its unit.
        unit: &'static str,
    },
    /// A non-positive or non-finite mean gap.
    #[error("the mean gap is {0} m; it must be positive and finite")]
    MeanGap(f64),
    /// The approach never reached a mean pressure.
    #[error("the approach did not reach the mean pressure {pressure} Pa")]
    Unreached {
        /// The mean pressure asked for (Pa).
        pressure: f64,
    },
    /// Pixel sizes that are not positive and finite.
    #[error("the pixel size is {dx} × {dy} m; both must be positive and finite")]
    PixelSize {
        /// Along x.
        dx: f64,
        /// Along y.
        dy: f64,
    },
}

/// How a solve ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Outcome {
    /// The residual met the tolerance.
    Converged,
    /// The iteration limit came first; the residual says how far it got.
    IterationLimit,
}

/// The contact at one mean pressure.
#[derive(Debug, Clone, PartialEq)]
pub struct Solution {
    /// The mean pressure asked for (Pa).
    pub pressure: f64,
    /// Pixels carrying pressure / all pixels.
    pub real_area_fraction: f64,
    /// Pixels at the hardness / all pixels (0 without a cap).
    pub plastic_area_fraction: f64,
    /// 4-connected clusters of contacting pixels, merged across the periodic edges.
    pub contact_patches: usize,
    /// The mean gap between the surfaces over the map (m); 0 where in contact.
    pub mean_gap: f64,
    /// The largest pixel pressure (Pa).
    pub max_pressure: f64,
    /// The complementarity residual at the returned pressures (dimensionless):
    /// the pressure-weighted mean |gap| over the contact, the mean
    /// interpenetration outside it and the mean open gap under saturated pixels,
    /// each over the map's rms height; the largest of the three.
    pub residual: f64,
    /// Conjugate-gradient iterations.
    pub iterations: usize,
    /// How the solve ended.
    pub outcome: Outcome,
    /// The pixel pressures (Pa), row-major, `ny` rows of `nx`.
    pub pressures: Vec<f64>,
    /// The pixel gaps (m), row-major; 0 where in contact.
    pub gaps: Vec<f64>,
}

/// A periodic rigid surface against an elastic half-space, ready to solve at
/// any number of mean pressures (the FFT plans are made once).
pub struct Solver {
    nx: usize,
    ny: usize,
    /// The heights, mean removed (m).
    heights: Vec<f64>,
    /// Their rms about the mean (m).
    rms: f64,
    /// The rms of their slope (forward differences across the periodic edges).
    slope_rms: f64,
    /// Pixel sides (m).
    dx: f64,
    dy: f64,
    /// E* (Pa).
    modulus: f64,
    compliance: Compliance,
}

impl Solver {
    /// The solver for a map of `ny` rows of `nx` heights (m, row-major, already
    /// levelled: the map is taken as one period), `dx` × `dy` pixels (m), against a
    /// half-space of composite modulus `modulus` (E*, Pa).
    pub fn new(
        nx: usize,
        ny: usize,
        dx: f64,
        dy: f64,
        heights: &[f64],
        modulus: f64,
    ) -> Result<Self, ContactError> {
        if nx < MIN_SIDE || ny < MIN_SIDE {
            return Err(ContactError::TooSmall { nx, ny });
        }
        let missing = heights.iter().filter(|h| !h.is_finite()).count();
        if missing > 0 {
            return Err(ContactError::Missing {
                missing,
                total: heights.len(),
            });
        }
        if !(dx.is_finite() && dx > 0.0 && dy.is_finite() && dy > 0.0) {
            return Err(ContactError::PixelSize { dx, dy });
        }
        if !(modulus.is_finite() && modulus > 0.0) {
            return Err(ContactError::Modulus(modulus));
        }
        debug_assert_eq!(heights.len(), nx * ny);
        let n = (nx * ny) as f64;
        let mean = heights.iter().sum::<f64>() / n;
        let heights: Vec<f64> = heights.iter().map(|h| h - mean).collect();
        let rms = (heights.iter().map(|h| h * h).sum::<f64>() / n).sqrt();
        let mut slope = 0.0;
        for j in 0..ny {
            for i in 0..nx {
                let here = heights[j * nx + i];
                let sx = (heights[j * nx + (i + 1) % nx] - here) / dx;
                let sy = (heights[((j + 1) % ny) * nx + i] - here) / dy;
                slope += sx * sx + sy * sy;
            }
        }
        Ok(Solver {
            nx,
            ny,
            heights,
            rms,
            slope_rms: (slope / n).sqrt(),
            dx,
            dy,
            modulus,
            compliance: Compliance::new(nx, ny, dx, dy, modulus),
        })
    }

    /// Points along x and along y.
    pub fn shape(&self) -> (usize, usize) {
        (self.nx, self.ny)
    }

    /// The contact at mean pressure `pressure` (Pa). `start`, a previous
    /// solution's pressures, seeds the iteration (rescaled to the new mean).
    ///
    /// The solve runs on a worker of rayon's pool: its parallel loops (the
    /// FFTs') then start from inside the pool, instead of each one waking a
    /// worker and parking the calling thread.
    pub fn solve(
        &mut self,
        pressure: f64,
        settings: &Settings,
        start: Option<&[f64]>,
    ) -> Result<Solution, ContactError> {
        on_pool_worker(|| self.solve_in_pool(pressure, settings, start))
    }

    fn solve_in_pool(
        &mut self,
        pressure: f64,
        settings: &Settings,
        start: Option<&[f64]>,
    ) -> Result<Solution, ContactError> {
        let cap = settings.hardness;
        if !(pressure.is_finite() && pressure > 0.0) {
            return Err(ContactError::Pressure(pressure));
        }
        if cap.is_nan() || cap <= 0.0 {
            return Err(ContactError::Hardness(cap));
        }
        if pressure >= cap {
            return Err(ContactError::AboveHardness {
                pressure,
                hardness: cap,
            });
        }
        let n = self.nx * self.ny;
        if self.rms == 0.0 {
            // A flat map: uniform pressure, no gap.
            return Ok(self.finish(
                pressure,
                vec![pressure; n],
                vec![0.0; n],
                0.0,
                0,
                Outcome::Converged,
                cap,
            ));
        }
        let mut p: Vec<f64> = match start {
            Some(s) if s.len() == n && s.iter().any(|&x| x > 0.0) => {
                s.iter().map(|&x| x.clamp(0.0, cap)).collect()
            }
            _ => vec![pressure; n],
        };
        let mut g = vec![0.0; n];
        let (iterations, residual, outcome) = if cap.is_finite() {
            // The conjugate scheme, and should it not converge (its active
            // sets could cycle), the projected gradient from where it stopped:
            // slower, but convergent on this convex problem.
            let (first, residual, outcome) =
                self.capped_conjugate(&mut p, &mut g, pressure, cap, settings);
            if outcome == Outcome::Converged {
                (first, residual, outcome)
            } else {
                let (more, residual, outcome) =
                    self.capped_projected(&mut p, &mut g, pressure, cap, settings);
                (first + more, residual, outcome)
            }
        } else {
            self.polonsky_keer(&mut p, &mut g, pressure, settings)
        };
        let gaps: Vec<f64> = g
            .iter()
            .zip(&p)
            .map(|(&gi, &pi)| if pi > 0.0 { 0.0 } else { gi.max(0.0) })
            .collect();
        Ok(self.finish(pressure, p, gaps, residual, iterations, outcome, cap))
    }

    /// The gap `g = K p − h − offset` of pressures `p`, its offset fixed where
    /// 0 < p < cap (else where p > 0): the Lagrange multiplier of the mean.
    fn gap(&mut self, p: &[f64], g: &mut [f64], cap: f64) {
        self.compliance.apply(p, g);
        for (g, h) in g.iter_mut().zip(&self.heights) {
            *g -= h;
        }
        let offset = mean_where(g, p, |x| x > 0.0 && x < cap)
            .or_else(|| mean_where(g, p, |x| x > 0.0))
            .unwrap_or(0.0);
        g.iter_mut().for_each(|x| *x -= offset);
    }

    /// Polonsky & Keer's constrained conjugate gradient (elastic): `p` in, the
    /// solution's pressures and gaps out. The element-wise work of an iteration
    /// is fused into five passes, and the displacement of the new pressures is
    /// updated by linearity (`K(s(p − τt)) = s(Kp − τKt)`) whenever the step
    /// neither clamped nor loaded a pixel, which saves one of its two
    /// convolutions; convergence is only ever declared on a fresh `K p`.
    fn polonsky_keer(
        &mut self,
        p: &mut [f64],
        g: &mut [f64],
        pressure: f64,
        settings: &Settings,
    ) -> (usize, f64, Outcome) {
        let n = p.len();
        let h = &self.heights;
        scale_mean(p, pressure);
        let mut u = vec![0.0; n];
        let mut t = vec![0.0; n];
        let mut r = vec![0.0; n];
        self.compliance.apply(p, &mut u);
        let mut fresh = true;
        let mut conjugate = false;
        let mut g_norm_old = 1.0;
        let mut iterations = 0;
        loop {
            // The gap, its offset the mean over the contact.
            let [sum, count] = lane_sum(n, |i| {
                g[i] = u[i] - h[i];
                let m = mask(p[i]);
                [m * g[i], m]
            });
            let offset = if count > 0.0 { sum / count } else { 0.0 };
            let count = count as usize;
            let [weighted, load, g_norm, overlap_sum] = lane_sum(n, |i| {
                g[i] -= offset;
                let (gi, pi) = (g[i], p[i]);
                let m = mask(pi);
                [pi * gi.abs(), pi, m * gi * gi, (1.0 - m) * (-gi).max(0.0)]
            });
            let contact = if load > 0.0 { weighted / load } else { 0.0 };
            let residual = contact.max(overlap_sum / n as f64) / self.rms;
            if residual <= settings.tolerance || iterations >= settings.max_iterations {
                if !fresh {
                    self.compliance.apply(p, &mut u);
                    fresh = true;
                    continue;
                }
                let outcome = if residual <= settings.tolerance {
                    Outcome::Converged
                } else {
                    Outcome::IterationLimit
                };
                return (iterations, residual, outcome);
            }
            iterations += 1;
            // The conjugate direction on the contact.
            let beta = if conjugate { g_norm / g_norm_old } else { 0.0 };
            g_norm_old = g_norm;
            for ((ti, &pi), &gi) in t.iter_mut().zip(p.iter()).zip(g.iter()) {
                *ti = if pi > 0.0 { gi + beta * *ti } else { 0.0 };
            }
            self.compliance.apply(&t, &mut r);
            let [r_sum, t_sum, gt, rt] = lane_sum(n, |i| {
                let (ti, ri) = (t[i], r[i]);
                // t is zero off the contact.
                [mask(p[i]) * ri, ti, g[i] * ti, ri * ti]
            });
            // Σ (r − r̄) t over the contact, r̄ its mean there.
            let rt = rt - r_sum / count.max(1) as f64 * t_sum;
            let tau = if rt > 0.0 { gt / rt } else { 0.0 };
            // The step; pixels it empties are clamped, pixels that overlap with
            // no pressure are loaded by the gradient step (and the conjugate
            // sequence restarts).
            let (mut clamped, mut overlap, mut total) = (false, false, 0.0);
            for ((pi, &ti), &gi) in p.iter_mut().zip(&t).zip(g.iter()) {
                if *pi > 0.0 {
                    let next = *pi - tau * ti;
                    if next < 0.0 {
                        clamped = true;
                        *pi = 0.0;
                    } else {
                        *pi = next;
                    }
                } else if gi < 0.0 {
                    *pi = -tau * gi;
                    overlap = true;
                }
                total += *pi;
            }
            conjugate = !overlap;
            let s = if total > 0.0 {
                pressure * n as f64 / total
            } else {
                1.0
            };
            if clamped || overlap || total <= 0.0 {
                if total <= 0.0 {
                    p.iter_mut().for_each(|x| *x = pressure);
                } else {
                    p.iter_mut().for_each(|x| *x *= s);
                }
                self.compliance.apply(p, &mut u);
                fresh = true;
            } else {
                for ((pi, ui), &ri) in p.iter_mut().zip(u.iter_mut()).zip(&r) {
                    *pi *= s;
                    *ui = s * (*ui - tau * ri);
                }
                fresh = false;
            }
        }
    }

    /// The capped contact by Polonsky & Keer's scheme with a second bound:
    /// pixels at the cap carry H and leave the conjugate set like empty ones;
    /// a saturated pixel whose gap opens is unloaded by the gradient step; the
    /// mean is restored by a shift of the free pixels.
    fn capped_conjugate(
        &mut self,
        p: &mut [f64],
        g: &mut [f64],
        pressure: f64,
        cap: f64,
        settings: &Settings,
    ) -> (usize, f64, Outcome) {
        let n = p.len();
        restore_capped_mean(p, pressure, cap);
        let mut t = vec![0.0; n];
        let mut r = vec![0.0; n];
        let mut conjugate = false;
        let mut g_norm_old = 1.0;
        let mut iterations = 0;
        let mut best = (f64::INFINITY, 0);
        loop {
            self.gap(p, g, cap);
            let residual = self.residual(p, g, cap);
            if residual <= settings.tolerance {
                return (iterations, residual, Outcome::Converged);
            }
            // A stall (no new best residual for STALL iterations) is a cycle of
            // active sets: hand over to the projected gradient.
            if residual < best.0 {
                best = (residual, iterations);
            }
            if iterations >= settings.max_iterations || iterations - best.1 > STALL {
                return (iterations, residual, Outcome::IterationLimit);
            }
            iterations += 1;
            let saturated = !p.iter().any(|&x| x > 0.0 && x < cap);
            let moves = |x: f64| x > 0.0 && (x < cap || saturated);
            let mut g_norm = 0.0;
            for (&pi, &gi) in p.iter().zip(g.iter()) {
                if moves(pi) {
                    g_norm += gi * gi;
                }
            }
            let beta = if conjugate && !saturated {
                g_norm / g_norm_old
            } else {
                0.0
            };
            g_norm_old = g_norm;
            for ((ti, &pi), &gi) in t.iter_mut().zip(p.iter()).zip(g.iter()) {
                *ti = if moves(pi) { gi + beta * *ti } else { 0.0 };
            }
            self.compliance.apply(&t, &mut r);
            let r_offset = mean_where(&r, p, moves).unwrap_or(0.0);
            let (mut gt, mut rt) = (0.0, 0.0);
            for (((&pi, &gi), &ti), &ri) in p.iter().zip(g.iter()).zip(&t).zip(&r) {
                if moves(pi) {
                    gt += gi * ti;
                    rt += (ri - r_offset) * ti;
                }
            }
            let tau = if rt > 0.0 { gt / rt } else { 0.0 };
            let mut overlap = false;
            for ((pi, &ti), &gi) in p.iter_mut().zip(&t).zip(g.iter()) {
                if moves(*pi) {
                    *pi = (*pi - tau * ti).clamp(0.0, cap);
                } else if (*pi == 0.0 && gi < 0.0) || (*pi == cap && gi > 0.0) {
                    *pi = (*pi - tau * gi).clamp(0.0, cap);
                    overlap = true;
                }
            }
            conjugate = !overlap;
            restore_capped_mean(p, pressure, cap);
        }
    }

    /// The capped (perfectly plastic) contact by a projected gradient with
    /// Nesterov's acceleration and adaptive restart (O'Donoghue & Candès 2015) on
    /// the convex problem min ½ pᵀKp − hᵀp over {0 ≤ p ≤ H, mean p = p̄}, the
    /// projection exact. One convolution per iteration: K is linear, so K of the
    /// extrapolated point is combined from the last two.
    fn capped_projected(
        &mut self,
        p: &mut [f64],
        g: &mut [f64],
        pressure: f64,
        cap: f64,
        settings: &Settings,
    ) -> (usize, f64, Outcome) {
        let n = p.len();
        // 1 / (the largest eigenvalue of K): 2 / (E* q_min), q_min = 2π / the
        // longer side.
        let step = 1.0 / self.compliance.largest_eigenvalue();
        project(p, pressure, cap);
        let mut kp = vec![0.0; n];
        self.compliance.apply(p, &mut kp);
        let mut p_old = p.to_vec();
        let mut kp_old = kp.clone();
        let mut y = vec![0.0; n];
        let mut momentum = 1.0_f64;
        let mut iterations = 0;
        loop {
            self.gap(p, g, cap);
            let residual = self.residual(p, g, cap);
            if residual <= settings.tolerance {
                return (iterations, residual, Outcome::Converged);
            }
            if iterations >= settings.max_iterations {
                return (iterations, residual, Outcome::IterationLimit);
            }
            iterations += 1;
            let next = 0.5 * (1.0 + (1.0 + 4.0 * momentum * momentum).sqrt());
            let beta = (momentum - 1.0) / next;
            momentum = next;
            // y = p + β (p − p_old); its gradient K y − h, a step down it, projected.
            for i in 0..n {
                let ky = kp[i] + beta * (kp[i] - kp_old[i]);
                y[i] = p[i] + beta * (p[i] - p_old[i]) - step * (ky - self.heights[i]);
            }
            project(&mut y, pressure, cap);
            // Restart when the step goes uphill: (y − p) · ∇f(y) > 0, tested
            // with the gradient at p (the usual gradient restart).
            let uphill: f64 = (0..n)
                .map(|i| (y[i] - p[i]) * (kp[i] - self.heights[i]))
                .sum();
            if uphill > 0.0 {
                momentum = 1.0;
            }
            p_old.copy_from_slice(p);
            p.copy_from_slice(&y);
            std::mem::swap(&mut kp_old, &mut kp);
            self.compliance.apply(p, &mut kp);
        }
    }

    /// The residual of pressures `p` and gaps `g` (see [`Solution::residual`]).
    fn residual(&self, p: &[f64], g: &[f64], cap: f64) -> f64 {
        let (mut contact, mut overlap, mut open) = (0.0, 0.0, 0.0);
        let mut load = 0.0;
        for (&pi, &gi) in p.iter().zip(g) {
            if pi > 0.0 {
                load += pi;
                if pi < cap {
                    contact += pi * gi.abs();
                } else {
                    open += gi.max(0.0);
                }
            } else {
                overlap += (-gi).max(0.0);
            }
        }
        let n = p.len() as f64;
        let contact = if load > 0.0 { contact / load } else { 0.0 };
        contact.max(overlap / n).max(open / n) / self.rms
    }

    #[allow(clippy::too_many_arguments)]
    fn finish(
        &self,
        pressure: f64,
        p: Vec<f64>,
        gaps: Vec<f64>,
        residual: f64,
        iterations: usize,
        outcome: Outcome,
        cap: f64,
    ) -> Solution {
        let n = p.len() as f64;
        let contact: Vec<bool> = p.iter().map(|&x| x > 0.0).collect();
        let in_contact = contact.iter().filter(|&&c| c).count();
        let plastic = p.iter().filter(|&&x| x >= cap).count();
        Solution {
            pressure,
            real_area_fraction: in_contact as f64 / n,
            plastic_area_fraction: plastic as f64 / n,
            contact_patches: patches::count_patches(&contact, self.nx, self.ny),
            mean_gap: gaps.iter().sum::<f64>() / n,
            max_pressure: p.iter().copied().fold(0.0, f64::max),
            residual,
            iterations,
            outcome,
            pressures: p,
            gaps,
        }
    }
}

/// Runs `f` on a worker thread of rayon's pool (directly when already on one).
/// A solve makes three parallel loops per convolution, hundreds a solve: from
/// outside the pool each one parks the caller and wakes a worker, which on a
/// 512² map costs a fifth of the solve's time; from inside, none does. The
/// arithmetic, and so every number, is the same either way.
fn on_pool_worker<R: Send>(f: impl FnOnce() -> R + Send) -> R {
    rayon::scope(|_| f())
}

/// The mean of `x` over the pixels whose pressure satisfies `keep`; None if none does.
fn mean_where(x: &[f64], p: &[f64], keep: impl Fn(f64) -> bool) -> Option<f64> {
    let (mut sum, mut count) = (0.0, 0usize);
    for (&xi, &pi) in x.iter().zip(p) {
        if keep(pi) {
            sum += xi;
            count += 1;
        }
    }
    (count > 0).then(|| sum / count as f64)
}

/// 1 where a pixel carries pressure (or, in the adhesive scheme, where its gap
/// is open), else 0: a multiplier, so that the sums have no branches.
fn mask(p: f64) -> f64 {
    if p > 0.0 {
        1.0
    } else {
        0.0
    }
}

/// The sums of `f(i)` over `0..n`, accumulated in four interleaved lanes (i mod 4;
/// the tail in lane 0) and added as (l0 + l1) + (l2 + l3): a fixed order, the
/// same on every machine and thread count, and four additions in flight instead
/// of one chain.
fn lane_sum<const K: usize>(n: usize, mut f: impl FnMut(usize) -> [f64; K]) -> [f64; K] {
    let mut acc = [[0.0; K]; 4];
    let full = n / 4 * 4;
    let mut i = 0;
    while i < full {
        for (l, lane) in acc.iter_mut().enumerate() {
            let v = f(i + l);
            for (a, x) in lane.iter_mut().zip(v) {
                *a += x;
            }
        }
        i += 4;
    }
    for j in full..n {
        let v = f(j);
        for (a, x) in acc[0].iter_mut().zip(v) {
            *a += x;
        }
    }
    let mut out = [0.0; K];
    for (k, o) in out.iter_mut().enumerate() {
        *o = (acc[0][k] + acc[1][k]) + (acc[2][k] + acc[3][k]);
    }
    out
}

/// Scales the field to mean `target` (Polonsky & Keer's load step; the gaps'
/// mean in the adhesive scheme, its zeros kept in contact).
fn scale_mean(p: &mut [f64], target: f64) {
    let n = p.len() as f64;
    let sum: f64 = p.iter().sum();
    if sum <= 0.0 {
        p.iter_mut().for_each(|x| *x = target);
    } else {
        let s = target * n / sum;
        p.iter_mut().for_each(|x| *x *= s);
    }
}

/// Restores the mean to `target` under the cap: by a shift of the free pixels,
/// and where those cannot carry it (too few loaded pixels, even at the cap), by
/// the projection onto {0 ≤ p ≤ cap, mean = target} over every pixel, which
/// loads new ones.
fn restore_capped_mean(p: &mut [f64], target: f64, cap: f64) {
    shift_mean(p, target, cap);
    let mean = p.iter().sum::<f64>() / p.len() as f64;
    if (mean - target).abs() > 1e-12 * target {
        project(p, target, cap);
    }
}

/// Restores the mean to `target` by a shift of the free pixels (0 < p < cap),
/// each kept in [0, cap]; of every loaded pixel when none is free.
fn shift_mean(p: &mut [f64], target: f64, cap: f64) {
    let goal = target * p.len() as f64;
    let any_free = p.iter().any(|&x| x > 0.0 && x < cap);
    let moves = |x: f64| x > 0.0 && (x < cap || !any_free);
    let fixed: f64 = p.iter().filter(|&&x| !moves(x)).sum();
    let total = |lambda: f64| -> (f64, f64) {
        let (mut value, mut slope) = (fixed, 0.0);
        for &x in p.iter().filter(|&&x| moves(x)) {
            let y = x + lambda;
            if y >= cap {
                value += cap;
            } else if y > 0.0 {
                value += y;
                slope += 1.0;
            }
        }
        (value - goal, slope)
    };
    let (lo0, hi0) = p
        .iter()
        .filter(|&&x| moves(x))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    if !lo0.is_finite() {
        return;
    }
    let (mut lo, mut hi) = (-hi0, cap - lo0);
    let mut lambda = 0.0_f64.clamp(lo, hi);
    for _ in 0..200 {
        let (f, slope) = total(lambda);
        if f.abs() <= 1e-15 * goal {
            break;
        }
        if f < 0.0 {
            lo = lambda;
        } else {
            hi = lambda;
        }
        let newton = if slope > 0.0 {
            lambda - f / slope
        } else {
            f64::NAN
        };
        lambda = if newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        if hi - lo <= 1e-16 * (hi.abs() + lo.abs()) {
            break;
        }
    }
    p.iter_mut().for_each(|x| {
        if moves(*x) {
            *x = (*x + lambda).clamp(0.0, cap);
        }
    });
}

/// The Euclidean projection onto {0 ≤ p ≤ cap, mean p = target}:
/// p ← clamp(p − λ, 0, cap) with λ the root of a decreasing piecewise-linear
/// function (Newton's steps kept inside a bisection bracket; exact once the
/// active set is found). Needs 0 < target < cap.
fn project(p: &mut [f64], target: f64, cap: f64) {
    let goal = target * p.len() as f64;
    let total = |lambda: f64| -> (f64, f64) {
        let (mut value, mut slope) = (0.0, 0.0);
        for &x in p.iter() {
            let y = x - lambda;
            if y >= cap {
                value += cap;
            } else if y > 0.0 {
                value += y;
                slope += 1.0;
            }
        }
        (value - goal, slope)
    };
    let (min, max) = p
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    // At λ = min − cap every pixel is at the cap (too much), at λ = max none
    // carries anything (too little).
    let (mut lo, mut hi) = (min - cap, max);
    let mut lambda = 0.0_f64.clamp(lo, hi);
    for _ in 0..200 {
        let (f, slope) = total(lambda);
        if f.abs() <= 1e-15 * goal {
            break;
        }
        if f > 0.0 {
            lo = lambda;
        } else {
            hi = lambda;
        }
        let newton = if slope > 0.0 {
            lambda + f / slope
        } else {
            f64::NAN
        };
        lambda = if newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        if hi - lo <= 1e-16 * (hi.abs() + lo.abs()) {
            break;
        }
    }
    p.iter_mut()
        .for_each(|x| *x = (*x - lambda).clamp(0.0, cap));
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// h = amplitude cos(2πx/λ) along x, one wavelength λ over `nx` pixels, `ny` rows.
    fn sinusoid(nx: usize, ny: usize, amplitude: f64) -> Vec<f64> {
        (0..nx * ny)
            .map(|i| amplitude * (2.0 * PI * (i % nx) as f64 / nx as f64).cos())
            .collect()
    }

    /// Westergaard (Johnson, Contact Mechanics §13.2): above p* = π E* g / λ the
    /// contact is full and p(x) = p̄ + p* cos(2πx/λ) — on the grid too, since a
    /// grid cosine is an eigenvector of the discrete kernel.
    #[test]
    fn full_contact_of_a_sinusoid_is_westergaards() {
        let (nx, ny, lambda, g, e) = (64, 8, 1e-6, 1e-9, 1e11);
        let dx = lambda / nx as f64;
        let heights = sinusoid(nx, ny, g);
        let mut solver = Solver::new(nx, ny, dx, dx, &heights, e).unwrap();
        let p_star = PI * e * g / lambda;
        let s = solver
            .solve(1.5 * p_star, &Settings::default(), None)
            .unwrap();
        assert_eq!(s.outcome, Outcome::Converged);
        assert_eq!(s.real_area_fraction, 1.0);
        assert_eq!(s.contact_patches, 1);
        for (i, p) in s.pressures.iter().enumerate() {
            let want = 1.5 * p_star + p_star * (2.0 * PI * (i % nx) as f64 / nx as f64).cos();
            assert!((p - want).abs() < 1e-6 * p_star, "{i}: {p} vs {want}");
        }
    }

    /// Below p*, the contact half-width a obeys p̄/p* = sin²(πa/λ) (Johnson eq.
    /// 13.11): area fraction 2a/λ = (2/π) arcsin √(p̄/p*), within 1 % (a pixel
    /// is 0.1 % of λ here).
    #[test]
    fn partial_contact_of_a_sinusoid_matches_johnson() {
        let (nx, ny, lambda, g, e) = (1024, 8, 1e-6, 1e-9, 1e11);
        let dx = lambda / nx as f64;
        let heights = sinusoid(nx, ny, g);
        let mut solver = Solver::new(nx, ny, dx, dx, &heights, e).unwrap();
        let p_star = PI * e * g / lambda;
        let mut start: Option<Vec<f64>> = None;
        for ratio in [0.05, 0.2, 0.5, 0.8] {
            let s = solver
                .solve(ratio * p_star, &Settings::default(), start.as_deref())
                .unwrap();
            assert_eq!(s.outcome, Outcome::Converged, "{ratio}: {}", s.residual);
            let want = 2.0 / PI * ratio.sqrt().asin();
            let err = (s.real_area_fraction - want).abs() / want;
            assert!(
                err < 0.01,
                "p̄/p* = {ratio}: {} vs {want}",
                s.real_area_fraction
            );
            assert_eq!(s.contact_patches, 1);
            start = Some(s.pressures);
        }
    }

    /// A paraboloid h = −r²/(2R) pressed by F = p̄ L²: Hertz's radius
    /// a = (3FR / 4E*)^{1/3}; the pixel area converges on πa² as the grid refines
    /// (the periodic images a few radii away stiffen it by well under 1 %).
    #[test]
    fn a_sphere_approaches_hertz() {
        let (l, radius, e): (f64, f64, f64) = (1e-6, 2e-6, 1e11);
        let force: f64 = 1.3e-4;
        let a = (3.0 * force * radius / (4.0 * e)).cbrt();
        let mut errors = Vec::new();
        for n in [64, 128, 256] {
            let dx = l / n as f64;
            let heights: Vec<f64> = (0..n * n)
                .map(|i| {
                    let x = (i % n) as f64 * dx - l / 2.0;
                    let y = (i / n) as f64 * dx - l / 2.0;
                    -(x * x + y * y) / (2.0 * radius)
                })
                .collect();
            let mut solver = Solver::new(n, n, dx, dx, &heights, e).unwrap();
            let s = solver
                .solve(force / (l * l), &Settings::default(), None)
                .unwrap();
            assert_eq!(s.outcome, Outcome::Converged);
            assert_eq!(s.contact_patches, 1);
            let area = s.real_area_fraction * l * l;
            errors.push((area / (PI * a * a) - 1.0).abs());
            // Hertz's peak pressure 3F/(2πa²), within the grid's reach.
            let p0 = 3.0 * force / (2.0 * PI * a * a);
            assert!(
                (s.max_pressure / p0 - 1.0).abs() < 0.05,
                "{n}: {} vs {p0}",
                s.max_pressure
            );
        }
        assert!(errors[2] < 0.03, "{errors:?}");
        assert!(errors[2] < errors[0], "{errors:?}");
    }

    /// A cap at H bounds every pixel and the mean still holds; pixels at the cap
    /// are counted plastic and the elastic solve is recovered for H = ∞.
    #[test]
    fn the_hardness_caps_the_pressure() {
        let (nx, ny, lambda, g, e) = (256, 8, 1e-6, 1e-9, 1e11);
        let dx = lambda / nx as f64;
        let heights = sinusoid(nx, ny, g);
        let mut solver = Solver::new(nx, ny, dx, dx, &heights, e).unwrap();
        let p_star = PI * e * g / lambda;
        let elastic = solver
            .solve(0.3 * p_star, &Settings::default(), None)
            .unwrap();
        let hardness = 0.6 * elastic.max_pressure;
        let settings = Settings {
            hardness,
            ..Settings::default()
        };
        let capped = solver.solve(0.3 * p_star, &settings, None).unwrap();
        assert_eq!(capped.outcome, Outcome::Converged, "{}", capped.residual);
        assert!(capped.max_pressure <= hardness);
        assert!(capped.plastic_area_fraction > 0.0);
        let mean = capped.pressures.iter().sum::<f64>() / (nx * ny) as f64;
        assert!((mean / (0.3 * p_star) - 1.0).abs() < 1e-12);
        // Spreading the load widens the contact.
        assert!(capped.real_area_fraction > elastic.real_area_fraction);
    }

    #[test]
    fn bad_input_is_refused() {
        let h = vec![0.0; 64];
        assert!(matches!(
            Solver::new(8, 7, 1.0, 1.0, &h[..56], 1.0),
            Err(ContactError::TooSmall { .. })
        ));
        let mut nan = h.clone();
        nan[3] = f64::NAN;
        assert!(matches!(
            Solver::new(8, 8, 1.0, 1.0, &nan, 1.0),
            Err(ContactError::Missing {
                missing: 1,
                total: 64
            })
        ));
        assert!(Solver::new(8, 8, 1.0, 1.0, &h, 0.0).is_err());
        let mut s = Solver::new(8, 8, 1.0, 1.0, &h, 1.0).unwrap();
        assert!(s.solve(0.0, &Settings::default(), None).is_err());
        let capped = Settings {
            hardness: 1.0,
            ..Settings::default()
        };
        assert!(s.solve(1.0, &capped, None).is_err());
        // A flat map: full contact at the mean pressure.
        let flat = s.solve(0.5, &Settings::default(), None).unwrap();
        assert_eq!(flat.real_area_fraction, 1.0);
        assert_eq!(flat.max_pressure, 0.5);
    }

    /// The capped contact has one solution (the problem is strictly convex):
    /// the conjugate scheme and the accelerated projected gradient, two
    /// independent methods, reach the same pressures on a random surface.
    #[test]
    fn two_methods_agree_on_a_capped_random_surface() {
        use crate::surface::synthetic::{random_surface, Spectrum};
        let n = 64;
        let pixel = 1.0 / n as f64;
        let map = random_surface(
            n,
            pixel,
            Spectrum::SelfAffine {
                hurst: 0.8,
                rolloff: 2.0 * PI * 4.0,
                cutoff: 2.0 * PI * 16.0,
            },
            1.0,
            3,
        )
        .unwrap();
        let mut solver = Solver::new(n, n, pixel, pixel, map.heights(), 1.0).unwrap();
        let pressure = 0.5;
        let elastic = solver.solve(pressure, &Settings::default(), None).unwrap();
        let settings = Settings {
            hardness: 0.4 * elastic.max_pressure,
            tolerance: 1e-12,
            ..Settings::default()
        };
        let mut results = Vec::new();
        for projected in [false, true] {
            let mut p = vec![pressure; n * n];
            let mut g = vec![0.0; n * n];
            let (_, residual, outcome) = if projected {
                solver.capped_projected(&mut p, &mut g, pressure, settings.hardness, &settings)
            } else {
                solver.capped_conjugate(&mut p, &mut g, pressure, settings.hardness, &settings)
            };
            assert_eq!(outcome, Outcome::Converged, "{projected}: {residual}");
            results.push(p);
        }
        let plastic = results[0]
            .iter()
            .filter(|&&x| x == settings.hardness)
            .count();
        assert!(plastic > 10, "{plastic} saturated pixels");
        for (a, b) in results[0].iter().zip(&results[1]) {
            assert!((a - b).abs() < 1e-6 * settings.hardness, "{a} vs {b}");
        }
    }

    /// A cap barely above the mean pressure: nearly every pixel must carry
    /// nearly H, and the mean is held whatever the active set (a stalled shift of
    /// the few loaded pixels once returned one pixel at H, "converged").
    #[test]
    fn a_cap_just_above_the_mean_loads_the_whole_map() {
        let (nx, ny, lambda, g, e) = (64, 8, 1e-6, 1e-9, 1e11);
        let dx = lambda / nx as f64;
        let heights = sinusoid(nx, ny, g);
        let mut solver = Solver::new(nx, ny, dx, dx, &heights, e).unwrap();
        let pressure = 1e6;
        for factor in [1.0000001, 1.01, 1.5] {
            let settings = Settings {
                hardness: factor * pressure,
                ..Settings::default()
            };
            let s = solver.solve(pressure, &settings, None).unwrap();
            assert_eq!(s.outcome, Outcome::Converged, "{factor}");
            let mean = s.pressures.iter().sum::<f64>() / (nx * ny) as f64;
            assert!((mean / pressure - 1.0).abs() < 1e-12, "{factor}: {mean}");
            assert!(s.real_area_fraction >= 1.0 / factor - 1e-12, "{factor}");
        }
    }
}
