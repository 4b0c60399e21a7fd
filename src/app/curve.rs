//! `wearopt curve`: the non-dimensional model along a range of separations, one
//! law and one (θ, λ), or at many (θ, λ, h) at once (Python's arrays).

use rayon::prelude::*;
use serde::Serialize;

use crate::model::{AsperityLaw, Coefficients, Model, Quadrature};

use super::{AppError, OptionName};

pub use crate::model::{AdhesionModel, AttractionKind};

/// The asperity law of a curve, as the options name it.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LawOptions {
    /// The law (default JKR).
    pub adhesion_model: AdhesionModel,
    /// The attraction of a law that takes one (default van der Waals).
    pub attraction: Option<AttractionKind>,
    /// The attraction's range over σ: z0 = Z0/σ (van der Waals, Lennard-Jones),
    /// Δ_h = h0/σ (Dugdale); required by DMT and Lennard-Jones.
    pub attraction_range: Option<f64>,
}

/// The law `name` ("jkr", "dmt", "lennard_jones") from the registry of laws, for the option `option`.
pub fn adhesion_model(option: OptionName, name: &str) -> Result<AdhesionModel, AppError> {
    AdhesionModel::from_name(name).ok_or_else(|| AppError::Invalid {
        options: vec![(option, format!("{name:?}"))],
        rule: format!("expected {}", quoted_list(&AdhesionModel::names())),
    })
}

/// The attraction `name` ("van_der_waals", "dugdale"), for the option `option`.
pub fn attraction(option: OptionName, name: &str) -> Result<AttractionKind, AppError> {
    AttractionKind::from_name(name).ok_or_else(|| AppError::Invalid {
        options: vec![(option, format!("{name:?}"))],
        rule: format!("expected {}", quoted_list(&AttractionKind::names())),
    })
}

/// `"a" or "b"`, `"a", "b" or "c"`.
fn quoted_list(names: &[&str]) -> String {
    let q: Vec<String> = names.iter().map(|n| format!("{n:?}")).collect();
    match q.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} or {last}", rest.join(", ")),
        _ => q.join(""),
    }
}

impl LawOptions {
    /// The law these options name, or the clash between them.
    pub fn law(&self) -> Result<AsperityLaw, AppError> {
        let law = self.adhesion_model.law();
        if !law.takes_attraction() {
            if !law.has_own_range() {
                if self.attraction.is_some() || self.attraction_range.is_some() {
                    return Err(AppError::AttractionNotTaken);
                }
            } else if self.attraction.is_some() {
                return Err(AppError::AttractionRefused {
                    law: self.adhesion_model,
                });
            }
        }
        let attraction = self.attraction.unwrap_or_default();
        if !(law.takes_attraction() || law.has_own_range()) {
            return Ok(law.with_range(attraction, 0.0));
        }
        let range = self.attraction_range.ok_or(AppError::WithoutRange {
            law: self.adhesion_model,
        })?;
        if !(range > 0.0 && range.is_finite()) {
            return Err(AppError::Invalid {
                options: vec![(OptionName("attraction_range"), range.to_string())],
                rule: "must be finite and > 0".to_string(),
            });
        }
        Ok(law.with_range(attraction, range))
    }
}

/// The options of `wearopt curve`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CurveOptions {
    /// θ > 0 (∞: no adhesion).
    pub theta: f64,
    /// λ > 0 (∞: no plasticity).
    pub lambda: f64,
    /// c_h > 0, used only with θ = ∞ (∞: no plasticity).
    pub hardness_coefficient: f64,
    /// First separation h = d/σ.
    pub from: f64,
    /// Last separation (inclusive).
    pub to: f64,
    /// Number of points, 1 to 1,000,000.
    pub points: usize,
    /// The asperity law.
    pub law: LawOptions,
}

/// One row of a curve: the model at one separation h.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CurveRow {
    /// h = d/σ.
    pub h: f64,
    /// P̄(h).
    pub load: f64,
    /// Ā(h), which is also the non-dimensional wear volume V̄ (eq. 16).
    pub area: f64,
    /// Ā_p(h).
    pub plastic_area: f64,
    /// Δc (∞ without plasticity: `inf` in CSV, `null` in JSON).
    pub critical_interference: f64,
    /// dP̄/dh.
    pub dload_dh: f64,
    /// The share of P̄ carried by attracted asperities not in contact (DMT; ≤ 0, 0 under JKR).
    pub noncontact_load: f64,
}

/// What `wearopt curve` computes: its rows.
#[derive(Debug, Clone, PartialEq)]
pub struct CurveDocument {
    /// One row per separation, in order.
    pub rows: Vec<CurveRow>,
}

/// The model at one (θ, λ, c_h) under one law: checked, then evaluated at any h.
#[derive(Debug, Clone)]
pub struct CurveModel {
    model: Model,
    critical_interference: f64,
}

/// θ, λ and c_h each > 0 (∞ allowed), checked in that order.
fn check_indices(theta: f64, lambda: f64, c_h: f64) -> Result<(), AppError> {
    for (option, x, what) in [
        ("theta", theta, "adhesion"),
        ("lambda", lambda, "plasticity"),
        ("hardness_coefficient", c_h, "plasticity"),
    ] {
        if x.is_nan() || x <= 0.0 {
            return Err(AppError::Invalid {
                options: vec![(OptionName(option), x.to_string())],
                rule: format!("must be > 0 (or inf for no {what})"),
            });
        }
    }
    Ok(())
}

