//! The evaluator against high-precision tables (tests/data/*.csv), computed at
//! 40 significant digits with mpmath by `scripts/reference.py` by two independent
//! methods (the s = Δ1^{1/4} substitution with closed-form plastic terms, and a
//! root solve for Δ1(Δ) at every quadrature node) that agree to ≥ 25 digits; the
//! γ = 0, H = ∞ rows also match the parabolic-cylinder identity
//! F_n(h) = Γ(n+1) e^{-h²/4} D_{-n-1}(h)/√(2π). See scripts/README.md.
//!
//! Tolerance: 1e-12 relative (the bound), measured against
//! max(|value|, |elastic part| + |plastic part|) for loads, since P̄ crosses zero
//! where any method can only be accurate relative to the size of its parts.

use crate::common::{num, rel, table};
use wearopt::model::{landscape, solve_separation, Coefficients, Model, SeparationOutcome};

const TOLERANCE: f64 = 1e-12;

fn model_of(row: &std::collections::HashMap<String, String>) -> Model {
    let (theta, lambda) = (num(&row["theta"]), num(&row["lambda"]));
    let c = match row["case"].as_str() {
        "adhesive" => Coefficients::from_indices(theta, lambda),
        _ => Coefficients::new(num(&row["c_a"]), num(&row["c_h"])),
    };
    Model::new(c)
}

#[test]
fn points_match_the_high_precision_table() {
    let rows = table("reference_points.csv");
    assert!(rows.len() >= 100, "table too small: {}", rows.len());
    let mut worst = (0.0f64, String::new());
    for row in &rows {
        let m = model_of(row);
        let h = num(&row["h"]);
        let at = m.at(h);
        let (le, lp) = (num(&row["load_elastic"]), num(&row["load_plastic"]));
        let parts = le.abs() + lp.abs();
        let checks = [
            (
                "load",
                at.load_elastic + at.load_plastic,
                num(&row["load"]),
                parts,
            ),
            ("load_elastic", at.load_elastic, le, parts),
            ("load_plastic", at.load_plastic, lp, parts),
            ("area", at.area, num(&row["area"]), 0.0),
            (
                "plastic_area",
                at.plastic_area,
                num(&row["plastic_area"]),
                0.0,
            ),
            (
                "dload_dh",
                at.dload_dh_elastic + at.dload_dh_plastic,
                num(&row["dload_dh"]),
                at.dload_dh_elastic.abs() + at.dload_dh_plastic.abs(),
            ),
        ];
        for (what, got, want, scale) in checks {
            // A reference below the double range must come out as (nearly) nothing.
            if want == 0.0 && scale == 0.0 {
                assert!(got.abs() < 1e-290, "{what} at {row:?}: {got}");
                continue;
            }
            let e = rel(got, want, scale);
            if e > worst.0 {
                worst = (
                    e,
                    format!(
                        "{what} θ={} λ={} h={h}: {got} vs {want}",
                        row["theta"], row["lambda"]
                    ),
                );
            }
        }
        let dc = num(&row["critical_interference"]);
        assert!(
            rel(m.critical_interference(), dc, 0.0) < 1e-14
                || dc.is_infinite() && m.critical_interference().is_infinite(),
            "Δc at {row:?}: {}",
            m.critical_interference()
        );
    }
    eprintln!(
        "worst relative error over {} rows: {:e} ({})",
        rows.len(),
        worst.0,
        worst.1
    );
    assert!(worst.0 <= TOLERANCE, "worst {:e}: {}", worst.0, worst.1);
}

#[test]
fn extrema_match_the_high_precision_table() {
    let rows = table("reference_extrema.csv");
    assert!(!rows.is_empty());
    for row in &rows {
        let m = model_of(row);
        let h_ref = num(&row["h_min"]);
        let land = landscape(&m);
        let cp = land
            .critical_points
            .iter()
            .min_by(|a, b| {
                (a.separation - h_ref)
                    .abs()
                    .total_cmp(&(b.separation - h_ref).abs())
            })
            .unwrap_or_else(|| panic!("no critical point for {row:?}"));
        assert_eq!(cp.is_minimum, row["kind"] == "min", "{row:?}");
        // The location of an extremum is determined only to ~√ε relative by the
        // flat load there; its value to full precision.
        assert!(
            (cp.separation - h_ref).abs() < 1e-7 * h_ref.abs().max(1.0),
            "{row:?}: {}",
            cp.separation
        );
        let log10 = num(&row["log10_abs_load_min"]);
        assert!(
            (cp.load.log10_abs() - log10).abs() < 1e-12 * log10.abs().max(1.0),
            "{row:?}: {}",
            cp.load.log10_abs()
        );
    }
}

#[test]
fn separation_roots_follow_the_rule() {
    let rows = table("reference_roots.csv");
    assert!(!rows.is_empty());
    for row in rows.iter().filter(|r| r["kind"] != "all_roots") {
        let m = model_of(row);
        let target = num(&row["target_load"]);
        let out = solve_separation(&m, target);
        if row["kind"] == "none_separates" || row["h_root"] == "none" {
            assert!(
                matches!(out, SeparationOutcome::Separated { .. }),
                "{row:?}: {out:?}"
            );
            continue;
        }
        let want = num(&row["h_root"]);
        match out {
            SeparationOutcome::Contact { separation, .. } => assert!(
                (separation - want).abs() < 1e-10 * want.abs().max(1.0),
                "{row:?}: {separation}"
            ),
            other => panic!("{row:?}: {other:?}"),
        }
    }
}
