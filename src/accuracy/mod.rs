//! Work–precision of the evaluator: how accurate and how fast each accuracy
//! setting is, measured against an independent high-precision reference.
//!
//! * [`reference`](mod@reference): the direct form of docs/model.md §3 by adaptive Gauss–Kronrod
//!   with a root solve for Δ1(Δ) at every node (validated against 40-digit
//!   mpmath tables in `tests/all/accuracy.rs`).
//! * [`finite_difference`]: the step rules of the wear-rate sensitivities and a
//!   Richardson-tableau reference derivative.
//! * [`work_precision`]: the report's numbers: for every [`Quadrature`] setting
//!   the max and median relative error of P̄, Ā, Ā_p and the wear rate and the
//!   median time per evaluation; for every step rule the error of the
//!   elasticities and the time per elasticity.
//!
//! * [`dmt_rows`] (run by [`work_precision`]): the same for the DMT law of
//!   docs/model.md §7 with either attraction, at the default setting, against
//!   [`reference::ReferenceModel::with_law`]: the contact share of P̄, the
//!   non-contact share N (relative to |N|, which never crosses zero; points where
//!   the reference underflows are left out), Ā, Ā_p and the wear rate.
//!
//! Relative errors: a load against max(|P̄|, |elastic| + |plastic|) of the
//! reference (P̄ crosses zero); an area against the reference area (values whose
//! reference and fast mantissas are both below [`NEGLIGIBLE`] count as exact);
//! a wear rate against the reference wear rate; an elasticity against the
//! largest |elasticity| of its scene's gradient (normwise, since an elasticity
//! can be 0). Only the elastic integral depends on the quadrature settings:
//! the areas are closed forms, so their rows are the same for every setting.

pub mod finite_difference;
pub mod lennard_jones;
pub mod reference;

use std::hint::black_box;
use std::time::Instant;

use crate::model::{
    evaluate, gauss, wear, AdhesionModel, AsperityLaw, Attraction, AttractionKind, Coefficients,
    EvaluationOptions, Model, Quadrature, Scaled, Scene, SceneParameter, Status,
};
use finite_difference::StepRule;
use reference::ReferenceModel;

/// Mantissas below this are treated as zero when comparing areas.
pub const NEGLIGIBLE: f64 = 1e-280;

/// A quantity of the report.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// P̄.
    Load,
    /// Ā.
    Area,
    /// Ā_p.
    PlasticArea,
    /// The wear rate of a scene (separation solve included).
    WearRate,
    /// The elasticities of the wear rate (finite differences).
    Gradient,
    /// DMT: the load of the attracted asperities out of contact.
    NoncontactLoad,
}

impl Quantity {
    /// The CSV name.
    pub fn as_str(self) -> &'static str {
        match self {
            Quantity::Load => "load",
            Quantity::Area => "area",
            Quantity::PlasticArea => "plastic_area",
            Quantity::WearRate => "wear_rate",
            Quantity::Gradient => "gradient",
            Quantity::NoncontactLoad => "noncontact_load",
        }
    }

    /// All, in report order.
    pub const ALL: [Quantity; 6] = [
        Quantity::Load,
        Quantity::NoncontactLoad,
        Quantity::Area,
        Quantity::PlasticArea,
        Quantity::WearRate,
        Quantity::Gradient,
    ];
}

/// The asperity law a row measures.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum RowLaw {
    /// JKR (docs/model.md §3): every quadrature setting, the gradient.
    #[default]
    Jkr,
    /// DMT (docs/model.md §7) with this attraction, at the default setting.
    Dmt(AttractionKind),
    /// The Lennard-Jones sphere (docs/model.md §11): its table and grid.
    LennardJones,
}

impl RowLaw {
    /// The law's name (`adhesion_model`).
    pub fn adhesion_model(self) -> AdhesionModel {
        match self {
            RowLaw::Jkr => AdhesionModel::Jkr,
            RowLaw::Dmt(_) => AdhesionModel::Dmt,
            RowLaw::LennardJones => AdhesionModel::LennardJones,
        }
    }

    /// The attraction (DMT only).
    pub fn attraction(self) -> Option<AttractionKind> {
        match self {
            RowLaw::Jkr | RowLaw::LennardJones => None,
            RowLaw::Dmt(kind) => Some(kind),
        }
    }

