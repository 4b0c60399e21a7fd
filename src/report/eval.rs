//! The report of one scene evaluation (`wearopt eval`): text and JSON.

use serde_json::{json, Map, Value};

use super::format::FormatError;
use super::{si, sig, sig_exp};
use crate::app::eval::{EvalDocument, EvalOptions, LOAD_CURVE_POINTS};
use crate::model::law::{DUGDALE_STRESS_FACTOR, TRANSITION_TABOR};
use crate::model::{AdhesionModel, Evaluation, Scene, Sensitivity, WearArea};

/// The stress-assisted law's inputs and numbers (docs/model.md §12), one line each;
/// none under Archard.
fn wear_law_lines(sc: &Scene, ev: &Evaluation) -> Vec<String> {
    let (Some(a), Some(w)) = (sc.activation, ev.wear_details) else {
        return Vec::new();
    };
    let ev_unit = crate::units::ELECTRON_VOLT;
    let stress = match a.stress {
        crate::model::wear_law::ContactStress::Normal => {
            "each summit's mean contact pressure (H on a plastic junction)"
        }
        crate::model::wear_law::ContactStress::Shear => "the interface's shear strength τ",
    };
    let mut out = vec![
        format!(
            "activation energy ΔU = {} eV, activation volume ΔV = {}, attempt frequency f0 = {}",
            sig(a.activation_energy / ev_unit, 4),
            si(a.activation_volume, "m³", 4),
            si(a.attempt_frequency, "Hz", 4)
        ),
        format!(
            "site spacing a0 = {}, atomic volume Ω = {}, temperature T = {}, sliding speed v = {}",
            si(a.site_spacing, "m", 4),
            si(a.atomic_volume, "m³", 4),
            si(sc.temperature, "K", 5),
            si(a.sliding_speed, "m/s", 4)
        ),
        format!("the stress that assists: {stress}"),
    ];
    if let Some(k) = w.effective_wear_coefficient {
        // Below a double's range (a cold or slow contact): k_eff in logarithms.
        let log10_k = w.log10_effective_wear_coefficient.filter(|_| k == 0.0);
        let value = if let Some(log10_k) = log10_k {
            format!(
                "10^{} (below the smallest number a double holds)",
                sig(log10_k, 5)
            )
        } else if k == 0.0 {
            "below the smallest number a double holds".to_string()
        } else {
            sig_exp(k, 4)
        };
        out.push(format!(
            "effective wear coefficient k_eff = {value} (the one-pass cap Ω/a0³ = {})",
            sig(a.atomic_volume / a.site_spacing.powi(3), 4)
        ));
    }
    if let Some(s) = w.mean_contact_stress {
        out.push(format!(
            "mean contact stress (area-weighted) = {}",
            si(s, "Pa", 4)
        ));
    }
    if let Some(f) = w.saturated_fraction {
        out.push(format!(
            "saturated share of the rate (Γa0/v > 1: every site of the path removed) = {} %",
            sig(100.0 * f, 4)
        ));
    }
    if let Some(e) = w.apparent_activation_energy {
        out.push(format!(
            "apparent activation energy −d ln(rate)/d(1/k_BT) = {} eV",
            sig(e / ev_unit, 5)
        ));
    }
    out
}

/// The formats `wearopt eval` writes (the first is the default).
pub const FORMATS: &[super::Format] = &[
    super::Format::Text,
    super::Format::Json,
    super::Format::Html,
];

/// The formats `wearopt eval` writes, with what each needs computed.
pub fn options(format: super::Format) -> EvalOptions {
    EvalOptions {
        load_curve_points: (format == super::Format::Html).then_some(LOAD_CURVE_POINTS),
    }
}

/// The document in `format` (one of [`FORMATS`]).
pub fn render(doc: &EvalDocument, format: super::Format) -> Result<String, FormatError> {
    let r = view(doc);
    match format {
        super::Format::Text => Ok(text(&r)),
        super::Format::Json => Ok(super::json_text(&json_value(&r))),
        super::Format::Html => Ok(html(&r, doc.load_curve.as_ref())),
        given => Err(FormatError::NotRendered {
            command: "eval",
            given,
            accepted: FORMATS,
        }),
    }
}

/// The JSON document as a value (what Python reads).
pub fn json_document(doc: &EvalDocument) -> Value {
    json_value(&view(doc))
}

/// The report's view of a document.
pub fn view(doc: &EvalDocument) -> EvalReport<'_> {
    EvalReport {
        name: &doc.name,
        scene: &doc.scene,
        input_notes: &doc.input_notes,
        evaluation: &doc.evaluation,
        sensitivities: &doc.sensitivities,
        scan: doc.scan.as_ref(),
        scan_contact: doc.scan_contact.as_ref(),
    }
}

/// Everything an evaluation report shows.
pub struct EvalReport<'a> {
    /// The problem's name.
    pub name: &'a str,
    /// The scene as evaluated.
    pub scene: &'a Scene,
    /// Notes from reading the problem file (catalogue values taken, overrides, …).
    pub input_notes: &'a [crate::problem::InputNote],
    /// The evaluation.
    pub evaluation: &'a Evaluation,
    /// Wear-rate elasticities.
    pub sensitivities: &'a [Sensitivity],
    /// The measured scan σ, R and N came from, if any.
    pub scan: Option<&'a crate::problem::ScanSource>,
    /// The exact contact on that scan at the operating point, or why there is none.
    pub scan_contact: Option<&'a Result<crate::app::contact::ScanContact, String>>,
}

fn opt(x: Option<f64>) -> Value {
    x.map_or(Value::Null, |v| json!(v))
}

/// One JSON object, SI units.
pub fn json(r: &EvalReport) -> String {
    super::json_text(&json_value(r))
}

