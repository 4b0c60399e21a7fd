//! Adhesion in the boundary-element contact: an attractive surface interaction
//! of finite range, solved by the constrained conjugate gradient of Rey,
//! Anciaux & Molinari (Comput. Mech. 60, 2017) on the gap (docs/contact.md).
//!
//! The interaction is the exponential law: an energy `−γ e^{−g/ρ}` per unit
//! area at gap `g`, a tensile traction `(γ/ρ) e^{−g/ρ}`, work of adhesion `γ`
//! (the energy to separate unit area from contact to infinity), range `ρ`. For
//! an imposed mean gap `ḡ` the gaps minimise
//! `Π(g) = ½ ⟨g + h, K⁻¹(g + h)⟩ − γ Σ e^{−g/ρ}` over `g ≥ 0`, `mean g = ḡ`;
//! the mean pressure is the multiplier of the mean. The functional is convex at
//! the pixel scale when the stiffness of the finest mode, `E* π / (2 Δx)`,
//! exceeds the law's largest curvature `γ/ρ²`: the same condition, up to a
//! factor, as the cohesive (process) zone `π E* ρ² / (4γ)` spanning a few
//! pixels ([`Solver::resolution`]). A given mean pressure is reached along the
//! approach (the bodies brought together from out of range), and the pull-off
//! of the map is the most tensile mean pressure on the way back out.

use std::f64::consts::PI;

use super::{lane_sum, mask, patches, scale_mean, ContactError, Outcome, Settings, Solver};

/// Process-zone pixels (along the coarser axis) at which the range counts as
/// resolved; below, the solve is refused unless the range is coarse-grained.
pub const RESOLVED_PIXELS: f64 = 3.0;

/// Process-zone pixels below which a resolved solve is still called marginal.
pub const WELL_RESOLVED_PIXELS: f64 = 6.0;

/// Mean-gap steps of a sweep before it gives up.
const MAX_STEPS: usize = 20_000;

/// The exponential adhesion law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Adhesion {
    /// γ, the work of adhesion (J/m²).
    pub work: f64,
    /// ρ, the range (m).
    pub range: f64,
}

impl Adhesion {
    /// The law of work `work` (J/m²) and range `range` (m), both positive and finite.
    pub fn new(work: f64, range: f64) -> Result<Self, ContactError> {
        if !(work.is_finite() && work > 0.0) {
            return Err(ContactError::Adhesion {
                what: "work of adhesion",
                value: work,
                unit: "J/m²",
            });
        }
        if !(range.is_finite() && range > 0.0) {
            return Err(ContactError::Adhesion {
                what: "adhesion range",
                value: range,
                unit: "m",
            });
        }
        Ok(Adhesion { work, range })
    }

    /// The tensile traction at gap `gap` (Pa, ≥ 0): `(γ/ρ) e^{−g/ρ}`.
    pub fn traction(&self, gap: f64) -> f64 {
        self.work / self.range * (-gap / self.range).exp()
    }

    /// The largest tensile traction, at contact: `γ/ρ` (Pa).
    pub fn peak_stress(&self) -> f64 {
        self.work / self.range
    }

    /// The cohesive-zone length of a crack front under this law on a half-space
    /// of composite modulus `modulus` (m): Maugis–Dugdale's `π E* γ / (4 σ₀²)`
    /// with `σ₀ = γ/ρ`, that is `π E* ρ² / (4γ)`.
    pub fn process_zone(&self, modulus: f64) -> f64 {
        PI * modulus * self.range * self.range / (4.0 * self.work)
    }

    /// The range whose process zone is `length` (m) at the same work:
    /// `√(4 γ length / (π E*))`.
    pub fn range_for_process_zone(work: f64, modulus: f64, length: f64) -> f64 {
        (4.0 * work * length / (PI * modulus)).sqrt()
    }
}

/// How well a map's pixels resolve an adhesion law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Resolution {
    /// The process zone (m), [`Adhesion::process_zone`].
    pub process_zone: f64,
    /// It over the coarser pixel side.
    pub process_zone_pixels: f64,
    /// The coarser pixel side over ρ.
    pub pixel_over_range: f64,
    /// The rms height rise from one pixel to the next (rms slope × pixel side) over ρ.
    pub rise_over_range: f64,
}