    /// JKR, then DMT with van der Waals, then with Dugdale, then Lennard-Jones.
    pub const ALL: [RowLaw; 4] = [
        RowLaw::Jkr,
        RowLaw::Dmt(AttractionKind::VanDerWaals),
        RowLaw::Dmt(AttractionKind::Dugdale),
        RowLaw::LennardJones,
    ];
}

/// One row of the work–precision table.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// What was measured.
    pub quantity: Quantity,
    /// The setting, e.g. `order=20;step=6;cut=46` or `fd=central;delta=1e-4`.
    pub setting: String,
    /// Largest relative error over the samples.
    pub max_rel_error: f64,
    /// Median relative error.
    pub median_rel_error: f64,
    /// Median wall time of one evaluation (ns): one `Model::at` for load and
    /// areas, one `evaluate` for the wear rate, one elasticity for the gradient.
    pub time_per_eval_ns: f64,
    /// True for the evaluator's default.
    pub is_default: bool,
    /// Samples the statistics are over.
    pub samples: usize,
    /// Model evaluations per value (gradient: wear-rate evaluations per elasticity).
    pub evaluations_per_value: usize,
    /// The asperity law measured.
    pub law: RowLaw,
}

/// One (coefficients, h) point of the grid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GridPoint {
    /// The coefficients.
    pub coefficients: Coefficients,
    /// h.
    pub separation: f64,
}

/// What the work–precision run measured, with provenance.
#[derive(Debug, Clone, PartialEq)]
pub struct WorkPrecision {
    /// The rows, quantity by quantity.
    pub rows: Vec<Row>,
    /// Grid points (P̄, Ā, Ā_p samples).
    pub grid_points: usize,
    /// Scene load points (wear-rate samples).
    pub wear_points: usize,
    /// Elasticities compared (gradient samples).
    pub gradient_points: usize,
    /// The largest estimated relative error of the reference over the grid (loads
    /// relative to |elastic| + |plastic|), a floor below which errors are not resolved.
    pub reference_error: f64,
    /// The largest estimated error of a reference elasticity (normwise).
    pub reference_gradient_error: f64,
    /// Scenes whose region was added to the grid.
    pub scenes: Vec<String>,
    /// DMT grid points per attraction (P̄, Ā, Ā_p samples of the DMT rows).
    pub dmt_grid_points: usize,
    /// The largest estimated relative error of the DMT reference over its grid
    /// (contact loads relative to their parts, N to |N|).
    pub dmt_reference_error: f64,
    /// Points of the Lennard-Jones rows (P̄ samples).
    pub lennard_jones_points: usize,
    /// The Lennard-Jones law's pull-off error of the closed-form law where it
    /// stands in: (DMT below μ = 0.01, one summit's; JKR above μ = 3.58e6, the
    /// rough surface's where adhesion is strong).
    pub lennard_jones_stand_in_error: (f64, f64),
}

/// Options of the run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Timed repetitions of each evaluation (the median over points is reported).
    pub repetitions: usize,
}

impl Default for Options {
    fn default() -> Self {
        Options { repetitions: 16 }
    }
}

/// The quadrature settings compared: every order of [`gauss::ORDERS`] with
/// panel steps 3, 6, 12 and cuts 30, 46, 60 (those that validate), default included.
pub fn settings() -> Vec<Quadrature> {
    let mut out = Vec::new();
    for &order in &gauss::ORDERS {
        for &step in &[3.0, 6.0, 12.0] {
            for &cut in &[30.0, 46.0, 60.0] {
                let q = Quadrature {
                    order,
                    log_weight_step: step,
                    log_weight_cut: cut,
                };
                if q.validate().is_ok() {
                    out.push(q);
                }
            }
        }
    }
    if !out.contains(&Quadrature::default()) {
        out.push(Quadrature::default());
    }
    out
}

/// `order=20;step=6;cut=46`.
pub fn setting_label(q: &Quadrature) -> String {
    format!(
        "order={};step={};cut={}",
        q.order, q.log_weight_step, q.log_weight_cut
    )
}

/// The step rules compared: δ ∈ {1e-2 … 1e-6}, central and Richardson.
pub fn step_rules() -> Vec<StepRule> {
    let mut out = Vec::new();
    for &d in &[1e-2, 1e-3, 1e-4, 1e-5, 1e-6] {
        for richardson in [false, true] {
            out.push(StepRule {
                log_step: d,
                richardson,
            });
        }
    }
    out
}