/// The object [`json()`] writes, as a value.
pub fn json_value(r: &EvalReport) -> Value {
    let ev = r.evaluation;
    let mut v = super::words::evaluation_json(ev);
    if let Value::Object(obj) = &mut v {
        // Indices at the top level, as the contract names them.
        if let Some(Value::Object(idx)) = obj.remove("indices") {
            for (k, x) in idx {
                obj.insert(k, x);
            }
        }
        let mut notes = super::words::input_notes(r.input_notes);
        notes.extend(super::words::notes(ev));
        obj.insert("notes".into(), json!(notes));
        obj.insert("input_note_details".into(), json!(r.input_notes));
        obj.insert("name".into(), json!(r.name));
        // The stiction verdict under the other law too, where eval computed it.
        if let (Some(Value::Object(st)), Some(other)) =
            (obj.get_mut("stiction"), other_stiction(ev))
        {
            st.insert(
                "other_model".into(),
                json!({
                    "adhesion_model": other.0.as_str(),
                    "pull_off_force": other.1.pull_off_force,
                    "margin": other.1.margin,
                    "verdict": other.1.verdict,
                }),
            );
        }
        obj.insert(
            "scene".into(),
            serde_json::to_value(r.scene).unwrap_or(Value::Null),
        );
        // The wear law's inputs, under a law that takes them (docs/model.md §12).
        if let Some(a) = r.scene.activation {
            obj.insert(
                "wear_inputs".into(),
                json!({
                    "activation_energy": a.activation_energy,
                    "activation_volume": a.activation_volume,
                    "attempt_frequency": a.attempt_frequency,
                    "site_spacing": a.site_spacing,
                    "atomic_volume": a.atomic_volume,
                    "stress": a.stress,
                    "sliding_speed": a.sliding_speed,
                    "temperature": r.scene.temperature,
                }),
            );
        }
        obj.insert(
            "roughness_source".into(),
            r.scan.map_or(Value::Null, super::roughness::scan_json),
        );
        obj.insert(
            "contact_model".into(),
            json!(r.scan.map_or("statistical", |s| s.contact_model.as_str())),
        );
        obj.insert("real_area_scale".into(), json!(r.scene.real_area_scale));
        if let Some(c) = r.scan_contact {
            let (bem, ratio, detail) = match c {
                Ok(c) => (
                    json!(c.solution.real_area_fraction),
                    opt(c.area_ratio()),
                    json!({
                        "pressure": c.pressure,
                        "modulus": c.modulus,
                        "hardness": if c.hardness.is_finite() { json!(c.hardness) } else { Value::Null },
                        "pixels": c.pixels,
                        "real_area_fraction": c.solution.real_area_fraction,
                        "plastic_area_fraction": c.solution.plastic_area_fraction,
                        "contact_patches": c.solution.contact_patches,
                        "mean_gap": c.solution.mean_gap,
                        "max_pressure": c.solution.max_pressure,
                        "residual": c.solution.residual,
                        "iterations": c.solution.iterations,
                        "status": super::contact::status_word(c.solution.outcome),
                        "gw_real_area_fraction": c.statistical.real_area_fraction,
                        "gw_contact_count": c.statistical.contact_count,
                    }),
                ),
                Err(reason) => (Value::Null, Value::Null, json!({ "error": reason })),
            };
            obj.insert("bem_real_area_fraction".into(), bem);
            obj.insert("area_ratio".into(), ratio);
            obj.insert("scan_contact".into(), detail);
        }
        let mut sens = Map::new();
        for s in r.sensitivities {
            sens.insert(
                s.parameter.as_str().to_string(),
                json!({
                    "elasticity": opt(s.elasticity),
                    "error": opt(s.error),
                    "note": s.note.map(super::words::sensitivity_gap),
                    "note_kind": s.note,
                }),
            );
        }
        obj.insert("sensitivities".into(), Value::Object(sens));
    }
    v
}

/// The humid air's numbers as (label, value) rows, for the text and HTML pages.
fn humidity_rows(h: &crate::model::wear::Humidity) -> Vec<[String; 2]> {
    let deg = |rad: f64| format!("{}°", sig(rad.to_degrees(), 4));
    let mut rows = vec![
        [
            "relative humidity RH".to_string(),
            format!("{} %", sig(100.0 * h.relative_humidity, 4)),
        ],
        [
            "temperature T".into(),
            format!(
                "{} (surface tension γ_L = {})",
                si(h.temperature, "K", 5),
                si(h.surface_tension, "N/m", 4)
            ),
        ],
        [
            "contact angles θ_a, θ_b".into(),
            format!("{}, {}", deg(h.contact_angle_a), deg(h.contact_angle_b)),
        ],
    ];
    match (h.kelvin_radius, h.meniscus_height, h.laplace_pressure) {
        (Some(r), Some(d), Some(p)) => {
            rows.push(["Kelvin radius r_K".into(), si(r, "m", 4)]);
            rows.push([
                "meniscus height d_K".into(),
                format!("{} (the widest gap the liquid bridges)", si(d, "m", 4)),
            ]);
            rows.push(["Laplace pressure Δp".into(), si(p, "Pa", 4)]);
        }
        _ if h.relative_humidity == 0.0 => {
            rows.push(["meniscus".into(), "none: dry air (RH = 0)".into()])
        }
        _ => rows.push([
            "meniscus".into(),
            "none: the liquid does not wet the pair (cos θ_a + cos θ_b ≤ 0)".into(),
        ]),
    }
    if let (Some(load), Some(wet)) = (h.capillary_load, h.wetted_fraction) {
        rows.push([
            "capillary load".into(),
            format!(
                "{} (in the load balance and the pull-off force)",
                si(load, "N", 4)
            ),
        ]);
        rows.push(["wet fraction of the nominal area".into(), sig_exp(wet, 3)]);
    }
    rows.push([
        "apparent work of adhesion Γ".into(),
        h.apparent_work_of_adhesion
            .map_or("— (computed with the pull-off)".into(), |g| {
                format!(
                    "{} (what a cantilever-beam test measures)",
                    si(g, "J/m²", 4)
                )
            }),
    ]);
    if let Some(l) = h.detachment_length {
        rows.push([
            "cantilever detachment length".into(),
            format!("{} (longer beams stay stuck)", si(l, "m", 4)),
        ]);
    }
    rows
}

/// The asperity law in a few words (a table cell): its name, the attraction
/// of a law that takes one, the closed form that stands in for a law outside
/// its table.
fn law_label(ev: &Evaluation, sc: &Scene) -> String {
    let law = ev.adhesion_model.law();
    let name = if law.takes_attraction() {
        format!("{}, {}", law.title(), sc.attraction.label())
    } else {
        law.title().to_string()
    };
    match ev.stand_in_model {
        Some(m) => format!("{name} ({} stands in)", m.label()),
        None => name,
    }
}

/// The asperity law in words, with its attraction's range and Hamaker
/// constant where it has them (the law's own description, the scene's numbers
/// put in).
fn law_words(ev: &Evaluation, sc: &Scene) -> String {
    let words = ev.adhesion_model.law().description(sc.attraction);
    let mut out = words.to_string();
    if words.contains("{z0}") {
        out = out.replace("{z0}", &sig_exp(sc.interatomic_distance / sc.sigma, 4));
    }
    if words.contains("{hamaker}") {
        out = out.replace(
            "{hamaker}",
            &sig_exp(ev.hamaker_constant.unwrap_or(f64::NAN), 4),
        );
    }
    if words.contains("{dugdale_range}") {
        let range = sc.interatomic_distance / (DUGDALE_STRESS_FACTOR * sc.sigma);
        out = out.replace("{dugdale_range}", &sig_exp(range, 4));
    }
    out
}

