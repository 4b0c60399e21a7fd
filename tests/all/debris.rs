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

/// The table on the hub: (τ_j, d*, contact share, area share, mechanism).
/// d* is the closed form. The shares come from the hub's Lennard-Jones junction
/// sizes: they are the closed forms Q(h + δ*/σ)/Q(h) and
/// [φ(a) − hQ(a)]/[φ(h) − hQ(h)] at the law's cut (`junction_cut`, checked
/// against the solved sphere in `each_law_cuts_at_its_own_contact_diameter`;
/// `junction_fractions`, with the plastic junctions' cut),
/// to 1e-7 (the separation comes out of the Lennard-Jones solve to about 1e-9,
/// and the far-tail share moves by (a − h)·a·Δh relative with it). With
/// Hertz's sizes the numbers (mpmath at 40 digits at the hub's
/// h = 2.082115779067568, `scripts/reference_debris.py`; the unit test
/// `model::debris::tests::the_hub_table` holds them to 1e-12) are lower bounds:
/// the sphere's junctions are wider.
#[test]
fn the_hub_table_through_eval() {
    use wearopt::model::debris::{junction_cut, junction_fractions};
    let scene = wearopt::problem::load(std::path::Path::new("problems/micro-gear.toml"))
        .unwrap()
        .scene;
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
    for (tau, d, hertz_count, hertz_area, mechanism) in table {
        let v = json_with(&format!("shear_strength = \"{tau}\""));
        let h = v["nondimensional_separation"].as_f64().unwrap();
        assert!((h - 2.082115779067568).abs() < 1e-9, "{h}");
        let f = |k: &str| v[k].as_f64().unwrap_or_else(|| panic!("{k}: {v}"));
        let rel =
            |a: f64, b: f64, tol: f64| assert!((a / b - 1.0).abs() < tol, "{tau}: {a} vs {b}");
        rel(f("critical_junction_size"), d, 1e-11);
        // Elastic summits beyond the law's cut, plastic ones (Δc = 28 σ here)
        // beyond d*²/(8R).
        let (s, r) = (scene.sigma, scene.asperity_radius);
        let (count, area) = junction_fractions(
            h,
            junction_cut(&scene, d),
            f("critical_interference") / s,
            d * d / (8.0 * r) / s,
        );
        rel(f("debris_contact_fraction"), count, 1e-7);
        rel(f("debris_area_fraction"), area, 1e-7);
        assert!(
            count > hertz_count && area > hertz_area,
            "{tau}: {count} {area}"
        );
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
    // The warning names the wear law in use and the share (76.1 % at 1 GPa).
    let v = json_with("shear_strength = \"1 GPa\"");
    let words: Vec<&str> = v["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w.as_str().unwrap())
        .collect();
    assert!(
        words
            .iter()
            .any(|w| w.contains("76.1 % of the real area") && w.contains("archard")),
        "{words:?}"
    );
    // And the note says which junction size is used.
    assert!(
        v["notes"]
            .to_string()
            .contains("an elastic summit's under the Lennard-Jones law"),
        "{}",
        v["notes"]
    );
}

/// Λ scales d* linearly (d* = Λ w G / τ²): Λ = 3 at τ = 0.5 GPa gives the d* of
/// Λ = 12 at τ = 1 GPa, so the same shares.
#[test]
fn the_shape_factor_is_read() {
    let v = json_with("shear_strength = \"0.5 GPa\"\ndebris_shape_factor = 3");
    let twelve = json_with("shear_strength = \"1 GPa\"");
    assert!((v["critical_junction_size"].as_f64().unwrap() / 7.86885245902e-8 - 1.0).abs() < 1e-11);
    assert_eq!(v["debris_area_fraction"], twelve["debris_area_fraction"]);
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

/// Each law's junction cut δ* (`junction_cut`, docs/model.md §13) on the hub
/// (`problems/micro-gear.toml`) at τ_j = 1 GPa (d* = 78.7 nm), against an
/// independent statement of the law's contact radius there:
/// - DMT: Hertz, a*² = Rδ*, exactly;
/// - JKR: in Maugis units, δ̂ = â² − (2/3)√(6â) (the JKR curve of `wearopt
///   asperity`, docs/model.md §11) at â = a*/(πwR²/K)^{1/3}, to 1e-12;
/// - Lennard-Jones: the solved sphere at the hub's μ = 0.374 (converged rows,
///   independent of the law's curves and their interpolation in μ) has the
///   contact radius a* at δ̂*, within 1e-6 relative (measured 3.1e-9).
///
/// And the order JKR < Lennard-Jones < Hertz (the sphere's contact is wider
/// than Hertz's, narrower than JKR's, at μ between them).
#[test]
fn each_law_cuts_at_its_own_contact_diameter() {
    use wearopt::model::asperity_curve::{lennard_jones_rows_at, Branch, RowAccuracy};
    use wearopt::model::debris::{critical_junction_size, junction_cut, shear_modulus};
    use wearopt::model::lennard_jones::SphereSettings;
    use wearopt::model::AdhesionModel;
    let problem = wearopt::problem::load(std::path::Path::new("problems/micro-gear.toml")).unwrap();
    let mut scene = problem.scene.clone();
    let (r, s, w) = (scene.asperity_radius, scene.sigma, scene.work_of_adhesion);
    let g = shear_modulus(scene.youngs_modulus_a, scene.poisson_ratio_a);
    let d = critical_junction_size(12.0, w, g, 1e9);
    let a = d / 2.0;
    let e = wearopt::model::equivalent_modulus(&scene);
    let k = 4.0 / 3.0 * e;
    let (radius_unit, interference_unit) = (
        (std::f64::consts::PI * w * r * r / k).cbrt(),
        (std::f64::consts::PI.powi(2) * w * w * r / (k * k)).cbrt(),
    );
    let mut cut = |model| {
        scene.adhesion_model = model;
        junction_cut(&scene, d) * s
    };
    let (hertz, jkr, lj) = (
        cut(AdhesionModel::Dmt),
        cut(AdhesionModel::Jkr),
        cut(AdhesionModel::LennardJones),
    );
    assert!((hertz / (a * a / r) - 1.0).abs() < 1e-14, "{hertz}");
    let a_hat = a / radius_unit;
    let jkr_maugis = (a_hat * a_hat - (2.0 / 3.0) * (6.0 * a_hat).sqrt()) * interference_unit;
    assert!((jkr / jkr_maugis - 1.0).abs() < 1e-12, "{jkr} {jkr_maugis}");
    assert!(jkr < lj && lj < hertz, "{jkr} {lj} {hertz}");
    let mu = (r * w * w / (e * e * scene.interatomic_distance.powi(3))).cbrt();
    let at = lj / interference_unit;
    let curve = lennard_jones_rows_at(mu, &[at], SphereSettings::default(), RowAccuracy::Converged)
        .expect("converges");
    let row = curve
        .points
        .iter()
        .find(|p| p.branch == Branch::Contact)
        .expect("in contact");
    let error = (row.contact_radius / a_hat - 1.0).abs();
    eprintln!(
        "μ = {mu}: δ̂* = {at}, â {} against {a_hat}: {error:.1e}",
        row.contact_radius
    );
    assert!(error < 1e-6, "{error}");
}

/// A soft hub (H = 0.3 GPa, so Δc is below the elastic cut) at τ_j = 1 GPa:
/// its plastic junctions, 2√(2Rδ) wide, make debris from d*²/(8R) on, so the
/// shares are those of `junction_fractions` and above the elastic cut's tail
/// alone (what the shares were before plastic sizes were read).
#[test]
fn plastic_junctions_make_debris_at_their_own_size() {
    use wearopt::model::debris::{debris_fractions, junction_cut, junction_fractions};
    let v = json_with("hardness = \"0.3 GPa\"\nshear_strength = \"1 GPa\"");
    let f = |k: &str| v[k].as_f64().unwrap_or_else(|| panic!("{k}: {v}"));
    let scene = wearopt::problem::load(std::path::Path::new("problems/micro-gear.toml"))
        .unwrap()
        .scene;
    let (s, r, d) = (
        scene.sigma,
        scene.asperity_radius,
        f("critical_junction_size"),
    );
    let mut soft = scene.clone();
    soft.hardness = 3e8;
    let (h, critical) = (
        f("nondimensional_separation"),
        f("critical_interference") / s,
    );
    let elastic = junction_cut(&soft, d);
    assert!(
        critical < elastic,
        "Δc {critical} against the cut {elastic}"
    );
    let (count, area) = junction_fractions(h, elastic, critical, d * d / (8.0 * r) / s);
    assert!((f("debris_contact_fraction") / count - 1.0).abs() < 1e-12);
    assert!((f("debris_area_fraction") / area - 1.0).abs() < 1e-12);
    let alone = debris_fractions(h, elastic);
    // Measured: 0.574 and 0.879 of the contacts and the area, against 0.476 and 0.810.
    assert!(
        count > 1.1 * alone.0 && area > alone.1,
        "{count} {area} {alone:?}"
    );
}