/// The extreme-range grid: θ ∈ [1e-3, 1e8], λ ∈ [1e-6, 1e6], h ∈ [-4, 60] (with
/// h = −1e-3, just left of the switch of panel layout at 0), the
/// limits γ = 0 and H = ∞, and for each scene its (θ, λ) × {½, 1, 2} each and its
/// h + {−1, −½, 0, ½, 1}.
pub fn grid(scenes: &[Scene]) -> Vec<GridPoint> {
    let hs = [
        -4.0, -2.0, -1.0, -1e-3, 0.0, 0.5, 1.0, 2.0, 4.0, 8.0, 15.0, 30.0, 60.0,
    ];
    let thetas = [1e-3, 1e-2, 0.1, 1.0, 10.0, 100.0, 1e4, 1e6, 1e8];
    let lambdas = [1e-6, 1e-4, 1e-2, 1.0, 100.0, 1e4, 1e6];
    let mut coefficients = Vec::new();
    for &t in &thetas {
        for &l in &lambdas {
            coefficients.push(Coefficients::from_indices(t, l));
        }
        coefficients.push(Coefficients::from_indices_or_limits(t, f64::INFINITY, 0.0));
    }
    for &c_h in &[0.3, 3.0, 30.0, f64::INFINITY] {
        coefficients.push(Coefficients::new(0.0, c_h));
    }
    let mut out: Vec<GridPoint> = coefficients
        .iter()
        .flat_map(|&c| {
            hs.iter().map(move |&h| GridPoint {
                coefficients: c,
                separation: h,
            })
        })
        .collect();
    for scene in scenes {
        let ev = evaluate(scene, &EvaluationOptions::default());
        let Some(h) = ev.nondimensional_separation else {
            continue;
        };
        let idx = wear::indices(scene);
        let (theta, lambda) = (idx.elastic_adhesion_index, idx.plastic_adhesion_index);
        for &a in &[0.5, 1.0, 2.0] {
            for &b in &[0.5, 1.0, 2.0] {
                let c = if theta.is_finite() && lambda.is_finite() {
                    Coefficients::from_indices(theta * a, lambda * b)
                } else if theta.is_finite() {
                    Coefficients::from_indices_or_limits(theta * a, f64::INFINITY, 0.0)
                } else {
                    // γ = 0: move c_h instead (θ and λ are infinite).
                    let c = wear::coefficients(scene);
                    Coefficients::new(0.0, c.c_h * a * b.powf(0.25))
                };
                for &dh in &[-1.0, -0.5, 0.0, 0.5, 1.0] {
                    out.push(GridPoint {
                        coefficients: c,
                        separation: h + dh,
                    });
                }
            }
        }
    }
    out
}

fn median(v: &mut [f64]) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

fn stats(mut errors: Vec<f64>, mut times: Vec<f64>) -> (f64, f64, f64, usize) {
    let max = errors.iter().copied().fold(0.0, f64::max);
    let n = errors.len();
    (max, median(&mut errors), median(&mut times), n)
}

fn rel(got: f64, want: f64, scale: f64) -> f64 {
    if got == want {
        0.0
    } else {
        (got - want).abs() / scale
    }
}

/// Relative error of an area mantissa (both negligible: exact).
fn area_error(got: f64, want: f64) -> f64 {
    if got.abs() < NEGLIGIBLE && want.abs() < NEGLIGIBLE {
        0.0
    } else {
        rel(got, want, want.abs().max(NEGLIGIBLE))
    }
}

/// Relative error of a wear rate from its value and log10 (when a value underflows).
fn wear_error(got: (f64, f64), want_ln: f64) -> f64 {
    let (value, log10) = got;
    let ln = if value > 1e-290 {
        value.ln()
    } else {
        log10 * std::f64::consts::LN_10
    };
    (ln - want_ln).exp_m1().abs()
}