/// The stiction verdict under the other asperity law (JKR–DMT transition only).
fn other_stiction(
    ev: &Evaluation,
) -> Option<(crate::model::law::AdhesionModel, crate::model::Stiction)> {
    let st = ev.stiction.as_ref()?;
    let other = ev.other_model.as_ref()?;
    let f = other.pull_off_force?;
    Some((
        other.adhesion_model,
        crate::model::Stiction::new(f, st.restoring_force),
    ))
}

fn verdict_words(v: crate::model::StictionVerdict) -> &'static str {
    match v {
        crate::model::StictionVerdict::Sticks => "STICKS (margin ≥ 1)",
        crate::model::StictionVerdict::Releases => "releases (margin < 1)",
    }
}

/// The load–separation curve as an SVG plot: W against d, the operating point and
/// the pull-off marked. A pull-off beyond the sampled stretch of the curve (the model
/// samples at most 40 σ; a pull-off that underflows sits far out) is left unmarked
/// rather than stretch the axis until the curve is a sliver.
pub fn load_curve_svg(title: &str, c: &crate::model::LoadCurve) -> String {
    use super::svg::{Axis, LinePlot, Marker, Series};
    let (d_lo, d_hi) = c
        .points
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
            (a.min(p.0), b.max(p.0))
        });
    let pull_off = c.pull_off_point.filter(|p| (d_lo..=d_hi).contains(&p.0));
    // Without a pull-off to show, the curve past a few times the operating point's
    // distance from the start is a flat line at W = 0: leave it out.
    let d_end = match (pull_off, c.operating_point) {
        (None, Some(op)) if op.0 > d_lo => (op.0 + 3.0 * (op.0 - d_lo)).min(d_hi),
        _ => d_hi,
    };
    let points: Vec<(f64, f64)> = c.points.iter().copied().filter(|p| p.0 <= d_end).collect();
    let max_w = points
        .iter()
        .chain(c.operating_point.iter())
        .chain(pull_off.iter())
        .map(|p| p.1.abs())
        .fold(0.0, f64::max);
    let (wf, wu) = crate::units::axis_unit(max_w, "N");
    let (df, du) =
        crate::units::axis_unit(points.iter().map(|p| p.0.abs()).fold(0.0, f64::max), "m");
    let scaled = |p: &(f64, f64)| (p.0 / df, p.1 / wf);
    let mut plot = LinePlot::new(
        title,
        Axis::linear("mean-plane separation d").with_unit(du),
        Axis::linear("load W, positive presses").with_unit(wu),
    )
    .with_series(
        Series::new("W(d), the model", points.iter().map(scaled).collect())
            .with_marker(Marker::None),
    );
    if let Some(p) = &c.operating_point {
        plot = plot.with_series(
            Series::new("operating point", vec![scaled(p)])
                .without_line()
                .with_marker(Marker::Circle),
        );
    }
    if let Some(p) = &pull_off {
        plot = plot.with_series(
            Series::new("pull-off", vec![scaled(p)])
                .without_line()
                .with_marker(Marker::Triangle),
        );
    }
    plot.to_svg()
}

/// Where the pull-off is under a twentieth of the largest load on the curve (on
/// [`load_curve_svg`]'s axis a dot on a flat line): a second plot of the tensile
/// part alone — from where W falls to three times the pull-off force on — with
/// the pull-off marked and labelled with its force and separation; else None.
pub fn load_curve_tension_svg(title: &str, c: &crate::model::LoadCurve) -> Option<String> {
    use super::svg::{Axis, LinePlot, Marker, Series};
    if !pull_off_drawn(c) {
        return None;
    }
    let pull = c.pull_off_point?;
    let tension = -pull.1;
    let max_w = c.points.iter().map(|p| p.1.abs()).fold(0.0, f64::max);
    if !(tension > 0.0 && tension < max_w / 20.0) {
        return None;
    }
    let start = c.points.iter().position(|p| p.1 <= 3.0 * tension)?;
    let points: Vec<(f64, f64)> = c.points[start..].to_vec();
    let (d_lo, d_hi) = (points.first()?.0, points.last()?.0);
    let (wf, wu) = crate::units::axis_unit(3.0 * tension, "N");
    let (df, du) = crate::units::axis_unit(d_hi.abs(), "m");
    let scaled = |p: &(f64, f64)| (p.0 / df, p.1 / wf);
    let mut plot = LinePlot::new(
        title,
        Axis::linear("mean-plane separation d")
            .with_unit(du)
            .with_range(d_lo / df, d_hi / df),
        Axis::linear("load W, negative pulls")
            .with_unit(wu)
            .with_range(-1.25 * tension / wf, 3.0 * tension / wf),
    )
    .with_series(
        Series::new("W(d), the model", points.iter().map(scaled).collect())
            .with_marker(Marker::None),
    );
    if let Some(op) = c
        .operating_point
        .filter(|p| p.0 >= d_lo && p.1 <= 3.0 * tension)
    {
        plot = plot.with_series(
            Series::new("operating point", vec![scaled(&op)])
                .without_line()
                .with_marker(Marker::Circle)
                .with_color(super::svg::PALETTE[1]),
        );
    }
    plot = plot.with_series(
        Series::new(
            format!(
                "pull-off {} at d = {}",
                crate::units::format_quantity(tension, crate::units::Dimension::Force),
                crate::units::format_quantity(pull.0, crate::units::Dimension::Length)
            ),
            vec![scaled(&pull)],
        )
        .without_line()
        .with_marker(Marker::Triangle)
        .with_color(super::svg::PALETTE[2]),
    );
    Some(plot.to_svg())
}

/// Whether [`load_curve_svg`] marks the pull-off (it lies on the sampled curve).
fn pull_off_drawn(c: &crate::model::LoadCurve) -> bool {
    let (lo, hi) = c
        .points
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
            (a.min(p.0), b.max(p.0))
        });
    c.pull_off_point.is_some_and(|p| (lo..=hi).contains(&p.0))
}

/// The caption of [`load_curve_svg`]'s plot, saying what is marked.
pub(crate) fn load_curve_caption(what: &str, c: &crate::model::LoadCurve) -> String {
    let marked = match (c.operating_point.is_some(), pull_off_drawn(c)) {
        (true, true) => {
            ", with the operating point and the pull-off (the most tensile load the contact holds)"
        }
        (true, false) => {
            ", with the operating point; the pull-off lies far beyond the drawn range (its force is in the table)"
        }
        (false, true) => ", with the pull-off (the most tensile load the contact holds)",
        (false, false) => "",
    };
    format!("{what} against the mean-plane separation d{marked}.")
}

