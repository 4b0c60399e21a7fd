//! The robust-design engine (`wearopt::uq::robust`) on problems with known
//! answers: Youn & Choi's reliability-based design benchmark (as the
//! Hock–Schittkowski set tests the SQP), statistic objectives whose optimum is
//! closed-form, the coverage of the statistics' intervals, and determinism.

use wearopt::optimize::NonlinearProgram;
use wearopt::uq::distribution::{
    std_normal_cdf, std_normal_pdf, std_normal_quantile, Distribution,
};
use wearopt::uq::model::InputModel;
use wearopt::uq::reliability::SamplingMethod;
use wearopt::uq::robust::{
    estimate, inverse_form, optimize_robust, InverseFormSettings, InverseFormStatus, Outputs,
    RobustResult, RobustSettings, RobustStatus, ShiftedProgram, Statistic, UncertainProgram,
    Verify,
};

/// Youn & Choi 2004 ("A new response surface methodology for reliability-based
/// design optimization", Comput. Struct. 82:241; also Youn, Choi & Du 2005, and
/// Du & Chen 2004's SORA example): minimise d1 + d2 over d ∈ [0, 10]², X_i ~ N(d_i,
/// s²) independent, P(g_j(X) ≤ 0) ≤ Φ(−β_t), j = 1..3.
struct YounChoi {
    sd: f64,
}

impl UncertainProgram for YounChoi {
    fn dimension(&self) -> usize {
        2
    }
    fn bounds(&self) -> (Vec<f64>, Vec<f64>) {
        (vec![0.0; 2], vec![10.0; 2])
    }
    fn inputs(&self, d: &[f64]) -> InputModel {
        InputModel::independent(
            d.iter()
                .map(|&mean| Distribution::Normal { mean, sd: self.sd })
                .collect(),
        )
        .unwrap()
    }
    fn outputs(&self, d: &[f64], x: &[f64]) -> Option<Outputs> {
        let (x1, x2) = (x[0], x[1]);
        Some(Outputs {
            objective: d[0] + d[1],
            limit_states: vec![
                x1 * x1 * x2 / 20.0 - 1.0,
                (x1 + x2 - 5.0).powi(2) / 30.0 + (x1 - x2 - 12.0).powi(2) / 120.0 - 1.0,
                80.0 / (x1 * x1 + 8.0 * x2 + 5.0) - 1.0,
            ],
            constraints: Vec::new(),
        })
    }
}

/// P(X1² X2 / 20 ≤ 1) for X_i ~ N(d_i, s²) independent: ∫ φ((x1 − d1)/s)/s ·
/// Φ((20/x1² − d2)/s) dx1 by composite Simpson over d1 ± 12 s (x1 > 0 there for
/// the designs tested; 20 000 intervals, error far below 1e-9).
fn g1_probability(d: &[f64], s: f64) -> f64 {
    let n = 20_000;
    let (a, b) = (d[0] - 12.0 * s, d[0] + 12.0 * s);
    let h = (b - a) / n as f64;
    let f =
        |x: f64| std_normal_pdf((x - d[0]) / s) / s * std_normal_cdf((20.0 / (x * x) - d[1]) / s);
    let inner: f64 = (1..n)
        .map(|i| f(a + i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 })
        .sum();
    (f(a) + f(b) + inner) * h / 3.0
}

fn youn_choi(sd: f64, beta: f64, verify: Verify) -> RobustResult {
    let p = std_normal_cdf(-beta);
    let settings = RobustSettings {
        targets: vec![p; 3],
        verify,
        ..RobustSettings::default()
    };
    optimize_robust(
        &YounChoi { sd },
        &[vec![5.0, 5.0], vec![2.0, 8.0]],
        &settings,
    )
}

