//! The stress-assisted, thermally activated wear law (docs/model.md §12; Gotsmann &
//! Lantz 2008, Jacobs & Carpick 2013): atoms leave a contact under stress σ at the
//! transition-state rate Γ(σ) = f₀ exp(−(ΔU − σΔV)/k_BT), and per unit sliding distance
//!
//! ```text
//! dV/ds = Σᵢ (Ω Aᵢ / a₀³) (1 − exp(−Γ(σᵢ) a₀ / v)),
//! ```
//!
//! Aᵢ = πRδᵢ the summit's area (the measure of the real area, §3), σᵢ = Pᵢ/Aᵢ its
//! mean pressure under the scene's asperity law, H on a plastic junction. On the
//! rough surface the sum is the real area's Gaussian-weighted integral over the
//! summit heights with the factor F(σ) = 1 − exp(−c e^{bσ}) inside, c = f₀ e^{−ΔU/k_BT}
//! a₀/v, b = ΔV/k_BT. Under `stress = "shear"` σ = τ is the same on every summit and
//! the integral is F(τ) times the wearing area, a closed form.
//!
//! The elastic summits' integral is taken by adaptive Gauss–Kronrod (7–15) in the
//! model's own variables (v = s − s₀ under JKR, x = Δ^{1/2} under DMT, where the
//! summit's stress is smooth), over the heights where the integrand is within e^{−46}
//! of its largest value, the ends of the saturated band (Γa₀/v = 1) being panel
//! edges. Every integrand is carried as a logarithm and the result as a
//! [`Scaled`], so that c = 10⁻³⁰ or h = 60 neither underflows nor loses digits.

use super::{Activation, ContactStress, WearDetails, WearInput, WearLaw, WearModel, WearOutcome};
use crate::model::integrals::Model;
use crate::model::scaled::Scaled;
use crate::model::scene::WearArea;

/// k_B, the Boltzmann constant (J/K, exact in the SI since 2019).
pub const BOLTZMANN: f64 = 1.380_649e-23;

/// The relative accuracy the adaptive quadrature aims at (the reference of
/// tests/data is met to 1e-12).
const TOLERANCE: f64 = 1e-13;

/// How far below its largest value (in ln) the integrand is left out: e^{−46} ≈ 1e-20.
const SUPPORT_DEPTH: f64 = 46.0;

/// The most panels the adaptive quadrature splits into.
const MAX_PANELS: usize = 4000;

/// Γ a₀/v = c e^{bσ}: Γ(σ) times the time a site stays under the contact.
pub struct StressAssisted;

impl WearLaw for StressAssisted {
    fn name(&self) -> &'static str {
        "stress_assisted"
    }
    fn label(&self) -> &'static str {
        "stress-assisted"
    }
    fn formula(&self) -> &'static str {
        "dV/ds = Σ (Ω A/a₀³)(1 − exp(−Γ(σ) a₀/v)), Γ = f₀ exp(−(ΔU − σΔV)/k_BT)"
    }
    fn section(&self) -> &'static str {
        "docs/model.md §12"
    }
    fn rate(&self, input: &WearInput<'_>) -> WearOutcome {
        let Some(activation) = input.scene.activation else {
            // Scene::validate refuses this law without its inputs.
            return WearOutcome {
                rate: Scaled::ZERO,
                details: None,
            };
        };
        let kernel = Kernel::new(&activation, input.scene.temperature);
        let prefactor = activation.atomic_volume / activation.site_spacing.powi(3);
        let shear = match activation.stress {
            ContactStress::Shear => input.scene.requirements.shear_strength,
            ContactStress::Normal => None,
        };
        let parts = match (input.separation, shear) {
            (None, _) => Parts::default(),
            (Some(_), Some(tau)) => Parts::uniform(&kernel, tau, input.wearing_area),
            (Some(h), None) => {
                let plastic = Parts::uniform(&kernel, input.scene.hardness, input.plastic_area);
                match input.scene.wear_area {
                    WearArea::Plastic => plastic,
                    WearArea::Total => {
                        let stress_scale = contact_stress_scale(input);
                        elastic_parts(input.model, h, &kernel, stress_scale).plus(&plastic)
                    }
                }
            }
        };
        let rate = parts.rate.scale(prefactor * input.area_scale);
        let has_area = input.wearing_area.mantissa > 0.0;
        let mean_contact_stress = match shear {
            Some(tau) => has_area.then_some(tau),
            None => match input.scene.wear_area {
                WearArea::Plastic => has_area.then_some(input.scene.hardness),
                // Σ σᵢAᵢ / ΣAᵢ = (K/π)(σ/R)^{1/2} (Σp + c_h Ā_p)/Ā: the elastic
                // summits' load and H on the plastic junctions (H over the
                // stress scale is c_h).
                WearArea::Total => has_area.then(|| {
                    let mut carried = input.elastic_load;
                    if input.plastic_area.mantissa > 0.0 {
                        carried =
                            carried.plus(input.plastic_area.scale(input.model.coefficients.c_h));
                    }
                    contact_stress_scale(input) * carried.ratio(input.wearing_area)
                }),
            },
        };
        WearOutcome {
            rate,
            details: Some(WearDetails {
                wear_law: WearModel::StressAssisted,
                effective_wear_coefficient: has_area
                    .then(|| prefactor * parts.rate.ratio(input.wearing_area)),
                mean_contact_stress,
                saturated_fraction: (parts.rate.mantissa > 0.0)
                    .then(|| parts.saturated.ratio(parts.rate)),
                apparent_activation_energy: (parts.rate.mantissa > 0.0)
                    .then(|| parts.activation.ratio(parts.rate)),
                temperature: input.scene.temperature,
            }),
        }
    }
}