/// A self-contained HTML page: the tables of [`text`] and the load–separation curve
/// and sensitivity bars as inline SVG.
pub fn html(r: &EvalReport, curve: Option<&crate::model::LoadCurve>) -> String {
    let ev = r.evaluation;
    let sc = r.scene;
    let mut p = super::html::Page::new(&format!("wearopt eval — {}", r.name));
    p.paragraph(&format!("Status: {}", ev.status.as_str()), Some("status"));
    let warnings = super::words::warnings(ev);
    p.list(
        &warnings
            .iter()
            .map(|w| format!("WARNING: {w}"))
            .collect::<Vec<_>>(),
        "warn",
    );
    let q = |x: f64, u: &str| si(x, u, 4);
    // The answer first, the inputs after: what a designer opens the page for.
    p.heading("The answer");
    let verdict = |v: crate::model::StictionVerdict| match v {
        crate::model::StictionVerdict::Sticks => "sticks",
        crate::model::StictionVerdict::Releases => "releases",
    };
    let mut answer = vec![
        vec!["wear rate V/L".into(), q(ev.wear_rate, "m³/m")],
        vec![
            "pull-off force".into(),
            ev.pull_off_force.map_or("—".into(), |x| q(x, "N")),
        ],
        vec![
            "stiction".into(),
            match &ev.stiction {
                Some(st) => format!(
                    "{}: pull-off {} against restoring force {}, margin {} ({} law)",
                    verdict(st.verdict),
                    q(st.pull_off_force, "N"),
                    q(st.restoring_force, "N"),
                    sig_exp(st.margin, 3),
                    ev.adhesion_model.label()
                ),
                None => "not judged: the problem gives no restoring force".into(),
            },
        ],
    ];
    if let Some((law, st)) = other_stiction(ev) {
        answer.push(vec![
            format!("stiction under the {} law instead", law.label()),
            format!(
                "{}: pull-off {}, margin {}",
                verdict(st.verdict),
                q(st.pull_off_force, "N"),
                sig_exp(st.margin, 3)
            ),
        ]);
    }
    p.table(&["result", "value"], &answer, &[1]);
    p.heading("Scene");
    let rows = vec![
        vec![
            "Young's modulus E1 (body a)".into(),
            q(sc.youngs_modulus_a, "Pa"),
        ],
        vec!["Poisson ratio ν1".into(), sig(sc.poisson_ratio_a, 3)],
        vec![
            "Young's modulus E2 (counterface b)".into(),
            if sc.youngs_modulus_b.is_infinite() {
                "rigid".into()
            } else {
                q(sc.youngs_modulus_b, "Pa")
            },
        ],
        vec![
            "equivalent modulus E".into(),
            q(ev.equivalent_modulus, "Pa"),
        ],
        vec![
            "hardness H".into(),
            if sc.hardness.is_infinite() {
                "∞ (no plasticity)".into()
            } else {
                q(sc.hardness, "Pa")
            },
        ],
        vec!["work of adhesion γ".into(), q(sc.work_of_adhesion, "J/m²")],
        vec!["roughness σ".into(), q(sc.sigma, "m")],
        vec!["asperity radius R".into(), q(sc.asperity_radius, "m")],
        vec!["asperity density N".into(), q(sc.asperity_density, "m⁻²")],
        vec!["load W".into(), q(sc.load, "N")],
        vec!["nominal area A_n".into(), q(sc.nominal_area, "m²")],
        vec!["sliding distance L".into(), q(sc.sliding_distance, "m")],
        match sc.wear_law {
            crate::model::WearModel::Archard => {
                vec!["wear coefficient k".into(), sig_exp(sc.wear_coefficient, 3)]
            }
            law => vec!["wear law".into(), law.law().label().into()],
        },
        vec!["asperity law".into(), law_label(ev, sc)],
    ];
    p.table(&["input", "value"], &rows, &[]);
    p.list(&super::words::input_notes(r.input_notes), "note");
    if let Some(c) = r.scan_contact {
        p.heading("The real area on the scan itself");
        let lines: Vec<String> = scan_contact_lines(c, r.scene.real_area_scale != 1.0)
            .into_iter()
            .map(|l| l.trim().to_string())
            .collect();
        p.list(&lines, "note");
    }
    p.heading("Indices and regime");
    let i = &ev.indices;
    p.table(
        &["index", "value", "meaning"],
        &[
            vec![
                "elastic adhesion index θ".into(),
                sig_exp(i.elastic_adhesion_index, 4),
                "≤ 10: adhesion matters".into(),
            ],
            vec![
                "plastic adhesion index λ".into(),
                sig_exp(i.plastic_adhesion_index, 4),
                "≤ 0.125: adhesion matters".into(),
            ],
            vec![
                "plasticity index ψ".into(),
                sig_exp(i.plasticity_index, 4),
                ev.regime.deformation.into(),
            ],
            vec![
                "Tabor parameter φ0".into(),
                sig_exp(i.tabor_parameter, 4),
                format!("regime: {}", ev.regime.adhesion_model),
            ],
            vec![
                "critical interference Δc·σ".into(),
                q(ev.critical_interference, "m"),
                "an asperity turns plastic beyond it".into(),
            ],
        ],
        &[2],
    );
    p.list(&super::words::notes(ev), "note");
    p.heading("Contact");
    let mut rows = vec![
        vec![
            "separation d".into(),
            ev.separation.map_or("— (apart)".into(), |d| q(d, "m")),
        ],
        vec!["real area A_r".into(), q(ev.real_area, "m²")],
        vec![
            "real area fraction A_r/A_n".into(),
            sig_exp(ev.real_area_fraction, 3),
        ],
        vec![
            "elastic contacts / plastic junctions".into(),
            format!(
                "{} / {}",
                part(
                    ev.elastic_real_area,
                    ev.real_area,
                    q(ev.elastic_real_area, "m²")
                ),
                part(
                    ev.plastic_real_area,
                    ev.real_area,
                    q(ev.plastic_real_area, "m²")
                )
            ),
        ],
        vec!["contacts".into(), sig_exp(ev.contact_count, 4)],
        vec![
            "mean real pressure W/A_r".into(),
            ev.mean_real_pressure.map_or("—".into(), |x| {
                format!("{}{}", q(x, "Pa"), pressure_note(ev, x, sc.hardness))
            }),
        ],
        vec![
            "pull-off force".into(),
            ev.pull_off_force.map_or("—".into(), |x| q(x, "N")),
        ],
        vec![
            "pull-off of one asperity".into(),
            q(ev.law_asperity_pull_off_force, "N"),
        ],
        vec!["wear rate V/L".into(), q(ev.wear_rate, "m³/m")],
        vec!["wear volume V".into(), q(ev.wear_volume, "m³")],
        vec![
            "wear depth rate V/(A_n L)".into(),
            format!("{} per m slid", q(ev.wear_depth_rate, "m")),
        ],
    ];
    if let Some(nc) = ev
        .noncontact_load
        .filter(|_| ev.adhesion_model.law().attracts_out_of_contact())
    {
        rows.insert(
            6,
            vec![
                "load carried by attracted asperities not in contact".into(),
                q(nc, "N"),
            ],
        );
    }
    if let Some(l) = ev.life_sliding_distance {
        rows.push(vec![
            "life: sliding distance to the allowed depth".into(),
            q(l, "m"),
        ]);
    }
    if let Some(n) = ev.life_cycles {
        rows.push(vec![
            "life: cycles to the allowed depth".into(),
            sig_exp(n, 3),
        ]);
    }
    if let Some(st) = &ev.stiction {
        rows.push(vec![
            format!("stiction ({} law)", ev.adhesion_model.label()),
            format!(
                "margin {} → {}",
                sig_exp(st.margin, 3),
                match st.verdict {
                    crate::model::StictionVerdict::Sticks => "sticks",
                    crate::model::StictionVerdict::Releases => "releases",
                }
            ),
        ]);
    }
    if let Some((law, st)) = other_stiction(ev) {
        rows.push(vec![
            format!("stiction under the {} law instead", law.label()),
            format!(
                "pull-off {}, margin {} → {}",
                q(st.pull_off_force, "N"),
                sig_exp(st.margin, 3),
                match st.verdict {
                    crate::model::StictionVerdict::Sticks => "sticks",
                    crate::model::StictionVerdict::Releases => "releases",
                }
            ),
        ]);
    }
    if let Some(om) = &ev.other_model {
        rows.push(vec![
            format!("under the {} law instead", om.adhesion_model.label()),
            match om.nondimensional_separation {
                Some(_) => format!(
                    "real area {}, pull-off {}, wear rate {}",
                    q(om.real_area, "m²"),
                    om.pull_off_force.map_or("—".into(), |f| q(f, "N")),
                    q(om.wear_rate, "m³/m")
                ),
                None => format!(
                    "{} (no contact under this load), pull-off {}",
                    om.status.as_str(),
                    om.pull_off_force.map_or("—".into(), |f| q(f, "N"))
                ),
            },
        ]);
    }
    if let Some(f) = ev.friction_force {
        rows.push(vec!["friction force τ A_r".into(), q(f, "N")]);
    }
    if let Some(mu) = ev.friction_coefficient {
        rows.push(vec!["friction coefficient F/W".into(), sig_exp(mu, 3)]);
    }
    if let Some(d) = &ev.debris {
        rows.push(vec![
            "critical junction size d* = Λ w G / τ²".into(),
            q(d.critical_junction_size, "m"),
        ]);
        if let (Some(c), Some(a), Some(m)) = (
            d.debris_contact_fraction,
            d.debris_area_fraction,
            d.wear_mechanism,
        ) {
            rows.push(vec![
                "junctions wider than d* (debris)".into(),
                format!(
                    "{} of the contacts, {} of the real area → {}",
                    sig_exp(c, 3),
                    sig_exp(a, 3),
                    m.as_str()
                ),
            ]);
        }
    }
    p.table(&["result", "value"], &rows, &[]);
    if let Some(hum) = &ev.humidity {
        p.heading("Humid air (capillary adhesion)");
        let rows: Vec<Vec<String>> = humidity_rows(hum).into_iter().map(Vec::from).collect();
        p.table(&["quantity", "value"], &rows, &[1]);
    }
    if let Some(curve) = curve {
        p.figure(
            "load-separation",
            &load_curve_svg(&format!("Load against separation — {}", r.name), curve),
            &load_curve_caption("The model's load W", curve),
        );
        if let Some(svg) =
            load_curve_tension_svg(&format!("The tensile part, enlarged — {}", r.name), curve)
        {
            p.figure(
                "load-separation-tension",
                &svg,
                "The same curve where the surfaces pull: the pull-off is the most tensile load the contact holds.",
            );
        }
    }
    if !r.sensitivities.is_empty() {
        p.heading("Sensitivity of the wear rate");
        let rows: Vec<Vec<String>> = r
            .sensitivities
            .iter()
            .map(|s| {
                vec![
                    s.parameter.as_str().to_string(),
                    s.elasticity.map_or("—".into(), |e| format!("{e:+.6}")),
                    s.error.map_or(gap(s).to_string(), |e| sig_exp(e, 2)),
                ]
            })
            .collect();
        p.table(
            &["parameter x", "d ln(wear rate) / d ln x", "error estimate"],
            &rows,
            &[],
        );
        let bars: Vec<(String, f64)> = r
            .sensitivities
            .iter()
            .map(|s| {
                (
                    s.parameter.as_str().to_string(),
                    s.elasticity.unwrap_or(f64::NAN),
                )
            })
            .collect();
        p.figure(
            "sensitivities",
            &super::svg::bar_chart(
                "Elasticities of the wear rate",
                "d ln(wear rate) / d ln x (Richardson-extrapolated central differences)",
                &bars,
            ),
            "A bar of +1 means the wear rate grows in proportion to the parameter.",
        );
    }
    p.finish()
}