/// s = 0.3, β_t = 3: the FORM-based optimum d = (3.4391, 3.2866), f = 6.7257
/// (Youn & Choi 2004, Table 2; the same by RIA, PMA and SORA in Du & Chen 2004),
/// with g1 and g2 active at β = 3 and g3 inactive at β ≈ 10.04. FORM is 12 %
/// unconservative on g1 there: sampling gives P(g1 ≤ 0) ≈ 0.00151 against
/// Φ(−3) = 0.00135 (Youn & Choi's Monte Carlo), so the status is
/// `chance_constraint_violated`.
#[test]
fn youn_choi_form_optimum_is_reported_as_violated() {
    let r = youn_choi(0.3, 3.0, Verify::Report);
    let d = &r.design;
    assert!((d[0] - 3.4391).abs() < 1e-3, "{d:?}");
    assert!((d[1] - 3.2866).abs() < 1e-3, "{d:?}");
    assert!((d[0] + d[1] - 6.7257).abs() < 1e-3, "{d:?}");
    assert!((r.objective.value - 6.7257).abs() < 1e-3);
    for (j, want, tol) in [(0, 3.0, 1e-3), (1, 3.0, 1e-3), (2, 10.04, 0.01)] {
        let beta = r.chance[j].form_beta.unwrap();
        assert!((beta - want).abs() < tol, "β{} = {beta}", j + 1);
    }
    let g1 = &r.chance[0];
    let v = &g1.verification;
    let p = v.probability.unwrap();
    let [lo, hi] = v.interval.unwrap();
    eprintln!(
        "P(g1 ≤ 0) = {p:.6} [{lo:.6}, {hi:.6}], P(g2 ≤ 0) = {:?} {:?}, cycles {}, evaluations {}",
        r.chance[1].verification.probability,
        r.chance[1].verification.interval,
        r.cycles,
        r.evaluations
    );
    assert_eq!(
        v.sampling.as_ref().unwrap().method,
        SamplingMethod::ImportanceSampling
    );
    // The exact probability at the design found, by quadrature (independent of
    // the sampler), lies in the sampled interval.
    let exact = g1_probability(d, 0.3);
    eprintln!("d = {d:?}, exact P(g1 ≤ 0) = {exact:.6}");
    assert!(lo <= exact && exact <= hi, "{exact} ∉ [{lo}, {hi}]");
    // Youn & Choi's Monte Carlo value 0.00151 (±~3 % at their sample size; the
    // quadrature at their rounded design gives 0.001483) to 6 %.
    assert!((p / 0.00151 - 1.0).abs() < 0.06, "{p}");
    assert!(lo > 0.00135);
    assert!(g1.violated);
    assert!((g1.excess.unwrap() - (exact / std_normal_cdf(-3.0) - 1.0)).abs() < 0.05);
    assert!(!r.chance[2].violated);
    assert_eq!(r.status, RobustStatus::ChanceConstraintViolated);
    assert_eq!(r.status.as_str(), "chance_constraint_violated");
}

/// The same under `verify = "correct"`: the PMA target of g1 is raised by its
/// sampled deficit of β until the sampled probability meets Φ(−3).
#[test]
fn youn_choi_corrected_meets_the_target_by_sampling() {
    let r = youn_choi(0.3, 3.0, Verify::Correct);
    let target = std_normal_cdf(-3.0);
    for c in &r.chance {
        let [lo, _] = c.verification.interval.unwrap();
        assert!(lo <= target, "{:?}", c.verification.probability);
        assert!(!c.violated);
    }
    let g1 = &r.chance[0];
    assert!(g1.pma_beta > 3.0 && g1.corrected_target.unwrap() < target);
    assert!(r.corrections >= 1);
    assert_eq!(r.status, RobustStatus::Optimal);
    // The corrected design costs more than FORM's.
    assert!(r.objective.value > 6.7257);
    eprintln!(
        "corrected: d = {:?}, f = {}, β'1 = {}, P1 = {:?}",
        r.design, r.objective.value, g1.pma_beta, g1.verification.probability
    );
}