impl Resolution {
    /// Whether the process zone spans [`RESOLVED_PIXELS`] pixels.
    pub fn resolved(&self) -> bool {
        self.process_zone_pixels >= RESOLVED_PIXELS
    }
}

/// An adhesive contact at one mean gap.
#[derive(Debug, Clone, PartialEq)]
pub struct AdhesiveSolution {
    /// The mean gap (m), imposed.
    pub mean_gap: f64,
    /// The mean pressure (Pa): contact pressure less adhesive traction; negative
    /// in tension.
    pub pressure: f64,
    /// The mean adhesive traction over the map (Pa, ≥ 0): the part of the load
    /// the attraction pulls.
    pub adhesive_pressure: f64,
    /// Pixels in contact (zero gap) / all pixels.
    pub real_area_fraction: f64,
    /// 4-connected clusters of contacting pixels, merged across the periodic edges.
    pub contact_patches: usize,
    /// The largest pixel pressure (Pa, net of the adhesive traction).
    pub max_pressure: f64,
    /// The largest pixel tension (Pa, ≥ 0).
    pub max_tension: f64,
    /// The rms force imbalance over the map (the gradient of the energy on the
    /// open pixels, its negative part on the contacting ones) over the pressure
    /// scale `max(E* h'_rms / 2, γ/ρ)`.
    pub residual: f64,
    /// Conjugate-gradient iterations.
    pub iterations: usize,
    /// How the solve ended.
    pub outcome: Outcome,
    /// The pixel pressures (Pa, net; negative where the attraction pulls), row-major.
    pub pressures: Vec<f64>,
    /// The pixel gaps (m), row-major; 0 in contact.
    pub gaps: Vec<f64>,
}

/// The pull-off of a map: the most tensile mean pressure on the way out.
#[derive(Debug, Clone, PartialEq)]
pub struct PullOff {
    /// The most tensile mean pressure met (Pa, ≤ 0).
    pub pressure: f64,
    /// The mean gap where it was met (m).
    pub mean_gap: f64,
    /// The contact fraction there.
    pub real_area_fraction: f64,
    /// Mean-gap steps taken (the coarse sweep and the refinement about the minimum).
    pub steps: usize,
    /// The coarse step (m); the refinement took an eighth of it.
    pub step: f64,
    /// Conjugate-gradient iterations, all steps.
    pub iterations: usize,
    /// `Converged` when every step converged.
    pub outcome: Outcome,
}

impl Solver {
    /// How the map's pixels resolve `adhesion` against this solver's E*.
    pub fn resolution(&self, adhesion: &Adhesion) -> Resolution {
        let pixel = self.dx.max(self.dy);
        let process_zone = adhesion.process_zone(self.modulus);
        Resolution {
            process_zone,
            process_zone_pixels: process_zone / pixel,
            pixel_over_range: pixel / adhesion.range,
            rise_over_range: self.slope_rms * pixel / adhesion.range,
        }
    }

    /// The coarser pixel side (m).
    pub fn pixel(&self) -> f64 {
        self.dx.max(self.dy)
    }

    /// The composite modulus E* (Pa).
    pub fn modulus(&self) -> f64 {
        self.modulus
    }

    /// The adhesive contact at mean gap `mean_gap` (m, > 0). `start`, a previous
    /// solution's gaps, seeds the iteration (its open gaps shifted to the new
    /// mean, its contact kept); without
    /// it the iteration starts from the undeformed gaps (the map's shape, its
    /// negative part cut to contact). `settings.hardness` is not used: the
    /// adhesive contact is elastic.
    pub fn adhesive_at_gap(
        &mut self,
        mean_gap: f64,
        adhesion: &Adhesion,
        settings: &Settings,
        start: Option<&[f64]>,
    ) -> Result<AdhesiveSolution, ContactError> {
        super::on_pool_worker(|| self.adhesive_at_gap_in_pool(mean_gap, adhesion, settings, start))
    }

