//! The study as functions of a unit design point: the objective (in ln) and
//! the constraint rows `g_j(x) ≤ 0`, scaled so that all are O(1).

use super::study::{Constraint, ConstraintQuantity, Objective};
use crate::model::quantity::LN_CEIL;
use crate::model::{evaluate_from, Evaluation, EvaluationOptions, Quadrature, SearchHints, Status};

use super::design::DesignSpace;
use super::program::{NonlinearProgram, Values};

/// A row is never reported below this (ln units, a factor e^-700 inside its
/// limit): a row that far from its limit cannot matter, and its value must
/// not swamp the subproblem (a pull-off of 10^-2.6e8 N against a 1 µN cap).
pub const ROW_FLOOR: f64 = -700.0;

/// Which side of a constraint a row enforces (or of a bound the design lies on).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Side {
    /// quantity ≥ limit.
    Min,
    /// quantity ≤ limit.
    Max,
}

impl Side {
    /// "min" or "max", as problem files and reports write it.
    pub fn as_str(self) -> &'static str {
        match self {
            Side::Min => "min",
            Side::Max => "max",
        }
    }
}

impl std::fmt::Display for Side {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.pad(self.as_str())
    }
}

/// How a quantity is scaled into a row.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Scaling {
    /// `ln q - ln limit` (positive quantities).
    Log,
    /// `(q - limit) / scale` (quantities that may be ≤ 0).
    Linear(f64),
}

/// One scalar constraint row `g(x) ≤ 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Row {
    /// Index of the `[[constraint]]` it comes from.
    pub constraint: usize,
    /// The quantity.
    pub quantity: ConstraintQuantity,
    /// Min or max side.
    pub side: Side,
    /// The limit (SI).
    pub limit: f64,
    /// Scaling of the row.
    pub scaling: Scaling,
    /// The relative humidity the row holds at, in a study over a humidity range
    /// (docs/model.md §10: each limit holds at each of the range's humidities).
    pub humidity: Option<f64>,
}

impl Row {
    /// d(ln objective)/d(ln limit) for a multiplier λ of this row (envelope theorem).
    pub fn shadow_price(&self, multiplier: f64) -> f64 {
        let per_unit_b = match self.scaling {
            Scaling::Log => 1.0,
            Scaling::Linear(scale) => self.limit / scale,
        };
        match self.side {
            Side::Max => -multiplier * per_unit_b,
            Side::Min => multiplier * per_unit_b,
        }
    }
}

/// The value of a constraint quantity in SI (None where it does not exist): its
/// row of the quantity table's ([`crate::model::Quantity::value`]).
pub fn quantity_value(
    q: ConstraintQuantity,
    ev: &Evaluation,
    scene: &crate::model::Scene,
) -> Option<f64> {
    q.quantity().value(ev, scene)
}

/// The objective's ln value at an evaluation: the quantity table's
/// ([`crate::model::Quantity::ln_value`]), with NaN (no value to compare) as
/// [`LN_CEIL`], the worst.
pub fn ln_objective(o: Objective, ev: &Evaluation, scene: &crate::model::Scene) -> f64 {
    let v = o.quantity().ln_value(ev, scene);
    if v.is_nan() {
        LN_CEIL
    } else {
        v
    }
}

/// The objective in SI at an evaluation, 0 where it does not exist or is negative.
pub fn objective_value(o: Objective, ev: &Evaluation, scene: &crate::model::Scene) -> f64 {
    o.quantity().value(ev, scene).unwrap_or(0.0).max(0.0)
}

/// The study's functions at a design point.
#[derive(Debug, Clone, PartialEq)]
pub struct Point {
    /// The unit design point.
    pub x: Vec<f64>,
    /// ln of the objective.
    pub objective: f64,
    /// The constraint rows' values (≤ 0 is feasible).
    pub rows: Vec<f64>,
    /// The separation and pull-off found here, to start nearby searches from.
    pub hints: SearchHints,
}

