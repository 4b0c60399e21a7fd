//! `wearopt._wearopt`: the compiled half of the Python package `wearopt`.
//!
//! An adapter, as the command line is: each function turns keyword arguments into
//! the options of one `wearopt::app` function, calls it, and hands the document to
//! the report stage for the JSON `wearopt … --format json` writes. A Python result
//! and the command line's JSON therefore agree to the last digit by construction.
//! Errors are worded in keyword arguments (`points=1: must lie in 2..=200`), never
//! in flags. The Python half (`python/wearopt/__init__.py`) turns the JSON into
//! dicts and the arrays into numpy shapes. The GIL is released while the model runs.

use numpy::{IntoPyArray, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use wearopt::app::curve::LawOptions;
use wearopt::app::fit_adhesion::{FitAdhesionOptions, FrictionCoefficient, Modulus};
use wearopt::app::pareto::{ParetoOptions, Silent};
use wearopt::app::quantity::OptionQuantity;
use wearopt::app::roughness::RoughnessOptions;
use wearopt::app::sweep::SweepOptions;
use wearopt::app::{self, AppError, OptionName, Problem, Vocabulary};
use wearopt::report;

fn value_error(message: impl Into<String>) -> PyErr {
    PyValueError::new_err(message.into())
}

/// An application error in Python's words.
fn words(e: AppError) -> String {
    e.message(Vocabulary::Keywords)
}

/// Where a problem comes from: a file path, or a dict sent as JSON text.
fn load(source: &str, is_path: bool) -> Result<(Problem, String), String> {
    if is_path {
        let problem = app::load(std::path::Path::new(source)).map_err(|e| e.to_string())?;
        Ok((problem, source.to_string()))
    } else {
        let origin = "<problem dict>";
        let value: serde_json::Value = serde_json::from_str(source)
            .map_err(|e| format!("{origin}: not a JSON-compatible dict: {e}"))?;
        let text = toml::to_string(&value).map_err(|e| {
            format!("{origin}: cannot be written as a problem file ({e}); values must be strings, numbers, booleans, lists or dicts (no None)")
        })?;
        // Line numbers would point into the generated TOML, not at anything the
        // caller wrote: the dotted key names the place instead.
        let problem = app::parse(&text, origin).map_err(|e| {
            let message = e.to_string();
            match message
                .strip_prefix(origin)
                .and_then(|rest| rest.strip_prefix(':'))
            {
                Some(rest) if rest.starts_with(|c: char| c.is_ascii_digit()) => {
                    format!(
                        "{origin}{}",
                        rest.trim_start_matches(|c: char| c.is_ascii_digit())
                    )
                }
                _ => message,
            }
        })?;
        Ok((problem, origin.to_string()))
    }
}

/// [`load`], and the problem-file text the problem was parsed from (a dict's:
/// the TOML it was turned into).
fn load_with_text(source: &str, is_path: bool) -> Result<(Problem, String, String), String> {
    if is_path {
        let (problem, origin) = load(source, true)?;
        let text = std::fs::read_to_string(source).map_err(|e| format!("{source}: {e}"))?;
        Ok((problem, origin, text))
    } else {
        let value: serde_json::Value = serde_json::from_str(source)
            .map_err(|e| format!("<problem dict>: not a JSON-compatible dict: {e}"))?;
        let (problem, origin) = load(source, false)?;
        let text = toml::to_string(&value).map_err(|e| e.to_string())?;
        Ok((problem, origin, text))
    }
}

/// Runs `f` without the GIL; its error becomes a `ValueError`.
fn detached<T: Send>(py: Python<'_>, f: impl FnOnce() -> Result<T, String> + Send) -> PyResult<T> {
    py.detach(f).map_err(value_error)
}

/// Runs `f` on a thread of its own while this one, without the GIL, wakes every
/// 100 ms to let Python handle its signals: Ctrl-C raises `KeyboardInterrupt` at
/// once (under [`detached`] it arrived only when the call returned, seconds to
/// minutes later). The abandoned work finishes on its thread and is dropped: the
/// solvers have no point to stop at, and nothing it holds is shared.
fn interruptible<T: Send + 'static>(
    py: Python<'_>,
    f: impl FnOnce() -> Result<T, String> + Send + 'static,
) -> PyResult<T> {
    let (sender, receiver) = std::sync::mpsc::channel();
    std::thread::Builder::new()
        .name("wearopt-contact".into())
        .spawn(move || {
            // A receiver gone (the call was interrupted) leaves nothing to tell.
            let _ = sender.send(f());
        })
        .map_err(|e| value_error(format!("cannot start the solve's thread: {e}")))?;
    let mut receiver = receiver;
    loop {
        // The receiver goes to the GIL-free wait and comes back (it is Send, not Sync).
        let (got, back) = py.detach(move || {
            let got = receiver.recv_timeout(std::time::Duration::from_millis(100));
            (got, receiver)
        });
        receiver = back;
        match got {
            Ok(result) => return result.map_err(value_error),
            Err(std::sync::mpsc::RecvTimeoutError::Timeout) => py.check_signals()?,
            Err(std::sync::mpsc::RecvTimeoutError::Disconnected) => {
                return Err(value_error(
                    "the solve's thread ended without a result (a bug: please report it)"
                        .to_string(),
                ))
            }
        }
    }
}