/// One SORA cycle is the deterministic design at the median: the corner where g1
/// and g2 vanish at x = d (d ≈ (3.1139, 2.0626), f ≈ 5.1765); every MPTP then moves
/// from 0 onto its sphere |u| = β (a change of |u*|/β = 1), so with
/// `max_cycles = 1` the status is `cycle_limit`. Invalid settings evaluate
/// nothing and say `stalled`.
#[test]
fn youn_choi_cycle_limit_and_bad_settings() {
    let p = std_normal_cdf(-3.0);
    let settings = RobustSettings {
        targets: vec![p; 3],
        max_cycles: 1,
        ..RobustSettings::default()
    };
    let r = optimize_robust(&YounChoi { sd: 0.3 }, &[vec![5.0, 5.0]], &settings);
    assert_eq!(r.status, RobustStatus::CycleLimit);
    assert_eq!(r.history.len(), 1);
    assert!(
        (r.history[0].shift_change - 1.0).abs() < 1e-12,
        "{:?}",
        r.history[0]
    );
    let at = YounChoi { sd: 0.3 }.outputs(&r.design, &r.design).unwrap();
    assert!(
        at.limit_states[0].abs() < 1e-7 && at.limit_states[1].abs() < 1e-7,
        "{at:?}"
    );
    assert!(at.limit_states[2] > 0.0);
    // The deterministic optimum costs less than the reliable one.
    assert!(r.objective.value < 6.7257 - 1.0, "{}", r.objective.value);
    let bad = RobustSettings {
        targets: vec![0.7; 3],
        ..RobustSettings::default()
    };
    assert!(bad
        .validate()
        .unwrap_err()
        .to_string()
        .contains("targets = 0.7"));
    let r = optimize_robust(&YounChoi { sd: 0.3 }, &[vec![5.0, 5.0]], &bad);
    assert_eq!((r.status, r.evaluations), (RobustStatus::Stalled, 0));
}

/// The shifted program's rows are −g_j(d + s u*_j) for X ~ N(d, s²): SORA's
/// shift of the mean by s·u*_j (Du & Chen 2004, eq. 14), held in u while d moves.
#[test]
fn shifted_rows_are_the_sora_shift() {
    let program = YounChoi { sd: 0.3 };
    let mptp = vec![vec![-2.0, -2.2], vec![1.0, 2.0], vec![0.5, -0.5]];
    let shifted = ShiftedProgram::new(&program, None, &[], mptp.clone());
    for d in [[3.0, 3.0], [5.0, 1.5]] {
        let rows = shifted.constraints(&d).unwrap();
        for (j, u) in mptp.iter().enumerate() {
            let x = [d[0] + 0.3 * u[0], d[1] + 0.3 * u[1]];
            let g = program.outputs(&d, &x).unwrap().limit_states[j];
            assert!(
                (rows[j] + g).abs() < 1e-12 * g.abs().max(1.0),
                "{j}: {rows:?}"
            );
        }
        assert_eq!(shifted.objective(&d), Some(d[0] + d[1]));
    }
}

/// PMA on g = 5 − u₁ − u₂² (standard normal u), β_t = 2: on the circle u =
/// 2(cos θ, sin θ), g = 1 − 2c + 4c², least at c = ¼: g = 0.75, u = (0.5, ±√3.75)
/// (closed form). From the median alone the search stops at (2, 0), where ∇g is
/// normal to the circle but g = 3 is its maximum along it; the multistart finds
/// the minimum.
#[test]
fn inverse_form_multistart_finds_the_minimum_on_the_sphere() {
    let model =
        InputModel::independent(vec![Distribution::Normal { mean: 0.0, sd: 1.0 }; 2]).unwrap();
    let g = |x: &[f64]| Some(5.0 - x[0] - x[1] * x[1]);
    let single = InverseFormSettings {
        multistart: false,
        ..InverseFormSettings::default()
    };
    let r = inverse_form(&model, g, 2.0, None, &single);
    assert!((r.performance - 3.0).abs() < 1e-9, "{r:?}");
    let r = inverse_form(&model, g, 2.0, None, &InverseFormSettings::default());
    assert_eq!(r.status, InverseFormStatus::Converged);
    assert!((r.performance - 0.75).abs() < 1e-9, "{r:?}");
    assert!((r.u[0] - 0.5).abs() < 1e-6 && (r.u[1].abs() - 3.75f64.sqrt()).abs() < 1e-6);
    assert!(((r.u[0].powi(2) + r.u[1].powi(2)).sqrt() - 2.0).abs() < 1e-12);
}