impl Point {
    /// Σ max(0, g_j): the ℓ1 infeasibility.
    pub fn violation(&self) -> f64 {
        self.rows.iter().map(|g| g.max(0.0)).sum()
    }

    /// max_j max(0, g_j).
    pub fn max_violation(&self) -> f64 {
        self.rows.iter().fold(0.0, |m, g| m.max(*g))
    }
}

/// A study ready to evaluate: design space, objective, constraint rows.
#[derive(Debug, Clone)]
pub struct StudyFunctions {
    /// The scaled design space.
    pub space: DesignSpace,
    /// What to minimise.
    pub objective: Objective,
    /// The constraint rows.
    pub rows: Vec<Row>,
    /// What each evaluation computes.
    pub options: EvaluationOptions,
    /// Over a humidity range: the humidities every row is replicated at (empty: the
    /// scene's one humidity).
    pub humidities: Vec<f64>,
    /// Over a humidity range: the humidity the objective is taken at (the file's
    /// `design_humidity`, else the worst for the objective at the baseline design).
    pub objective_humidity: Option<f64>,
    /// A row holds the real area at or below the nominal one
    /// (`real_area_fraction` with a max ≤ 1): a design whose only fault is a
    /// real area above the nominal one is then evaluated (status
    /// `out_of_range`, every number finite) and the row, violated, steers the
    /// search back, instead of a wall the search runs into.
    pub area_row: bool,
}

/// Whether an evaluation's only fault is a real area above the nominal one
/// (its numbers all finite): what an explicit `real_area_fraction ≤ 1` row
/// can judge.
fn only_the_area_is_out_of_range(ev: &Evaluation) -> bool {
    use crate::model::Warning;
    ev.status == Status::OutOfRange
        && ev.separation.is_some()
        && ev
            .warnings
            .iter()
            .any(|w| matches!(w, Warning::RealAreaExceedsNominal { .. }))
        && !ev.warnings.iter().any(|w| {
            matches!(
                w,
                Warning::NonFiniteResult { .. } | Warning::LoadBeyondModel { .. }
            )
        })
}

impl StudyFunctions {
    /// The functions of a study; the pull-off search runs only when the
    /// objective or a constraint asks for the pull-off force.
    pub fn new(space: DesignSpace, objective: Objective, constraints: &[Constraint]) -> Self {
        let mut rows = Vec::new();
        for (i, c) in constraints.iter().enumerate() {
            let linear = matches!(
                c.quantity,
                ConstraintQuantity::Separation | ConstraintQuantity::PlasticAreaFraction
            );
            for (side, limit) in [(Side::Min, c.min), (Side::Max, c.max)] {
                let Some(limit) = limit else { continue };
                let scaling = if linear {
                    let reference = match c.quantity {
                        ConstraintQuantity::Separation => space.baseline.sigma,
                        _ => 0.01,
                    };
                    Scaling::Linear(limit.abs().max(reference))
                } else {
                    Scaling::Log
                };
                rows.push(Row {
                    constraint: i,
                    quantity: c.quantity,
                    side,
                    limit,
                    scaling,
                    humidity: None,
                });
            }
        }
        let pull_off = objective.quantity().needs_pull_off()
            || constraints
                .iter()
                .any(|c| c.quantity.quantity().needs_pull_off());
        let options = EvaluationOptions {
            pull_off,
            quadrature: Quadrature::default(),
            // No objective or constraint reads Γ: the integral is not needed.
            work_of_adhesion: false,
        };
        let area_row = constraints.iter().any(|c| {
            c.quantity == ConstraintQuantity::RealAreaFraction && c.max.is_some_and(|m| m <= 1.0)
        });
        let range = space
            .baseline
            .environment
            .and_then(|e| e.humidity_range.map(|r| (e.relative_humidity, r)));
        let Some((scene_rh, range)) = range else {
            return StudyFunctions {
                space,
                objective,
                rows,
                options,
                humidities: Vec::new(),
                objective_humidity: None,
                area_row,
            };
        };
        let humidities = range.humidities();
        let rows = rows
            .iter()
            .flat_map(|r| {
                let at: Vec<f64> = if constraints[r.constraint].only_at_objective_humidity {
                    vec![scene_rh]
                } else {
                    humidities.clone()
                };
                at.into_iter().map(move |h| Row {
                    humidity: Some(h),
                    ..*r
                })
            })
            .collect();
        let mut f = StudyFunctions {
            space,
            objective,
            rows,
            options,
            humidities,
            objective_humidity: Some(scene_rh),
            area_row,
        };
        if !range.design_given {
            // The worst humidity for the objective at the baseline design.
            let x = f.space.baseline_unit();
            let worst = f
                .humidities
                .iter()
                .filter_map(|&h| {
                    let scene = at_humidity(f.space.scene_at(&x), h);
                    let ev = evaluate_from(&scene, &f.options, SearchHints::default());
                    (ev.status == Status::Ok).then(|| (h, ln_objective(objective, &ev, &scene)))
                })
                .max_by(|a, b| a.1.total_cmp(&b.1));
            if let Some((h, _)) = worst {
                f.objective_humidity = Some(h);
            }
        }
        // Rows held only at the objective's humidity follow it.
        for r in f.rows.iter_mut() {
            if constraints[r.constraint].only_at_objective_humidity {
                r.humidity = f.objective_humidity;
            }
        }
        f
    }

