//! Limits, invariants and the numbers docs/model.md quotes, each with its provenance.

use wearopt::model::{
    asperity, find_pull_off, landscape, solve_separation, Coefficients, Model, Quadrature,
    SeparationOutcome,
};

fn contact_h(o: SeparationOutcome) -> f64 {
    match o {
        SeparationOutcome::Contact { separation, .. } => separation,
        other => panic!("expected contact, got {other:?}"),
    }
}

/// γ → 0 is Greenwood–Williamson: with c_a tiny the load tends to the c_a = 0 value,
/// and at c_a = 0, H = ∞: P̄(0) = √(2π) F_{3/2}(0) = 2^{1/4} Γ(5/4) (closed form;
/// Γ(5/4) = 0.9064024770554771, A&S 6.1).
#[test]
fn no_adhesion_limit_is_greenwood_williamson() {
    let gw = Model::new(Coefficients::new(0.0, f64::INFINITY));
    let exact = 2f64.powf(0.25) * 0.906_402_477_055_477;
    assert!((gw.at(0.0).load().value() / exact - 1.0).abs() < 1e-13);
    // Continuity in γ: c_a = 1e-9 differs from c_a = 0 by O(c_a).
    for &h in &[-2.0, 0.0, 1.5, 4.0] {
        let a = Model::new(Coefficients::new(0.0, 2.0)).at(h).load().value();
        let b = Model::new(Coefficients::new(1e-9, 2.0))
            .at(h)
            .load()
            .value();
        assert!((a - b).abs() < 1e-7 * a.abs(), "h={h}: {a} {b}");
    }
    // Ā(0) = √(2π) F_1(0) = 1 exactly.
    assert!((gw.at(0.0).area().value() - 1.0).abs() < 1e-15);
}

/// JKR: one asperity's pull-off is -(3/2)πγR, i.e. -c_a²/4 in model units, and
/// its load at zero interference is -(4/3)πγR = -c_a c_d/3 (docs/model.md §3).
#[test]
fn jkr_single_asperity() {
    let m = Model::new(Coefficients::from_indices(7.0, 0.3));
    let c = m.coefficients;
    let theta = 7.0;
    // In units of γR: c_a²/4 · K R^{1/2} σ^{3/2} = (6π/θ)/4 · θ γR = 1.5π γR.
    assert!(
        (-asperity::jkr_pull_off(&m) * theta / (1.5 * std::f64::consts::PI) - 1.0).abs() < 1e-14
    );
    assert!(
        (-asperity::elastic_load(&m, 0.0) * theta / (4.0 / 3.0 * std::f64::consts::PI) - 1.0).abs()
            < 1e-13
    );
    assert!((c.c_0 * theta / (2.0 * std::f64::consts::PI) - 1.0).abs() < 1e-14);
}

/// docs/model.md §4's quoted values (its own high-precision evaluation).
#[test]
fn model_md_quoted_values() {
    let m = Model::new(Coefficients::from_indices(10.0, 1.0));
    let po = find_pull_off(&m).unwrap();
    assert!((po.separation - 1.86).abs() < 0.005, "{}", po.separation);
    assert!((po.load.value() / -5.15e-3 - 1.0).abs() < 2e-3);

    let m = Model::new(Coefficients::from_indices(0.1, 1e-3));
    let land = landscape(&m);
    let cps: Vec<(f64, f64)> = land
        .critical_points
        .iter()
        .map(|c| (c.separation, c.load.value()))
        .collect();
    assert!(
        cps.iter()
            .any(|&(h, p)| (h + 25.489).abs() < 1e-3 && (p - 226.21).abs() < 5e-3),
        "{cps:?}"
    );
    assert!(
        cps.iter()
            .any(|&(h, p)| (h + 28.838).abs() < 1e-3 && (p - 143.94).abs() < 5e-3),
        "{cps:?}"
    );
    // P̄ = 180 has three roots; the rule takes the largest, right of the local maximum.
    let h = contact_h(solve_separation(&m, 180.0));
    assert!(h > -25.489);
    assert!((m.at(h).load().value() / 180.0 - 1.0).abs() < 1e-12);

    let m = Model::new(Coefficients::from_indices(1e4, 100.0));
    let po = find_pull_off(&m).unwrap();
    assert!((po.separation - 232.5).abs() < 0.05, "{}", po.separation);
    // ≈ -2e-11753: log10 between -11753 and -11752.
    let l = po.load.log10_abs();
    assert!(l > -11753.0 && l < -11752.5, "{l}");
    assert_eq!(po.load.value(), 0.0);
    let h = contact_h(solve_separation(&m, 100.0));
    assert!((h + 172.0).abs() < 1.0, "{h}");
}

