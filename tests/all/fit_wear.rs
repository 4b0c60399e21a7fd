//! `wearopt fit-wear` through the command line (docs/model.md §14): the shipped
//! example, the formats and the bad input. The fit's accuracy against known values
//! (1e-10 without noise, ≥ 90 of 100 intervals with 5 % noise) is
//! `wear_fit::tests` in the library.

use crate::common::wearopt;

fn run(args: &[&str]) -> (String, String, i32) {
    let out = wearopt().args(args).output().unwrap();
    (
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
        out.status.code().unwrap(),
    )
}

/// `problems/wear-rates.csv` was generated (its header says how) from ΔU = 0.9 eV,
/// ΔV = 60 Å³, A = 1e13 atoms/s with 3 % scatter. The fit equals an independent
/// least squares (`scripts/reference_fit_wear.py`: mpmath, 50 digits, normal
/// equations): ln A 29.817836240647112 ± 0.1144830438, ΔV 59.808225267417584 Å³
/// ± 0.09571675203, ΔU 0.89561939106081334 eV ± 0.003248401888; and its intervals
/// hold the generating values.
#[test]
fn the_shipped_example_recovers_its_values() {
    let (out, err, code) = run(&["fit-wear", "problems/wear-rates.csv", "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let covers = |e: &serde_json::Value, x: f64| {
        e["lower"].as_f64().unwrap() <= x && x <= e["upper"].as_f64().unwrap()
    };
    assert!(
        covers(&v["activation_energy_ev"], 0.9),
        "{}",
        v["activation_energy_ev"]
    );
    assert!(
        covers(&v["activation_volume"], 60e-30),
        "{}",
        v["activation_volume"]
    );
    assert!(
        covers(&v["ln_prefactor"], 1e13f64.ln()),
        "{}",
        v["ln_prefactor"]
    );
    let close = |e: &serde_json::Value, x: f64, se: f64| {
        let rel = |a: f64, b: f64| (a / b - 1.0).abs();
        assert!(
            rel(e["estimate"].as_f64().unwrap(), x) < 1e-10,
            "{e} against {x}"
        );
        assert!(
            rel(e["standard_error"].as_f64().unwrap(), se) < 1e-8,
            "{e} against {se}"
        );
    };
    close(&v["ln_prefactor"], 29.817_836_240_647_11, 0.114_483_043_8);
    close(
        &v["activation_volume"],
        5.980_822_526_741_758e-29,
        0.09571675203e-30,
    );
    close(
        &v["activation_energy_ev"],
        0.895_619_391_060_813_3,
        0.003248401888,
    );
    assert_eq!(v["points"], 12);
    assert_eq!(v["degrees_of_freedom"], 9);
    assert_eq!(v["saturated"], false);
    assert_eq!(v["rate_unit"], "atoms/s");
    assert_eq!(v["temperatures"], serde_json::json!([300.0, 325.0, 350.0]));
    let (text, _, code) = run(&["fit-wear", "problems/wear-rates.csv"]);
    assert_eq!(code, 0);
    assert!(
        text.contains("activation energy ΔU") && text.contains(" eV ± "),
        "{text}"
    );
}

/// One temperature (the file's first four rows, at 300 K, given by --temperature):
/// ΔU is said to be unidentifiable, and ΔV is still fitted.
#[test]
fn one_temperature_says_so() {
    let text = std::fs::read_to_string("problems/wear-rates.csv").unwrap();
    let rows: Vec<&str> = text.lines().filter(|l| l.ends_with(",300")).collect();
    let csv = format!(
        "stress_Pa,rate_atoms_per_s\n{}\n",
        rows.iter()
            .map(|r| r.trim_end_matches(",300"))
            .collect::<Vec<_>>()
            .join("\n")
    );
    let path = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fit-wear-300.csv");
    std::fs::write(&path, csv).unwrap();
    let (out, err, code) = run(&[
        "fit-wear",
        path.to_str().unwrap(),
        "--temperature",
        "300 K",
        "--format",
        "json",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert!(v["activation_energy"].is_null());
    assert!(
        v["notes"][0]
            .as_str()
            .unwrap()
            .contains("cannot be identified"),
        "{}",
        v["notes"]
    );
    assert!(v["activation_volume"]["estimate"].as_f64().unwrap() > 0.0);
}

#[test]
fn bad_input_exits_2_naming_the_field() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let cases = [
        (
            "two.csv",
            "stress_Pa,rate_m3_per_s\n1e9,1e-20\n2e9,2e-20\n",
            vec![],
            "at least 3 points",
        ),
        (
            "zero.csv",
            "stress_Pa,rate_m3_per_s\n1e9,1e-20\n2e9,0\n3e9,3e-20\n",
            vec![],
            "rate_m3_per_s",
        ),
        (
            "flat.csv",
            "stress_Pa,rate_m3_per_s\n1e9,1e-20\n1e9,2e-20\n1e9,3e-20\n",
            vec![],
            "one stress value only",
        ),
        ("head.csv", "stress,rate\n1e9,1e-20\n", vec![], "stress_Pa"),
        (
            "perm.csv",
            "stress_Pa,rate_m3_per_m\n1e9,1e-20\n2e9,2e-20\n3e9,4e-20\n",
            vec![],
            "--speed",
        ),
        (
            "speed.csv",
            "stress_Pa,rate_m3_per_m\n1e9,1e-20\n2e9,2e-20\n3e9,4e-20\n",
            vec!["--speed", "fast"],
            "--speed",
        ),
    ];
    for (name, csv, extra, says) in cases {
        let path = dir.join(format!("fit-wear-{name}"));
        std::fs::write(&path, csv).unwrap();
        let mut args = vec!["fit-wear", path.to_str().unwrap()];
        args.extend(extra);
        let (out, err, code) = run(&args);
        assert_eq!(code, 2, "{name}: {err}");
        assert!(out.is_empty(), "{name}");
        assert!(err.contains(says), "{name}: {err}");
    }
    // A rate in m³/m with a speed is turned into m³/s.
    let path = dir.join("fit-wear-perm.csv");
    let (out, err, code) = run(&[
        "fit-wear",
        path.to_str().unwrap(),
        "--speed",
        "1 mm/s",
        "--format",
        "json",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["speed"], 1e-3);
    assert!((v["per_point"][0]["rate"].as_f64().unwrap() / 1e-23 - 1.0).abs() < 1e-12);
}
