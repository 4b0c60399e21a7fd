//! The DMT law (MODEL.md §7) against 40-digit tables computed with mpmath by
//! `scripts/reference_dmt.py` by two independent methods (closed forms, s = Δ^{1/2}
//! and t = z0/(z0 - Δ) substitutions; and plain quadrature over Δ for every part)
//! that agree to ≥ 25 digits (the table header states the worst agreement).
//! See scripts/README.md.
//!
//! Tolerance: 1e-12 relative (the bound). Contact loads are measured against
//! the sum of their parts' magnitudes, as for JKR (tests/reference.rs), since the
//! elastic share Δ^{3/2} - c_0 crosses zero; the non-contact load never does (it is
//! ≤ 0), and is measured against itself. Its h-derivative changes sign where the
//! weight's peak sits inside the attraction's reach, so it is measured against
//! |N|·(1 + |h|), the size of the terms ±u φ it integrates.

use crate::common::{num, rel, table};
use wearopt::model::{find_pull_off, AsperityLaw, Attraction, Coefficients, Model, Quadrature};

const TOLERANCE: f64 = 1e-12;

fn model_of(row: &std::collections::HashMap<String, String>) -> Model {
    let (theta, lambda) = (num(&row["theta"]), num(&row["lambda"]));
    let c = match row["case"].as_str() {
        "adhesive" => Coefficients::from_indices(theta, lambda),
        "no_plasticity" => {
            let mut c =
                Coefficients::new((6.0 * std::f64::consts::PI / theta).sqrt(), f64::INFINITY);
            c.c_0 = 2.0 * std::f64::consts::PI / theta;
            c
        }
        _ => Coefficients::new(0.0, num(&row["c_h"])),
    };
    let range = num(&row["range"]);
    let attraction = match row["attraction"].as_str() {
        "van_der_waals" => Attraction::VanDerWaals { range },
        "dugdale" => Attraction::Dugdale { range },
        other => panic!("attraction {other}"),
    };
    Model::with_law(c, AsperityLaw::Dmt(attraction), Quadrature::default())
}

#[test]
fn dmt_points_match_the_high_precision_table() {
    let rows = table("reference_dmt_points.csv");
    assert!(rows.len() >= 1000, "table too small: {}", rows.len());
    let mut worst = (0.0f64, String::new());
    let mut worst_of: std::collections::BTreeMap<&str, f64> = Default::default();
    for row in &rows {
        let m = model_of(row);
        let h = num(&row["h"]);
        let at = m.at(h);
        let (le, lp) = (num(&row["load_elastic"]), num(&row["load_plastic"]));
        let parts = le.abs() + lp.abs();
        let nc = num(&row["noncontact_load"]);
        let checks = [
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
                "dload_dh_contact",
                at.dload_dh_elastic + at.dload_dh_plastic,
                num(&row["dload_dh_contact"]),
                at.dload_dh_elastic.abs() + at.dload_dh_plastic.abs(),
            ),
            ("noncontact_load", at.load_noncontact, nc, 0.0),
            (
                "dnoncontact_dh",
                at.dload_dh_noncontact,
                num(&row["dnoncontact_dh"]),
                nc.abs() * (1.0 + h.abs()),
            ),
            (
                "noncontact_exponent",
                at.noncontact_exponent,
                // Without adhesion there is no term, and no scale to compare.
                if nc == 0.0 {
                    at.noncontact_exponent
                } else {
                    num(&row["noncontact_exponent"])
                },
                1.0,
            ),
        ];
        for (what, got, want, scale) in checks {
            if want == 0.0 && scale == 0.0 {
                assert!(got.abs() < 1e-290, "{what} at {row:?}: {got}");
                continue;
            }
            let e = rel(got, want, scale);
            let w = worst_of.entry(what).or_default();
            *w = w.max(e);
            if e > worst.0 {
                worst = (
                    e,
                    format!(
                        "{what} θ={} λ={} {} {} h={h}: {got} vs {want}",
                        row["theta"], row["lambda"], row["attraction"], row["range"]
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
    eprintln!("worst by field: {worst_of:?}");
    assert!(worst.0 <= TOLERANCE, "worst {:e}: {}", worst.0, worst.1);
}

/// The pull-off minimum of P̄ (docs/model.md §4 under §7) against
/// `reference_dmt_extrema.csv`: mpmath's findroot on P̄'/|P̄| at 40 digits, P̄ there by
/// both of the script's methods (≥ 25 digits apart at worst). Rows give θ (c_0 = 2π/θ)
/// and c_h directly (the hub's c_h = 5.12; `inf` is H = ∞).
///
/// The location of a minimum is fixed only to ~√ε relative by the flat load there;
/// its value to full precision: h_min to 1e-7, P̄_min and log10|P̄_min| to 1e-12.
#[test]
fn dmt_pull_off_minima_match_the_high_precision_table() {
    let rows = table("reference_dmt_extrema.csv");
    assert!(rows.len() >= 7, "table too small: {}", rows.len());
    for row in &rows {
        let theta = num(&row["theta"]);
        let mut c = Coefficients::new(
            (6.0 * std::f64::consts::PI / theta).sqrt(),
            num(&row["c_h"]),
        );
        c.c_0 = 2.0 * std::f64::consts::PI / theta;
        let range = num(&row["range"]);
        let attraction = match row["attraction"].as_str() {
            "van_der_waals" => Attraction::VanDerWaals { range },
            "dugdale" => Attraction::Dugdale { range },
            other => panic!("attraction {other}"),
        };
        let m = Model::with_law(c, AsperityLaw::Dmt(attraction), Quadrature::default());
        let p = find_pull_off(&m).unwrap_or_else(|| panic!("no pull-off for {row:?}"));
        assert_eq!(p.local_minima, 1, "{row:?}");
        let h_ref = num(&row["h_min"]);
        assert!(
            (p.separation - h_ref).abs() < 1e-7 * h_ref.abs().max(1.0),
            "{row:?}: h = {}",
            p.separation
        );
        let log10 = num(&row["log10_abs_load_min"]);
        assert!(
            (p.load.log10_abs() - log10).abs() < TOLERANCE * log10.abs().max(1.0),
            "{row:?}: log10 = {}",
            p.load.log10_abs()
        );
        let want = num(&row["load_min"]);
        let err = rel(p.load.value(), want, 0.0);
        assert!(
            err < TOLERANCE,
            "{row:?}: P = {:e}, rel {err:e}",
            p.load.value()
        );
    }
}