/// Solving h for P̄(h) gives h back, on the stable branch, across the box.
#[test]
fn separation_round_trip() {
    for &(theta, lambda) in &[
        (1e-2, 1e-4),
        (1.0, 1.0),
        (10.0, 0.125),
        (100.0, 5.0),
        (1e6, 1e6),
    ] {
        let m = Model::new(Coefficients::from_indices(theta, lambda));
        let po = find_pull_off(&m).unwrap();
        for &h in &[-4.0, -1.0, 0.0, 1.0, 3.0, 8.0] {
            if h >= po.separation {
                continue;
            }
            let target = m.at(h).load().value();
            if target == 0.0 {
                continue;
            }
            let got = contact_h(solve_separation(&m, target));
            assert!(
                (got - h).abs() < 1e-9 * h.abs().max(1.0),
                "θ={theta} λ={lambda} h={h}: {got}"
            );
        }
    }
    // Light loads on a GW surface: P̄ = 1e-300 still has a contact (h ≈ 37).
    let gw = Model::new(Coefficients::new(0.0, f64::INFINITY));
    let h = contact_h(solve_separation(&gw, 1e-300));
    assert!((gw.at(h).load().ln_abs() - 1e-300f64.ln()).abs() < 1e-12);
}

/// Load falls with separation on the stable branch; plastic area ≤ total area;
/// every output finite, over the extreme box.
#[test]
fn invariants_over_the_box() {
    let thetas = [1e-4, 1e-3, 0.1, 10.0, 1e4, 1e8, 1e10];
    let lambdas = [1e-8, 1e-6, 1e-2, 1.0, 1e4, 1e8];
    for &theta in &thetas {
        for &lambda in &lambdas {
            let m = Model::new(Coefficients::from_indices(theta, lambda));
            let po = find_pull_off(&m).unwrap();
            let mut prev: Option<(f64, f64)> = None;
            for i in 0..=90 {
                let h = -10.0 + i as f64;
                let at = m.at(h);
                for x in [
                    at.load_elastic,
                    at.load_plastic,
                    at.dload_dh_elastic,
                    at.dload_dh_plastic,
                    at.area,
                    at.plastic_area,
                ] {
                    assert!(x.is_finite(), "θ={theta} λ={lambda} h={h}: {at:?}");
                }
                assert!(at.area >= 0.0 && at.plastic_area >= 0.0);
                assert!(
                    at.plastic_area <= at.area * (1.0 + 1e-12),
                    "θ={theta} λ={lambda} h={h}"
                );
                let load = at.load();
                if h < po.separation && m.transition.jump >= 0.0 {
                    if let Some((_, p)) = prev {
                        assert!(load.value() <= p, "θ={theta} λ={lambda} h={h}");
                    }
                    prev = Some((h, load.value()));
                }
            }
        }
    }
}

/// The quadrature converges: the default agrees with a much finer rule.
#[test]
fn default_quadrature_agrees_with_a_finer_rule() {
    let fine = Quadrature {
        order: 32,
        log_weight_step: 2.5,
        log_weight_cut: 60.0,
    };
    assert!(fine.validate().is_ok());
    assert!(Quadrature::default().validate().is_ok());
    let mut worst = 0.0f64;
    for &theta in &[1e-3, 0.1, 1.0, 10.0, 100.0, 1e3, 1e4, 1e8] {
        for &lambda in &[1e-6, 1e-3, 0.125, 1.0, 100.0, 1e6] {
            for &h in &[-4.0, -1.0, 0.0, 0.5, 2.0, 5.0, 12.0, 35.0, 60.0] {
                let c = Coefficients::from_indices(theta, lambda);
                let a = Model::new(c).at(h);
                let b = Model::with_quadrature(c, fine).at(h);
                let scale = a.load_elastic.abs() + a.load_plastic.abs();
                worst = worst.max((a.load_elastic - b.load_elastic).abs() / scale);
            }
        }
    }
    // The graded panel orders trade the last digits of far panels for speed;
    // the accuracy proper is checked against the 40-digit tables (reference.rs).
    assert!(worst < 2.5e-13, "worst {worst:e}");
}

/// The wear-rate elasticities of `eval` against plain central differences at a
/// different step (independent of the Richardson rule used inside).
#[test]
fn sensitivities_match_plain_central_differences() {
    use wearopt::model::{evaluate, sensitivities, EvaluationOptions, SceneParameter};
    let p = wearopt::problem::load(std::path::Path::new("problems/gold-switch.toml")).unwrap();
    let opts = EvaluationOptions::default();
    let sens = sensitivities(
        &p.scene,
        opts.quadrature,
        wearopt::model::Quantity::WearRate,
    );
    let ln_wear =
        |s: &wearopt::model::Scene| evaluate(s, &opts).log10_wear_rate * std::f64::consts::LN_10;
    let d: f64 = 1e-5;
    for s in &sens {
        let mut up = p.scene.clone();
        let mut down = p.scene.clone();
        let f = d.exp();
        match s.parameter {
            SceneParameter::YoungsModulus => {
                up.youngs_modulus_a *= f;
                down.youngs_modulus_a /= f;
                // gold on gold: both bodies share E and move together.
                up.youngs_modulus_b *= f;
                down.youngs_modulus_b /= f;
            }
            SceneParameter::Hardness => {
                up.hardness *= f;
                down.hardness /= f;
            }
            SceneParameter::WorkOfAdhesion => {
                up.work_of_adhesion *= f;
                down.work_of_adhesion /= f;
            }
            SceneParameter::Sigma => {
                up.sigma *= f;
                down.sigma /= f;
            }
            SceneParameter::AsperityRadius => {
                up.asperity_radius *= f;
                down.asperity_radius /= f;
            }
            other => panic!("{other} is not one of eval's sensitivities"),
        }
        let plain = (ln_wear(&up) - ln_wear(&down)) / (2.0 * d);
        let got = s.elasticity.unwrap();
        // Central differences at 1e-5 carry ~1e-13/1e-5 = 1e-8 of rounding.
        assert!(
            (got - plain).abs() < 1e-6 * (1.0 + plain.abs()),
            "{:?}: {got} vs {plain}",
            s.parameter
        );
        eprintln!(
            "{:?}: {got} vs {plain}, error estimate {:e}",
            s.parameter,
            s.error.unwrap()
        );
        assert!(s.error.unwrap() < 1e-6);
    }
}