    /// The scene at design x, at the humidity the objective is taken at.
    pub fn scene_at(&self, x: &[f64]) -> crate::model::Scene {
        let scene = self.space.scene_at(x);
        match self.objective_humidity {
            Some(h) => at_humidity(scene, h),
            None => scene,
        }
    }

    /// n.
    pub fn dim(&self) -> usize {
        self.space.dim()
    }

    /// Objective and rows at x (None when the surfaces are not in contact there).
    pub fn at(&self, x: &[f64]) -> Option<Point> {
        self.at_from(x, SearchHints::default())
    }

    /// As [`StudyFunctions::at`], starting the model's searches from `hints`
    /// (those of a nearby point); the result does not depend on them beyond
    /// the last few ulps of the separation.
    pub fn at_from(&self, x: &[f64], hints: SearchHints) -> Option<Point> {
        self.evaluated_at(x, hints).map(|(p, _)| p)
    }

    /// As [`StudyFunctions::at_from`], with the evaluation at the objective's
    /// humidity.
    pub fn evaluated_at(&self, x: &[f64], hints: SearchHints) -> Option<(Point, Evaluation)> {
        let scene = self.scene_at(x);
        let ev = evaluate_from(&scene, &self.options, hints);
        if !self.evaluable(&ev) {
            return None;
        }
        if self.humidities.is_empty() {
            return Some((self.point_of(x, &ev, &scene), ev));
        }
        // Every row at its humidity: one evaluation per humidity of the range.
        let mut point = self.point_of(x, &ev, &scene);
        for &h in &self.humidities {
            let s = at_humidity(self.space.scene_at(x), h);
            let e = if Some(h) == self.objective_humidity {
                ev.clone()
            } else {
                evaluate_from(&s, &self.options, SearchHints::default())
            };
            if !self.evaluable(&e) {
                return None;
            }
            for (j, r) in self.rows.iter().enumerate() {
                if r.humidity == Some(h) {
                    point.rows[j] = row_value(r, &e, &s);
                }
            }
        }
        Some((point, ev))
    }

    /// Whether the rows can judge an evaluation: status `ok`, or with an
    /// explicit area row ([`StudyFunctions::area_row`]) a real area above the
    /// nominal one as its only fault.
    fn evaluable(&self, ev: &Evaluation) -> bool {
        ev.status == Status::Ok || (self.area_row && only_the_area_is_out_of_range(ev))
    }

