//! Debris or smoothing through `wearopt eval` on a problem file (docs/model.md §13):
//! the table on the shipped hub, the words and the bad input.

use crate::common::wearopt;

/// `problems/micro-gear.toml` (the hub: h = 2.08212 under its Lennard-Jones law,
/// σ = 3 nm, R = 1 µm, polysilicon G = 160 GPa / 2.44 = 65.6 GPa, w = 0.1 J/m²) with
/// `extra` added to its `[interface]`, evaluated in `format`: (stdout, stderr, code).
fn hub_with(extra: &str, format: &str) -> (String, String, i32) {
    let text = std::fs::read_to_string("problems/micro-gear.toml").unwrap();
    let anchor = "[interface]\n";
    assert!(text.contains(anchor));
    let text = text.replacen(anchor, &format!("{anchor}{extra}\n"), 1);
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let path = dir.join(format!("debris-{:x}.toml", {
        use std::hash::{Hash, Hasher};
        let mut h = std::collections::hash_map::DefaultHasher::new();
        text.hash(&mut h);
        h.finish()
    }));
    std::fs::write(&path, &text).unwrap();
    let out = wearopt()
        .args(["eval", path.to_str().unwrap(), "--format", format])
        .output()
        .unwrap();
    (
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
        out.status.code().unwrap(),
    )
}

fn json_with(extra: &str) -> serde_json::Value {
    let (out, err, code) = hub_with(extra, "json");
    assert_eq!(code, 0, "{err}");
    serde_json::from_str(&out).unwrap()
}

/// The table: (τ_j, d*, contact share, area share). References: mpmath at
/// 40 digits of the closed forms Q(h + δ*/σ)/Q(h) and [φ(a) − hQ(a)]/[φ(h) − hQ(h)]
/// at the hub's h = 2.082115779067568 (the area share also by mpmath quadrature,
/// agreeing to 15 digits; the unit test `model::debris::tests::the_hub_table` holds
/// them to 1e-12). Here the tolerance is 1e-9: the separation comes out of the
/// Lennard-Jones solve to about that (its own tolerance), and the far-tail share
/// moves by (a − h)·a·Δh ≈ 85 Δh relative with it.
#[test]
fn the_hub_table_through_eval() {
    let table = [
        (
            "1 GPa",
            7.86885245902e-8,
            0.251097679393895,
            0.572657675313914,
            "debris",
        ),
        (
            "2 GPa",
            1.96721311475e-8,
            0.923716547827155,
            0.996659111278884,
            "debris",
        ),
        (
            "0.5 GPa",
            3.14754098361e-7,
            1.27110200451798e-23,
            2.9159233626524e-22,
            "smoothing",
        ),
    ];
    for (tau, d, count, area, mechanism) in table {
        let v = json_with(&format!("shear_strength = \"{tau}\""));
        let h = v["nondimensional_separation"].as_f64().unwrap();
        assert!((h - 2.082115779067568).abs() < 1e-9, "{h}");
        let f = |k: &str| v[k].as_f64().unwrap_or_else(|| panic!("{k}: {v}"));
        let rel =
            |a: f64, b: f64, tol: f64| assert!((a / b - 1.0).abs() < tol, "{tau}: {a} vs {b}");
        rel(f("critical_junction_size"), d, 1e-11);
        rel(f("debris_contact_fraction"), count, 1e-7);
        rel(f("debris_area_fraction"), area, 1e-7);
        assert_eq!(v["wear_mechanism"], mechanism, "{tau}");
        assert_eq!(f("debris_shape_factor"), 12.0);
        let kinds: Vec<&str> = v["warning_details"]
            .as_array()
            .unwrap()
            .iter()
            .map(|w| w["kind"].as_str().unwrap())
            .collect();
        assert_eq!(
            kinds.contains(&"debris_regime"),
            mechanism == "debris",
            "{tau}: {kinds:?}"
        );
    }
    // The warning names the wear law in use and the share.
    let v = json_with("shear_strength = \"2 GPa\"");
    let words: Vec<&str> = v["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w.as_str().unwrap())
        .collect();
    assert!(
        words
            .iter()
            .any(|w| w.contains("99.7 % of the real area") && w.contains("archard")),
        "{words:?}"
    );
    // And the note says which junction size is used.
    assert!(v["notes"].to_string().contains("2√(Rδ)"), "{}", v["notes"]);
}

/// Λ scales d* linearly (d* = Λ w G / τ²): Λ = 3 at τ = 0.5 GPa gives the d* of
/// Λ = 12 at τ = 1 GPa, so the same shares.
#[test]
fn the_shape_factor_is_read() {
    let v = json_with("shear_strength = \"0.5 GPa\"\ndebris_shape_factor = 3");
    assert!((v["critical_junction_size"].as_f64().unwrap() / 7.86885245902e-8 - 1.0).abs() < 1e-11);
    assert!((v["debris_area_fraction"].as_f64().unwrap() / 0.572657675313914 - 1.0).abs() < 1e-7);
    assert_eq!(v["debris_shape_factor"], 3.0);
}

/// Without a shear strength there are no debris numbers, and the text says them
/// when there are.
#[test]
fn absent_without_shear_strength_and_in_the_text() {
    let v = json_with("");
    assert!(v.get("critical_junction_size").is_none(), "{v}");
    assert!(v.get("wear_mechanism").is_none());
    let (t, _, code) = hub_with("shear_strength = \"1 GPa\"", "text");
    assert_eq!(code, 0);
    assert!(t.contains("critical junction size d* = 78.69 nm"), "{t}");
    assert!(t.contains("wear mechanism: debris"), "{t}");
    assert!(t.contains("(Λ = 12, G = 65.57 GPa"), "{t}");
    let (h, _, code) = hub_with("shear_strength = \"1 GPa\"", "html");
    assert_eq!(code, 0);
    assert!(h.contains("junctions wider than d*"));
}

#[test]
fn a_shape_factor_not_above_zero_is_refused() {
    for bad in ["0", "-1"] {
        let (out, err, code) = hub_with(
            &format!("shear_strength = \"1 GPa\"\ndebris_shape_factor = {bad}"),
            "json",
        );
        assert_eq!(code, 2, "{err}");
        assert!(out.is_empty());
        assert!(err.contains("interface.debris_shape_factor"), "{err}");
        assert!(err.contains("> 0"), "{err}");
    }
}