/// (K/π)(σ/R)^{1/2} (Pa): a summit's mean pressure is this times p(Δ)/Δ, p and Δ
/// in the model's units (P = K R^{1/2} σ^{3/2} p, A = πRσΔ); H over it is c_h.
fn contact_stress_scale(input: &WearInput<'_>) -> f64 {
    let s = input.scene;
    let k = 4.0 / 3.0 * input.equivalent_modulus;
    k / std::f64::consts::PI * (s.sigma / s.asperity_radius).sqrt()
}

/// The law at one temperature: ln c and b of x = c e^{bσ}, and ΔU, ΔV for the
/// temperature derivative.
#[derive(Debug, Clone, Copy)]
pub struct Kernel {
    /// ln c = ln(f₀ a₀/v) − ΔU/k_BT.
    pub ln_c: f64,
    /// b = ΔV/k_BT (1/Pa).
    pub b: f64,
    /// ΔU (J).
    pub activation_energy: f64,
    /// ΔV (m³).
    pub activation_volume: f64,
}

impl Kernel {
    /// The law's constants at temperature T (K).
    pub fn new(a: &Activation, temperature: f64) -> Kernel {
        let beta = 1.0 / (BOLTZMANN * temperature);
        Kernel {
            ln_c: (a.attempt_frequency * a.site_spacing / a.sliding_speed).ln()
                - a.activation_energy * beta,
            b: a.activation_volume * beta,
            activation_energy: a.activation_energy,
            activation_volume: a.activation_volume,
        }
    }

    /// ln x = ln(Γ(σ) a₀/v) at a stress σ (Pa).
    pub fn ln_x(&self, stress: f64) -> f64 {
        if self.b == 0.0 {
            self.ln_c
        } else {
            self.ln_c + self.b * stress
        }
    }

    /// ln F, F = 1 − e^{−x}, from ln x (exact to rounding for tiny x).
    pub fn ln_removal(ln_x: f64) -> f64 {
        if ln_x < -40.0 {
            // 1 − e^{−x} = x (1 − x/2 + …): the correction is below 1e-17.
            ln_x
        } else if ln_x > 6.0 {
            // e^{−x} < 1e-175: F = 1 to rounding.
            (-(-(ln_x.exp())).exp()).ln_1p()
        } else {
            (-(-(ln_x.exp())).exp_m1()).ln()
        }
    }

    /// x e^{−x} / F (the share of F that a change of ln x moves), from ln x.
    pub fn sensitivity(ln_x: f64) -> f64 {
        if ln_x < -40.0 {
            1.0
        } else {
            let x = ln_x.exp();
            if x > 745.0 {
                0.0
            } else {
                x * (-x).exp() / -(-x).exp_m1()
            }
        }
    }