/// `wearopt eval FILE --format json`.
#[pyfunction]
fn evaluate_json(py: Python<'_>, source: String, is_path: bool) -> PyResult<String> {
    detached(py, || {
        let (problem, origin) = load(&source, is_path)?;
        let doc = app::eval::eval(&problem, &origin, &Default::default()).map_err(words)?;
        Ok(report::eval::json_document(&doc).to_string())
    })
}

/// `wearopt optimize FILE --format json` (a ranking when `[design]` lists materials).
#[pyfunction]
fn optimize_json(py: Python<'_>, source: String, is_path: bool) -> PyResult<String> {
    detached(py, || {
        let (problem, origin) = load(&source, is_path)?;
        let doc = app::optimize::optimize(&problem, &origin, Default::default()).map_err(words)?;
        Ok(report::optimize::json_document(&doc).to_string())
    })
}

/// `wearopt pareto FILE [--points N] [--adhesion M] [--direction D] --format json`.
#[pyfunction]
#[pyo3(signature = (source, is_path, points=None, adhesion=None, direction=None))]
fn pareto_json(
    py: Python<'_>,
    source: String,
    is_path: bool,
    points: Option<usize>,
    adhesion: Option<String>,
    direction: Option<String>,
) -> PyResult<String> {
    detached(py, || {
        let (problem, origin) = load(&source, is_path)?;
        // A front against a probability ([pareto] event): its own document.
        if problem.robust.front.is_some() {
            if let Some((name, value)) = adhesion
                .as_ref()
                .map(|v| ("adhesion", v))
                .or(direction.as_ref().map(|v| ("direction", v)))
            {
                return Err(words(AppError::Invalid {
                    options: vec![(OptionName(name), value.clone())],
                    rule: format!(
                        "{origin} draws a front against the probability of an event ([pareto] event): its second axis is that probability, the low end preferred; leave {name} out"
                    ),
                }));
            }
            let doc = app::robust_front::event_front(&problem, &origin, points, &mut |_| {})
                .map_err(words)?;
            return Ok(report::robust_front::json_value(&doc).to_string());
        }
        let options = ParetoOptions {
            points,
            constraint_values: false,
            adhesion: adhesion
                .as_deref()
                .map(|t| app::pareto::measure(OptionName("adhesion"), t))
                .transpose()
                .map_err(words)?,
            direction: direction
                .as_deref()
                .map(|t| app::pareto::direction(OptionName("direction"), t))
                .transpose()
                .map_err(words)?,
        };
        // A robust study against an adhesion measure: one robust optimum per level.
        if problem.robust.is_robust() {
            let doc = app::robust_adhesion_front::adhesion_front(
                &problem,
                &origin,
                &options,
                &mut |_| {},
            )
            .map_err(words)?;
            return Ok(report::robust_adhesion_front::json_value(&doc).to_string());
        }
        let doc = app::pareto::pareto(&problem, &origin, &options, &Silent).map_err(words)?;
        Ok(report::pareto::json_document(&doc).to_string())
    })
}

/// `wearopt humidity FILE --from RH0 --to RH1 --points N --format json`.
#[pyfunction]
#[pyo3(signature = (source, is_path, from_, to, points))]
fn humidity_json(
    py: Python<'_>,
    source: String,
    is_path: bool,
    from_: String,
    to: String,
    points: usize,
) -> PyResult<String> {
    detached(py, || {
        let options = app::humidity::HumidityOptions {
            from: app::humidity::relative_humidity(OptionName("from"), &from_).map_err(words)?,
            to: app::humidity::relative_humidity(OptionName("to"), &to).map_err(words)?,
            points,
        };
        options.validate().map_err(words)?;
        let (problem, origin) = load(&source, is_path)?;
        let doc = app::humidity::humidity(&problem, &origin, &options).map_err(words)?;
        Ok(report::humidity::json(&doc))
    })
}