/// The work–precision run over `scenes` (their regions are added to the grid;
/// their loads × {1/100, 1/10, 1, 10, 100} are the wear-rate samples and their
/// five elasticities the gradient samples).
pub fn work_precision(scenes: &[(String, Scene)], options: Options) -> WorkPrecision {
    let scene_list: Vec<Scene> = scenes.iter().map(|(_, s)| s.clone()).collect();
    // The JKR rows take every scene under JKR (a DMT scene too); the DMT rows below
    // take every scene under DMT with each attraction.
    let jkr_scenes: Vec<Scene> = scene_list
        .iter()
        .map(|s| Scene {
            adhesion_model: AdhesionModel::Jkr,
            ..s.clone()
        })
        .collect();
    let points = grid(&jkr_scenes);
    let reps = options.repetitions.max(1);
    // The reference at every grid point.
    let references: Vec<_> = points
        .iter()
        .map(|p| ReferenceModel::new(p.coefficients).at(p.separation))
        .collect();
    let reference_error = references
        .iter()
        .map(|r| {
            let load = r.load_error() / r.load_parts().max(r.load().abs()).max(NEGLIGIBLE);
            let area = r.area.error / r.area.value.abs().max(NEGLIGIBLE);
            load.max(area)
        })
        .fold(0.0, f64::max);
    // Wear-rate samples and their reference.
    let mut wear_scenes = Vec::new();
    for s in &jkr_scenes {
        for &f in &[0.01, 0.1, 1.0, 10.0, 100.0] {
            let mut sc = s.clone();
            sc.load *= f;
            if let Some(ln) = finite_difference::reference_ln_wear_rate(&sc) {
                wear_scenes.push((sc, ln));
            }
        }
    }
    let mut rows = Vec::new();
    let mut per_quantity: [Vec<Row>; 4] = Default::default();
    for q in settings() {
        let label = setting_label(&q);
        let is_default = q == Quadrature::default();
        let (mut el, mut ea, mut ep, mut times) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        for (p, r) in points.iter().zip(&references) {
            let m = Model::with_quadrature(p.coefficients, q);
            let at = m.at(p.separation);
            let load = at.load_elastic + at.load_plastic;
            el.push(rel(
                load,
                r.load(),
                r.load_parts().max(r.load().abs()).max(NEGLIGIBLE),
            ));
            ea.push(area_error(at.area, r.area.value));
            ep.push(area_error(at.plastic_area, r.plastic_area.value));
            let start = Instant::now();
            for _ in 0..reps {
                black_box(m.at(black_box(p.separation)));
            }
            times.push(start.elapsed().as_nanos() as f64 / reps as f64);
        }
        let eval_options = EvaluationOptions {
            pull_off: false,
            quadrature: q,
            work_of_adhesion: false,
        };
        let (mut ew, mut tw) = (Vec::new(), Vec::new());
        for (sc, want) in &wear_scenes {
            let ev = evaluate(sc, &eval_options);
            if ev.status != Status::Ok {
                ew.push(f64::INFINITY);
                continue;
            }
            ew.push(wear_error((ev.wear_rate, ev.log10_wear_rate), *want));
            let w_reps = reps.div_ceil(4);
            let start = Instant::now();
            for _ in 0..w_reps {
                black_box(evaluate(black_box(sc), &eval_options));
            }
            tw.push(start.elapsed().as_nanos() as f64 / w_reps as f64);
        }
        let errors = [el, ea, ep, ew];
        let quantities = [
            Quantity::Load,
            Quantity::Area,
            Quantity::PlasticArea,
            Quantity::WearRate,
        ];
        for (i, (e, quantity)) in errors.into_iter().zip(quantities).enumerate() {
            let t = if i < 3 { times.clone() } else { tw.clone() };
            let (max, med, time, n) = stats(e, t);
            per_quantity[i].push(Row {
                quantity,
                setting: label.clone(),
                max_rel_error: max,
                median_rel_error: med,
                time_per_eval_ns: time,
                is_default,
                samples: n,
                evaluations_per_value: 1,
                law: RowLaw::Jkr,
            });
        }
    }
    for group in per_quantity {
        rows.extend(group);
    }
    // Gradient: the scenes' elasticities under each step rule.
    let mut references_fd = Vec::new();
    let mut reference_gradient_error: f64 = 0.0;
    for s in &jkr_scenes {
        let mut grad = Vec::new();
        for p in SceneParameter::SENSITIVITIES {
            if !finite_difference::differentiable(p, s) {
                continue;
            }
            if let Some(r) = finite_difference::reference_elasticity(s, p) {
                grad.push((p, r));
            }
        }
        let norm = grad.iter().map(|(_, r)| r.value.abs()).fold(0.0, f64::max);
        if norm > 0.0 {
            for (_, r) in &grad {
                reference_gradient_error = reference_gradient_error.max(r.error / norm);
            }
            references_fd.push((s.clone(), grad, norm));
        }
    }
    let gradient_points = references_fd.iter().map(|(_, g, _)| g.len()).sum();
    for rule in step_rules() {
        let (mut errors, mut times) = (Vec::new(), Vec::new());
        for (s, grad, norm) in &references_fd {
            for (p, r) in grad {
                let start = Instant::now();
                let got = finite_difference::elasticity(s, *p, rule, Quadrature::default());
                times.push(start.elapsed().as_nanos() as f64);
                errors.push(got.map_or(f64::INFINITY, |g| (g - r.value).abs() / norm));
            }
        }
        let (max, med, time, n) = stats(errors, times);
        rows.push(Row {
            quantity: Quantity::Gradient,
            setting: rule.label(),
            max_rel_error: max,
            median_rel_error: med,
            time_per_eval_ns: time,
            is_default: rule == StepRule::DEFAULT,
            samples: n,
            evaluations_per_value: rule.evaluations(),
            law: RowLaw::Jkr,
        });
    }
    let mut dmt_grid_points = 0;
    let mut dmt_reference_error: f64 = 0.0;
    for kind in [AttractionKind::VanDerWaals, AttractionKind::Dugdale] {
        let d = dmt_rows(kind, &scene_list, reps);
        dmt_grid_points = d.grid_points;
        dmt_reference_error = dmt_reference_error.max(d.reference_error);
        rows.extend(d.rows);
    }
    let lj_scenes: Vec<(Coefficients, f64)> = scene_list
        .iter()
        .filter(|s| s.work_of_adhesion > 0.0)
        .map(|s| (wear::coefficients(s), s.interatomic_distance / s.sigma))
        .collect();
    let lj_points = lennard_jones::points(&lj_scenes);
    rows.extend(lennard_jones::rows(&lj_points, reps));
    WorkPrecision {
        lennard_jones_points: lj_points.len(),
        lennard_jones_stand_in_error: lennard_jones::stand_in_errors(),
        rows,
        grid_points: points.len(),
        wear_points: wear_scenes.len(),
        gradient_points,
        reference_error,
        reference_gradient_error,
        scenes: scenes.iter().map(|(n, _)| n.clone()).collect(),
        dmt_grid_points,
        dmt_reference_error,
    }
}