    /// −d ln F / dβ (J), β = 1/k_BT, at a stress σ: (ΔU − σΔV) times the
    /// sensitivity.
    pub fn activation(&self, stress: f64, ln_x: f64) -> f64 {
        let barrier = if self.activation_volume == 0.0 {
            self.activation_energy
        } else {
            self.activation_energy - stress * self.activation_volume
        };
        barrier * Kernel::sensitivity(ln_x)
    }
}

/// The integrals the law's outputs are made of (each a [`Scaled`] value of a
/// non-dimensional integral over summit heights): the rate's ∫ΔF φ̄, its
/// saturated share (Γa₀/v > 1), and ∫Δ F (−d ln F/dβ) φ̄ (J).
#[derive(Debug, Clone, Copy)]
struct Parts {
    rate: Scaled,
    saturated: Scaled,
    activation: Scaled,
}

impl Default for Parts {
    fn default() -> Self {
        Parts {
            rate: Scaled::ZERO,
            saturated: Scaled::ZERO,
            activation: Scaled::ZERO,
        }
    }
}

impl Parts {
    /// Every summit of `area` at one stress.
    fn uniform(kernel: &Kernel, stress: f64, area: Scaled) -> Parts {
        if area.mantissa == 0.0 {
            return Parts::default();
        }
        let ln_x = kernel.ln_x(stress);
        let ln_f = Kernel::ln_removal(ln_x);
        let rate = Scaled::new(area.mantissa, area.exponent - ln_f);
        Parts {
            rate,
            saturated: if ln_x > 0.0 { rate } else { Scaled::ZERO },
            activation: rate.scale(kernel.activation(stress, ln_x)),
        }
    }

    fn plus(&self, other: &Parts) -> Parts {
        Parts {
            rate: self.rate.plus(other.rate),
            saturated: self.saturated.plus(other.saturated),
            activation: self.activation.plus(other.activation),
        }
    }
}

/// One elastic summit in the model's variable t: its interference Δ, its
/// mean pressure over the stress scale (p/Δ), and dΔ/dt.
#[derive(Debug, Clone, Copy)]
struct Summit {
    interference: f64,
    pressure: f64,
    jacobian: f64,
}

/// The elastic summits of the scene's law as functions of the model's variable:
/// v = s − s₀ under JKR (Δ = s⁴ − c_d s, p = s⁶ − c_a s³), x = Δ^{1/2} under DMT
/// (p = x³ − c₀).
#[derive(Debug, Clone, Copy)]
enum Elastic<'a> {
    Jkr {
        model: &'a Model,
        s0: f64,
        s0_3: f64,
        c_a: f64,
    },
    Hertz {
        offset: f64,
    },
}

impl Elastic<'_> {
    fn at(&self, t: f64) -> Summit {
        match *self {
            Elastic::Jkr {
                model,
                s0,
                s0_3,
                c_a,
            } => {
                let s = s0 + t;
                let s3 = s * s * s;
                let d = model.interference_of_v(t);
                Summit {
                    interference: d,
                    pressure: s3 * (s3 - c_a) / d,
                    jacobian: 3.0 * s0_3 + t * (12.0 * s0 * s0 + t * (12.0 * s0 + 4.0 * t)),
                }
            }
            Elastic::Hertz { offset } => {
                let d = t * t;
                Summit {
                    interference: d,
                    pressure: (d * t - offset) / d,
                    jacobian: 2.0 * t,
                }
            }
        }
    }

    /// The variable at interference Δ.
    fn variable(&self, delta: f64, model: &Model) -> f64 {
        match self {
            Elastic::Jkr { .. } => model.v_of_interference(delta),
            Elastic::Hertz { .. } => delta.sqrt(),
        }
    }
}