/// Why W/A_r can exceed the hardness (the model's area measure), beside the
/// number where it does; empty otherwise.
fn pressure_note(ev: &Evaluation, pressure: f64, hardness: f64) -> String {
    if pressure > hardness {
        format!(
            " (above H = {}: A_r counts every contact as πRδ, the model's area, while a plastic \
             junction carries H over 2πRδ; a nominal pressure, not the pressure inside a contact)",
            si(hardness, "Pa", 3)
        )
    } else {
        match ev.mean_contact_pressure {
            // Adhesion makes the contacts bear far more than W, or bear
            // compression while W pulls: say what they carry.
            Some(c) if c.abs() > 2.0 * pressure.abs() || (pressure < 0.0 && c > 0.0) => format!(
                " (the contacts bear the load and the adhesive pulls besides: {} over A_r)",
                si(c, "Pa", 4)
            ),
            _ => String::new(),
        }
    }
}

/// A report for people.
pub fn text(r: &EvalReport) -> String {
    let ev = r.evaluation;
    let sc = r.scene;
    let mut o = String::new();
    let mut line = |s: String| {
        o.push_str(&s);
        o.push('\n');
    };
    line(format!("wearopt eval — {}", r.name));
    line(String::new());
    line("Scene".into());
    let body_b = if sc.youngs_modulus_b.is_infinite() {
        "rigid".to_string()
    } else {
        format!(
            "E2 = {}, ν2 = {}",
            si(sc.youngs_modulus_b, "Pa", 3),
            sig(sc.poisson_ratio_b, 3)
        )
    };
    line(format!(
        "  rough body a: E1 = {}, ν1 = {}; counterface b: {}; equivalent modulus E = {}",
        si(sc.youngs_modulus_a, "Pa", 3),
        sig(sc.poisson_ratio_a, 3),
        body_b,
        si(ev.equivalent_modulus, "Pa", 4)
    ));
    line(format!(
        "  hardness H = {}, work of adhesion γ = {}",
        if sc.hardness.is_infinite() {
            "∞ (no plasticity)".to_string()
        } else {
            si(sc.hardness, "Pa", 3)
        },
        if sc.work_of_adhesion == 0.0 {
            "0 (no adhesion)".to_string()
        } else {
            si(sc.work_of_adhesion, "J/m²", 3)
        }
    ));
    line(format!("  asperity law: {}", law_words(ev, sc)));
    line(format!(
        "  roughness σ = {}, asperity radius R = {}, asperity density N = {}",
        si(sc.sigma, "m", 3),
        si(sc.asperity_radius, "m", 3),
        si(sc.asperity_density, "m⁻²", 3)
    ));
    for l in r.scan.map(super::roughness::scan_lines).unwrap_or_default() {
        line(l);
    }
    // Under a law that computes its own coefficient the file's k is not read.
    let wear_word = match sc.wear_law {
        crate::model::WearModel::Archard => {
            format!("wear coefficient k = {}", sig_exp(sc.wear_coefficient, 3))
        }
        law => format!("{} wear law", law.law().label()),
    };
    line(format!(
        "  load W = {} on nominal area {}, sliding {}, {wear_word}, wearing area: {}",
        si(sc.load, "N", 3),
        si(sc.nominal_area, "m²", 4),
        si(sc.sliding_distance, "m", 3),
        match sc.wear_area {
            WearArea::Total => "all contacts",
            WearArea::Plastic => "plastic junctions only",
        }
    ));
    for n in super::words::input_notes(r.input_notes) {
        line(format!("  note: {n}"));
    }
    line(String::new());
    line("Indices and regime".into());
    let i = &ev.indices;
    line(format!(
        "  elastic adhesion index θ = {}   (≤ 10: adhesion matters)",
        sig_exp(i.elastic_adhesion_index, 4)
    ));
    line(format!(
        "  plastic adhesion index λ = {}   (≤ 0.125: adhesion matters)",
        sig_exp(i.plastic_adhesion_index, 4)
    ));
    line(format!(
        "  plasticity index ψ       = {}   ({})",
        sig_exp(i.plasticity_index, 4),
        ev.regime.deformation
    ));
    line(format!(
        "  Tabor parameter φ0       = {}   (regime: {})",
        sig_exp(i.tabor_parameter, 4),
        ev.regime.adhesion_model
    ));
    line(format!(
        "  critical interference Δc·σ = {}",
        si(ev.critical_interference, "m", 4)
    ));
    for w in super::words::warnings(ev) {
        line(format!("  WARNING: {w}"));
    }
    for n in super::words::notes(ev) {
        line(format!("  note: {n}"));
    }
    line(String::new());
    line(format!("Contact (status: {})", ev.status.as_str()));
    match ev.separation {
        Some(d) => line(format!(
            "  separation d = {}  (h = d/σ = {})",
            si(d, "m", 5),
            sig(ev.nondimensional_separation.unwrap_or(f64::NAN), 6)
        )),
        None => line("  separation: none — the surfaces are apart".into()),
    }
    line(format!(
        "  real area A_r = {}  ({} of nominal; 10^{} m²){}",
        si(ev.real_area, "m²", 4),
        sig_exp(ev.real_area_fraction, 3),
        sig(ev.log10_real_area, 5),
        if sc.real_area_scale != 1.0 {
            format!(
                "  — the statistical model's × {} (bem_corrected)",
                sig(sc.real_area_scale, 4)
            )
        } else {
            String::new()
        }
    ));
    let plastic_share = ev.plastic_real_area <= NEGLIGIBLE * ev.real_area;
    line(format!(
        "    elastic contacts {}   plastic junctions {}{}",
        part(
            ev.elastic_real_area,
            ev.real_area,
            si(ev.elastic_real_area, "m²", 4)
        ),
        part(
            ev.plastic_real_area,
            ev.real_area,
            si(ev.plastic_real_area, "m²", 4)
        ),
        if plastic_share {
            String::new()
        } else {
            format!(
                "  (plastic fraction {})",
                sig_exp(ev.plastic_area_fraction, 3)
            )
        }
    ));
    if let Some(c) = r.scan_contact {
        for l in scan_contact_lines(c, r.scene.real_area_scale != 1.0) {
            line(l);
        }
    }
    line(format!(
        "  contacts: {} in all; plastic: {}",
        sig_exp(ev.contact_count, 4),
        part(
            ev.plastic_contact_count,
            ev.contact_count,
            sig_exp(ev.plastic_contact_count, 4)
        )
    ));
    if let Some(p) = ev.mean_real_pressure {
        line(format!(
            "  mean real pressure W/A_r = {}{}",
            si(p, "Pa", 4),
            pressure_note(ev, p, sc.hardness)
        ));
    }
    let carried =
        ev.elastic_load.abs() + ev.plastic_load.abs() + ev.noncontact_load.map_or(0.0, f64::abs);
    let elastic = part(ev.elastic_load, carried, si(ev.elastic_load, "N", 4));
    let plastic = part(ev.plastic_load, carried, si(ev.plastic_load, "N", 4));
    match ev.noncontact_load {
        Some(nc) if ev.adhesion_model.law().attracts_out_of_contact() => line(format!(
            "  load carried: elastic {elastic}, plastic {plastic}, attracted asperities not in contact {}",
            si(nc, "N", 4)
        )),
        _ => line(format!("  load carried: elastic {elastic}, plastic {plastic}")),
    }
    match (ev.pull_off_force, ev.log10_pull_off_force) {
        (Some(f), Some(l)) => line(format!(
            "  pull-off force {} (10^{} N) at d = {}; one asperity ({}): {}",
            si(f, "N", 4),
            // Five significant digits would round 10^-310658.7 to 10^-310660.
            if l.abs() < 1e4 {
                sig(l, 5)
            } else {
                format!("{l:.1}")
            },
            ev.pull_off_separation.map_or("-".into(), |d| si(d, "m", 4)),
            {
                let law = ev.stand_in_model.unwrap_or(ev.adhesion_model).law();
                match law.closed_form_pull_off() {
                    Some(c) => format!("{} {c}πγR", law.label()),
                    None => format!(
                        "{} {}πγR",
                        law.title(),
                        sig(
                            1.5 * ev.law_asperity_pull_off_force / ev.asperity_pull_off_force,
                            4
                        )
                    ),
                }
            },
            si(ev.law_asperity_pull_off_force, "N", 3)
        )),
        (Some(f), None) => line(format!("  pull-off force {} (no adhesion)", si(f, "N", 3))),
        // γ > 0 but no pull-off: a warning above says why.
        (None, _) if ev.asperity_pull_off_force > 0.0 => {
            line("  pull-off force: none reported (see the warning above)".to_string())
        }
        _ => {}
    }
    if let Some(om) = &ev.other_model {
        line(format!(
            "  under the {} law, valid in this transition: {}",
            om.adhesion_model.label(),
            match om.nondimensional_separation {
                Some(h) => format!(
                    "h = {}, real area {}, pull-off force {}, wear rate {}",
                    sig(h, 6),
                    si(om.real_area, "m²", 4),
                    om.pull_off_force.map_or("-".into(), |f| si(f, "N", 4)),
                    si(om.wear_rate, "m³/m", 4)
                ),
                None => format!(
                    "{} (no contact under this load), pull-off force {}",
                    om.status.as_str(),
                    om.pull_off_force.map_or("-".into(), |f| si(f, "N", 4))
                ),
            }
        ));
    }
    if let Some(hum) = &ev.humidity {
        line(String::new());
        line("Humid air (capillary adhesion)".into());
        for [label, value] in humidity_rows(hum) {
            line(format!("  {label}: {value}"));
        }
        if let Some(r) = sc.environment.and_then(|e| e.humidity_range) {
            line(format!(
                "  the file's study holds its limits over RH {}–{} % ({} humidities); this evaluation is at {} %",
                sig(100.0 * r.min, 4),
                sig(100.0 * r.max, 4),
                r.points,
                sig(100.0 * hum.relative_humidity, 4)
            ));
        }
    }
    line(String::new());
    let wear_law = sc.wear_law.law();
    line(format!(
        "Wear ({}, {})",
        wear_law.label(),
        wear_law.formula()
    ));
    for l in wear_law_lines(sc, ev) {
        line(format!("  {l}"));
    }
    line(format!(
        "  wear volume V = {} over {}",
        si(ev.wear_volume, "m³", 4),
        si(sc.sliding_distance, "m", 3)
    ));
    if ev.log10_wear_rate.is_finite() && ev.wear_rate == 0.0 {
        // Too small for a double: the logarithm is the number.
        line(format!(
            "  wear rate V/L = 10^{} m³/m  (negligible: below the smallest number a double holds; {})",
            sig(ev.log10_wear_rate, 5),
            super::tiny_wear_reason(sc)
        ));
    } else if ev.log10_wear_rate.is_finite() {
        line(format!(
            "  wear rate V/L = {}  (10^{} m³/m)",
            si(ev.wear_rate, "m³/m", 4),
            sig(ev.log10_wear_rate, 5)
        ));
    } else {
        // No wearing area at all (its logarithm is -∞).
        let why = super::zero_wear_reason(sc);
        line(format!(
            "  wear rate V/L = {}  (zero: {why})",
            si(ev.wear_rate, "m³/m", 4)
        ));
    }
    line(format!(
        "  wear depth rate V/(A_n L) = {} per m slid ({} per km)",
        si(ev.wear_depth_rate, "m", 4),
        si(ev.wear_depth_rate * 1e3, "m", 4)
    ));
    let req = &sc.requirements;
    if let Some(depth) = req.allowed_wear_depth {
        match (ev.life_sliding_distance, ev.life_cycles) {
            (Some(l), Some(n)) => line(format!(
                "  life: wears {} deep after {} cycles ({} of sliding at {} per cycle)",
                si(depth, "m", 3),
                sig_exp(n, 3),
                si(l, "m", 3),
                si(req.sliding_per_cycle.unwrap_or(f64::NAN), "m", 3)
            )),
            (Some(l), None) => line(format!(
                "  life: wears {} deep after {} of sliding (give contact.sliding_per_cycle for cycles)",
                si(depth, "m", 3),
                si(l, "m", 3)
            )),
            _ => line(format!(
                "  life: no wear at this load, so the allowed {} is never reached",
                si(depth, "m", 3)
            )),
        }
    }
    if let Some(st) = &ev.stiction {
        line(String::new());
        line("Stiction".into());
        line(format!(
            "  pull-off force {} against restoring force {}: margin {} → {}",
            si(st.pull_off_force, "N", 4),
            si(st.restoring_force, "N", 4),
            sig_exp(st.margin, 3),
            verdict_words(st.verdict)
        ));
        line(format!("  adhesion law: {}", law_words(ev, sc)));
        if let Some(hum) = ev.humidity.filter(|h| h.kelvin_radius.is_some()) {
            line(format!(
                "  the pull-off force includes the capillary pull of the liquid at RH = {} % (the dry-air force: `wearopt humidity` at RH 0)",
                sig(100.0 * hum.relative_humidity, 4)
            ));
        }
        let phi = ev.indices.tabor_parameter;
        if let Some((law, o)) = other_stiction(ev) {
            line(format!(
                "  under the {} law instead: pull-off force {}, margin {} → {}",
                law.label(),
                si(o.pull_off_force, "N", 4),
                sig_exp(o.margin, 3),
                verdict_words(o.verdict)
            ));
            line(format!(
                "  φ0 = {} lies in the JKR–DMT transition (0.3–3), where {} is not exact and the {} law is ({}){}",
                sig_exp(phi, 3),
                ev.adhesion_model.label(),
                law.label(),
                law.law().section(),
                if o.verdict == st.verdict {
                    "; both give the same verdict".to_string()
                } else {
                    format!("; they DISAGREE: trust the {} verdict", law.label())
                }
            ));
        } else if let Some(general) = ev.adhesion_model.bracket(phi) {
            line(format!(
                "  φ0 = {} lies in the JKR–DMT transition (0.3–3), where {} is not exact: judge stiction under adhesion_model = \"{}\" ({})",
                sig_exp(phi, 3),
                ev.adhesion_model.label(),
                general.as_str(),
                general.law().section()
            ));
        } else if let Some(limit) =
            (phi > 0.0 && phi < TRANSITION_TABOR.0 && phi < ev.adhesion_model.valid_tabor().0)
                .then(|| AdhesionModel::valid_at(phi).find(|m| !m.law().general()))
                .flatten()
        {
            line(format!(
                "  φ0 = {} < {}: the {} law applies, and the {} verdict above understates adhesion ({})",
                sig_exp(phi, 3),
                TRANSITION_TABOR.0,
                limit.label(),
                ev.adhesion_model.label(),
                limit.law().section()
            ));
        }
    }
    if let (Some(f), Some(tau)) = (ev.friction_force, req.shear_strength) {
        line(String::new());
        line("Friction (Bowden–Tabor, F = τ A_r)".into());
        line(format!(
            "  friction force F = {} with junction shear strength τ = {}{}",
            si(f, "N", 4),
            si(tau, "Pa", 3),
            ev.friction_coefficient.map_or(String::new(), |mu| format!(
                "; friction coefficient F/W = {}",
                sig_exp(mu, 3)
            ))
        ));
    }
    if let Some(d) = &ev.debris {
        line(String::new());
        line(
            "Debris or smoothing (Aghababaei et al. 2016, d* = Λ w G / τ²; docs/model.md §13)"
                .into(),
        );
        line(format!(
            "  critical junction size d* = {} (Λ = {}, G = {} of body a)",
            si(d.critical_junction_size, "m", 4),
            crate::units::format_number(d.debris_shape_factor),
            si(d.shear_modulus, "Pa", 4)
        ));
        if let (Some(c), Some(a), Some(m)) = (
            d.debris_contact_fraction,
            d.debris_area_fraction,
            d.wear_mechanism,
        ) {
            line(format!(
                "  contacts wider than d*: {} of the contacts, {} of the real area → wear mechanism: {}",
                sig_exp(c, 3),
                sig_exp(a, 3),
                m.as_str()
            ));
        }
    }
    if !r.sensitivities.is_empty() {
        line(String::new());
        line(
            "Sensitivity of wear rate: elasticity d ln(wear) / d ln x (central differences at δ = 1e-3 and 2e-3 in ln x, Richardson-extrapolated; ± its error estimate)".into(),
        );
        for s in r.sensitivities {
            let name = s.parameter.as_str();
            match (s.elasticity, s.error) {
                (Some(e), Some(err)) => {
                    line(format!("  {name:<17} {:>+12.6}  ± {}", e, sig_exp(err, 2)))
                }
                _ => line(format!("  {name:<17} {:>12}  ({})", "—", gap(s))),
            }
        }
    }
    o
}

