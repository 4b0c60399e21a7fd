//! `wearopt._wearopt`: the compiled half of the Python package `wearopt`.
//!
//! Every function here calls the library functions the command line calls to
//! produce its JSON (the same loading, the same computation, the same report
//! writer), so a Python result and `wearopt … --format json` agree to the last
//! digit by construction. The Python half (`python/wearopt/__init__.py`) turns
//! the JSON into dicts and the arrays into numpy shapes. The GIL is released
//! while the model runs.

use numpy::{IntoPyArray, PyReadonlyArray1};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rayon::prelude::*;

use wearopt::documents::{self, RoughnessOptions};
use wearopt::model::{AsperityLaw, Attraction, Coefficients, Model, Quadrature};
use wearopt::problem::Problem;
use wearopt::report;
use wearopt::surface::Levelling;
use wearopt::sweep::{Method, Shard, Sweep, SweepError};

fn value_error(message: impl Into<String>) -> PyErr {
    PyValueError::new_err(message.into())
}

/// Where a problem comes from: a file path, or a dict sent as JSON text.
fn load(source: &str, is_path: bool) -> Result<(Problem, String), String> {
    if is_path {
        let problem =
            wearopt::problem::load(std::path::Path::new(source)).map_err(|e| e.to_string())?;
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
        let problem = wearopt::problem::parse(&text, origin).map_err(|e| {
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

/// A document as JSON text for the Python half to read.
fn text(document: serde_json::Value) -> String {
    document.to_string()
}

/// `wearopt eval FILE --format json`.
#[pyfunction]
fn evaluate_json(py: Python<'_>, source: String, is_path: bool) -> PyResult<String> {
    py.detach(|| {
        let (problem, origin) = load(&source, is_path)?;
        documents::eval_json(&problem, &origin)
            .map(text)
            .map_err(|e| e.to_string())
    })
    .map_err(|e: String| value_error(e))
}

/// `wearopt optimize FILE --format json` (a ranking when `[design]` lists materials).
#[pyfunction]
fn optimize_json(py: Python<'_>, source: String, is_path: bool) -> PyResult<String> {
    py.detach(|| {
        let (problem, origin) = load(&source, is_path)?;
        documents::optimize_json(&problem, &origin)
            .map(text)
            .map_err(|e| e.to_string())
    })
    .map_err(|e: String| value_error(e))
}

/// `wearopt pareto FILE [--points N] --format json`.
#[pyfunction]
#[pyo3(signature = (source, is_path, points=None))]
fn pareto_json(
    py: Python<'_>,
    source: String,
    is_path: bool,
    points: Option<usize>,
) -> PyResult<String> {
    py.detach(|| {
        let (problem, origin) = load(&source, is_path)?;
        documents::pareto_json(&problem, &origin, points)
            .map(text)
            .map_err(|e| e.to_string())
    })
    .map_err(|e: String| value_error(e))
}

/// The checks of `wearopt curve`, with its messages.
fn check_curve_input(theta: f64, lambda: f64, c_h: f64, h: f64) -> Result<(), String> {
    if theta.is_nan() || theta <= 0.0 {
        return Err(format!(
            "--theta {theta}: must be > 0 (or inf for no adhesion)"
        ));
    }
    if lambda.is_nan() || lambda <= 0.0 {
        return Err(format!(
            "--lambda {lambda}: must be > 0 (or inf for no plasticity)"
        ));
    }
    if c_h.is_nan() || c_h <= 0.0 {
        return Err(format!(
            "--hardness-coefficient {c_h}: must be > 0 (or inf for no plasticity)"
        ));
    }
    if !h.is_finite() {
        return Err(format!("h {h}: separations must be finite"));
    }
    Ok(())
}

/// The coefficients `wearopt curve` builds from θ, λ and c_h.
fn coefficients(theta: f64, lambda: f64, c_h: f64) -> Result<Coefficients, String> {
    let c = if theta.is_infinite() {
        Coefficients::new(0.0, c_h)
    } else if lambda.is_infinite() {
        Coefficients::from_indices_or_limits(theta, lambda, c_h)
    } else {
        Coefficients::from_indices(theta, lambda)
    };
    if c.c_a.is_nan() || c.c_h.is_nan() {
        return Err(format!(
            "coefficients are undefined for θ = {theta}, λ = {lambda}"
        ));
    }
    Ok(c)
}

/// The asperity law of `curve`, with the command line's messages.
fn curve_law(
    adhesion_model: &str,
    attraction: Option<&str>,
    range: Option<f64>,
) -> Result<AsperityLaw, String> {
    match adhesion_model {
        "jkr" => {
            if attraction.is_some() || range.is_some() {
                return Err("--attraction and --attraction-range apply to --adhesion-model dmt only (the default is jkr)".to_string());
            }
            Ok(AsperityLaw::Jkr)
        }
        "dmt" => {
            let range = range.ok_or_else(|| "--adhesion-model dmt needs --attraction-range D: z0 = Z0/σ for van_der_waals, h0/σ for dugdale (e.g. 0.1)".to_string())?;
            if !(range > 0.0 && range.is_finite()) {
                return Err(format!(
                    "--attraction-range {range}: must be finite and > 0"
                ));
            }
            Ok(AsperityLaw::Dmt(match attraction {
                None | Some("van_der_waals") => Attraction::VanDerWaals { range },
                Some("dugdale") => Attraction::Dugdale { range },
                Some(other) => {
                    return Err(format!(
                        "--attraction {other:?}: expected \"van_der_waals\" or \"dugdale\""
                    ))
                }
            }))
        }
        other => Err(format!(
            "--adhesion-model {other:?}: expected \"jkr\" or \"dmt\""
        )),
    }
}

/// Elements computed per parallel task (fixed: results never depend on threads).
const CURVE_CHUNK: usize = 2048;

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
    let law =
        curve_law(&adhesion_model, attraction.as_deref(), attraction_range).map_err(value_error)?;
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
    let n = h.len();
    if theta.len() != n || lam.len() != n || c_h.len() != n {
        return Err(value_error(
            "theta, lam, hardness_coefficient and h must have one length",
        ));
    }
    let columns = py.detach(|| -> Result<[Vec<f64>; 6], String> {
        for i in 0..n {
            check_curve_input(theta[i], lam[i], c_h[i], h[i]).map_err(|e| {
                if n > 1 {
                    format!("{e} (element {i})")
                } else {
                    e
                }
            })?;
        }
        let chunks: Vec<Result<Vec<[f64; 6]>, String>> = (0..n)
            .collect::<Vec<_>>()
            .par_chunks(CURVE_CHUNK)
            .map(|idx| -> Result<Vec<[f64; 6]>, String> {
                let mut model: Option<((f64, f64, f64), Model, f64)> = None;
                idx.iter()
                    .map(|&i| {
                        let key = (theta[i], lam[i], c_h[i]);
                        let fresh = !matches!(&model, Some((k, _, _)) if *k == key);
                        if fresh {
                            let m = Model::with_law(
                                coefficients(key.0, key.1, key.2)
                                    .map_err(|e| format!("{e} (element {i})"))?,
                                law,
                                Quadrature::default(),
                            );
                            let dc = m.critical_interference();
                            model = Some((key, m, dc));
                        }
                        let (_, m, dc) = model.as_ref().expect("model built above");
                        let at = m.at(h[i]);
                        Ok([
                            at.load().value(),
                            at.area().value(),
                            at.plastic_area().value(),
                            *dc,
                            at.dload_dh().value(),
                            at.noncontact_load().value(),
                        ])
                    })
                    .collect()
            })
            .collect();
        let mut cols: [Vec<f64>; 6] = Default::default();
        for c in &mut cols {
            c.reserve(n);
        }
        for chunk in chunks {
            for row in chunk? {
                for (c, v) in cols.iter_mut().zip(row) {
                    c.push(v);
                }
            }
        }
        Ok(cols)
    });
    let [load, area, plastic_area, critical_interference, dload_dh, noncontact_load] =
        columns.map_err(value_error)?;
    let out = PyDict::new(py);
    out.set_item("h", h.into_pyarray(py))?;
    out.set_item("load", load.into_pyarray(py))?;
    out.set_item("area", area.into_pyarray(py))?;
    out.set_item("plastic_area", plastic_area.into_pyarray(py))?;
    out.set_item(
        "critical_interference",
        critical_interference.into_pyarray(py),
    )?;
    out.set_item("dload_dh", dload_dh.into_pyarray(py))?;
    out.set_item("noncontact_load", noncontact_load.into_pyarray(py))?;
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
    py.detach(|| {
        let (problem, origin) = load(&source, is_path)?;
        let method = match method.as_str() {
            "sobol" => Method::Sobol,
            "lhs" => Method::Lhs,
            "grid" => Method::Grid,
            other => {
                return Err(format!(
                    "method {other:?}: expected \"sobol\", \"lhs\" or \"grid\""
                ))
            }
        };
        let format = match format.as_str() {
            "csv" => report::sweep::Encoding::Csv,
            "json" => report::sweep::Encoding::Json,
            other => return Err(format!("format {other:?}: expected \"csv\" or \"json\"")),
        };
        if !problem.study.materials.is_empty() {
            return Err(format!("{origin}: {}", SweepError::Materials));
        }
        let shard = Shard::new(shard_index, shard_count).map_err(|e| e.to_string())?;
        let sweep = Sweep::new(
            &problem.scene,
            &problem.study.design,
            &problem.study.constraints,
            method,
            samples,
            seed,
        )
        .map_err(|e| match e {
            SweepError::Samples { .. } | SweepError::Grid { .. } => {
                format!("--samples {samples}: {e}")
            }
            _ => format!("{origin}: {e}"),
        })?;
        let mut text = report::sweep::head(
            format,
            &report::sweep::Head {
                name: &problem.name,
                sweep: &sweep,
            },
        );
        let mut first = true;
        sweep
            .run(shard.range(samples), |rows| {
                for r in rows {
                    text.push_str(&report::sweep::row(format, &sweep, r, first));
                    first = false;
                }
                Ok::<(), String>(())
            })
            .map_err(|e| e.to_string())?;
        text.push_str(report::sweep::tail(format));
        Ok(text)
    })
    .map_err(|e: String| value_error(e))
}

/// `wearopt merge` of parts held in memory.
#[pyfunction]
#[pyo3(signature = (parts, samples=None))]
fn merge_text(py: Python<'_>, parts: Vec<String>, samples: Option<u64>) -> PyResult<String> {
    py.detach(|| {
        let texts: Vec<&str> = parts.iter().map(String::as_str).collect();
        report::sweep::merge(&texts, samples).map_err(|(i, e)| match i {
            Some(i) => format!("part {i}: {e}"),
            None => format!("{} parts: {e}", parts.len()),
        })
    })
    .map_err(value_error)
}

/// `wearopt roughness FILE [--cutoff L] [--level K] [--pixel-size L] [--height-unit U] --format json`.
#[pyfunction]
#[pyo3(signature = (path, cutoff=None, level="plane".to_string(), pixel_size=None, height_unit=None))]
fn roughness_json(
    py: Python<'_>,
    path: String,
    cutoff: Option<String>,
    level: String,
    pixel_size: Option<String>,
    height_unit: Option<String>,
) -> PyResult<String> {
    py.detach(|| {
        let level = match level.as_str() {
            "none" => Ok(Levelling::None),
            "plane" => Ok(Levelling::Plane),
            "quadratic" => Ok(Levelling::Quadratic),
            other => Err(format!(
                "level {other:?}: expected \"none\", \"plane\" or \"quadratic\""
            )),
        };
        // The options' own checks come first, as they always have.
        let options = RoughnessOptions::parse(
            cutoff.as_deref(),
            Levelling::Plane,
            pixel_size.as_deref(),
            height_unit.as_deref(),
        )
        .map_err(|e| e.to_string())?;
        let options = RoughnessOptions {
            level: level?,
            ..options
        };
        documents::roughness_json(std::path::Path::new(&path), &options)
            .map(text)
            .map_err(|e| e.to_string())
    })
    .map_err(|e: String| value_error(e))
}

/// The compiled functions of the `wearopt` package.
#[pymodule]
fn _wearopt(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(evaluate_json, m)?)?;
    m.add_function(wrap_pyfunction!(optimize_json, m)?)?;
    m.add_function(wrap_pyfunction!(pareto_json, m)?)?;
    m.add_function(wrap_pyfunction!(curve_arrays, m)?)?;
    m.add_function(wrap_pyfunction!(sweep_text, m)?)?;
    m.add_function(wrap_pyfunction!(merge_text, m)?)?;
    m.add_function(wrap_pyfunction!(roughness_json, m)?)?;
    Ok(())
}