/// `wearopt uncertainty FILE --method M [--samples N] [--seed S] --format json`.
#[pyfunction]
#[pyo3(signature = (source, is_path, method, samples, seed))]
fn uncertainty_json(
    py: Python<'_>,
    source: String,
    is_path: bool,
    method: String,
    samples: Option<u64>,
    seed: Option<u64>,
) -> PyResult<String> {
    detached(py, || {
        let method = app::uncertainty::method(app::OptionName("method"), &method).map_err(words)?;
        let (problem, origin) = load(&source, is_path)?;
        let doc = app::uncertainty::uncertainty(
            &problem,
            &origin,
            &app::uncertainty::UncertaintyOptions {
                method,
                samples,
                seed,
            },
            &app::Quiet,
        )
        .map_err(words)?;
        Ok(report::uncertainty::json(&doc))
    })
}

/// `wearopt uncertainty FILE --method M [--samples N] [--seed S] --shard I/N`:
/// the part's JSON. A dict's problem travels in the part as the problem-file
/// text it was turned into.
#[pyfunction]
#[pyo3(signature = (source, is_path, method, samples, seed, shard_index, shard_count))]
#[allow(clippy::too_many_arguments)]
fn uncertainty_part_json(
    py: Python<'_>,
    source: String,
    is_path: bool,
    method: String,
    samples: Option<u64>,
    seed: Option<u64>,
    shard_index: u64,
    shard_count: u64,
) -> PyResult<String> {
    detached(py, || {
        let method = app::uncertainty::method(app::OptionName("method"), &method).map_err(words)?;
        let shard = app::sweep::shard(shard_index, shard_count).map_err(words)?;
        let (problem, origin, text) = load_with_text(&source, is_path)?;
        let part = app::uncertainty::uncertainty_part(
            &problem,
            &origin,
            &text,
            &app::uncertainty::UncertaintyOptions {
                method,
                samples,
                seed,
            },
            shard,
            &app::Quiet,
        )
        .map_err(words)?;
        Ok(report::uncertainty::part_json(&part))
    })
}

/// Whether `text` is an uncertainty part (else a sweep's output).
#[pyfunction]
fn is_uncertainty_part(text: &str) -> bool {
    report::uncertainty::is_part(text)
}

/// `wearopt merge PARTS --format json` of uncertainty parts held in memory: the
/// unsharded run's JSON. Errors name the part by its position.
#[pyfunction]
#[pyo3(signature = (parts, samples=None))]
fn merge_uncertainty_json(
    py: Python<'_>,
    parts: Vec<String>,
    samples: Option<u64>,
) -> PyResult<String> {
    detached(py, || {
        let parts = parts
            .iter()
            .enumerate()
            .map(|(i, text)| {
                report::uncertainty::parse_part(text)
                    .map(|p| (format!("part {i}"), p))
                    .map_err(|e| format!("part {i}: {e}"))
            })
            .collect::<Result<Vec<_>, _>>()?;
        let doc = app::uncertainty::merge(parts, samples).map_err(words)?;
        Ok(report::uncertainty::json(&doc))
    })
}

/// `wearopt asperity --tabor MU --from D0 --to D1 --points N --adhesion-model LAW --format json`
/// (or the sphere in SI instead of μ: `--radius … --work-of-adhesion … --modulus …
/// --interatomic-distance …`; `--fast`).
#[pyfunction]
#[pyo3(signature = (tabor, from_, to, points, adhesion_model, radius, work_of_adhesion, modulus, interatomic_distance, fast))]
#[allow(clippy::too_many_arguments)]
fn asperity_json(
    py: Python<'_>,
    tabor: Option<f64>,
    from_: f64,
    to: f64,
    points: usize,
    adhesion_model: String,
    radius: Option<String>,
    work_of_adhesion: Option<String>,
    modulus: Option<String>,
    interatomic_distance: Option<String>,
    fast: Option<bool>,
) -> PyResult<String> {
    detached(py, || {
        let law = app::asperity::law(&adhesion_model).map_err(words)?;
        let (tabor, sphere) = app::asperity::tabor_or_sphere(
            tabor,
            [
                radius.as_deref(),
                work_of_adhesion.as_deref(),
                modulus.as_deref(),
                interatomic_distance.as_deref(),
            ],
        )
        .map_err(words)?;
        let doc = app::asperity::asperity(&app::asperity::AsperityOptions {
            tabor,
            from: from_,
            to,
            points,
            law,
            rows: app::asperity::rows_for(tabor, fast),
            sphere,
        })
        .map_err(words)?;
        Ok(report::asperity::json(&doc))
    })
}

