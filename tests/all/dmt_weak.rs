//! Weak adhesion under DMT (θ from 1e6 to 1e8 and beyond): the pull-off minimum of P̄
//! moves out to h ~ 1e2–1e6, where P̄ ~ e^{-h²/2} and the contact and attracted
//! shares cancel to ~1/h² of their size at the minimum (separation.rs module docs,
//! "Weak adhesion"). The million-case stability run found the search missing it
//! (θ = 6.45e7, H = ∞, Dugdale Δ_h = 1.97e-5) or returning a "minimum" with P̄ > 0
//! (θ = 3.9e8, c_h = 1.9e-3, Δ_h = 3.5e-6): both are rows of the table below.
//!
//! Checked against (a) `reference_dmt_weak.csv` (mpmath at 60 digits: a Laplace form
//! in x = hΔ and the closed-form/s-substitution method of `scripts/reference_dmt.py`
//! agree to ≥ 25 digits), (b) the closed-form limit of vanishing adhesion, and (c)
//! JKR's minimum on the same coefficients where the two laws are the same plastic law;
//! and at scene level: a pull-off, or a warning saying why there is none.

use std::path::Path;

use crate::common::{num, table};
use wearopt::model::{
    evaluate, find_pull_off, AdhesionModel, AsperityLaw, Attraction, AttractionKind, Coefficients,
    EvaluationOptions, Model, Quadrature, Warning,
};

fn coefficients(theta: f64, c_h: f64) -> Coefficients {
    let mut c = Coefficients::new((6.0 * std::f64::consts::PI / theta).sqrt(), c_h);
    c.c_0 = 2.0 * std::f64::consts::PI / theta;
    c
}

fn dugdale(c: Coefficients, range: f64) -> Model {
    Model::with_law(
        c,
        AsperityLaw::Dmt(Attraction::Dugdale { range }),
        Quadrature::default(),
    )
}

/// Γ(5/2) = 3√π/4.
fn gamma_5_2() -> f64 {
    0.75 * std::f64::consts::PI.sqrt()
}

/// The minima against the 60-digit table. h_min to 1e-13 relative (the slope's sign
/// is resolved to ~ε·h: a point off the minimum by δ has P̄' ~ (parts)·δ, its rounding
/// ε·h·(parts)); ln|P̄_min| to 8 ulps of itself: P̄_min = m·e^{-E} with E ≈ h²/2 a
/// double, so its relative error is E's rounding, 4e-16·E (6e-6 at h = 1.6e5, where
/// the force is 10^{-5.7e9} N). For |ln P̄| ≤ 500 that is 1e-12 relative in P̄.
#[test]
fn weak_adhesion_minima_match_the_high_precision_table() {
    let rows = table("reference_dmt_weak.csv");
    assert!(rows.len() >= 5, "table too small: {}", rows.len());
    for row in &rows {
        assert_eq!(row["attraction"], "dugdale");
        let c = coefficients(num(&row["theta"]), num(&row["c_h"]));
        let m = dugdale(c, num(&row["range"]));
        let p = find_pull_off(&m).unwrap_or_else(|| panic!("no pull-off for {row:?}"));
        assert_eq!(p.local_minima, 1, "{row:?}");
        assert!(p.load.signum() < 0.0, "{row:?}: {p:?}");
        let h_ref = num(&row["h_min"]);
        assert!(
            (p.separation / h_ref - 1.0).abs() < 1e-13,
            "{row:?}: h = {}",
            p.separation
        );
        let ln_ref = num(&row["ln_abs_load_min"]);
        let tol = (8.0 * f64::EPSILON * ln_ref.abs()).max(1e-12);
        assert!(
            (p.load.ln_abs() - ln_ref).abs() < tol,
            "{row:?}: ln|P̄| = {} (off by {:e})",
            p.load.ln_abs(),
            p.load.ln_abs() - ln_ref
        );
        // Weak adhesion costs no more than a few dozen evaluations.
        assert!(
            p.evaluations <= 40,
            "{row:?}: {} evaluations",
            p.evaluations
        );
    }
}