/// Where an elasticity is not defined the library says why, as a value: an
/// infinite hardness and a zero work of adhesion are limits, not points to
/// differentiate at; a scene without wear has no ln(wear) at all. (The
/// micro-gear wears over its whole real area, so H = ∞ still wears.)
#[test]
fn sensitivities_say_why_they_are_missing() {
    use wearopt::model::{sensitivities, Quadrature, SceneParameter, SensitivityGap};
    let p = wearopt::problem::load(std::path::Path::new("problems/micro-gear.toml")).unwrap();
    let gap = |scene: &wearopt::model::Scene, which: SceneParameter| {
        let s = sensitivities(
            scene,
            Quadrature::default(),
            wearopt::model::Quantity::WearRate,
        );
        let s = s.iter().find(|s| s.parameter == which).unwrap();
        assert_eq!(s.elasticity.is_none(), s.note.is_some(), "{s:?}");
        s.note
    };
    let mut limits = p.scene.clone();
    limits.hardness = f64::INFINITY;
    limits.work_of_adhesion = 0.0;
    assert_eq!(
        gap(&limits, SceneParameter::Hardness),
        Some(SensitivityGap::InfiniteParameter)
    );
    assert_eq!(
        gap(&limits, SceneParameter::WorkOfAdhesion),
        Some(SensitivityGap::ZeroParameter)
    );
    assert_eq!(gap(&limits, SceneParameter::Sigma), None);
    let mut no_wear = p.scene.clone();
    no_wear.wear_coefficient = 0.0;
    for which in SceneParameter::SENSITIVITIES {
        assert_eq!(gap(&no_wear, which), Some(SensitivityGap::NoWear));
    }
}

/// Ā_p with its own scale (`Model::plastic_area_scaled`): where the plastic share
/// is representable against e^{-κ(h)} it is the integrals' own to rounding; where
/// it underflows (the junctions far out in the heights' tail, h + Δc ≫ 1) its ln
/// is that of the asymptotic series of T_1(u) + Δc T_0(u) (A&S 7.1.23:
/// e^{u²/2} T_0(u) = (1/u) Σ (−1)^k (2k−1)!! / u^{2k}, and T_1 = e^{−u²/2} − u T_0),
/// an independent form, to 1e-12 of the ln.
#[test]
fn the_plastic_area_keeps_its_size_where_it_underflows() {
    let m = Model::new(Coefficients::from_indices(10.0, 0.5));
    let dc = m.transition.critical_interference;
    assert!(dc.is_finite() && dc > 0.0);
    for &h in &[-2.0, 0.0, 1.0, 3.0] {
        let own = m.plastic_area_scaled(h);
        let integrals = m.at(h).plastic_area();
        assert!(integrals.mantissa > 0.0, "h = {h}");
        let d = (own.ln_abs() - integrals.ln_abs()).abs();
        assert!(
            d < 1e-12 * own.ln_abs().abs().max(1.0),
            "h = {h}: {own:?} {integrals:?}"
        );
    }
    // Far out (at h = 1e5 the integrals' share is 0): the own-scale one is finite
    // and equal to the series (u ≥ 60: eight terms reach 1e-25).
    assert_eq!(m.at(1e5).plastic_area().mantissa, 0.0);
    for &h in &[60.0, 200.0, 3000.0, 1e5] {
        let u = h + dc;
        let series = |odd_start: f64| {
            // Σ_{k=0}^{7} (−1)^k (2k−1+odd_start)!!/u^{2k}, (−1)!! = 1.
            let (mut sum, mut term) = (1.0, 1.0);
            for k in 1..8 {
                term *= -(2.0 * k as f64 - 1.0 + odd_start) / (u * u);
                sum += term;
            }
            sum
        };
        // e^{u²/2} T_0 = series(0)/u; e^{u²/2} T_1 = 1 − u e^{u²/2} T_0 = series(2)/u².
        let scaled = series(2.0) / (u * u) + dc * series(0.0) / u;
        let ln_expected = scaled.ln() - 0.5 * u * u;
        let got = m.plastic_area_scaled(h).ln_abs();
        assert!(
            (got - ln_expected).abs() < 1e-12 * ln_expected.abs(),
            "h = {h}: {got} against {ln_expected}"
        );
    }
}
