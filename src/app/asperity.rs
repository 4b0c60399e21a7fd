//! `wearopt asperity`: one asperity's load against its interference in Maugis
//! units (docs/model.md §11) under the Lennard-Jones law, JKR or DMT, with its
//! branches, jumps and pull-off, for checking a law against the literature.

use crate::model::asperity_curve::{self, AsperityCurve, LimitNote};

use super::{AppError, OptionName};

pub use crate::model::asperity_curve::{
    Branch, CurveLaw, CurveMark, CurvePoint, Limit, RowAccuracy, CURVE_ERROR,
    INDEPENDENTLY_CHECKED, LIMIT_PULL_OFF_ERROR, MARKS_ERROR, ROWS_ERROR, SOLVED_TABOR,
};

/// A sphere in SI units (`--radius`, `--work-of-adhesion`, `--modulus`,
/// `--interatomic-distance`): its Tabor parameter, and the scales that turn
/// the curve's Maugis units into newtons and metres (docs/model.md §11).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SiSphere {
    /// The radius R (m).
    pub radius: f64,
    /// The work of adhesion γ (J/m²).
    pub work_of_adhesion: f64,
    /// The composite modulus E* (Pa), K = 4E*/3.
    pub modulus: f64,
    /// The equilibrium spacing Z0 of the Lennard-Jones law (m).
    pub interatomic_distance: f64,
}

impl SiSphere {
    /// μ = (Rγ²/(E*²Z0³))^{1/3}.
    pub fn tabor(&self) -> f64 {
        let (r, w, e, z) = (
            self.radius,
            self.work_of_adhesion,
            self.modulus,
            self.interatomic_distance,
        );
        (r * w * w / (e * e * z * z * z)).cbrt()
    }

    /// The load of P̂ = 1: πγR (N).
    pub fn load_scale(&self) -> f64 {
        std::f64::consts::PI * self.work_of_adhesion * self.radius
    }

    /// The interference of δ̂ = 1: (π²γ²R/K²)^{1/3} (m).
    pub fn interference_scale(&self) -> f64 {
        let k = 4.0 * self.modulus / 3.0;
        let pw = std::f64::consts::PI * self.work_of_adhesion;
        (pw * pw * self.radius / (k * k)).cbrt()
    }

    /// The contact radius of â = 1: (πγR²/K)^{1/3} (m).
    pub fn radius_scale(&self) -> f64 {
        let k = 4.0 * self.modulus / 3.0;
        (std::f64::consts::PI * self.work_of_adhesion * self.radius * self.radius / k).cbrt()
    }
}

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
    /// How a solved curve's rows are computed ([`rows_for`]).
    pub rows: RowAccuracy,
    /// The sphere in SI, when given instead of μ: `tabor` is then its
    /// [`SiSphere::tabor`], and the reports add newtons and metres.
    pub sphere: Option<SiSphere>,
}

/// Up to this Tabor parameter a solved curve's rows are converged by default;
/// above it converging them costs minutes on two cores (μ = 3: about 17 CPU-s
/// for 100 rows, μ = 30: over 150), so the default is the trace's mesh, said in
/// the report, and `--converged` asks for them.
pub const CONVERGED_ROWS_UP_TO: f64 = 5.0;

/// The rows a curve gets when neither `--fast` nor `--converged` is given:
/// converged up to μ = [`CONVERGED_ROWS_UP_TO`], the trace's mesh above.
pub fn default_rows(tabor: f64) -> RowAccuracy {
    if tabor <= CONVERGED_ROWS_UP_TO {
        RowAccuracy::Converged
    } else {
        RowAccuracy::Fast
    }
}

/// The rows asked for: `Some(true)` the trace's mesh (`--fast`), `Some(false)`
/// converged (`--converged`), `None` [`default_rows`].
pub fn rows_for(tabor: f64, fast: Option<bool>) -> RowAccuracy {
    match fast {
        Some(true) => RowAccuracy::Fast,
        Some(false) => RowAccuracy::Converged,
        None => default_rows(tabor),
    }
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
        if self.from == self.to {
            return Err(AppError::EmptyRange {
                value: self.from,
                points: self.points,
            });
        }
        if self.from > self.to {
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
    asperity_with(options, &super::Quiet)
}

/// [`asperity`], telling `progress` of the converged points (rows and marks)
/// of a solved curve as they finish (the trace before them is not counted).
pub fn asperity_with(
    options: &AsperityOptions,
    progress: &dyn super::Progress,
) -> Result<AsperityDocument, AppError> {
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
        match asperity_curve::asperity_curve_with(
            o.law,
            o.tabor,
            (o.from, o.to, o.points),
            o.rows,
            &|done, total| {
                if done == 0 {
                    progress.begin(total);
                } else {
                    progress.advance();
                }
            },
        ) {
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

/// The sphere's Tabor parameter and the sphere: from `tabor`, or from the
/// four SI quantities (radius, work of adhesion, composite modulus,
/// interatomic distance; each a number with its unit or a plausible bare SI
/// number, [`super::quantity::positive_quantity`]), never both, and all four
/// or none.
pub fn tabor_or_sphere(
    tabor: Option<f64>,
    [radius, work, modulus, distance]: [Option<&str>; 4],
) -> Result<(f64, Option<SiSphere>), AppError> {
    use super::quantity::{positive_quantity, OptionQuantity as Q};
    let names = [
        "radius",
        "work_of_adhesion",
        "modulus",
        "interatomic_distance",
    ];
    let given: Vec<(&str, &str)> = names
        .iter()
        .zip([radius, work, modulus, distance])
        .filter_map(|(n, t)| t.map(|t| (*n, t)))
        .collect();
    match (tabor, given.len()) {
        (Some(mu), 0) => Ok((mu, None)),
        (Some(mu), _) => Err(AppError::Invalid {
            options: std::iter::once((OptionName("tabor"), mu.to_string()))
                .chain(given.iter().map(|(n, t)| (OptionName(n), format!("{t:?}"))))
                .collect(),
            rule: "give the Tabor parameter or the sphere in SI (radius, work of adhesion, modulus, interatomic distance), not both".into(),
        }),
        (None, 4) => {
            let q = |k: usize, what: Q| {
                positive_quantity(OptionName(names[k]), given[k].1, what)
            };
            let sphere = SiSphere {
                radius: q(0, Q::SphereRadius)?,
                work_of_adhesion: q(1, Q::WorkOfAdhesion)?,
                modulus: q(2, Q::Modulus)?,
                interatomic_distance: q(3, Q::InteratomicDistance)?,
            };
            Ok((sphere.tabor(), Some(sphere)))
        }
        (None, 0) => Err(AppError::Invalid {
            options: vec![(OptionName("tabor"), "(none)".into())],
            rule: "give the Tabor parameter μ, or the sphere in SI: radius, work of adhesion, modulus and interatomic distance".into(),
        }),
        (None, _) => Err(AppError::Invalid {
            options: given
                .iter()
                .map(|(n, t)| (OptionName(n), format!("{t:?}")))
                .collect(),
            rule: format!(
                "a sphere in SI needs all four of radius, work of adhesion, modulus and interatomic distance: missing {}",
                names
                    .iter()
                    .filter(|n| !given.iter().any(|(g, _)| g == *n))
                    .map(|n| n.replace('_', " "))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        }),
    }
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