/// The asperity law of `curve`'s keyword arguments.
fn law(
    adhesion_model: &str,
    attraction: Option<&str>,
    attraction_range: Option<f64>,
) -> Result<LawOptions, AppError> {
    Ok(LawOptions {
        adhesion_model: app::curve::adhesion_model(OptionName("adhesion_model"), adhesion_model)?,
        attraction: attraction
            .map(|a| app::curve::attraction(OptionName("attraction"), a))
            .transpose()?,
        attraction_range,
    })
}

/// The columns of `wearopt curve` at each (θ, λ, c_h, h) of four equally long
/// arrays (the Python side broadcasts them).
#[pyfunction]
#[pyo3(signature = (theta, lam, hardness_coefficient, h, adhesion_model="jkr".to_string(), attraction=None, attraction_range=None))]
#[allow(clippy::too_many_arguments)]
fn curve_arrays<'py>(
    py: Python<'py>,
    theta: PyReadonlyArray1<'py, f64>,
    lam: PyReadonlyArray1<'py, f64>,
    hardness_coefficient: PyReadonlyArray1<'py, f64>,
    h: PyReadonlyArray1<'py, f64>,
    adhesion_model: String,
    attraction: Option<String>,
    attraction_range: Option<f64>,
) -> PyResult<Bound<'py, PyDict>> {
    let law = law(&adhesion_model, attraction.as_deref(), attraction_range)
        .map_err(|e| value_error(words(e)))?;
    let slice = |a: &PyReadonlyArray1<'py, f64>| -> PyResult<Vec<f64>> {
        Ok(a.as_slice()
            .map_err(|e| value_error(e.to_string()))?
            .to_vec())
    };
    let (theta, lam, c_h, h) = (
        slice(&theta)?,
        slice(&lam)?,
        slice(&hardness_coefficient)?,
        slice(&h)?,
    );
    let rows = detached(py, || {
        app::curve::curve_at(&theta, &lam, &c_h, &h, &law).map_err(words)
    })?;
    let column = |f: fn(&app::curve::CurveRow) -> f64| rows.iter().map(f).collect::<Vec<f64>>();
    let out = PyDict::new(py);
    out.set_item("h", h.into_pyarray(py))?;
    out.set_item("load", column(|r| r.load).into_pyarray(py))?;
    out.set_item("area", column(|r| r.area).into_pyarray(py))?;
    out.set_item("plastic_area", column(|r| r.plastic_area).into_pyarray(py))?;
    out.set_item(
        "critical_interference",
        column(|r| r.critical_interference).into_pyarray(py),
    )?;
    out.set_item("dload_dh", column(|r| r.dload_dh).into_pyarray(py))?;
    out.set_item(
        "noncontact_load",
        column(|r| r.noncontact_load).into_pyarray(py),
    )?;
    Ok(out)
}

/// `wearopt sweep FILE --samples N --method M --seed S [--shard I/N] --format F`,
/// the whole output as text.
#[pyfunction]
#[pyo3(signature = (source, is_path, samples, method, seed, shard_index, shard_count, format))]
#[allow(clippy::too_many_arguments)]
fn sweep_text(
    py: Python<'_>,
    source: String,
    is_path: bool,
    samples: u64,
    method: String,
    seed: u64,
    shard_index: u64,
    shard_count: u64,
    format: String,
) -> PyResult<String> {
    detached(py, || {
        let (problem, origin) = load(&source, is_path)?;
        let method = app::sweep::method(OptionName("method"), &method).map_err(words)?;
        let format = match format.as_str() {
            "csv" => report::sweep::Encoding::Csv,
            "json" => report::sweep::Encoding::Json,
            other => return Err(format!("format={other:?}: expected \"csv\" or \"json\"")),
        };
        let options = SweepOptions {
            samples,
            method,
            seed,
        };
        // The sweep is checked before the shard, as the command line does.
        let plan = app::sweep::plan(&problem, &origin, &options).map_err(words)?;
        let shard = app::sweep::shard(shard_index, shard_count).map_err(words)?;
        let plan = plan.part(shard);
        // The problem's content for the fingerprint, as the command line reads it.
        let bytes = if is_path {
            std::fs::read(&source).unwrap_or_default()
        } else {
            source.clone().into_bytes()
        };
        let bytes = app::sweep::fingerprint_content(&problem, &bytes);
        let mut text = report::sweep::head(
            format,
            &report::sweep::Head {
                name: &plan.name,
                sweep: &plan.sweep,
                problem: &bytes,
                shard,
            },
        );
        let mut first = true;
        plan.run(|rows| {
            for r in rows {
                text.push_str(&report::sweep::row(format, &plan.sweep, r, first));
                first = false;
            }
            Ok::<(), String>(())
        })?;
        text.push_str(report::sweep::tail(format));
        Ok(text)
    })
}