    /// Objective and rows from an evaluation already made.
    /// Over a humidity range every row is taken from this one evaluation: use
    /// [`StudyFunctions::at`] for the rows at their own humidities.
    pub fn point_of(&self, x: &[f64], ev: &Evaluation, scene: &crate::model::Scene) -> Point {
        let rows = self.rows.iter().map(|r| row_value(r, ev, scene)).collect();
        Point {
            x: x.to_vec(),
            objective: ln_objective(self.objective, ev, scene),
            rows,
            hints: SearchHints {
                separation: ev.nondimensional_separation,
                pull_off: ev.nondimensional_pull_off_separation,
            },
        }
    }
}

/// A row's value g (≤ 0 is feasible) from an evaluation.
fn row_value(r: &Row, ev: &Evaluation, scene: &crate::model::Scene) -> f64 {
    let g: f64 = match r.scaling {
        Scaling::Log => {
            let lq = r.quantity.quantity().ln_value(ev, scene);
            match r.side {
                Side::Max => lq - r.limit.ln(),
                Side::Min => r.limit.ln() - lq,
            }
        }
        Scaling::Linear(scale) => {
            let q = quantity_value(r.quantity, ev, scene).unwrap_or(0.0);
            match r.side {
                Side::Max => (q - r.limit) / scale,
                Side::Min => (r.limit - q) / scale,
            }
        }
    };
    if g.is_nan() {
        -ROW_FLOOR
    } else {
        g.max(ROW_FLOOR)
    }
}

/// The scene with its relative humidity set to `h` (its environment's other values kept).
pub fn at_humidity(mut scene: crate::model::Scene, h: f64) -> crate::model::Scene {
    if let Some(env) = scene.environment.as_mut() {
        env.relative_humidity = h;
    }
    scene
}

fn hints_of(near: &[f64]) -> SearchHints {
    let get = |i: usize| near.get(i).copied().filter(|v| v.is_finite());
    SearchHints {
        separation: get(0),
        pull_off: get(1),
    }
}

/// The study as a program on the unit box: f = ln(objective), g = the rows;
/// the warm-start data are the separation and pull-off found at a point.
impl NonlinearProgram for StudyFunctions {
    fn dimension(&self) -> usize {
        self.dim()
    }

    fn bounds(&self) -> (Vec<f64>, Vec<f64>) {
        (vec![0.0; self.dim()], vec![1.0; self.dim()])
    }

    /// f = ln(objective): the KKT test's complementarity is then in relative
    /// units of the objective, whatever unit it is written in.
    fn logarithmic_objective(&self) -> bool {
        true
    }

    fn objective(&self, x: &[f64]) -> Option<f64> {
        self.at(x).map(|p| p.objective)
    }

    fn constraints(&self, x: &[f64]) -> Option<Vec<f64>> {
        self.at(x).map(|p| p.rows)
    }

    fn evaluate(&self, x: &[f64], near: &[f64]) -> Option<Values> {
        self.values_at(x, near).map(|(v, _)| v)
    }
}

impl StudyFunctions {
    /// The program's values at x, searches started from `near` (a nearby
    /// point's `warm_start`), with the evaluation they come from.
    pub fn values_at(&self, x: &[f64], near: &[f64]) -> Option<(Values, Evaluation)> {
        let (p, ev) = self.evaluated_at(x, hints_of(near))?;
        let values = Values {
            objective: p.objective,
            constraints: p.rows,
            warm_start: vec![
                p.hints.separation.unwrap_or(f64::NAN),
                p.hints.pull_off.unwrap_or(f64::NAN),
            ],
        };
        Some((values, ev))
    }
}

impl Point {
    /// The point a solver's result describes.
    pub fn from_result(r: &super::SqpResult) -> Point {
        Point {
            x: r.x.clone(),
            objective: r.objective,
            rows: r.constraints.clone(),
            hints: hints_of(&r.warm_start),
        }
    }
}