/// ∫₀^{Δc} Δ F(p/Δ) φ̄ dΔ + F(c_h) Ā_p at separation h, F(s) = 1 − exp(−e^{ln c + b s}),
/// the summits' stress s = p/Δ in the model's units (over (K/π)(σ/R)^{1/2}; c_h on a
/// plastic junction): the non-dimensional integral the law's rate is Ω/a₀³ times the
/// real-area scale times (what tests/data/reference_stress_assisted.csv tabulates). Zero
/// under the Lennard-Jones law's table, whose summit stresses are not available.
pub fn removal_integral(model: &Model, h: f64, ln_c: f64, b: f64) -> Scaled {
    let kernel = Kernel {
        ln_c,
        b,
        activation_energy: 0.0,
        activation_volume: 0.0,
    };
    let plastic_area = model.plastic_area_scaled(h);
    let plastic = if plastic_area.mantissa > 0.0 {
        Parts::uniform(&kernel, model.coefficients.c_h, plastic_area)
    } else {
        Parts::default()
    };
    elastic_parts(model, h, &kernel, 1.0).plus(&plastic).rate
}

/// The elastic summits' parts at separation h: the Gaussian-weighted integrals over
/// 0 ≤ Δ ≤ Δc of the summit's area Δ times F, its saturated share and its
/// activation energy. `stress_scale` turns p/Δ into a stress (Pa).
fn elastic_parts(model: &Model, h: f64, kernel: &Kernel, stress_scale: f64) -> Parts {
    let Some(law) = model.contact_law() else {
        // The Lennard-Jones law's own table: refused by Scene::validate.
        return Parts::default();
    };
    let elastic = if law.hertz_offset != 0.0 {
        Elastic::Hertz {
            offset: law.hertz_offset,
        }
    } else {
        Elastic::Jkr {
            model,
            s0: law.s_touch,
            s0_3: law.c_d_cubed,
            c_a: law.c_a,
        }
    };
    elastic_integrals(
        model,
        &elastic,
        h,
        law.critical_interference,
        kernel,
        stress_scale,
    )
}

fn elastic_integrals(
    model: &Model,
    elastic: &Elastic<'_>,
    h: f64,
    critical_interference: f64,
    kernel: &Kernel,
    stress_scale: f64,
) -> Parts {
    // Beyond Δ_max the Gaussian weight is below e^{-800} of its largest value.
    let reach = (1600.0 + h.max(0.0).powi(2)).sqrt() - h;
    let top = critical_interference.min(reach.max(0.0));
    if top <= 0.0 {
        return Parts::default();
    }
    let t_top = elastic.variable(top, model);
    // ln of the rate's integrand Δ F(σ) φ̄(h + Δ) dΔ/dt (−∞ where it vanishes).
    let ln_rate = |t: f64| -> (f64, f64, f64) {
        let summit = elastic.at(t);
        let d = summit.interference;
        if d <= 0.0 || summit.jacobian <= 0.0 {
            return (f64::NEG_INFINITY, f64::NEG_INFINITY, 0.0);
        }
        let stress = stress_scale * summit.pressure;
        let ln_x = kernel.ln_x(stress);
        let u = h + d;
        let ln = d.ln() + Kernel::ln_removal(ln_x) - 0.5 * u * u + summit.jacobian.ln();
        (ln, ln_x, kernel.activation(stress, ln_x))
    };
    // A scan for the integrand's largest value, the heights that matter and
    // the edges of the saturated band.
    const GRID: usize = 96;
    let grid: Vec<(f64, f64, f64)> = (0..=GRID)
        .map(|i| {
            let t = t_top * i as f64 / GRID as f64;
            let (ln, ln_x, _) = ln_rate(t);
            (t, ln, ln_x)
        })
        .collect();
    let peak = grid.iter().map(|g| g.1).fold(f64::NEG_INFINITY, f64::max);
    if !peak.is_finite() {
        return Parts::default();
    }
    let keep = |i: usize| grid[i].1 > peak - SUPPORT_DEPTH;
    let first = (0..=GRID).find(|&i| keep(i)).unwrap_or(0);
    let last = (0..=GRID).rev().find(|&i| keep(i)).unwrap_or(GRID);
    let (lo, hi) = (first.saturating_sub(1), (last + 1).min(GRID));
    let mut edges: Vec<f64> = (lo..=hi)
        .step_by(((hi - lo) / 16).max(1))
        .map(|i| grid[i].0)
        .collect();
    if *edges.last().unwrap_or(&0.0) < grid[hi].0 {
        edges.push(grid[hi].0);
    }
    // The edges of the saturated band, by bisection on ln x = 0.
    for i in lo..hi {
        let (a, b) = (grid[i], grid[i + 1]);
        if a.2.is_finite() && b.2.is_finite() && (a.2 > 0.0) != (b.2 > 0.0) {
            let (mut l, mut r) = (a.0, b.0);
            for _ in 0..200 {
                let m = 0.5 * (l + r);
                if m <= l || m >= r {
                    break;
                }
                if (ln_rate(m).1 > 0.0) == (a.2 > 0.0) {
                    l = m;
                } else {
                    r = m;
                }
            }
            edges.push(0.5 * (l + r));
        }
    }
    edges.sort_by(f64::total_cmp);
    edges.dedup();
    // The three integrands relative to e^{peak}: rate, saturated rate, activation.
    let f = |t: f64| -> [f64; 3] {
        let (ln, ln_x, activation) = ln_rate(t);
        if !ln.is_finite() {
            return [0.0; 3];
        }
        let r = (ln - peak).exp();
        [r, if ln_x > 0.0 { r } else { 0.0 }, r * activation]
    };
    let [rate, saturated, activation] = adaptive(&f, &edges);
    let scaled = |m: f64| Scaled::new(m, -peak);
    Parts {
        rate: scaled(rate),
        saturated: scaled(saturated),
        activation: scaled(activation),
    }
}