/// `wearopt merge` of parts held in memory.
#[pyfunction]
#[pyo3(signature = (parts, samples=None))]
fn merge_text(py: Python<'_>, parts: Vec<String>, samples: Option<u64>) -> PyResult<String> {
    detached(py, || {
        let texts: Vec<&str> = parts.iter().map(String::as_str).collect();
        report::sweep::merge(&texts, samples).map_err(|(i, e)| match i {
            Some(i) => format!("part {i}: {e}"),
            None => format!("{} parts: {e}", parts.len()),
        })
    })
}

/// The roughness options of keyword arguments, checked in the command line's order:
/// pixel size, height unit, cut-off, level.
fn roughness_options(
    cutoff: Option<&str>,
    level: &str,
    pixel_size: Option<&str>,
    height_unit: Option<&str>,
) -> Result<RoughnessOptions, AppError> {
    use app::roughness::{height_unit as unit, length, levelling};
    let pixel_size = pixel_size
        .map(|t| length(OptionName("pixel_size"), t))
        .transpose()?;
    let height_unit = height_unit
        .map(|t| unit(OptionName("height_unit"), t))
        .transpose()?;
    let cutoff = cutoff
        .map(|t| length(OptionName("cutoff"), t))
        .transpose()?;
    Ok(RoughnessOptions {
        cutoff,
        level: levelling(OptionName("level"), level)?,
        pixel_size,
        height_unit,
        decimal_comma: false,
    })
}

/// `wearopt roughness FILE [--cutoff L] [--level K] [--pixel-size L] [--height-unit U] --format json`.
#[pyfunction]
#[pyo3(signature = (path, cutoff=None, level="plane".to_string(), pixel_size=None, height_unit=None, decimal_comma=false))]
fn roughness_json(
    py: Python<'_>,
    path: String,
    cutoff: Option<String>,
    level: String,
    pixel_size: Option<String>,
    height_unit: Option<String>,
    decimal_comma: bool,
) -> PyResult<String> {
    detached(py, || {
        let mut options = roughness_options(
            cutoff.as_deref(),
            &level,
            pixel_size.as_deref(),
            height_unit.as_deref(),
        )
        .map_err(words)?;
        options.decimal_comma = decimal_comma;
        let doc =
            app::roughness::roughness(std::path::Path::new(&path), &options).map_err(words)?;
        Ok(report::roughness::json_document(&doc).to_string())
    })
}

/// The roughness of heights in memory (a 2-D array, rows along y), as
/// `wearopt roughness` reports a scan.
#[pyfunction]
#[pyo3(signature = (heights, pixel_size, cutoff=None, level="plane".to_string(), height_unit=None))]
fn roughness_array_json(
    py: Python<'_>,
    heights: PyReadonlyArray2<'_, f64>,
    pixel_size: String,
    cutoff: Option<String>,
    level: String,
    height_unit: Option<String>,
) -> PyResult<String> {
    let array = heights.as_array();
    let (ny, nx) = array.dim();
    let values: Vec<f64> = array.iter().copied().collect();
    detached(py, || {
        let options = roughness_options(
            cutoff.as_deref(),
            &level,
            Some(&pixel_size),
            height_unit.as_deref(),
        )
        .map_err(words)?;
        let doc = app::roughness::roughness_of_heights("<height array>", nx, ny, values, &options)
            .map_err(words)?;
        Ok(report::roughness::json_document(&doc).to_string())
    })
}