/// One DMT grid point: coefficients, attraction, h.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DmtGridPoint {
    /// The coefficients (c_0 = 2π/θ, c_h; c_a and c_d are not used by DMT).
    pub coefficients: Coefficients,
    /// The attraction with its range.
    pub attraction: Attraction,
    /// h.
    pub separation: f64,
}

/// The DMT grid of one attraction: θ ∈ [1e-3, 1e8], λ ∈ [1e-6, 1e6] and H = ∞,
/// ranges z0 ∈ [1e-4, 10] (van der Waals) or Δ_h ∈ [1e-6, 1e3] (Dugdale),
/// h ∈ [-4, 60]; and each scene's region under DMT with this attraction, as for JKR.
pub fn dmt_grid(kind: AttractionKind, scenes: &[Scene]) -> Vec<DmtGridPoint> {
    let hs = [-4.0, -1.0, 0.0, 0.5, 2.0, 5.0, 12.0, 25.0, 40.0, 60.0];
    let thetas = [1e-3, 1.0, 184.0, 1e4, 1e8];
    let lambdas = [1e-6, 1e-2, 1.0, 1e6];
    let ranges: [f64; 4] = match kind {
        AttractionKind::VanDerWaals => [1e-4, 1e-2, 0.1, 10.0],
        AttractionKind::Dugdale => [1e-6, 1e-3, 0.1, 1e3],
    };
    let mut coefficients = Vec::new();
    for &t in &thetas {
        for &l in &lambdas {
            coefficients.push(Coefficients::from_indices(t, l));
        }
        coefficients.push(Coefficients::from_indices_or_limits(t, f64::INFINITY, 0.0));
    }
    let mut out = Vec::new();
    for c in &coefficients {
        for &r in &ranges {
            for &h in &hs {
                out.push(DmtGridPoint {
                    coefficients: *c,
                    attraction: Attraction::new(kind, r),
                    separation: h,
                });
            }
        }
    }
    for scene in scenes {
        let mut sc = scene.clone();
        sc.adhesion_model = AdhesionModel::Dmt;
        sc.attraction = kind;
        let ev = evaluate(&sc, &EvaluationOptions::default());
        let Some(h) = ev.nondimensional_separation else {
            continue;
        };
        let idx = wear::indices(&sc);
        let (theta, lambda) = (idx.elastic_adhesion_index, idx.plastic_adhesion_index);
        if !(theta.is_finite() && lambda.is_finite()) {
            continue;
        }
        let attraction = Attraction::new(kind, kind.range(sc.interatomic_distance, sc.sigma));
        for &a in &[0.5, 1.0, 2.0] {
            for &b in &[0.5, 1.0, 2.0] {
                for &dh in &[-1.0, -0.5, 0.0, 0.5, 1.0] {
                    out.push(DmtGridPoint {
                        coefficients: Coefficients::from_indices(theta * a, lambda * b),
                        attraction,
                        separation: h + dh,
                    });
                }
            }
        }
    }
    out
}