/// s = 0.6, β_t = 2: d = (3.6089, 3.6593), f = 7.2683 (Youn & Choi 2004, Table 3).
#[test]
fn youn_choi_wider_scatter() {
    let r = youn_choi(0.6, 2.0, Verify::Report);
    let d = &r.design;
    assert!((d[0] - 3.6089).abs() < 1e-3, "{d:?}");
    assert!((d[1] - 3.6593).abs() < 1e-3, "{d:?}");
    assert!((d[0] + d[1] - 7.2683).abs() < 1e-3, "{d:?}");
}

/// f(d, X) = (d − 2)² + d·X, X ~ N(0, 1), d ∈ [0.1, 4]: for d > 0 each statistic S
/// of f is (d − 2)² + d·c with c = S of N(0, 1) (mean 0, p95 z₀.₉₅, p99 z₀.₉₉,
/// CVaR₉₅ φ(z₀.₉₅)/0.05, mean + 3 sd = 3), minimised at d* = 2 − c/2 with
/// S* = 2c − c²/4 (closed form).
struct Quadratic {
    /// A deterministic row d ≤ cap.
    cap: Option<f64>,
    /// The objective is exp of the above, minimised in logarithms.
    exponential: bool,
}

const QUADRATIC: Quadratic = Quadratic {
    cap: None,
    exponential: false,
};

impl UncertainProgram for Quadratic {
    fn dimension(&self) -> usize {
        1
    }
    fn bounds(&self) -> (Vec<f64>, Vec<f64>) {
        (vec![0.1], vec![4.0])
    }
    fn inputs(&self, _d: &[f64]) -> InputModel {
        InputModel::independent(vec![Distribution::Normal { mean: 0.0, sd: 1.0 }]).unwrap()
    }
    fn outputs(&self, d: &[f64], x: &[f64]) -> Option<Outputs> {
        let f = (d[0] - 2.0).powi(2) + d[0] * x[0];
        Some(Outputs {
            objective: if self.exponential { f.exp() } else { f },
            limit_states: Vec::new(),
            constraints: self.cap.map(|c| vec![d[0] - c]).unwrap_or_default(),
        })
    }
    fn logarithmic_objective(&self) -> bool {
        self.exponential
    }
}

fn exact(statistic: Statistic) -> f64 {
    let z95 = std_normal_quantile(0.95);
    match statistic {
        Statistic::Mean => 0.0,
        Statistic::P95 => z95,
        Statistic::P99 => std_normal_quantile(0.99),
        Statistic::Cvar95 => std_normal_pdf(z95) / 0.05,
        Statistic::MeanPlus3Sd => 3.0,
    }
}

/// Each statistic's optimum against the closed form: the true statistic at the
/// design found lies in the verified interval, the design is d* to within what
/// the interval of c allows (|d − d*| = |ĉ − c|/2), and the verified statistic is
/// S* (its true value exceeds S* by (d − d*)² only).
#[test]
fn statistic_objectives_meet_the_closed_form() {
    for statistic in Statistic::ALL {
        let settings = RobustSettings {
            statistic: Some(statistic),
            ..RobustSettings::default()
        };
        let r = optimize_robust(&QUADRATIC, &[vec![1.0]], &settings);
        assert_eq!(r.status, RobustStatus::Optimal, "{statistic}: {r:?}");
        let c = exact(statistic);
        let d = r.design[0];
        let truth = (d - 2.0).powi(2) + d * c;
        let best = 2.0 * c - c * c / 4.0;
        let check = r.objective_verified.unwrap();
        // The interval of ĉ on the CRN sample, from that of the statistic at d.
        let [lo, hi] = r.objective.interval;
        let c_lo = (lo - (d - 2.0).powi(2)) / d;
        let c_hi = (hi - (d - 2.0).powi(2)) / d;
        eprintln!(
            "{statistic}: d = {d:.5} (d* = {:.5}), S = {:.5} [{lo:.5}, {hi:.5}], verified {:.5} {:?}, S* = {best:.5}",
            2.0 - c / 2.0,
            r.objective.value,
            check.value,
            check.interval
        );
        assert!(
            c_lo <= c && c <= c_hi,
            "{statistic}: c = {c} ∉ [{c_lo}, {c_hi}]"
        );
        assert!(
            (d - (2.0 - c / 2.0)).abs() <= 0.5 * (c_hi - c_lo) + 1e-6,
            "{statistic}: d = {d}"
        );
        assert!(
            check.interval[0] <= truth && truth <= check.interval[1],
            "{statistic}: {truth} ∉ {:?}",
            check.interval
        );
        assert!(truth - best >= -1e-12 && truth - best < 0.01, "{statistic}");
        // On the CRN sample the statistic is (d − 2)² + d·ĉ, ĉ fixed: the SQP's
        // optimum is d = 2 − ĉ/2 to its tolerance.
        let c_hat = (r.objective.value - (d - 2.0).powi(2)) / d;
        assert!(
            (d - (2.0 - c_hat / 2.0)).abs() < 1e-5,
            "{statistic}: ĉ = {c_hat}"
        );
    }
}