/// The contact options of keyword arguments, checked in the command line's order.
#[allow(clippy::too_many_arguments)]
fn contact_options(
    modulus: &str,
    pressures: &[String],
    hardness: Option<&str>,
    level: &str,
    pixel_size: Option<&str>,
    height_unit: Option<&str>,
    tolerance: f64,
    fields: bool,
    adhesion: (Option<&str>, Option<&str>, bool),
) -> Result<app::contact::ContactOptions, AppError> {
    use app::contact::positive;
    use app::roughness::{height_unit as unit, length, levelling};
    let pixel_size = pixel_size
        .map(|t| length(OptionName("pixel_size"), t))
        .transpose()?;
    let height_unit = height_unit
        .map(|t| unit(OptionName("height_unit"), t))
        .transpose()?;
    let modulus = positive(OptionName("modulus"), modulus, OptionQuantity::Modulus)?;
    if pressures.is_empty() {
        return Err(AppError::Invalid {
            options: vec![(OptionName("pressures"), "[]".to_string())],
            rule: "give one or more mean pressures".to_string(),
        });
    }
    let pressures = pressures
        .iter()
        .map(|t| positive(OptionName("pressures"), t, OptionQuantity::MeanPressure))
        .collect::<Result<Vec<f64>, _>>()?;
    let hardness = hardness
        .map(|t| positive(OptionName("hardness"), t, OptionQuantity::Hardness))
        .transpose()?;
    let adhesion = match adhesion {
        (Some(w), Some(r), coarse_grain) => Some(app::contact::AdhesionOptions {
            work: positive(OptionName("work_of_adhesion"), w, OptionQuantity::WorkOfAdhesion)?,
            range: positive(OptionName("adhesion_range"), r, OptionQuantity::AttractionRange)?,
            coarse_grain,
        }),
        (None, None, false) => None,
        (w, r, _) => {
            return Err(AppError::Invalid {
                options: vec![
                    (OptionName("work_of_adhesion"), format!("{w:?}")),
                    (OptionName("adhesion_range"), format!("{r:?}")),
                ],
                rule: "adhesion needs both work_of_adhesion and adhesion_range (coarse_grain only with them)".to_string(),
            })
        }
    };
    Ok(app::contact::ContactOptions {
        modulus,
        pressures,
        hardness,
        level: levelling(OptionName("level"), level)?,
        pixel_size,
        height_unit,
        tolerance,
        fields,
        adhesion,
        decimal_comma: false,
    })
}

/// (ny, nx) arrays, one per point.
type Fields<'py> = Vec<Bound<'py, numpy::PyArray2<f64>>>;

/// The JSON of a contact document and, when asked, each point's pressure and gap
/// fields as (ny, nx) arrays, then those of the adhesive solves.
type ContactOut<'py> = (String, Fields<'py>, Fields<'py>, Fields<'py>, Fields<'py>);

fn contact_out<'py>(
    py: Python<'py>,
    doc: app::contact::ContactDocument,
) -> PyResult<ContactOut<'py>> {
    let json = report::contact::json_document(&doc).to_string();
    let [nx, ny] = doc.pixels;
    let (mut pressures, mut gaps) = (Vec::new(), Vec::new());
    let (mut adhesive_pressures, mut adhesive_gaps) = (Vec::new(), Vec::new());
    let shape = |v: Vec<f64>| -> PyResult<Bound<'py, numpy::PyArray2<f64>>> {
        v.into_pyarray(py)
            .reshape([ny, nx])
            .map_err(|e| value_error(e.to_string()))
    };
    for pt in doc.points {
        if let Some(a) = pt.adhesive.filter(|a| !a.pressures.is_empty()) {
            adhesive_pressures.push(shape(a.pressures)?);
            adhesive_gaps.push(shape(a.gaps)?);
        }
        if pt.solution.pressures.is_empty() {
            continue;
        }
        pressures.push(shape(pt.solution.pressures)?);
        gaps.push(shape(pt.solution.gaps)?);
    }
    Ok((json, pressures, gaps, adhesive_pressures, adhesive_gaps))
}

/// `wearopt contact FILE --modulus E --pressure P1,… [--hardness H] … --format json`.
#[pyfunction]
#[pyo3(signature = (path, modulus, pressures, hardness=None, level="plane".to_string(), pixel_size=None, height_unit=None, tolerance=app::contact::DEFAULT_TOLERANCE, fields=false, work_of_adhesion=None, adhesion_range=None, coarse_grain=false, decimal_comma=false))]
#[allow(clippy::too_many_arguments)]
fn contact_json<'py>(
    py: Python<'py>,
    path: String,
    modulus: String,
    pressures: Vec<String>,
    hardness: Option<String>,
    level: String,
    pixel_size: Option<String>,
    height_unit: Option<String>,
    tolerance: f64,
    fields: bool,
    work_of_adhesion: Option<String>,
    adhesion_range: Option<String>,
    coarse_grain: bool,
    decimal_comma: bool,
) -> PyResult<ContactOut<'py>> {
    let doc = interruptible(py, move || {
        let options = contact_options(
            &modulus,
            &pressures,
            hardness.as_deref(),
            &level,
            pixel_size.as_deref(),
            height_unit.as_deref(),
            tolerance,
            fields,
            (
                work_of_adhesion.as_deref(),
                adhesion_range.as_deref(),
                coarse_grain,
            ),
        )
        .map_err(words)?;
        app::contact::contact(
            std::path::Path::new(&path),
            &app::contact::ContactOptions {
                decimal_comma,
                ..options
            },
        )
        .map_err(words)
    })?;
    contact_out(py, doc)
}