/// Gauss–Kronrod 7–15: the Kronrod nodes on [0, 1] (the symmetric half) and weights.
const XGK: [f64; 8] = [
    0.991_455_371_120_812_6,
    0.949_107_912_342_758_5,
    0.864_864_423_359_769_1,
    0.741_531_185_599_394_4,
    0.586_087_235_467_691_1,
    0.405_845_151_377_397_2,
    0.207_784_955_007_898_5,
    0.0,
];
const WGK: [f64; 8] = [
    0.022_935_322_010_529_22,
    0.063_092_092_629_978_55,
    0.104_790_010_322_250_2,
    0.140_653_259_715_525_9,
    0.169_004_726_639_267_9,
    0.190_350_578_064_785_4,
    0.204_432_940_075_298_9,
    0.209_482_141_084_727_8,
];
/// The Gauss weights of the 7 nodes XGK[1], XGK[3], XGK[5], XGK[7].
const WG: [f64; 4] = [
    0.129_484_966_168_869_7,
    0.279_705_391_489_276_7,
    0.381_830_050_505_118_9,
    0.417_959_183_673_469_4,
];

/// One panel: the Kronrod estimates of the three integrands and the error of the first.
fn kronrod(f: &impl Fn(f64) -> [f64; 3], a: f64, b: f64) -> ([f64; 3], f64) {
    let (c, half) = (0.5 * (a + b), 0.5 * (b - a));
    let mut k = [0.0; 3];
    let mut g = 0.0;
    for (j, (&x, &w)) in XGK.iter().zip(WGK.iter()).enumerate() {
        let points: &[f64] = if x == 0.0 { &[0.0] } else { &[-1.0, 1.0] };
        for &sgn in points {
            let v = f(c + sgn * half * x);
            for (acc, vi) in k.iter_mut().zip(v) {
                *acc += w * vi;
            }
            if j % 2 == 1 {
                g += WG[j / 2] * v[0];
            }
        }
    }
    let k = k.map(|x| x * half);
    (k, (k[0] - g * half).abs())
}