    fn adhesive_at_gap_in_pool(
        &mut self,
        mean_gap: f64,
        adhesion: &Adhesion,
        settings: &Settings,
        start: Option<&[f64]>,
    ) -> Result<AdhesiveSolution, ContactError> {
        if !(mean_gap.is_finite() && mean_gap > 0.0) {
            return Err(ContactError::MeanGap(mean_gap));
        }
        let n = self.nx * self.ny;
        let top = self.heights.iter().copied().fold(f64::MIN, f64::max);
        let mut g: Vec<f64> = match start {
            Some(s) if s.len() == n && s.iter().any(|&x| x > 0.0) => {
                // The open pixels moved together to the new mean, the contact
                // kept (a rigid step of the body, the nearest guess to the
                // new equilibrium); any overshoot is taken back by scaling.
                let open = s.iter().filter(|&&x| x > 0.0).count() as f64;
                let shift = (mean_gap - s.iter().sum::<f64>() / n as f64) * n as f64 / open;
                s.iter()
                    .map(|&x| if x > 0.0 { (x + shift).max(0.0) } else { 0.0 })
                    .collect()
            }
            _ => self
                .heights
                .iter()
                .map(|&h| (mean_gap.max(top) - h).max(0.0))
                .collect(),
        };
        let (iterations, residual, outcome, pressure) =
            self.adhesive_conjugate(&mut g, mean_gap, adhesion, settings);
        Ok(self.adhesive_finish(
            mean_gap, pressure, g, adhesion, residual, iterations, outcome,
        ))
    }

