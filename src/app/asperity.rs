//! `wearopt asperity`: one asperity's load against its interference in Maugis
//! units (docs/model.md §11) under the Lennard-Jones law, JKR or DMT, with its
//! branches, jumps and pull-off, for checking a law against the literature.

use crate::model::asperity_curve::{self, AsperityCurve, LimitNote};

use super::{AppError, OptionName};

pub use crate::model::asperity_curve::{
    Branch, CurveLaw, CurveMark, CurvePoint, Limit, CURVE_ERROR, INDEPENDENTLY_CHECKED,
    LIMIT_PULL_OFF_ERROR, SOLVED_TABOR,
};

/// The most interferences one run evaluates.
pub const MAX_POINTS: usize = 10_000;

/// The most interferences of a traced Lennard-Jones curve (μ inside
/// [`SOLVED_TABOR`]): each is a root on the traced path, tens of milliseconds
/// apiece (200 took 20 s, 10 000 ran 25 min before this bound).
pub const MAX_TRACED_POINTS: usize = 1_000;

/// The widest interferences |δ̂| of a traced Lennard-Jones curve (μ inside
/// [`SOLVED_TABOR`]): the trace starts beyond `from` and steps to `to`, its
/// time growing with both (from −1000: 41 s; from −10⁴: 166 s, then not
/// converged; to 10⁶: still tracing after 32 min). JKR, DMT and the limits
/// outside [`SOLVED_TABOR`] are closed forms and take the full ±1e6.
pub const MAX_TRACED_INTERFERENCE: f64 = 1_000.0;

/// The options of `wearopt asperity`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AsperityOptions {
    /// The Tabor parameter μ = (Rγ²/(E²Z0³))^{1/3}, > 0.
    pub tabor: f64,
    /// The first interference δ̂ (Maugis units).
    pub from: f64,
    /// The last interference (inclusive), above `from`.
    pub to: f64,
    /// How many evenly spaced interferences, ≥ 2.
    pub points: usize,
    /// The law.
    pub law: CurveLaw,
}

impl AsperityOptions {
    /// Refuses values outside their ranges, naming the options.
    pub fn validate(&self) -> Result<(), AppError> {
        if !(self.tabor > 0.0 && self.tabor.is_finite()) {
            return Err(AppError::Invalid {
                options: vec![(OptionName("tabor"), self.tabor.to_string())],
                rule: "the Tabor parameter μ must be positive and finite (JKR holds above about 3, DMT below about 0.3)".into(),
            });
        }
        for (name, x) in [("from", self.from), ("to", self.to)] {
            if !(x.is_finite() && x.abs() <= 1e6) {
                return Err(AppError::Invalid {
                    options: vec![(OptionName(name), x.to_string())],
                    rule: "an interference must be finite, within ±1e6 (Maugis units)".into(),
                });
            }
        }
        if self.from >= self.to {
            return Err(AppError::Order {
                low: (OptionName("from"), self.from.to_string()),
                high: (OptionName("to"), self.to.to_string()),
            });
        }
        if !(2..=MAX_POINTS).contains(&self.points) {
            return Err(AppError::Invalid {
                options: vec![(OptionName("points"), self.points.to_string())],
                rule: format!("must lie in 2..={MAX_POINTS}"),
            });
        }
        if self.traced() {
            let why = format!(
                "the Lennard-Jones sphere at μ = {} is traced point by point (μ from {} to {} is solved), which this bound keeps to about a minute; JKR and DMT (--adhesion-model) take up to {MAX_POINTS} points within ±1e6",
                self.tabor, SOLVED_TABOR.0, SOLVED_TABOR.1
            );
            for (name, x) in [("from", self.from), ("to", self.to)] {
                if x.abs() > MAX_TRACED_INTERFERENCE {
                    return Err(AppError::Invalid {
                        options: vec![(OptionName(name), x.to_string())],
                        rule: format!(
                            "must lie within ±{MAX_TRACED_INTERFERENCE} (Maugis units): {why}"
                        ),
                    });
                }
            }
            if self.points > MAX_TRACED_POINTS {
                return Err(AppError::Invalid {
                    options: vec![(OptionName("points"), self.points.to_string())],
                    rule: format!("must lie in 2..={MAX_TRACED_POINTS}: {why}"),
                });
            }
        }
        Ok(())
    }

    /// Whether the curve is traced by the Lennard-Jones solver (its law at a
    /// Tabor parameter inside [`SOLVED_TABOR`]), not a closed form.
    pub fn traced(&self) -> bool {
        self.law == CurveLaw::LennardJones
            && (SOLVED_TABOR.0..=SOLVED_TABOR.1).contains(&self.tabor)
    }
}

/// Whether the curve was traced.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum AsperityStatus {
    /// Every point converged.
    Ok,
    /// The continuation stalled (Newton's method failed at every shorter step):
    /// no points.
    NotConverged,
}

impl AsperityStatus {
    /// The word in reports.
    pub fn as_str(self) -> &'static str {
        match self {
            AsperityStatus::Ok => "ok",
            AsperityStatus::NotConverged => "not_converged",
        }
    }
}

/// What `wearopt asperity` computes.
#[derive(Debug, Clone, PartialEq)]
pub struct AsperityDocument {
    /// The options it ran with.
    pub options: AsperityOptions,
    /// The curve asked for (None when not converged).
    pub curve: Option<AsperityCurve>,
    /// Whether it was traced.
    pub status: AsperityStatus,
    /// Where the apex gap was when the trace stalled.
    pub stalled_at: Option<f64>,
    /// For the Lennard-Jones law outside the solved range: the limit used.
    pub limit: Option<LimitNote>,
    /// JKR's and DMT's curves over the same interferences, for comparison.
    pub comparison: Vec<AsperityCurve>,
}

/// Runs `wearopt asperity`.
pub fn asperity(options: &AsperityOptions) -> Result<AsperityDocument, AppError> {
    options.validate()?;
    let o = *options;
    let comparison = [CurveLaw::Jkr, CurveLaw::Dmt]
        .into_iter()
        .filter(|&law| law != o.law)
        .filter_map(|law| {
            asperity_curve::asperity_curve(law, o.tabor, o.from, o.to, o.points)
                .ok()
                .map(|c| c.0)
        })
        .collect();
    Ok(
        match asperity_curve::asperity_curve(o.law, o.tabor, o.from, o.to, o.points) {
            Ok((curve, limit)) => AsperityDocument {
                options: o,
                curve: Some(curve),
                status: AsperityStatus::Ok,
                stalled_at: None,
                limit,
                comparison,
            },
            Err(asperity_curve::CurveError::NotConverged(apex)) => AsperityDocument {
                options: o,
                curve: None,
                status: AsperityStatus::NotConverged,
                stalled_at: Some(apex),
                limit: None,
                comparison,
            },
        },
    )
}

/// The law named `name` (`lennard_jones`, `jkr`, `dmt`), or the error naming the
/// accepted ones.
pub fn law(name: &str) -> Result<CurveLaw, AppError> {
    CurveLaw::from_name(name).ok_or_else(|| AppError::Invalid {
        options: vec![(OptionName("adhesion_model"), name.to_string())],
        rule: format!(
            "the asperity laws are {}",
            CurveLaw::ALL.map(CurveLaw::as_str).join(", ")
        ),
    })
}