/// The integrals of `f` over the union of panels `edges`, split where the first
/// integrand's error is largest until the sum of errors is below [`TOLERANCE`] of it.
fn adaptive(f: &impl Fn(f64) -> [f64; 3], edges: &[f64]) -> [f64; 3] {
    let mut panels: Vec<(f64, f64, [f64; 3], f64)> = edges
        .windows(2)
        .filter(|w| w[1] > w[0])
        .map(|w| {
            let (k, e) = kronrod(f, w[0], w[1]);
            (w[0], w[1], k, e)
        })
        .collect();
    loop {
        let total: f64 = panels.iter().map(|p| p.2[0]).sum();
        let error: f64 = panels.iter().map(|p| p.3).sum();
        if error <= TOLERANCE * total.abs() || panels.len() >= MAX_PANELS {
            break;
        }
        let (worst, _) = panels
            .iter()
            .enumerate()
            .max_by(|a, b| a.1 .3.total_cmp(&b.1 .3))
            .expect("at least one panel");
        let (a, b, _, _) = panels.swap_remove(worst);
        let m = 0.5 * (a + b);
        if m <= a || m >= b {
            break;
        }
        for (l, r) in [(a, m), (m, b)] {
            let (k, e) = kronrod(f, l, r);
            panels.push((l, r, k, e));
        }
    }
    // Summed in order of position: the same sum on any machine and thread.
    panels.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut sum = [0.0; 3];
    for p in &panels {
        for (s, v) in sum.iter_mut().zip(p.2) {
            *s += v;
        }
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Si values of docs/model.md §12 at 300 K: ΔV/k_BT = 1.618 GPa⁻¹, and
    /// k_eff = (Ω/a₀³)(1 − exp(−f₀ e^{−(ΔU − τΔV)/k_BT} a₀/v)) at the speeds and
    /// shear stresses the issue quotes (the formula's own numbers, 3 digits).
    #[test]
    fn silicon_numbers() {
        let a = Activation {
            activation_energy: 0.91 * crate::units::ELECTRON_VOLT,
            activation_volume: 6.7e-30,
            attempt_frequency: 1e13,
            site_spacing: 0.384e-9,
            atomic_volume: 20.02e-30,
            stress: ContactStress::Shear,
            sliding_speed: 1e-6,
        };
        let k = Kernel::new(&a, 300.0);
        assert!((k.b * 1e9 - 1.618).abs() < 5e-4, "{}", k.b * 1e9);
        assert!(((k.b * 1e9).exp() - 5.04).abs() < 5e-3);
        let keff = |a: &Activation, tau: f64| {
            let k = Kernel::new(a, 300.0);
            a.atomic_volume / a.site_spacing.powi(3) * Kernel::ln_removal(k.ln_x(tau)).exp()
        };
        let fast = Activation {
            sliding_speed: 38e-3,
            ..a
        };
        for (got, want) in [
            (keff(&a, 0.0), 7.01e-7),
            (keff(&fast, 0.0), 1.84e-11),
            (keff(&a, 1e9), 3.53e-6),
            (keff(&fast, 1e9), 9.29e-11),
        ] {
            // The issue's three digits.
            assert_eq!(format!("{got:.2e}"), format!("{want:.2e}"));
        }
        // The one-pass cap Ω/a₀³ = 0.354.
        assert!((a.atomic_volume / a.site_spacing.powi(3) - 0.3536).abs() < 1e-4);
    }

    /// F = exp(ln F) against 1 − e^{−x} computed directly where that is accurate
    /// (x ≥ 0.1), against its Taylor series for x = 1e-3, and its limits: ln F = ln x
    /// for tiny x, 0 for large.
    #[test]
    fn removal_probability() {
        for x in [0.1f64, 1.0, 5.0, 30.0] {
            let want = 1.0 - (-x).exp();
            let got = Kernel::ln_removal(x.ln()).exp();
            assert!((got / want - 1.0).abs() < 1e-14, "{x}: {got} vs {want}");
        }
        let x = 1e-3f64;
        let series = x - x * x / 2.0 + x.powi(3) / 6.0 - x.powi(4) / 24.0 + x.powi(5) / 120.0;
        assert!((Kernel::ln_removal(x.ln()).exp() / series - 1.0).abs() < 1e-14);
        assert_eq!(Kernel::ln_removal(-100.0), -100.0);
        assert_eq!(Kernel::ln_removal(10.0), 0.0);
    }

    /// The adaptive rule integrates a smooth function and a sharp sigmoid to its
    /// tolerance (closed forms: ∫₀¹ eˣ = e − 1; ∫₀² 1/(1 + e^{−200(x−1)}) = 1).
    #[test]
    fn adaptive_quadrature() {
        let [i, _, _] = adaptive(&|x: f64| [x.exp(), 0.0, 0.0], &[0.0, 1.0]);
        assert!((i / (std::f64::consts::E - 1.0) - 1.0).abs() < 1e-15);
        let [j, _, _] = adaptive(
            &|x: f64| [1.0 / (1.0 + (-200.0 * (x - 1.0)).exp()), 0.0, 0.0],
            &[0.0, 2.0],
        );
        assert!((j - 1.0).abs() < 1e-13, "{j}");
    }
}