/// The contact of heights in memory (a 2-D array, rows along y).
#[pyfunction]
#[pyo3(signature = (heights, pixel_size, modulus, pressures, hardness=None, level="plane".to_string(), height_unit=None, tolerance=app::contact::DEFAULT_TOLERANCE, fields=false, work_of_adhesion=None, adhesion_range=None, coarse_grain=false))]
#[allow(clippy::too_many_arguments)]
fn contact_array<'py>(
    py: Python<'py>,
    heights: PyReadonlyArray2<'py, f64>,
    pixel_size: String,
    modulus: String,
    pressures: Vec<String>,
    hardness: Option<String>,
    level: String,
    height_unit: Option<String>,
    tolerance: f64,
    fields: bool,
    work_of_adhesion: Option<String>,
    adhesion_range: Option<String>,
    coarse_grain: bool,
) -> PyResult<ContactOut<'py>> {
    let array = heights.as_array();
    let (ny, nx) = array.dim();
    let values: Vec<f64> = array.iter().copied().collect();
    let doc = interruptible(py, move || {
        let options = contact_options(
            &modulus,
            &pressures,
            hardness.as_deref(),
            &level,
            Some(&pixel_size),
            height_unit.as_deref(),
            tolerance,
            fields,
            (
                work_of_adhesion.as_deref(),
                adhesion_range.as_deref(),
                coarse_grain,
            ),
        )
        .map_err(words)?;
        app::contact::contact_of_heights("<height array>", nx, ny, values, &options).map_err(words)
    })?;
    contact_out(py, doc)
}

/// A quantity keyword argument: a string with a unit, or a number in SI where
/// plausible, read as `quantity`.
fn quantity(name: &'static str, text: &str, quantity: OptionQuantity) -> Result<f64, AppError> {
    app::quantity::positive_quantity(OptionName(name), text, quantity)
}

/// `wearopt fit-adhesion DATA --radius R … --format json`.
#[pyfunction]
#[pyo3(signature = (path, radius, mu=None, fit_mu=false, modulus=None, materials=None, quoted_gamma=None, quoted_bond_strength=None))]
#[allow(clippy::too_many_arguments)]
fn fit_adhesion_json(
    py: Python<'_>,
    path: String,
    radius: String,
    mu: Option<f64>,
    fit_mu: bool,
    modulus: Option<String>,
    materials: Option<Vec<String>>,
    quoted_gamma: Option<String>,
    quoted_bond_strength: Option<String>,
) -> PyResult<String> {
    detached(py, || {
        let options = (|| -> Result<FitAdhesionOptions, AppError> {
            if let (Some(mu), true) = (mu, fit_mu) {
                return Err(AppError::Invalid {
                    options: vec![
                        (OptionName("mu"), mu.to_string()),
                        (OptionName("fit_mu"), "True".to_string()),
                    ],
                    rule: "give mu (held fixed) or fit_mu=True (fitted), not both".to_string(),
                });
            }
            let modulus = match (modulus, materials) {
                (Some(e), Some(m)) => {
                    return Err(AppError::Invalid {
                        options: vec![
                            (OptionName("modulus"), format!("{e:?}")),
                            (OptionName("materials"), format!("{m:?}")),
                        ],
                        rule: "give modulus or materials, not both".to_string(),
                    })
                }
                (Some(e), None) => {
                    Modulus::Value(quantity("modulus", &e, OptionQuantity::Modulus)?)
                }
                (None, Some(m)) => Modulus::Materials(m),
                (None, None) => Modulus::None,
            };
            Ok(FitAdhesionOptions {
                radius: quantity("radius", &radius, OptionQuantity::SphereRadius)?,
                friction_coefficient: match (mu, fit_mu) {
                    (Some(mu), _) => FrictionCoefficient::Given(mu),
                    (None, true) => FrictionCoefficient::Fit,
                    (None, false) => FrictionCoefficient::Default,
                },
                modulus,
                quoted_gamma: quoted_gamma
                    .as_deref()
                    .map(|q| quantity("quoted_gamma", q, OptionQuantity::WorkOfAdhesion))
                    .transpose()?,
                quoted_bond_strength: quoted_bond_strength
                    .as_deref()
                    .map(|q| quantity("quoted_bond_strength", q, OptionQuantity::Stress))
                    .transpose()?,
            })
        })()
        .map_err(words)?;
        let c = app::fit_adhesion::fit_adhesion(std::path::Path::new(&path), &options)
            .map_err(words)?;
        report::calibrate::render_for(&c, report::Format::Json, app::Vocabulary::Keywords)
            .map_err(|e| e.to_string())
    })
}