/// The DMT rows of one attraction and what they were measured over.
#[derive(Debug, Clone, PartialEq)]
pub struct DmtRows {
    /// Load (contact share), non-contact load, Ā, Ā_p and wear rate, default setting.
    pub rows: Vec<Row>,
    /// Grid points.
    pub grid_points: usize,
    /// The reference's largest estimated relative error over the grid.
    pub reference_error: f64,
}

/// The DMT rows of one attraction at the default quadrature (module docs): the
/// grid of [`dmt_grid`], and the scenes under DMT with this attraction at their
/// loads × {1/100, 1/10, 1, 10, 100} for the wear rate.
pub fn dmt_rows(kind: AttractionKind, scenes: &[Scene], repetitions: usize) -> DmtRows {
    let q = Quadrature::default();
    let points = dmt_grid(kind, scenes);
    let reps = repetitions.max(1);
    let (mut el, mut en, mut ea, mut ep, mut times) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new(), Vec::new());
    let mut reference_error: f64 = 0.0;
    for p in &points {
        let law = AsperityLaw::Dmt(p.attraction);
        let m = Model::with_law(p.coefficients, law, q);
        let r = reference::ReferenceModel::with_law(p.coefficients, law).at(p.separation);
        let at = m.at(p.separation);
        let parts = r.load_parts().max(r.load().abs()).max(NEGLIGIBLE);
        reference_error = reference_error.max(r.load_error() / parts);
        el.push(rel(at.load_elastic + at.load_plastic, r.load(), parts));
        let n = &r.noncontact_load;
        if n.value.abs() >= NEGLIGIBLE {
            reference_error = reference_error.max(n.error / n.value.abs());
            let want = Scaled::new(n.value, r.noncontact_exponent);
            en.push(at.noncontact_load().minus(want).ratio(want).abs());
        }
        ea.push(area_error(at.area, r.area.value));
        ep.push(area_error(at.plastic_area, r.plastic_area.value));
        let start = Instant::now();
        for _ in 0..reps {
            black_box(m.at(black_box(p.separation)));
        }
        times.push(start.elapsed().as_nanos() as f64 / reps as f64);
    }
    let options = EvaluationOptions {
        pull_off: false,
        quadrature: q,
        work_of_adhesion: false,
    };
    let (mut ew, mut tw) = (Vec::new(), Vec::new());
    for s in scenes {
        for &f in &[0.01, 0.1, 1.0, 10.0, 100.0] {
            let mut sc = s.clone();
            sc.adhesion_model = AdhesionModel::Dmt;
            sc.attraction = kind;
            sc.load *= f;
            let Some(want) = finite_difference::reference_ln_wear_rate(&sc) else {
                continue;
            };
            let ev = evaluate(&sc, &options);
            ew.push(wear_error((ev.wear_rate, ev.log10_wear_rate), want));
            let w_reps = reps.div_ceil(4);
            let start = Instant::now();
            for _ in 0..w_reps {
                black_box(evaluate(black_box(&sc), &options));
            }
            tw.push(start.elapsed().as_nanos() as f64 / w_reps as f64);
        }
    }
    let mut rows = Vec::new();
    for (quantity, errors, t) in [
        (Quantity::Load, el, &times),
        (Quantity::NoncontactLoad, en, &times),
        (Quantity::Area, ea, &times),
        (Quantity::PlasticArea, ep, &times),
        (Quantity::WearRate, ew, &tw),
    ] {
        let (max, med, time, n) = stats(errors, t.clone());
        rows.push(Row {
            quantity,
            setting: setting_label(&q),
            max_rel_error: max,
            median_rel_error: med,
            time_per_eval_ns: time,
            is_default: true,
            samples: n,
            evaluations_per_value: 1,
            law: RowLaw::Dmt(kind),
        });
    }
    DmtRows {
        rows,
        grid_points: points.len(),
        reference_error,
    }
}