/// Why a sensitivity has no value, in words ("" when it has one).
fn gap(s: &crate::model::Sensitivity) -> &'static str {
    s.note.map_or("", super::words::sensitivity_gap)
}

/// The exact contact on the scene's scan in words: the like-for-like comparison
/// (both without adhesion) and what it means for this report's real area and wear.
pub(crate) fn scan_contact_lines(
    c: &Result<crate::app::contact::ScanContact, String>,
    corrected: bool,
) -> Vec<String> {
    let c = match c {
        Ok(c) => c,
        Err(reason) => {
            return vec![format!(
                "  on the scan itself: no exact contact solved ({reason})"
            )]
        }
    };
    let s = &c.solution;
    let mut out = vec![format!(
        "  on the scan itself (exact contact, FFT boundary elements on its {} × {} map at the nominal pressure {}, no adhesion): real area {} of nominal in {} patches; the statistical model on the same terms gives {}",
        c.pixels[0],
        c.pixels[1],
        si(c.pressure, "Pa", 3),
        sig_exp(s.real_area_fraction, 3),
        s.contact_patches,
        sig_exp(c.statistical.real_area_fraction, 3)
    )];
    if s.outcome != crate::contact::Outcome::Converged {
        out.push(format!(
            "  WARNING: the exact contact stopped at its iteration limit (residual {}): its area is the last iterate's",
            sig_exp(s.residual, 2)
        ));
    }
    if let Some(ratio) = c.area_ratio() {
        let words = if corrected {
            "this report's real area, wear and friction are the statistical model's divided by it (contact_model = \"bem_corrected\")"
        } else if ratio < 0.95 {
            "the statistical model's real area, and so this report's wear, is low by that factor"
        } else if ratio > 1.05 {
            "the statistical model's real area, and so this report's wear, is high by that factor"
        } else {
            "the two agree within 5 %"
        };
        out.push(format!(
            "    area ratio statistical / exact = {}: {words}",
            sig(ratio, 3)
        ));
    }
    let pixels = s.real_area_fraction * (c.pixels[0] * c.pixels[1]) as f64;
    if s.contact_patches > 0 && pixels < 20.0 * s.contact_patches as f64 {
        out.push(format!(
            "    note: {} contacting pixels in {} patches: the exact area is resolution-limited at this pressure (a finer scan would give a smaller one)",
            pixels.round(),
            s.contact_patches
        ));
    }
    out
}