    /// The conjugate gradient on the gaps: `g` in (any non-negative field), the
    /// solution out; returns iterations, residual, outcome and mean pressure.
    fn adhesive_conjugate(
        &mut self,
        g: &mut [f64],
        mean_gap: f64,
        adhesion: &Adhesion,
        settings: &Settings,
    ) -> (usize, f64, Outcome, f64) {
        let n = g.len();
        let scale = (0.5 * self.modulus * self.slope_rms).max(adhesion.peak_stress());
        scale_mean(g, mean_gap);
        // `elastic` holds K⁻¹(g + h); after a step that neither clamps nor opens
        // a pixel it is updated by linearity (K⁻¹(g − τt + h) = K⁻¹(g + h) − τK⁻¹t,
        // the mean untouched since t sums to zero), which saves one of the two
        // convolutions; convergence is only ever declared on a fresh one.
        let mut elastic = vec![0.0; n];
        let mut w = vec![0.0; n];
        let mut t = vec![0.0; n];
        let mut r = vec![0.0; n];
        // `recompute`: K⁻¹(g + h) to be convolved afresh at the top of the loop;
        // `exact`: it was, this iteration.
        let (mut recompute, mut exact) = (true, false);
        let mut conjugate = false;
        let mut norm_old = 1.0;
        let mut iterations = 0;
        loop {
            if recompute {
                for ((s, &gi), &hi) in w.iter_mut().zip(g.iter()).zip(&self.heights) {
                    *s = gi + hi;
                }
                self.compliance.apply_inverse(&w, &mut elastic);
                exact = true;
            }
            // The gradient of the energy, centred on the open pixels: there its
            // mean is minus the mean pressure.
            let [sum, count] = lane_sum(n, |i| {
                w[i] = elastic[i] + adhesion.traction(g[i]);
                let open = mask(g[i]);
                [open * w[i], open]
            });
            let centre = if count > 0.0 { sum / count } else { 0.0 };
            let [norm, imbalance] = lane_sum(n, |i| {
                w[i] -= centre;
                let wi = w[i];
                let open = mask(g[i]);
                let pull = (1.0 - open) * wi.min(0.0);
                [open * wi * wi, open * wi * wi + pull * pull]
            });
            let residual = (imbalance / n as f64).sqrt() / scale;
            if residual <= settings.tolerance || iterations >= settings.max_iterations {
                if !exact {
                    recompute = true;
                    continue;
                }
                let outcome = if residual <= settings.tolerance {
                    Outcome::Converged
                } else {
                    Outcome::IterationLimit
                };
                return (iterations, residual, outcome, -centre);
            }
            iterations += 1;
            let beta = if conjugate { norm / norm_old } else { 0.0 };
            norm_old = norm;
            for ((ti, &gi), &wi) in t.iter_mut().zip(g.iter()).zip(&w) {
                *ti = if gi > 0.0 { wi + beta * *ti } else { 0.0 };
            }
            self.compliance.apply_inverse(&t, &mut r);
            let [r_sum, t_sum, wt, rt] = lane_sum(n, |i| {
                let (ti, ri) = (t[i], r[i]);
                [mask(g[i]) * ri, ti, w[i] * ti, ri * ti]
            });
            // Σ (r − r̄) t over the open pixels, r̄ their mean (t is zero elsewhere).
            let rt = rt - r_sum / count.max(1.0) * t_sum;
            let tau = if rt > 0.0 { wt / rt } else { 0.0 };
            // The step; pixels it closes are clamped to contact, contacting
            // pixels the attraction or the elastic field would open are opened
            // by the gradient step (and the conjugate sequence restarts).
            let (mut opened, mut clamped) = (false, false);
            for (gi, (&ti, &wi)) in g.iter_mut().zip(t.iter().zip(&w)) {
                if *gi > 0.0 {
                    let next = *gi - tau * ti;
                    if next <= 0.0 {
                        clamped = true;
                        *gi = 0.0;
                    } else {
                        *gi = next;
                    }
                } else if wi < 0.0 {
                    *gi = -tau * wi;
                    opened = true;
                }
            }
            conjugate = !opened;
            if opened || clamped {
                scale_mean(g, mean_gap);
                recompute = true;
            } else {
                for (e, &ri) in elastic.iter_mut().zip(&r) {
                    *e -= tau * ri;
                }
                (recompute, exact) = (iterations % 64 == 0, false);
            }
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn adhesive_finish(
        &mut self,
        mean_gap: f64,
        pressure: f64,
        gaps: Vec<f64>,
        adhesion: &Adhesion,
        residual: f64,
        iterations: usize,
        outcome: Outcome,
    ) -> AdhesiveSolution {
        let n = gaps.len();
        let shifted: Vec<f64> = gaps.iter().zip(&self.heights).map(|(g, h)| g + h).collect();
        let mut p = vec![0.0; n];
        self.compliance.apply_inverse(&shifted, &mut p);
        // The elastic pressure: the mean pressure plus the stiffness's field.
        // Off the contact it balances the attraction; on it, contact pressure
        // less attraction.
        let mut pulled = 0.0;
        for (pi, &gi) in p.iter_mut().zip(&gaps) {
            *pi += pressure;
            let a = adhesion.traction(gi);
            pulled += a;
            if gi > 0.0 {
                // Converged, this is −a to the residual; written exactly.
                *pi = -a;
            }
        }
        let contact: Vec<bool> = gaps.iter().map(|&g| g <= 0.0).collect();
        let in_contact = contact.iter().filter(|&&c| c).count();
        AdhesiveSolution {
            mean_gap,
            pressure,
            adhesive_pressure: pulled / n as f64,
            real_area_fraction: in_contact as f64 / n as f64,
            contact_patches: patches::count_patches(&contact, self.nx, self.ny),
            max_pressure: p.iter().copied().fold(f64::MIN, f64::max),
            max_tension: p.iter().copied().fold(0.0, |m, x| m.max(-x)),
            residual,
            iterations,
            outcome,
            pressures: p,
            gaps,
        }
    }

    /// The adhesive contact at each mean pressure of `pressures` (Pa, positive,
    /// any order; answered in that order), reached along the approach: the mean
    /// gap brought down from out of range (the highest summit `5ρ` from the
    /// flat) in steps, each solve seeded by the last, and each pressure met by
    /// a bracketed root search on the mean gap seeded from the approach side.
    pub fn adhesive_loading(
        &mut self,
        pressures: &[f64],
        adhesion: &Adhesion,
        settings: &Settings,
    ) -> Result<Vec<AdhesiveSolution>, ContactError> {
        for &p in pressures {
            if !(p.is_finite() && p > 0.0) {
                return Err(ContactError::Pressure(p));
            }
        }
        let n = self.nx * self.ny;
        if self.rms == 0.0 {
            // A flat map: in full contact at any compressive load.
            return Ok(pressures
                .iter()
                .map(|&p| AdhesiveSolution {
                    mean_gap: 0.0,
                    pressure: p,
                    adhesive_pressure: adhesion.peak_stress(),
                    real_area_fraction: 1.0,
                    contact_patches: 1,
                    max_pressure: p,
                    max_tension: 0.0,
                    residual: 0.0,
                    iterations: 0,
                    outcome: Outcome::Converged,
                    pressures: vec![p; n],
                    gaps: vec![0.0; n],
                })
                .collect());
        }
        let mut order: Vec<usize> = (0..pressures.len()).collect();
        order.sort_by(|&a, &b| pressures[a].total_cmp(&pressures[b]));
        let mut out: Vec<Option<AdhesiveSolution>> = vec![None; pressures.len()];
        let top = self.heights.iter().copied().fold(f64::MIN, f64::max);
        let mut gap = top + 5.0 * adhesion.range;
        let mut state = self.adhesive_at_gap(gap, adhesion, settings, None)?;
        let largest_step = (0.25 * self.rms).max(adhesion.range);
        let mut step = adhesion.range;
        let mut steps = 0;
        for &k in &order {
            let target = pressures[k];
            while state.pressure < target {
                steps += 1;
                if steps > MAX_STEPS {
                    return Err(ContactError::Unreached { pressure: target });
                }
                let next_gap = gap - step;
                if next_gap <= 1e-9 * self.rms {
                    // The mean gap has closed as far as it can without the
                    // target met (the attraction can make the load fall as
                    // the last gaps close): the surfaces snap into full
                    // contact, if that is an equilibrium at the target.
                    if gap <= 1e-6 * self.rms {
                        state = self.full_contact(target, adhesion)?;
                        out[k] = Some(state.clone());
                        break;
                    }
                    step = 0.5 * gap;
                    continue;
                }
                let next = self.adhesive_at_gap(next_gap, adhesion, settings, Some(&state.gaps))?;
                if next.pressure >= target {
                    let met = self.meet_pressure(
                        target,
                        (gap, &state),
                        (next_gap, &next),
                        adhesion,
                        settings,
                    )?;
                    gap = met.mean_gap;
                    state = met;
                    out[k] = Some(state.clone());
                    break;
                }
                step = (step * 1.5).min(largest_step);
                gap = next_gap;
                state = next;
            }
            if out[k].is_none() {
                // Already past this pressure (equal pressures given twice).
                out[k] = Some(state.clone());
            }
        }
        Ok(out.into_iter().flatten().collect())
    }

    /// Full contact at mean pressure `pressure`: zero gaps, the pressures
    /// `p̄ + K⁻¹h`; an equilibrium when no pixel's contact pressure (its pressure
    /// plus the attraction at contact, γ/ρ) is negative.
    fn full_contact(
        &mut self,
        pressure: f64,
        adhesion: &Adhesion,
    ) -> Result<AdhesiveSolution, ContactError> {
        let n = self.nx * self.ny;
        let mut p = vec![0.0; n];
        self.compliance.apply_inverse(&self.heights.clone(), &mut p);
        p.iter_mut().for_each(|x| *x += pressure);
        let lowest = p.iter().copied().fold(f64::MAX, f64::min);
        if lowest + adhesion.peak_stress() < 0.0 {
            return Err(ContactError::Unreached { pressure });
        }
        let contact = vec![true; n];
        Ok(AdhesiveSolution {
            mean_gap: 0.0,
            pressure,
            adhesive_pressure: adhesion.peak_stress(),
            real_area_fraction: 1.0,
            contact_patches: patches::count_patches(&contact, self.nx, self.ny),
            max_pressure: p.iter().copied().fold(f64::MIN, f64::max),
            max_tension: (-lowest).max(0.0),
            residual: 0.0,
            iterations: 0,
            outcome: Outcome::Converged,
            pressures: p,
            gaps: vec![0.0; n],
        })
    }

    /// The state at mean pressure `target` between a mean gap `low` whose
    /// pressure is below it and `high` above (mean gaps: `low.0 > high.0`), by
    /// the Illinois variant of regula falsi on the mean gap, each trial seeded by
    /// the approach-side state.
    fn meet_pressure(
        &mut self,
        target: f64,
        low: (f64, &AdhesiveSolution),
        high: (f64, &AdhesiveSolution),
        adhesion: &Adhesion,
        settings: &Settings,
    ) -> Result<AdhesiveSolution, ContactError> {
        let (mut a, mut fa) = (low.0, low.1.pressure - target);
        let (mut b, mut fb) = (high.0, high.1.pressure - target);
        let mut seed = low.1.gaps.clone();
        let mut best = high.1.clone();
        let mut side = 0;
        for _ in 0..100 {
            if (best.pressure - target).abs() <= 1e-9 * target || (a - b).abs() <= 1e-13 * a {
                break;
            }
            let c = if fa != fb {
                b - fb * (b - a) / (fb - fa)
            } else {
                0.5 * (a + b)
            };
            let c = if c > b.min(a) && c < b.max(a) {
                c
            } else {
                0.5 * (a + b)
            };
            let trial = self.adhesive_at_gap(c, adhesion, settings, Some(&seed))?;
            let fc = trial.pressure - target;
            if fc >= 0.0 {
                b = c;
                fb = fc;
                if side == 1 {
                    fa *= 0.5;
                }
                side = 1;
                best = trial;
            } else {
                a = c;
                fa = fc;
                if side == -1 {
                    fb *= 0.5;
                }
                side = -1;
                seed = trial.gaps.clone();
                if fc.abs() < (best.pressure - target).abs() {
                    best = trial;
                }
            }
        }
        Ok(best)
    }

    /// The pull-off from `from` (a loaded state): the mean gap raised in steps of
    /// `max(ρ/2, h_rms/64)`, each solve seeded by the last, until the map has
    /// left contact and the tension has fallen to half its largest; then the
    /// steps about the most tensile one are retraced an eighth as long.
    pub fn pull_off(
        &mut self,
        from: &AdhesiveSolution,
        adhesion: &Adhesion,
        settings: &Settings,
    ) -> Result<PullOff, ContactError> {
        let step = (0.5 * adhesion.range).max(self.rms / 64.0);
        let mut state = from.clone();
        let mut previous = from.clone();
        let mut best = from.clone();
        let mut before_best = from.clone();
        let (mut steps, mut iterations) = (0, 0);
        let mut converged = from.outcome == Outcome::Converged;
        loop {
            steps += 1;
            if steps > MAX_STEPS {
                break;
            }
            // The next gaps foreseen by extrapolating the last two states'.
            let guess: Vec<f64> = state
                .gaps
                .iter()
                .zip(&previous.gaps)
                .map(|(&g, &h)| if g > 0.0 && h > 0.0 { 2.0 * g - h } else { g })
                .collect();
            let next =
                self.adhesive_at_gap(state.mean_gap + step, adhesion, settings, Some(&guess))?;
            iterations += next.iterations;
            converged &= next.outcome == Outcome::Converged;
            previous = std::mem::replace(&mut state, next);
            if state.pressure < best.pressure {
                best = state.clone();
                before_best = previous.clone();
            }
            if state.real_area_fraction == 0.0
                && best.pressure < 0.0
                && state.pressure > 0.5 * best.pressure
            {
                break;
            }
        }
        // Retrace the two steps about the minimum an eighth as long.
        let fine = step / 8.0;
        let mut trace = before_best;
        for _ in 0..16 {
            let next =
                self.adhesive_at_gap(trace.mean_gap + fine, adhesion, settings, Some(&trace.gaps))?;
            steps += 1;
            iterations += next.iterations;
            converged &= next.outcome == Outcome::Converged;
            trace = next;
            if trace.pressure < best.pressure {
                best = trace.clone();
            }
        }
        Ok(PullOff {
            pressure: best.pressure.min(0.0),
            mean_gap: best.mean_gap,
            real_area_fraction: best.real_area_fraction,
            steps,
            step,
            iterations,
            outcome: if converged {
                Outcome::Converged
            } else {
                Outcome::IterationLimit
            },
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn waves(nx: usize, ny: usize, amplitude: f64) -> Vec<f64> {
        (0..nx * ny)
            .map(|i| amplitude * (2.0 * PI * (i % nx) as f64 / nx as f64).cos())
            .collect()
    }

    /// A periodic self-affine map, `n` × `n`, unit side, unit rms height.
    fn rough(n: usize, seed: u64) -> Vec<f64> {
        use crate::surface::synthetic::{random_surface, Spectrum};
        let spectrum = Spectrum::SelfAffine {
            hurst: 0.8,
            rolloff: 2.0 * PI * 2.0,
            cutoff: 2.0 * PI * n as f64 / 4.0,
        };
        random_surface(n, 1.0 / n as f64, spectrum, 1.0, seed)
            .unwrap()
            .heights()
            .to_vec()
    }

    fn tight() -> Settings {
        Settings {
            tolerance: 1e-9,
            max_iterations: 20_000,
            ..Settings::default()
        }
    }

    /// Johnson's wavy surface (Int. J. Solids Struct. 32, 1995): `Δ cos(2πx/λ)`,
    /// 1024 × 8 points over one wavelength, E* = 1, α = 0.2; the solver, p*,
    /// the adhesion of a process zone `zone_pixels` wide, and the error of a
    /// solution against Johnson's load at its contact width, over p*.
    struct Johnson {
        solver: Solver,
        p_star: f64,
        alpha: f64,
        work: f64,
        dx: f64,
    }

    impl Johnson {
        fn new() -> Self {
            let (nx, ny, lambda, delta, e) = (1024, 8, 1.0, 0.01, 1.0);
            let dx = lambda / nx as f64;
            let alpha: f64 = 0.2;
            Johnson {
                solver: Solver::new(nx, ny, dx, dx, &waves(nx, ny, delta), e).unwrap(),
                p_star: PI * e * delta / lambda,
                alpha,
                work: alpha * alpha * PI * PI * e * delta * delta / (2.0 * lambda),
                dx,
            }
        }

        fn adhesion(&self, zone_pixels: f64) -> Adhesion {
            let range = Adhesion::range_for_process_zone(self.work, 1.0, zone_pixels * self.dx);
            Adhesion::new(self.work, range).unwrap()
        }

        fn error(&self, s: &AdhesiveSolution) -> f64 {
            let psi = PI * 0.5 * s.real_area_fraction;
            let exact = self.p_star * (psi.sin().powi(2) - self.alpha * psi.tan().sqrt());
            (s.pressure - exact).abs() / self.p_star
        }
    }

    /// Johnson (Int. J. Solids Struct. 32, 1995): a wavy surface `Δ cos(2πx/λ)`
    /// in adhesive contact of half-width `a` carries
    /// `p̄ = p* [sin²(πa/λ) − α √tan(πa/λ)]`, `p* = π E* Δ / λ`,
    /// `α = √(2λγ / (π² E* Δ²))` — the JKR limit, which a short-range law
    /// approaches as its process zone shrinks against `a`. Every equilibrium
    /// met on the approach satisfies it; the error falls as ρ does.
    #[test]
    fn a_wavy_surface_tends_to_johnsons_adhesive_solution() {
        let mut j = Johnson::new();
        let mut errors = Vec::new();
        for zone_pixels in [16.0, 4.0] {
            let adhesion = j.adhesion(zone_pixels);
            let mut start: Option<Vec<f64>> = None;
            let mut worst: f64 = 0.0;
            for gap in [8e-3, 6e-3, 4e-3] {
                let s = j
                    .solver
                    .adhesive_at_gap(gap, &adhesion, &tight(), start.as_deref())
                    .unwrap();
                assert_eq!(s.outcome, Outcome::Converged);
                worst = worst.max(j.error(&s));
                start = Some(s.gaps);
            }
            errors.push(worst);
        }
        // Measured: 2.5 % and 0.84 % of p*, the error about proportional to the zone.
        assert!(errors[1] < 0.012, "{errors:?}");
        assert!(errors[1] < 0.5 * errors[0], "{errors:?}");
        // Under load control, along the approach, at a pressure on the branch.
        let adhesion = j.adhesion(4.0);
        let p_star = j.p_star;
        let s = j
            .solver
            .adhesive_loading(&[0.3 * p_star], &adhesion, &tight())
            .unwrap();
        assert!((s[0].pressure / p_star - 0.3).abs() < 1e-8);
        assert!(j.error(&s[0]) < 0.012);
        // Above the branch's largest load (0.553 p* at α = 0.2) the surfaces
        // jump into full contact.
        let s = j
            .solver
            .adhesive_loading(&[0.7 * p_star], &adhesion, &tight())
            .unwrap();
        assert_eq!(s[0].real_area_fraction, 1.0);
        assert_eq!(s[0].pressure, 0.7 * p_star);
    }

    /// The pull-off of Johnson's wavy surface (4-pixel zone), from a light
    /// load on the branch (0.02 p*): Johnson's least load, min over ψ of
    /// sin²ψ − α √tan ψ on the small-contact branch (ψ < 0.6; toward π/2 the
    /// load falls again, where the surfaces snap into full contact instead).
    /// The walk's solves to 1e-6 (the check is 1 %).
    #[test]
    fn the_wavy_surface_pulls_off_at_johnsons_least_load() {
        let mut j = Johnson::new();
        let adhesion = j.adhesion(4.0);
        let p_star = j.p_star;
        let s = j
            .solver
            .adhesive_loading(&[0.02 * p_star], &adhesion, &tight())
            .unwrap();
        let off = j
            .solver
            .pull_off(
                &s[0],
                &adhesion,
                &Settings {
                    tolerance: 1e-6,
                    ..tight()
                },
            )
            .unwrap();
        let alpha = j.alpha;
        let least = (1..6_000)
            .map(|i| {
                let psi = i as f64 * 1e-4;
                psi.sin().powi(2) - alpha * psi.tan().sqrt()
            })
            .fold(f64::MAX, f64::min);
        assert_eq!(off.outcome, Outcome::Converged);
        // Measured: −0.055624 p* against −0.055611 p* (2.4e-4 relative).
        assert!(
            (off.pressure / p_star - least).abs() < 0.01 * least.abs(),
            "{}",
            off.pressure / p_star
        );
    }

    /// A stiff body hardly deforms: the gaps are the map's shape, and the mean
    /// pressure is minus the mean traction of those gaps (Bradley's rigid limit).
    #[test]
    fn a_rigid_body_is_pulled_by_the_mean_traction_of_its_gaps() {
        let n = 32;
        let heights = rough(n, 5);
        let adhesion = Adhesion::new(1e-3, 0.2).unwrap();
        let mut solver = Solver::new(n, n, 1.0 / n as f64, 1.0 / n as f64, &heights, 1e12).unwrap();
        let top = heights.iter().copied().fold(f64::MIN, f64::max);
        let mean = heights.iter().sum::<f64>() / heights.len() as f64;
        let gap = top - mean + 0.1;
        let s = solver
            .adhesive_at_gap(gap, &adhesion, &tight(), None)
            .unwrap();
        let exact: f64 = heights
            .iter()
            .map(|h| -adhesion.traction(gap - (h - mean)))
            .sum::<f64>()
            / heights.len() as f64;
        assert_eq!(s.real_area_fraction, 0.0);
        assert!(
            (s.pressure - exact).abs() < 1e-8 * exact.abs(),
            "{} {exact}",
            s.pressure
        );
    }

    /// Weak adhesion changes the contact little: the area tends to the
    /// adhesion-free solver's (an independent scheme, on the pressures).
    #[test]
    fn weak_adhesion_tends_to_the_adhesion_free_contact() {
        let (nx, ny) = (64, 64);
        let heights = rough(nx, 3);
        let e = 1.0;
        let mut solver = Solver::new(nx, ny, 1.0 / 64.0, 1.0 / 64.0, &heights, e).unwrap();
        let p = 0.02 * e * solver.slope_rms;
        let dry = solver.solve(p, &Settings::default(), None).unwrap();
        let adhesion = Adhesion::new(1e-9, 1e-3).unwrap();
        let wet = solver.adhesive_loading(&[p], &adhesion, &tight()).unwrap();
        let n = (nx * ny) as f64;
        assert!(
            (wet[0].real_area_fraction - dry.real_area_fraction).abs() * n <= 2.0,
            "{} {}",
            wet[0].real_area_fraction,
            dry.real_area_fraction
        );
        assert!((wet[0].mean_gap - dry.mean_gap).abs() < 1e-3 * dry.mean_gap);
    }
}