/// The limit of vanishing adhesion (H = ∞, short Dugdale range). With e^{-Δ²/2} =
/// 1 - Δ²/2 + … under the Laplace integrals,
///
/// ```text
/// e^{h²/2} P̄ = Γ(5/2) h^{-5/2} (1 - 35/(8h²)) - (c_0/h)(1 - 1/h²)
///              - c_0 (Δ_h/2)(1 + hΔ_h/3 + (hΔ_h)²/12) + …
/// ```
///
/// which crosses zero at h_z^{3/2} = (Γ(5/2)/c_0)(1 - 35/(8h²))/(1 - 1/h² + hΔ_h/2 +
/// (hΔ_h)²/6); P̄' = 0 (where e^{h²/2} P̄ equals its slope over h) lies one step 1/h
/// further: h_min = h_z + 1/h_z, up to O(h^{-3}) and O((hΔ_h)³). At the minimum
/// P̄ = e^{-h²/2} (e^{h²/2} P̄)'/h, which tends to -(3/2) Γ(5/2) h^{-9/2} e^{-h²/2}, up
/// to O(hΔ_h) and O(h^{-2}).
#[test]
fn weak_adhesion_tends_to_the_closed_form_limit() {
    for (theta, range) in [
        (1e6, 1e-9),
        (1e6, 1e-6),
        (1e8, 1e-9),
        (1e8, 1e-6),
        (1e9, 1e-9),
        (1e10, 1e-9),
    ] {
        let c = coefficients(theta, f64::INFINITY);
        let g = gamma_5_2() / c.c_0;
        let mut hz = g.powf(2.0 / 3.0);
        for _ in 0..50 {
            let (r2, x) = (1.0 / (hz * hz), hz * range);
            let ratio = (1.0 - 35.0 / 8.0 * r2) / (1.0 - r2 + 0.5 * x + x * x / 6.0);
            hz = (g * ratio).powf(2.0 / 3.0);
        }
        let closed = hz + 1.0 / hz;
        let p = find_pull_off(&dugdale(c, range))
            .unwrap_or_else(|| panic!("θ = {theta:e}, Δ_h = {range:e}: no pull-off"));
        let bound = (closed * range).powi(3) + closed.powi(-3) + 1e-13;
        assert!(
            (p.separation / closed - 1.0).abs() < bound,
            "θ = {theta:e}, Δ_h = {range:e}: h = {} vs {closed} (bound {bound:e})",
            p.separation
        );
        let h = p.separation;
        let lead = (1.5 * gamma_5_2()).ln() - 4.5 * h.ln() - 0.5 * h * h;
        let mantissa_bound = h * range + 4.0 / (h * h);
        // Beyond h = 1e6 the model does not resolve P̄_min's mantissa (its shares
        // cancel to 1/h² < 1e-12 of their size): only the location is checked there.
        assert!(
            h > 1e6 || (p.load.ln_abs() - lead).abs() < mantissa_bound,
            "θ = {theta:e}, Δ_h = {range:e}: ln|P̄| = {} vs {lead}",
            p.load.ln_abs()
        );
    }
}