/// A deterministic row at the median: the mean (d − 2)² is least at d = 2, so
/// with d ≤ 1.5 the optimum is the bound of the row, d = 1.5, S = 0.25 (exact on
/// any sample: the mean of d·X over the CRN is d·x̄, x̄ ≈ 0 but not 0, so to
/// 1.5·|x̄| ≤ 0.01).
#[test]
fn deterministic_rows_hold_at_the_median() {
    let settings = RobustSettings {
        statistic: Some(Statistic::Mean),
        ..RobustSettings::default()
    };
    let program = Quadratic {
        cap: Some(1.5),
        exponential: false,
    };
    let r = optimize_robust(&program, &[vec![1.0]], &settings);
    assert_eq!(r.status, RobustStatus::Optimal);
    assert!((r.design[0] - 1.5).abs() < 1e-7, "{:?}", r.design);
    assert!((r.objective.value - 0.25).abs() < 0.01, "{:?}", r.objective);
    assert!(r.sqp.multipliers[0] > 0.0);
}

/// The mean of (d − 2)² + d·X where the model fails for X > 2.5 (a fixed set of
/// the common random numbers, ~0.6 %: about 3 of 512): with no failure allowed
/// no design can be evaluated (`stalled`); with 8 allowed they are dropped and
/// the optimum is d = 2 − x̄/2, x̄ the mean of the points kept (closed form on the
/// sample: the objective is (d − 2)² + d·x̄ there).
#[test]
fn failed_samples_are_dropped_up_to_the_allowance() {
    struct Failing;
    impl UncertainProgram for Failing {
        fn dimension(&self) -> usize {
            1
        }
        fn bounds(&self) -> (Vec<f64>, Vec<f64>) {
            (vec![0.1], vec![4.0])
        }
        fn inputs(&self, d: &[f64]) -> InputModel {
            QUADRATIC.inputs(d)
        }
        fn outputs(&self, d: &[f64], x: &[f64]) -> Option<Outputs> {
            (x[0] <= 2.5).then(|| QUADRATIC.outputs(d, x).unwrap())
        }
    }
    let strict = RobustSettings {
        statistic: Some(Statistic::Mean),
        ..RobustSettings::default()
    };
    let r = optimize_robust(&Failing, &[vec![1.0]], &strict);
    assert_eq!(r.status, RobustStatus::Stalled);
    let lenient = RobustSettings {
        failures_allowed: 8,
        ..strict
    };
    let r = optimize_robust(&Failing, &[vec![1.0]], &lenient);
    assert_eq!(r.status, RobustStatus::Optimal);
    let points = wearopt::uq::robust::common_points(1, 512, lenient.seed);
    let kept: Vec<f64> = points.iter().map(|u| u[0]).filter(|x| *x <= 2.5).collect();
    assert!((1..=8).contains(&(512 - kept.len())), "{}", kept.len());
    let mean = kept.iter().sum::<f64>() / kept.len() as f64;
    assert!(
        (r.design[0] - (2.0 - mean / 2.0)).abs() < 1e-6,
        "{:?} {mean}",
        r.design
    );
}