/// `wearopt fit-wear DATA [--temperature T] [--speed v] --format json`; `source` is
/// the file's path (`is_path`) or the CSV text itself (rows given in Python).
#[pyfunction]
#[pyo3(signature = (source, is_path, temperature=None, speed=None))]
fn fit_wear_json(
    py: Python<'_>,
    source: String,
    is_path: bool,
    temperature: Option<String>,
    speed: Option<String>,
) -> PyResult<String> {
    detached(py, || {
        let settings = app::fit_wear::WearFitSettings {
            temperature: temperature
                .as_deref()
                .map(app::fit_wear::temperature_option)
                .transpose()
                .map_err(words)?,
            speed: speed
                .as_deref()
                .map(app::fit_wear::speed_option)
                .transpose()
                .map_err(words)?,
        };
        let fit = if is_path {
            app::fit_wear::fit_wear(std::path::Path::new(&source), &settings)
        } else {
            app::fit_wear::fit_wear_text(&source, "<rows>", &settings)
        }
        .map_err(words)?;
        report::fit_wear::render_for(&fit, report::Format::Json, app::Vocabulary::Keywords)
            .map_err(|e| e.to_string())
    })
}

/// `wearopt figures [--out DIR] --format json`: the summary, and the files written
/// into `out` when it is given.
#[pyfunction]
#[pyo3(signature = (points, load_min, load_max, out=None))]
fn figures_json(
    py: Python<'_>,
    points: usize,
    load_min: f64,
    load_max: f64,
    out: Option<String>,
) -> PyResult<String> {
    detached(py, || {
        let settings = app::figures::FigureSettings {
            points,
            load_min,
            load_max,
        };
        settings
            .validate()
            .map_err(|e| words(AppError::Figures(e)))?;
        let folder = std::path::PathBuf::from(out.as_deref().unwrap_or(""));
        if let Some(dir) = &out {
            std::fs::create_dir_all(dir).map_err(|e| {
                words(AppError::Output {
                    option: OptionName("out"),
                    path: dir.clone(),
                    reason: e.to_string(),
                })
            })?;
        }
        let doc = app::figures::figures(&settings, &folder).map_err(words)?;
        let doc = if out.is_some() {
            for (path, which) in &doc.files {
                std::fs::write(path, report::figures::file(&doc, *which))
                    .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
            }
            doc
        } else {
            app::figures::FiguresDocument {
                files: Vec::new(),
                ..doc
            }
        };
        report::figures::render(&doc, report::Format::Json).map_err(|e| e.to_string())
    })
}

/// `wearopt accuracy [FILE] --format json`.
#[pyfunction]
#[pyo3(signature = (source=None, is_path=true))]
fn accuracy_json(py: Python<'_>, source: Option<String>, is_path: bool) -> PyResult<String> {
    detached(py, || {
        let problem = source
            .as_deref()
            .map(|s| load(s, is_path).map(|(p, _)| p))
            .transpose()?;
        let wp = app::accuracy::accuracy(problem.as_ref()).map_err(words)?;
        report::accuracy::render(&wp, report::Format::Json).map_err(|e| e.to_string())
    })
}

/// The compiled functions of the `wearopt` package.
#[pymodule]
fn _wearopt(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(evaluate_json, m)?)?;
    m.add_function(wrap_pyfunction!(optimize_json, m)?)?;
    m.add_function(wrap_pyfunction!(pareto_json, m)?)?;
    m.add_function(wrap_pyfunction!(humidity_json, m)?)?;
    m.add_function(wrap_pyfunction!(uncertainty_json, m)?)?;
    m.add_function(wrap_pyfunction!(uncertainty_part_json, m)?)?;
    m.add_function(wrap_pyfunction!(is_uncertainty_part, m)?)?;
    m.add_function(wrap_pyfunction!(merge_uncertainty_json, m)?)?;
    m.add_function(wrap_pyfunction!(asperity_json, m)?)?;
    m.add_function(wrap_pyfunction!(curve_arrays, m)?)?;
    m.add_function(wrap_pyfunction!(sweep_text, m)?)?;
    m.add_function(wrap_pyfunction!(merge_text, m)?)?;
    m.add_function(wrap_pyfunction!(roughness_json, m)?)?;
    m.add_function(wrap_pyfunction!(roughness_array_json, m)?)?;
    m.add_function(wrap_pyfunction!(contact_json, m)?)?;
    m.add_function(wrap_pyfunction!(contact_array, m)?)?;
    m.add_function(wrap_pyfunction!(fit_adhesion_json, m)?)?;
    m.add_function(wrap_pyfunction!(fit_wear_json, m)?)?;
    m.add_function(wrap_pyfunction!(figures_json, m)?)?;
    m.add_function(wrap_pyfunction!(accuracy_json, m)?)?;
    Ok(())
}