/// Where the two laws are one: every asperity that counts at the minimum (Δ ≲ 40/h)
/// beyond both laws' critical interference (JKR's Δc ≈ c_a^{4/3}/3 for small c_h,
/// DMT's c_h²) carries c_p Δ - c_0 under either law, and the attraction (Δ_h ≪ 1/h)
/// adds c_0 Δ_h/2. The laws differ on a window of width w = Δc_JKR + Δc_DMT + Δ_h, a
/// change of e^{h²/2}P̄ by ≲ c_0 w against the size c_0/h of its parts, which moves the
/// minimum by ≲ h w relative. JKR finds its minimum by its own search (its guess and
/// its integrals), so this checks DMT's search on far minima (h = 32 to 3200) independently.
#[test]
fn far_minimum_agrees_with_jkr_where_the_laws_agree() {
    for (theta, c_h) in [(1e8, 1e-6), (1e8, 1e-5), (1e8, 1e-4)] {
        let range = 1e-12;
        let c = coefficients(theta, c_h);
        let jkr_model = Model::with_quadrature(c, Quadrature::default());
        let d = find_pull_off(&dugdale(c, range)).expect("DMT pull-off");
        let j = find_pull_off(&jkr_model).expect("JKR pull-off");
        let w = jkr_model.critical_interference() + c_h * c_h + range;
        let bound = d.separation * w;
        assert!(bound < 0.05, "not a case where the laws agree: {bound}");
        let off = (d.separation / j.separation - 1.0).abs();
        assert!(
            off < bound,
            "θ = {theta:e}, c_h = {c_h:e}: DMT h = {} vs JKR {} ({off:e} > {bound:e})",
            d.separation,
            j.separation
        );
        // Both minima sit at the plastic balance h ≈ c_p/c_0 (e^{h²/2} P̄ ≈ c_p/h² - c_0/h).
        let balance = c.c_p / c.c_0;
        assert!(
            (d.separation / balance - 1.0).abs() < 0.05,
            "{d:?} vs {balance}"
        );
    }
}

/// At scene level a weak-adhesion scene reports its pull-off (0 N as a double, with
/// its log10 and the underflow note), and one whose minimum lies beyond the
/// separations the model resolves (|h| > 1e6) reports none *with a warning*: no
/// accepted scene gives a silent null.
#[test]
fn weak_adhesion_scenes_report_a_pull_off_or_say_why_not() {
    let path = Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/problems/micro-gear.toml"
    ));
    let mut scene = wearopt::problem::load(path).expect("the hub loads").scene;
    scene.adhesion_model = AdhesionModel::Dmt;
    let opts = EvaluationOptions::default();
    let hub_gamma = scene.work_of_adhesion;
    for attraction in [AttractionKind::Dugdale, AttractionKind::VanDerWaals] {
        scene.attraction = attraction;
        // θ from the hub's 184 to 1.8e8: the pull-off is always reported.
        for factor in [1e-2, 1e-4, 1e-6] {
            scene.work_of_adhesion = hub_gamma * factor;
            let ev = evaluate(&scene, &opts);
            let theta = ev.indices.elastic_adhesion_index;
            let f = ev
                .pull_off_force
                .unwrap_or_else(|| panic!("{attraction:?} θ = {theta:e}: {ev:?}"));
            let log10 = ev.log10_pull_off_force.expect("log10 with a pull-off");
            assert!(
                f >= 0.0 && log10.is_finite(),
                "{attraction:?} θ = {theta:e}"
            );
            assert!(
                !ev.warnings.iter().any(|w| matches!(
                    w,
                    Warning::PullOffNotFound { .. } | Warning::PullOffBeyondModel { .. }
                )),
                "{attraction:?} θ = {theta:e}: {:?}",
                ev.warnings
            );
        }
    }
    // θ ≈ 1.8e16, no plasticity, a Dugdale range of 1e-9 σ: the minimum lies near
    // h ≈ (Γ(5/2)/c_0)^{2/3} ~ 1e10, far beyond the model's |h| ≤ 1e6. (With the
    // hub's Δ_h ≈ 0.1 it would sit at h ≈ ln(1/c_0)/Δ_h ≈ 316, where the attracted
    // share's e^{hΔ_h} meets the contacts': a pull-off of 0 N, as above.)
    scene.attraction = AttractionKind::Dugdale;
    scene.work_of_adhesion = hub_gamma * 1e-14;
    scene.hardness = f64::INFINITY;
    scene.interatomic_distance = 1e-9 * scene.sigma;
    let ev = evaluate(&scene, &opts);
    assert_eq!(ev.pull_off_force, None);
    assert!(
        ev.warnings.iter().any(|w| matches!(
            w,
            Warning::PullOffNotFound { .. } | Warning::PullOffBeyondModel { .. }
        )),
        "{:?}",
        ev.warnings
    );
}