/// Parts below this share of their whole are called negligible in words.
const NEGLIGIBLE: f64 = 1e-12;

/// `shown` (a part of `whole`, in its unit), or in words where it is a
/// negligible share of it: "none" at zero, else "negligible (share of the
/// total)" — a number like 3.6e-197 m² beside µm² values stands for none.
fn part(value: f64, whole: f64, shown: String) -> String {
    if value == 0.0 && whole > 0.0 {
        "none".to_string()
    } else if whole > 0.0 && value.abs() <= NEGLIGIBLE * whole {
        format!("negligible ({} of the total)", sig_exp(value / whole, 1))
    } else {
        shown
    }
}

#[cfg(test)]
mod load_curve_tests {
    use super::*;
    use crate::model::LoadCurve;

    /// A pull-off beyond the sampled curve is not marked, and the flat tail past the
    /// operating point is cut to three times its distance from the start.
    #[test]
    fn a_far_pull_off_is_not_marked_and_the_tail_is_cut() {
        let points: Vec<(f64, f64)> = (0..=400)
            .map(|i| {
                let d = 1e-9 + 1e-10 * i as f64;
                (d, 1e-3 * (-(d - 1e-9) / 1e-9).exp())
            })
            .collect();
        let c = LoadCurve {
            points: points.clone(),
            operating_point: Some((2e-9, 1e-3 * (-1.0f64).exp())),
            pull_off_point: Some((450e-9, -1e-30)),
        };
        let svg = load_curve_svg("t", &c);
        assert!(!svg.contains(">pull-off<"), "{svg}");
        // d runs 1 … 41 nm; the page shows 1 … 5 nm (operating point at 2 nm).
        assert!(
            svg.contains(">5</text>") && !svg.contains(">40</text>"),
            "{svg}"
        );
        assert!(load_curve_caption("W", &c).contains("far beyond the drawn range"));
        // On the curve it is marked and nothing is cut.
        let c = LoadCurve {
            points,
            operating_point: Some((2e-9, 1e-3 * (-1.0f64).exp())),
            pull_off_point: Some((30e-9, -1e-6)),
        };
        let svg = load_curve_svg("t", &c);
        assert!(
            svg.contains(">pull-off<") && svg.contains(">40</text>"),
            "{svg}"
        );
        assert!(load_curve_caption("W", &c).contains("the most tensile load"));
        // A pull-off of 1 µN against 1 mN at the start gets its own, enlarged
        // plot, labelled; one of a third of the largest load does not need it.
        let svg = load_curve_tension_svg("t", &c).unwrap();
        assert!(svg.contains("pull-off 1 µN at d = 30 nm"), "{svg}");
        let big = LoadCurve {
            pull_off_point: Some((30e-9, -3e-4)),
            ..c
        };
        assert!(load_curve_tension_svg("t", &big).is_none());
    }
}