/// A logarithmic objective: the mean of e^{(d−2)² + dX} is e^{(d−2)² + d²/2}
/// (lognormal mean), whose logarithm is least at d = 4/3 (closed form). The true
/// mean at the design found lies in the verified interval, and the design is
/// 4/3 to the sampling error of the 512 common random numbers.
#[test]
fn logarithmic_statistic_objective() {
    let settings = RobustSettings {
        statistic: Some(Statistic::Mean),
        ..RobustSettings::default()
    };
    let program = Quadratic {
        cap: None,
        exponential: true,
    };
    let r = optimize_robust(&program, &[vec![1.0]], &settings);
    assert_eq!(r.status, RobustStatus::Optimal);
    let d = r.design[0];
    let truth = ((d - 2.0).powi(2) + d * d / 2.0).exp();
    let check = r.objective_verified.unwrap();
    eprintln!(
        "d = {d} (4/3), mean {:?}, verified {check:?}, exact {truth}",
        r.objective
    );
    assert!(check.interval[0] <= truth && truth <= check.interval[1]);
    assert!((d - 4.0 / 3.0).abs() < 0.02, "{d}");
}

/// splitmix64: a reproducible i.i.d. stream for the coverage test.
fn splitmix(x: u64) -> u64 {
    let mut z = x.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// The 95 % intervals of `estimate` on i.i.d. N(0, 1) samples of 2000 contain the
/// exact statistic (quantiles z_p, CVaR₉₅ = φ(z₀.₉₅)/0.05, mean + 3 sd = 3) in
/// 90–99 % of 400 seeds (a binomial(400, 0.95) count lies in that range with
/// probability > 0.999; the order-statistic interval is conservative).
#[test]
fn estimate_intervals_cover_the_exact_statistic() {
    let (n, seeds) = (2000usize, 400u64);
    for statistic in Statistic::ALL {
        let c = exact(statistic);
        let mut hits = 0;
        for seed in 0..seeds {
            let v: Vec<f64> = (0..n as u64)
                .map(|k| {
                    let bits = splitmix(splitmix(seed) ^ k.wrapping_mul(0x2545_F491_4F6C_DD1D));
                    std_normal_quantile(((bits >> 11) as f64 + 0.5) / (1u64 << 53) as f64)
                })
                .collect();
            let e = estimate(&v, statistic);
            if e.interval[0] <= c && c <= e.interval[1] {
                hits += 1;
            }
        }
        let coverage = hits as f64 / seeds as f64;
        eprintln!("{statistic}: coverage {coverage:.3}");
        assert!((0.90..=0.99).contains(&coverage), "{statistic}: {coverage}");
    }
}

/// The same result on 1 and 4 threads, to the bit: the statistic over the common
/// random numbers, the SORA cycles and the verification.
#[test]
fn robust_results_do_not_depend_on_the_thread_count() {
    let run = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| {
                let q = optimize_robust(
                    &QUADRATIC,
                    &[vec![1.0], vec![3.0]],
                    &RobustSettings {
                        statistic: Some(Statistic::Cvar95),
                        ..RobustSettings::default()
                    },
                );
                let y = youn_choi(0.3, 3.0, Verify::Report);
                (q, y)
            })
    };
    // Everything but the SQP's trace, whose rows carry wall times.
    let key = |r: &RobustResult| {
        (
            r.design.clone(),
            r.objective,
            r.objective_verified,
            r.chance.clone(),
            r.history.clone(),
            r.evaluations,
            r.sqp.x.clone(),
            r.sqp.evaluations,
        )
    };
    let (one, four) = (run(1), run(4));
    assert_eq!(key(&one.0), key(&four.0));
    assert_eq!(key(&one.1), key(&four.1));
}

/// A deadline already past stops SORA at its first solve: status `time_limit`
/// (never `optimal` or `cycle_limit`), the design it reached still verified.
#[test]
fn a_past_deadline_ends_time_limit() {
    let settings = RobustSettings {
        targets: vec![std_normal_cdf(-3.0); 3],
        deadline: Some(std::time::Instant::now()),
        ..RobustSettings::default()
    };
    let r = optimize_robust(&YounChoi { sd: 0.3 }, &[vec![5.0, 5.0]], &settings);
    assert_eq!(r.status, RobustStatus::TimeLimit, "{:?}", r.status);
    assert_eq!(r.chance.len(), 3);
    assert!(r.history.len() <= 1, "{} cycles", r.history.len());
}
