//! Calibration of γ (and μ) from friction data, eq. 14 (docs/model.md §5): recovery of known
//! parameters, the per-point closed form, the paper's table, interval coverage, the
//! command line and every kind of bad data.

use crate::common;
use crate::common::wearopt;

use std::f64::consts::PI;
use std::path::PathBuf;

use wearopt::calibrate::{
    self, fit, jkr_friction, work_of_adhesion_from_point, FitSettings, FrictionCoefficient,
    FrictionData, Quoted,
};

fn settings(radius: f64, mu: FrictionCoefficient) -> FitSettings {
    FitSettings {
        radius,
        friction_coefficient: mu,
        equivalent_modulus: None,
        quoted: None,
    }
}

fn synthetic(loads: &[f64], gamma: f64, mu: f64, radius: f64) -> FrictionData {
    let pairs: Vec<(f64, f64)> = loads
        .iter()
        .map(|&p| (p, jkr_friction(p, gamma, mu, radius)))
        .collect();
    FrictionData::from_pairs("synthetic", &pairs).unwrap()
}

fn rel(a: f64, b: f64) -> f64 {
    (a / b - 1.0).abs()
}

/// γ solving eq. 14 for one point by bisection on the equation itself (independent of
/// the library's closed form): F(γ) is increasing in γ.
fn gamma_by_bisection(load: f64, friction: f64, mu: f64, radius: f64) -> f64 {
    let f = |g: f64| {
        let a = 3.0 * PI * g * radius;
        mu * (load + a + (6.0 * PI * g * radius * load + a * a).sqrt()) - friction
    };
    let (mut lo, mut hi) = (0.0, 1.0);
    while f(hi) < 0.0 {
        hi *= 2.0;
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if f(mid) < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

#[test]
fn exact_synthetic_data_recover_gamma_and_mu() {
    let cases = [
        (
            0.05,
            0.2,
            1e-4,
            vec![0.0, 5e-6, 20e-6, 50e-6, 100e-6, 300e-6],
        ),
        (2e-3, 0.1, 0.3e-3, vec![20e-6, 110e-6, 140e-6, 220e-6]),
        (0.5, 0.6, 2e-6, vec![1e-9, 1e-7, 1e-6, 5e-6]),
        (1e-4, 0.05, 1e-3, vec![1e-3, 2e-3, 5e-3]),
    ];
    for (gamma, mu, radius, loads) in cases {
        let data = synthetic(&loads, gamma, mu, radius);
        let both = fit(&data, &settings(radius, FrictionCoefficient::Fit)).unwrap();
        assert!(both.converged, "{gamma} {mu}: {:?}", both.notes);
        assert!(
            rel(both.work_of_adhesion, gamma) < 1e-8,
            "γ {} vs {gamma}",
            both.work_of_adhesion
        );
        assert!(
            rel(both.friction_coefficient, mu) < 1e-8,
            "μ {} vs {mu}",
            both.friction_coefficient
        );
        let held = fit(&data, &settings(radius, FrictionCoefficient::Given(mu))).unwrap();
        assert!(rel(held.work_of_adhesion, gamma) < 1e-8);
        assert_eq!(held.friction_coefficient, mu);
        assert_eq!(held.degrees_of_freedom, loads.len() - 1);
        assert_eq!(both.degrees_of_freedom, loads.len() - 2);
    }
}

#[test]
fn per_point_closed_form_agrees_with_the_fit_and_solves_eq_14() {
    let (gamma, mu, radius) = (0.03, 0.15, 50e-6);
    let loads = [0.0, 1e-6, 10e-6, 40e-6, 90e-6];
    let data = synthetic(&loads, gamma, mu, radius);
    let c = fit(&data, &settings(radius, FrictionCoefficient::Given(mu))).unwrap();
    for p in &c.per_point {
        let own = p.work_of_adhesion.expect("F ≥ μP on exact data");
        // The single-point value is the fitted one on exact data...
        assert!(
            rel(own, c.work_of_adhesion) < 1e-10,
            "{own} vs {}",
            c.work_of_adhesion
        );
        // ...and it solves eq. 14 for that point.
        assert!(rel(jkr_friction(p.load, own, mu, radius), p.friction) < 1e-13);
        assert!(rel(own, gamma_by_bisection(p.load, p.friction, mu, radius)) < 1e-12);
        assert!(p.residual.abs() < 1e-12 * p.friction);
    }
    // Below μP there is no solution; at μP, γ = 0.
    assert_eq!(
        work_of_adhesion_from_point(10e-6, 0.9e-6, 0.1, radius),
        None
    );
    assert_eq!(
        work_of_adhesion_from_point(2e-6, 1e-6, 0.5, radius),
        Some(0.0)
    );
}

#[test]
fn the_papers_table_gives_gamma_between_1_1e_3_and_4_7e_3() {
    let text = std::fs::read_to_string("problems/ando-friction.csv").unwrap();
    let data = calibrate::parse_csv(&text, "problems/ando-friction.csv").unwrap();
    assert!(data.is_ando_table());
    let mut s = settings(0.3e-3, FrictionCoefficient::Given(0.1));
    s.quoted = Some(Quoted::paper());
    let c = fit(&data, &s).unwrap();
    // Independently: bisection on eq. 14 at each printed point (P, F in µN).
    let table = [(20.0, 6.0), (110.0, 14.0), (140.0, 18.0), (220.0, 26.0)];
    let mut own = Vec::new();
    for (p, &(load, friction)) in c.per_point.iter().zip(&table) {
        let g = gamma_by_bisection(load * 1e-6, friction * 1e-6, 0.1, 0.3e-3);
        assert!(rel(p.work_of_adhesion.unwrap(), g) < 1e-10);
        own.push(g);
    }
    let lo = own.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = own.iter().copied().fold(0.0, f64::max);
    // docs/model.md §5: 1.1e-3 to 4.7e-3 N/m (two significant digits).
    assert!((1.05e-3..1.15e-3).contains(&lo), "{lo}");
    assert!((4.65e-3..4.75e-3).contains(&hi), "{hi}");
    assert_eq!(
        c.per_point_range,
        Some([
            c.per_point[3].work_of_adhesion.unwrap(),
            c.per_point[0].work_of_adhesion.unwrap()
        ])
    );
    // The fit lies among them, far below the quoted 0.1 N/m, which is flagged.
    assert!(lo < c.work_of_adhesion && c.work_of_adhesion < hi);
    let q = c
        .comparison
        .as_ref()
        .unwrap()
        .work_of_adhesion
        .as_ref()
        .unwrap();
    assert!(!q.agrees);
    assert_eq!(q.within_confidence_interval, Some(false));
    assert!(q.ratio_to_fit > 10.0);
    // With γ = 0.1 N/m, eq. 14 predicts far more friction than measured at every load.
    for (f, &(_, measured)) in q.predicted_friction.iter().zip(&table) {
        assert!(*f > 2.0 * measured * 1e-6);
    }
}

/// A small deterministic generator of standard normal deviates (xorshift + Box–Muller).
struct Normal(u64);
impl Normal {
    fn uniform(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        ((self.0 >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }
    fn next(&mut self) -> f64 {
        let (u, v) = (self.uniform(), self.uniform());
        (-2.0 * u.ln()).sqrt() * (2.0 * PI * v).cos()
    }
}

#[test]
fn confidence_intervals_cover_the_true_values() {
    // Noisy synthetic data: the 95 % intervals should contain the true γ (and μ) in
    // about 95 % of repetitions; 400 repetitions put the count within ±3.3 % at 3σ.
    let (gamma, mu, radius) = (0.02, 0.12, 100e-6);
    let loads = [2e-6, 10e-6, 25e-6, 50e-6, 80e-6, 120e-6, 200e-6, 300e-6];
    let noise = 0.3e-6;
    let mut rng = Normal(0x2545_F491_4F6C_DD1D);
    let trials = 400;
    let (mut covered_held, mut covered_gamma, mut covered_mu) = (0, 0, 0);
    for _ in 0..trials {
        let pairs: Vec<(f64, f64)> = loads
            .iter()
            .map(|&p| (p, jkr_friction(p, gamma, mu, radius) + noise * rng.next()))
            .collect();
        let data = FrictionData::from_pairs("noisy", &pairs).unwrap();
        let held = fit(&data, &settings(radius, FrictionCoefficient::Given(mu))).unwrap();
        let ci = held.confidence_interval.unwrap();
        covered_held += usize::from(ci[0] <= gamma && gamma <= ci[1]);
        let both = fit(&data, &settings(radius, FrictionCoefficient::Fit)).unwrap();
        let ci = both.confidence_interval.unwrap();
        covered_gamma += usize::from(ci[0] <= gamma && gamma <= ci[1]);
        let ci = both.friction_coefficient_confidence_interval.unwrap();
        covered_mu += usize::from(ci[0] <= mu && mu <= ci[1]);
    }
    for (what, k) in [
        ("γ (μ held)", covered_held),
        ("γ", covered_gamma),
        ("μ", covered_mu),
    ] {
        let share = k as f64 / trials as f64;
        assert!((0.91..=0.99).contains(&share), "{what}: coverage {share}");
    }
}

#[test]
fn cli_reports_the_papers_table_and_the_disagreement() {
    let out = common::stdout(
        wearopt().args([
            "fit-adhesion",
            "problems/ando-friction.csv",
            "--radius",
            "0.3 mm",
            "--materials",
            "steel,silicon",
        ]),
        0,
    );
    let text = String::from_utf8(out).unwrap();
    assert!(
        text.contains("γ from single points: 1.09 mN/m to 4.72 mN/m"),
        "{text}"
    );
    assert!(text.contains("quoted γ = 100 mN/m"), "{text}");
    assert!(text.contains("does NOT follow from these data"), "{text}");
    assert!(text.contains("65.0 MPa"), "{text}");

    let out = common::stdout(
        wearopt().args([
            "fit-adhesion",
            "problems/ando-friction.csv",
            "--radius",
            "0.3mm",
            "--mu",
            "0.1",
            "--modulus",
            "99 GPa",
            "--format",
            "json",
        ]),
        0,
    );
    let v: serde_json::Value = serde_json::from_slice(&out).expect("valid JSON");
    for key in [
        "work_of_adhesion",
        "standard_error",
        "confidence_interval",
        "friction_coefficient",
        "per_point",
        "mean_bond_strength",
        "comparison",
    ] {
        assert!(v.get(key).is_some(), "missing {key}");
    }
    let ci = v["confidence_interval"].as_array().unwrap();
    assert_eq!(ci.len(), 2);
    let g = v["work_of_adhesion"].as_f64().unwrap();
    assert!(ci[0].as_f64().unwrap() <= g && g <= ci[1].as_f64().unwrap());
    assert_eq!(v["friction_coefficient"].as_f64(), Some(0.1));
    let pts = v["per_point"].as_array().unwrap();
    assert_eq!(pts.len(), 4);
    for p in pts {
        for key in [
            "load",
            "friction",
            "work_of_adhesion",
            "residual",
            "bond_strength",
        ] {
            assert!(p.get(key).is_some(), "per_point missing {key}");
        }
    }
    assert_eq!(v["comparison"]["work_of_adhesion"]["agrees"], false);
    assert_eq!(v["comparison"]["bond_strength"]["agrees"], false);

    // A quoted value on other data is compared when asked for.
    let out = common::stdout(
        wearopt().args([
            "fit-adhesion",
            "problems/ando-friction.csv",
            "--radius",
            "0.3mm",
            "--quoted-gamma",
            "2 mJ/m^2",
        ]),
        0,
    );
    let text = String::from_utf8(out).unwrap();
    assert!(
        text.contains("The quoted γ is consistent with these data."),
        "{text}"
    );
    // Where the quoted values came from is said without a flag: Python's JSON is
    // the same document (it used to read "(--quoted-gamma, --quoted-bond-strength)").
    let out = common::stdout(
        wearopt().args([
            "fit-adhesion",
            "problems/ando-friction.csv",
            "--radius",
            "0.3mm",
            "--quoted-gamma",
            "2 mJ/m^2",
            "--format",
            "json",
        ]),
        0,
    );
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    assert_eq!(v["comparison"]["source"], "the quoted values");
}

fn data_file(name: &str, text: &str) -> PathBuf {
    let path = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("calibrate-{name}.csv"));
    std::fs::write(&path, text).unwrap();
    path
}

fn fails_with(args: &[&str], path: &PathBuf, needles: &[&str]) {
    let out = common::stderr(wearopt().arg("fit-adhesion").arg(path).args(args), 2);
    let err = String::from_utf8(out).unwrap();
    for n in needles {
        assert!(err.contains(n), "stderr lacks {n:?}: {err}");
    }
}

#[test]
fn bad_data_is_refused_with_file_line_and_value() {
    let radius = ["--radius", "0.3mm"];
    let p = data_file("one-point", "load,friction\n20 uN,6 uN\n");
    fails_with(
        &["--radius", "0.3mm", "--fit-mu"],
        &p,
        &["calibrate-one-point.csv", "1 measurement", "γ and μ"],
    );
    let p = data_file("empty", "load,friction\n");
    fails_with(&radius, &p, &["calibrate-empty.csv", "0 measurements"]);
    let p = data_file("one-load", "load,friction\n20 uN,6 uN\n20 uN,7 uN\n");
    fails_with(
        &["--radius", "0.3mm", "--fit-mu"],
        &p,
        &["same load", "two distinct loads"],
    );
    let p = data_file("negative", "load,friction\n20 uN,6 uN\n-5 uN,3 uN\n");
    fails_with(
        &radius,
        &p,
        &["calibrate-negative.csv:3", "load = \"-5 uN\"", "≥ 0"],
    );
    let p = data_file("below", "load,friction\n20 uN,6 uN\n110 uN,9 uN\n");
    fails_with(
        &radius,
        &p,
        &[
            "calibrate-below.csv:3",
            "friction = 9 µN",
            "below μP = 11 µN",
        ],
    );
    let p = data_file("unit", "load,friction\n20 uN,6 uN\n110 uQ,14 uN\n");
    fails_with(
        &radius,
        &p,
        &["calibrate-unit.csv:3", "load = \"110 uQ\"", "unknown unit"],
    );
    let p = data_file("dimension", "load,friction\n20 uN,6 GPa\n");
    fails_with(
        &radius,
        &p,
        &["calibrate-dimension.csv:2", "friction = \"6 GPa\""],
    );
    let p = data_file("fields", "load,friction\n# comment\n\n20 uN,6 uN,1\n");
    fails_with(
        &radius,
        &p,
        &["calibrate-fields.csv:4", "two comma-separated values"],
    );
    let p = data_file("header", "P,F\n20 uN,6 uN\n");
    fails_with(&radius, &p, &["calibrate-header.csv:1", "load,friction"]);
    let p = data_file("zero-friction", "load,friction\n0,0\n");
    fails_with(
        &radius,
        &p,
        &["calibrate-zero-friction.csv:2", "friction = \"0\"", "> 0"],
    );
    let missing = PathBuf::from("problems/no-such-file.csv");
    fails_with(&radius, &missing, &["no-such-file.csv", "cannot read"]);
    // Bad settings.
    let good = PathBuf::from("problems/ando-friction.csv");
    fails_with(&["--radius", "-1 mm"], &good, &["--radius"]);
    fails_with(&["--radius", "0.3 mN"], &good, &["--radius", "mN"]);
    fails_with(&["--radius", "0.3mm", "--mu", "0"], &good, &["--mu"]);
    fails_with(
        &["--radius", "0.3mm", "--materials", "stel,silicon"],
        &good,
        &["stel", "did you mean \"steel\""],
    );
    fails_with(
        &["--radius", "0.3mm", "--quoted-gamma", "0.1 GPa"],
        &good,
        &["--quoted-gamma"],
    );
    // A friction below μP is no error when μ is fitted: the point is reported.
    let p = data_file(
        "fit-mu",
        "load,friction\n20 uN,6 uN\n110 uN,9 uN\n220 uN,26 uN\n",
    );
    wearopt()
        .arg("fit-adhesion")
        .arg(&p)
        .args(["--radius", "0.3mm", "--fit-mu"])
        .assert()
        .success();
}

#[test]
fn exact_fit_has_no_interval() {
    let data = synthetic(&[10e-6], 0.01, 0.1, 1e-4);
    let c = fit(&data, &settings(1e-4, FrictionCoefficient::Default)).unwrap();
    assert_eq!(c.degrees_of_freedom, 0);
    assert_eq!(c.confidence_interval, None);
    assert!(rel(c.work_of_adhesion, 0.01) < 1e-8);
    assert!(c
        .notes
        .iter()
        .any(|n| matches!(n, wearopt::calibrate::CalibrationNote::FrictionCoefficientAssumed { value } if *value == 0.1)));
    assert!(c
        .notes
        .iter()
        .any(|n| wearopt::report::calibrate::note(n).contains("assumed")));
    // One measurement, one parameter (γ; μ held): the exact-fit note, as a value.
    assert!(c
        .notes
        .contains(&wearopt::calibrate::CalibrationNote::ExactFit {
            measurements: 1,
            parameters: 1
        }));
}

/// Degenerate data never print NaN: friction falling with the load cannot be
/// fitted with γ and μ (exit 2, the slope and the way out named; it printed
/// "± NaN" with exit 0), and where the data leave μ's 95 % interval below 0 it is
/// clipped there like γ's.
#[test]
fn degenerate_fits_say_so_instead_of_nan() {
    let falling = data_file(
        "falling.csv",
        "load,friction\n10 uN,30 uN\n20 uN,6 uN\n40 uN,1 uN\n80 uN,2 uN\n",
    );
    fails_with(
        &["--radius", "1um", "--fit-mu"],
        &falling,
        &["the friction falls as the load rises", "fix μ with --mu"],
    );
    let noisy = data_file(
        "noisy.csv",
        "load,friction\n10 uN,30 uN\n20 uN,6 uN\n40 uN,40 uN\n80 uN,41 uN\n",
    );
    let out = wearopt()
        .args([
            "fit-adhesion",
            noisy.to_str().unwrap(),
            "--radius",
            "1um",
            "--fit-mu",
        ])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(!text.contains("NaN") && !text.contains("inf"), "{text}");
    assert!(text.contains("0 to 1.207, clipped at 0"), "{text}");
}