impl CurveModel {
    /// The model at θ, λ and c_h (c_h read only with θ = ∞) under `law`.
    pub fn new(theta: f64, lambda: f64, c_h: f64, law: AsperityLaw) -> Result<Self, AppError> {
        check_indices(theta, lambda, c_h)?;
        let coefficients = if theta.is_infinite() {
            Coefficients::new(0.0, c_h)
        } else if lambda.is_infinite() {
            Coefficients::from_indices_or_limits(theta, lambda, c_h)
        } else {
            Coefficients::from_indices(theta, lambda)
        };
        if coefficients.c_a.is_nan() || coefficients.c_h.is_nan() {
            return Err(AppError::UndefinedCoefficients { theta, lambda });
        }
        let model = Model::with_law(coefficients, law, Quadrature::default());
        Ok(CurveModel {
            critical_interference: model.critical_interference(),
            model,
        })
    }

    /// The row at separation h.
    pub fn row(&self, h: f64) -> CurveRow {
        let at = self.model.at(h);
        CurveRow {
            h,
            load: at.load().value(),
            area: at.area().value(),
            plastic_area: at.plastic_area().value(),
            critical_interference: self.critical_interference,
            dload_dh: at.dload_dh().value(),
            noncontact_load: at.noncontact_load().value(),
        }
    }
}

/// The curve of `options`, as `wearopt curve` computes it.
pub fn curve(options: &CurveOptions) -> Result<CurveDocument, AppError> {
    let law = options.law.law()?;
    let CurveOptions {
        theta,
        lambda,
        hardness_coefficient,
        from,
        to,
        points,
        ..
    } = *options;
    let invalid = |options: Vec<(&'static str, String)>, rule: String| AppError::Invalid {
        options: options
            .into_iter()
            .map(|(o, v)| (OptionName(o), v))
            .collect(),
        rule,
    };
    // The indices first, as the command line always checked them.
    check_indices(theta, lambda, hardness_coefficient)?;
    let range = || vec![("from", from.to_string()), ("to", to.to_string())];
    if !from.is_finite() || !to.is_finite() {
        return Err(invalid(range(), "separations must be finite".to_string()));
    }
    if from > to {
        return Err(AppError::Order {
            low: (OptionName("from"), from.to_string()),
            high: (OptionName("to"), to.to_string()),
        });
    }
    if !(1..=1_000_000).contains(&points) {
        return Err(invalid(
            vec![("points", points.to_string())],
            "must lie in 1..=1000000".to_string(),
        ));
    }
    if points > 1 && from == to {
        return Err(AppError::EmptyRange {
            value: from,
            points,
        });
    }
    let model = CurveModel::new(theta, lambda, hardness_coefficient, law)?;
    let rows = (0..points)
        .map(|i| {
            let h = if points == 1 {
                from
            } else {
                from + (to - from) * (i as f64) / ((points - 1) as f64)
            };
            model.row(h)
        })
        .collect();
    Ok(CurveDocument { rows })
}

/// Elements computed per parallel task (fixed: results never depend on threads).
const CHUNK: usize = 2048;

/// The rows at every `(θ[i], λ[i], c_h[i], h[i])` of four equally long slices under
/// one law, in parallel (deterministic: fixed chunks). An error names the element
/// when there is more than one.
pub fn curve_at(
    theta: &[f64],
    lambda: &[f64],
    hardness_coefficient: &[f64],
    h: &[f64],
    law: &LawOptions,
) -> Result<Vec<CurveRow>, AppError> {
    let law = law.law()?;
    let n = h.len();
    if theta.len() != n || lambda.len() != n || hardness_coefficient.len() != n {
        return Err(AppError::Invalid {
            options: vec![
                (OptionName("theta"), theta.len().to_string()),
                (OptionName("lambda"), lambda.len().to_string()),
                (
                    OptionName("hardness_coefficient"),
                    hardness_coefficient.len().to_string(),
                ),
                (OptionName("h"), n.to_string()),
            ],
            rule: "the arrays must have one length".to_string(),
        });
    }
    let element = |i: usize, e: AppError| {
        if n > 1 {
            AppError::Element {
                index: i,
                error: Box::new(e),
            }
        } else {
            e
        }
    };
    for i in 0..n {
        check_indices(theta[i], lambda[i], hardness_coefficient[i]).map_err(|e| element(i, e))?;
        if !h[i].is_finite() {
            return Err(element(
                i,
                AppError::Invalid {
                    options: vec![(OptionName("h"), h[i].to_string())],
                    rule: "separations must be finite".to_string(),
                },
            ));
        }
    }
    let chunks: Vec<Result<Vec<CurveRow>, AppError>> = (0..n)
        .collect::<Vec<_>>()
        .par_chunks(CHUNK)
        .map(|idx| {
            let mut model: Option<((f64, f64, f64), CurveModel)> = None;
            idx.iter()
                .map(|&i| {
                    let key = (theta[i], lambda[i], hardness_coefficient[i]);
                    if !matches!(&model, Some((k, _)) if *k == key) {
                        let m = CurveModel::new(key.0, key.1, key.2, law).map_err(|e| {
                            AppError::Element {
                                index: i,
                                error: Box::new(e),
                            }
                        })?;
                        model = Some((key, m));
                    }
                    let (_, m) = model.as_ref().expect("set just above");
                    Ok(m.row(h[i]))
                })
                .collect()
        })
        .collect();
    let mut rows = Vec::with_capacity(n);
    for chunk in chunks {
        rows.extend(chunk?);
    }
    Ok(rows)
}
