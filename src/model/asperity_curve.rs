//! The load–interference curve of one asperity in Maugis units (P̂ = P/(πγR),
//! δ̂ = δ (K²/(π²γ²R))^{1/3}, â = a (K/(πγR²))^{1/3}) under each asperity law:
//! the self-consistent Lennard-Jones sphere ([`super::lennard_jones`]), and JKR
//! and DMT in closed form for comparison. Where the curve is S-shaped it has
//! three branches — approach (until the jump into contact), unstable, contact
//! (until the jump out) — and one interference can carry a point on each.

use serde::Serialize;

use super::lennard_jones::{
    spacing, Hold, NotConverged, Sphere, SpherePoint, SphereSettings, SphereState,
};

/// The asperity laws a single-asperity curve is drawn for (the names of
/// `adhesion_model`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum CurveLaw {
    /// The self-consistent Lennard-Jones sphere.
    LennardJones,
    /// JKR (μ → ∞).
    Jkr,
    /// DMT with van der Waals attraction (μ → 0).
    Dmt,
}

impl CurveLaw {
    /// Every law, in the order options list them.
    pub const ALL: [CurveLaw; 3] = [CurveLaw::LennardJones, CurveLaw::Jkr, CurveLaw::Dmt];

    /// The word in options and reports.
    pub fn as_str(self) -> &'static str {
        match self {
            CurveLaw::LennardJones => "lennard_jones",
            CurveLaw::Jkr => "jkr",
            CurveLaw::Dmt => "dmt",
        }
    }

    /// The law named `name`.
    pub fn from_name(name: &str) -> Option<CurveLaw> {
        Self::ALL.into_iter().find(|m| m.as_str() == name)
    }
}

/// Which branch of the curve a point lies on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Branch {
    /// Out of contact, or before the jump into contact.
    Approach,
    /// Between the two jumps (no stable equilibrium under a rigid support).
    Unstable,
    /// In contact, from the jump out onwards.
    Contact,
}

impl Branch {
    /// The word in CSV and reports.
    pub fn as_str(self) -> &'static str {
        match self {
            Branch::Approach => "approach",
            Branch::Unstable => "unstable",
            Branch::Contact => "contact",
        }
    }
}

/// One equilibrium on the curve.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CurvePoint {
    /// δ̂.
    pub interference: f64,
    /// P̂ (compressive positive).
    pub load: f64,
    /// â.
    pub contact_radius: f64,
    /// The branch.
    pub branch: Branch,
}

/// A point of the curve named by its interference and load.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CurveMark {
    /// δ̂.
    pub interference: f64,
    /// P̂.
    pub load: f64,
}

/// The curve of one asperity law at one Tabor parameter.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AsperityCurve {
    /// The law.
    pub law: CurveLaw,
    /// μ.
    pub tabor: f64,
    /// The points asked for, by interference then branch.
    pub points: Vec<CurvePoint>,
    /// The most tensile load of the curve (the pull-off under a load control)
    /// and where it is.
    pub pull_off: CurveMark,
    /// The last stable point of the approach branch (None if the curve is
    /// single-valued).
    pub jump_in: Option<CurveMark>,
    /// The last stable point of the contact branch on retraction.
    pub jump_out: Option<CurveMark>,
    /// The curve drawn densely, in order along it (for plots): for an S-shaped
    /// curve approach, unstable and contact branches in turn. A solved
    /// Lennard-Jones curve's are its trace's points and, between them, their
    /// cubic Hermite interpolant in the arclength (a drawing, not rows).
    pub path: Vec<CurvePoint>,
}

/// The evenly spaced interferences `from..=to` (`points` ≥ 2).
///
/// A point that rounding leaves a few ulps off zero is zero (−1.2 … 2 in nine
/// points printed its fourth as 2.2e-16).
fn targets(from: f64, to: f64, points: usize) -> Vec<f64> {
    let n = points.max(2);
    let ulps = 4.0 * f64::EPSILON * from.abs().max(to.abs());
    (0..n)
        .map(|i| {
            if i + 1 == n {
                to
            } else {
                let x = from + (to - from) * i as f64 / (n - 1) as f64;
                if x.abs() <= ulps {
                    0.0
                } else {
                    x
                }
            }
        })
        .collect()
}

/// The JKR curve (docs/model.md §3 in Maugis units): P̂ = â³ − √(6â³),
/// δ̂ = â² − (2/3)√(6â) in contact; no force before contact, and contact from
/// δ̂ = 0 on.
pub fn jkr_curve(from: f64, to: f64, points: usize) -> AsperityCurve {
    let six = 6.0_f64.sqrt();
    let at = |a: f64| CurvePoint {
        interference: a * a - 2.0 / 3.0 * (6.0 * a).sqrt(),
        load: a * a * a - six * (a * a * a).sqrt(),
        contact_radius: a,
        branch: Branch::Contact,
    };
    // dδ̂/dâ = 0 at â^{3/2} = √6/6: the jump out.
    let a_out = (six / 6.0).powf(2.0 / 3.0);
    let out = at(a_out);
    // The radius on a monotone stretch of δ̂(â) by bisection.
    let radius = |target: f64, mut lo: f64, mut hi: f64| {
        let rising = at(hi).interference > at(lo).interference;
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if (at(mid).interference < target) == rising {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    };
    let mut rows = Vec::new();
    for target in targets(from, to, points) {
        if target < 0.0 {
            rows.push(CurvePoint {
                interference: target,
                load: 0.0,
                contact_radius: 0.0,
                branch: Branch::Approach,
            });
        }
        if target >= out.interference && target < 0.0 {
            let a = radius(target, 0.0, a_out);
            rows.push(CurvePoint {
                branch: Branch::Unstable,
                interference: target,
                ..at(a)
            });
        }
        if target >= out.interference {
            let mut hi = 2.0;
            while at(hi).interference < target {
                hi *= 2.0;
            }
            let a = radius(target, a_out, hi);
            rows.push(CurvePoint {
                interference: target,
                ..at(a)
            });
        }
    }
    let a_pull = 1.5_f64.cbrt();
    let pull = at(a_pull);
    let mut a_to = 2.0;
    while at(a_to).interference < to {
        a_to *= 1.5;
    }
    let mut path = vec![
        CurvePoint {
            interference: from.min(0.0),
            load: 0.0,
            contact_radius: 0.0,
            branch: Branch::Approach,
        },
        CurvePoint {
            interference: 0.0,
            load: 0.0,
            contact_radius: 0.0,
            branch: Branch::Approach,
        },
    ];
    path.extend((0..=400).map(|i| {
        let a = a_to * (i as f64 / 400.0).powi(2);
        CurvePoint {
            branch: if a < a_out {
                Branch::Unstable
            } else {
                Branch::Contact
            },
            ..at(a)
        }
    }));
    AsperityCurve {
        law: CurveLaw::Jkr,
        tabor: f64::INFINITY,
        points: rows,
        pull_off: CurveMark {
            interference: pull.interference,
            load: -1.5,
        },
        jump_in: Some(CurveMark {
            interference: 0.0,
            load: 0.0,
        }),
        jump_out: Some(CurveMark {
            interference: out.interference,
            load: out.load,
        }),
        path,
    }
}

/// The DMT curve with van der Waals attraction (docs/model.md §7 in Maugis
/// units, ẑ0 of μ): P̂ = δ̂^{3/2} − 2 in contact, −2 (ẑ0/(ẑ0 − δ̂))² outside.
pub fn dmt_curve(tabor: f64, from: f64, to: f64, points: usize) -> AsperityCurve {
    let z0 = spacing(tabor);
    let at = |d: f64| {
        if d >= 0.0 {
            CurvePoint {
                interference: d,
                load: d * d.sqrt() - 2.0,
                contact_radius: d.sqrt(),
                branch: Branch::Contact,
            }
        } else {
            let x = z0 / (z0 - d);
            CurvePoint {
                interference: d,
                load: -2.0 * x * x,
                contact_radius: 0.0,
                branch: Branch::Approach,
            }
        }
    };
    single_valued(CurveLaw::Dmt, tabor, (from, to, points), at, true)
}

/// A single-valued closed-form curve whose pull-off is −2 at δ̂ = 0 (DMT and
/// the Bradley–DMT limit): rows at the targets, a 401-point path (with δ̂ = 0,
/// the joint of the two pieces, when `joint` and the range spans it).
fn single_valued(
    law: CurveLaw,
    tabor: f64,
    (from, to, points): (f64, f64, usize),
    at: impl Fn(f64) -> CurvePoint,
    joint: bool,
) -> AsperityCurve {
    let rows = targets(from, to, points).into_iter().map(&at).collect();
    let mut path: Vec<CurvePoint> = targets(from, to, 401).into_iter().map(&at).collect();
    if joint && from < 0.0 && to > 0.0 {
        path.push(at(0.0));
        path.sort_by(|a, b| a.interference.total_cmp(&b.interference));
    }
    AsperityCurve {
        law,
        tabor,
        points: rows,
        pull_off: CurveMark {
            interference: 0.0,
            load: -2.0,
        },
        jump_in: None,
        jump_out: None,
        path,
    }
}

/// The Tabor parameters over which the Lennard-Jones sphere is solved; outside,
/// its curve is its closed-form limit ([`bradley_dmt_curve`] below, JKR above).
pub const SOLVED_TABOR: (f64, f64) = (1e-3, 100.0);

/// The pull-off's relative error of the limit at each end of [`SOLVED_TABOR`],
/// measured against the converged solver there (1.999967 at μ = 10⁻³ against
/// Bradley's 2; 1.500206 at μ = 100 against JKR's 1.5 — 1.52572 at μ = 5,
/// 1.50931 at 10; `tests/all/asperity.rs`).
pub const LIMIT_PULL_OFF_ERROR: (f64, f64) = (1.6e-5, 1.38e-4);

/// What a solved Lennard-Jones curve's numbers are good to (absolute, in
/// Maugis units), measured against the independent solution of
/// `scripts/reference_lennard_jones.py` (docs/model.md §11, `tests/all/asperity.rs`):
/// the pull-off and the jumps, converged ([`CONVERGED_MARKS`]; the load at
/// the jump out 1.7e-5, the rest below 1e-7); the rows on the default mesh
/// out of contact (6.0e-4) and in it (4.4e-2 at μ = 3).
pub const CURVE_ERROR: (f64, f64, f64) = (2e-5, 1e-3, 5e-2);

/// The Tabor parameters at which the independent solution
/// (`scripts/reference_lennard_jones.py`) was computed and [`CURVE_ERROR`]
/// measured against it: μ = 0.05 … 10 (at 30 and 100 it did not run: its far
/// field's start fails, or it did not finish in 30 minutes). Outside, the
/// solver's own refinement is the check.
pub const INDEPENDENTLY_CHECKED: (f64, f64) = (0.05, 10.0);

/// What `wearopt asperity` solves with: the trace on the default mesh, the
/// pull-off and the jumps extrapolated to the converged solution.
pub const CONVERGED_MARKS: SphereSettings = SphereSettings {
    refinement: 1.0,
    extrapolate: true,
};

/// The closed form the Lennard-Jones law takes outside [`SOLVED_TABOR`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Limit {
    /// μ below the range: a rigid sphere (Bradley) out of contact, Hertz minus
    /// 2πγR (DMT) in it.
    BradleyDmt,
    /// μ above the range: JKR.
    Jkr,
}

impl Limit {
    /// The word in reports.
    pub fn as_str(self) -> &'static str {
        match self {
            Limit::BradleyDmt => "bradley_dmt",
            Limit::Jkr => "jkr",
        }
    }
}

/// Where a Lennard-Jones curve was replaced by its limit, and what that costs.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LimitNote {
    /// The limit used.
    pub limit: Limit,
    /// The Tabor parameter where the solver hands over.
    pub switch_tabor: f64,
    /// The pull-off's relative error of the limit there.
    pub pull_off_error: f64,
}

/// The small-μ limit of the Lennard-Jones sphere (docs/model.md §11): rigid,
/// Bradley's P̂ = (2/3)[(ẑ0/D)⁸ − 4(ẑ0/D)²] at apex gap D = ẑ0 − δ̂ < ẑ0, and
/// DMT's Hertz load minus 2 once δ̂ ≥ 0 (the two meet at −2); the contact
/// radius where the rigid gap is 3^{1/6} Z0.
pub fn bradley_dmt_curve(tabor: f64, from: f64, to: f64, points: usize) -> AsperityCurve {
    let z0 = spacing(tabor);
    let at = |d: f64| {
        let reach = 2.0 * (super::lennard_jones::sphere::TENSION_GAP * z0 - z0 + d);
        let contact_radius = if reach > 0.0 { reach.sqrt() } else { 0.0 };
        let load = if d >= 0.0 {
            d * d.sqrt() - 2.0
        } else {
            let x = z0 / (z0 - d);
            let x2 = x * x;
            2.0 / 3.0 * (x2 * x2 * x2 * x2 - 4.0 * x2)
        };
        CurvePoint {
            interference: d,
            load,
            contact_radius,
            branch: if contact_radius > 0.0 {
                Branch::Contact
            } else {
                Branch::Approach
            },
        }
    };
    single_valued(CurveLaw::LennardJones, tabor, (from, to, points), at, false)
}

/// The curve of `law` at Tabor parameter μ (> 0, finite) over `from..=to`
/// (`points` evenly spaced), and, for the Lennard-Jones law outside
/// [`SOLVED_TABOR`], which limit stands in for the solver. A solved curve's
/// rows are on the trace's mesh ([`RowAccuracy::Fast`]).
pub fn asperity_curve(
    law: CurveLaw,
    tabor: f64,
    from: f64,
    to: f64,
    points: usize,
) -> Result<(AsperityCurve, Option<LimitNote>), CurveError> {
    asperity_curve_with(
        law,
        tabor,
        (from, to, points),
        RowAccuracy::Fast,
        &|_, _| {},
    )
}

/// [`asperity_curve`] with a solved curve's rows computed as `rows` says,
/// and `progress(done, total)` called as its converged points finish
/// ([`lennard_jones_curve_with`]; closed forms call it never).
pub fn asperity_curve_with(
    law: CurveLaw,
    tabor: f64,
    (from, to, points): (f64, f64, usize),
    rows: RowAccuracy,
    progress: &dyn Fn(usize, usize),
) -> Result<(AsperityCurve, Option<LimitNote>), CurveError> {
    Ok(match law {
        CurveLaw::Jkr => (
            AsperityCurve {
                tabor,
                ..jkr_curve(from, to, points)
            },
            None,
        ),
        CurveLaw::Dmt => (dmt_curve(tabor, from, to, points), None),
        CurveLaw::LennardJones if tabor < SOLVED_TABOR.0 => (
            bradley_dmt_curve(tabor, from, to, points),
            Some(LimitNote {
                limit: Limit::BradleyDmt,
                switch_tabor: SOLVED_TABOR.0,
                pull_off_error: LIMIT_PULL_OFF_ERROR.0,
            }),
        ),
        CurveLaw::LennardJones if tabor > SOLVED_TABOR.1 => (
            AsperityCurve {
                law: CurveLaw::LennardJones,
                tabor,
                ..jkr_curve(from, to, points)
            },
            Some(LimitNote {
                limit: Limit::Jkr,
                switch_tabor: SOLVED_TABOR.1,
                pull_off_error: LIMIT_PULL_OFF_ERROR.1,
            }),
        ),
        CurveLaw::LennardJones => (
            lennard_jones_curve_with(tabor, (from, to, points), CONVERGED_MARKS, rows, progress)?,
            None,
        ),
    })
}

/// Why a Lennard-Jones curve could not be traced.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CurveError {
    /// Newton's method failed at this apex gap (over Z0) and at every shorter step.
    NotConverged(f64),
}

impl From<NotConverged> for CurveError {
    fn from(error: NotConverged) -> Self {
        CurveError::NotConverged(error.apex_gap)
    }
}

/// One step of the trace: the state it starts from (on the mesh of the step),
/// the arclength, and the state it reaches.
#[derive(Clone)]
struct Window {
    start: SphereState,
    length: f64,
    end: SphereState,
}

/// The state in `window` where `f` vanishes (`f` of opposite signs at its
/// ends), by the Illinois variant of regula falsi on the arclength, and its
/// arclength from the window's start.
fn root(
    sphere: &Sphere,
    window: &Window,
    f: impl Fn(&SphereState) -> f64,
) -> Result<(SphereState, f64), CurveError> {
    let (mut a, mut fa, mut state_a) = (0.0, f(&window.start), window.start.clone());
    let (mut b, mut fb, mut state_b) = (window.length, f(&window.end), window.end.clone());
    let mut best = (window.end.clone(), b);
    let mut side = 0;
    for _ in 0..100 {
        let mut x = b - fb * (b - a) / (fb - fa);
        if !(x > a.min(b) && x < a.max(b)) {
            x = 0.5 * (a + b);
        }
        let state = sphere.step_between(&window.start, x, (&state_a, a), (&state_b, b))?;
        let fx = f(&state);
        best = (state.clone(), x);
        if fx == 0.0 || (b - a).abs() <= 1e-13 * window.length {
            break;
        }
        if (fx > 0.0) == (fb > 0.0) {
            b = x;
            fb = fx;
            state_b = state;
            if side == 1 {
                fa *= 0.5;
            }
            side = 1;
        } else {
            a = x;
            fa = fx;
            state_a = state;
            if side == -1 {
                fb *= 0.5;
            }
            side = -1;
        }
    }
    Ok(best)
}

/// The Tabor parameter above which the trace's mesh stretches with the
/// contact radius once a contact has formed ([`Sphere::stretch`]); at and
/// below it, where the table's curves were written, the trace regrades a
/// fixed mesh as the edge moves.
pub const STRETCH_ABOVE: f64 = 5.0;

/// Traces the Lennard-Jones curve by pseudo-arclength continuation from the
/// far field (δ̂ below `from`) towards the flat, until the contact branch
/// passes `to` beyond the load minimum. On the contact branch: the apex in
/// repulsion (its gap below Z0) — above μ ≈ 4 the approach branch turns four
/// times, and between its turns δ̂ and P̂ both rise again before any contact
/// (at μ = 7 with `to` = −0.5 the trace stopped there, and reported a pull-off
/// of −0.149 for −1.517).
fn trace(sphere: &Sphere, from: f64, to: f64) -> Result<Vec<Window>, CurveError> {
    trace_until(sphere, from, to, |q| {
        q.interference >= to
            && q.interference_slope > 0.0
            && q.load_slope > 0.0
            && q.apex_gap < SPLIT_GAP
    })
}

/// The most tensile load along the traced path: the deepest minimum of P̂
/// (where a sphere under load control comes off, on the retraction neck or
/// the contact branch).
fn deepest_minimum(sphere: &Sphere, windows: &[Window]) -> Result<SphereState, CurveError> {
    let load_slope = |s: &SphereState| s.point.load_slope;
    let mut pull_off = windows
        .iter()
        .map(|w| &w.end)
        .min_by(|a, b| a.point.load.total_cmp(&b.point.load))
        .expect("a trace has a step")
        .clone();
    for w in windows {
        if load_slope(&w.start) < 0.0 && load_slope(&w.end) >= 0.0 {
            let (state, _) = root(sphere, w, load_slope)?;
            if state.point.load < pull_off.point.load {
                pull_off = state;
            }
        }
    }
    Ok(pull_off)
}

/// The far-field state at apex gap `start` (over Z0), or the first further
/// out (by factors of 1.5) where Newton's method from the rigid sphere
/// converges; `start` becomes that gap.
fn far_from(sphere: &Sphere, start: &mut f64) -> Result<SphereState, CurveError> {
    loop {
        match sphere.far(*start) {
            Ok(state) => return Ok(state),
            Err(e) if *start > 1e6 => return Err(e.into()),
            Err(_) => *start *= 1.5,
        }
    }
}

/// How a trace is stepped: the interference it starts at or below, its step
/// in δ̂ out of the stretching mesh, and the largest contact radius a
/// stretching mesh is made for ([`Sphere::stretch`]).
#[derive(Debug, Clone, Copy)]
struct TracePlan {
    from: f64,
    tau_d: f64,
    largest: f64,
}

/// [`trace`] until `done` holds of the last point (`to` only sets the step).
fn trace_until(
    sphere: &Sphere,
    from: f64,
    to: f64,
    done: impl Fn(&SpherePoint) -> bool,
) -> Result<Vec<Window>, CurveError> {
    let span = (to - from).abs().max(1e-3);
    let plan = TracePlan {
        from,
        tau_d: (span / 50.0).min(0.1).max(0.02 * sphere.z0),
        largest: 1.0 + 1.3 * (to.max(0.0) + 1.0).sqrt(),
    };
    trace_planned(sphere, plan, |q, _| done(q))
}

/// The trace of `plan` until `done` holds of the last point (and the number
/// of windows, that point's included).
fn trace_planned(
    sphere: &Sphere,
    plan: TracePlan,
    mut done: impl FnMut(&SpherePoint, usize) -> bool,
) -> Result<Vec<Window>, CurveError> {
    let z0 = sphere.z0;
    let from = plan.from;
    let mut start = (1.0 - from / z0 + 0.5).max(2.0);
    // Newton from the rigid sphere converges only where the attraction
    // deforms it little: at large μ not at a few Z0 (μ = 78 and 100 at 3.5
    // Z0, before the jump in), so the trace starts further out there.
    let mut first = far_from(sphere, &mut start)?;
    while first.point.interference > from {
        start *= 1.5;
        first = far_from(sphere, &mut start)?;
    }
    let (tau_d, tau_p, tau_a): (f64, f64, f64) = (plan.tau_d, 0.1, 0.1);
    let mut windows: Vec<Window> = Vec::new();
    let mut last = first;
    let mut length = 0.05 * start;
    for _ in 0..100_000 {
        if length < 1e-14 * (1.0 + last.point.apex_gap) {
            return Err(CurveError::NotConverged(last.point.apex_gap));
        }
        let from_state = sphere.regrade(&last).unwrap_or_else(|| last.clone());
        let next = match sphere.step(&from_state, length) {
            Ok(next) => next,
            Err(_) => {
                length *= 0.5;
                continue;
            }
        };
        let (p, q) = (&from_state.point, &next.point);
        // Deep in contact, steps of 5 % in P̂ (on the fixed mesh the contact
        // radius's step, at most 0.2, still binds there: at μ = 0.01 the
        // trace to δ̂ = 904, P̂ ≈ 2.5e4, would have taken 2.5e5 steps of 0.1,
        // and stopped at the loop's 1e5); on the stretching mesh in δ̂ too (a
        // curve to δ̂ = 30 at μ = 100, P̂ = 163, took 1600 steps of 0.1).
        let tau_p = tau_p.max(0.05 * p.load.abs());
        let tau_d = if from_state.stretches() {
            tau_d.max(0.05 * p.interference.abs())
        } else {
            tau_d
        };
        let ratio = ((q.interference - p.interference).abs() / tau_d)
            .max((q.load - p.load).abs() / tau_p)
            .max((q.contact_radius - p.contact_radius).abs() / tau_a.min(from_state.edge_reach()));
        if ratio > 2.0
            || q.apex_gap <= 0.05
            || next.turn(&from_state) < 0.9
            || hides_turns(
                length * p.interference_slope,
                length * q.interference_slope,
                q.interference - p.interference,
            )
        {
            length *= 0.5;
            continue;
        }
        let done = done(q, windows.len() + 1);
        windows.push(Window {
            start: from_state,
            length,
            end: next.clone(),
        });
        length *= (1.0 / ratio.max(1e-3)).clamp(0.5, 1.6);
        last = next;
        // Above the table's range the cohesive zone is so narrow against the
        // contact radius that a mesh graded at a fixed edge would bind the
        // steps to it (a trace at μ = 10 took 313 s that way, 12 s
        // stretching; μ = 100 would take some hours): once the contact is ten
        // such steps wide, the mesh stretches with the contact radius.
        if sphere.tabor > STRETCH_ABOVE
            && !last.stretches()
            && last.point.contact_radius >= 10.0 * last.edge_reach()
        {
            if let Some(stretched) = sphere.stretch(&last, plan.largest) {
                last = stretched;
            }
        }
        if done {
            return Ok(windows);
        }
    }
    Err(CurveError::NotConverged(last.point.apex_gap))
}

/// Whether a step whose δ̂ changes by `change`, with slopes `start` and `end`
/// (dδ̂/ds times the step's length) of one sign, hides two turns of δ̂: the
/// derivative of δ̂'s cubic Hermite interpolant over the step changes sign
/// inside it. Just above the cusp (μ_c = 0.6972) the S-shape's turns lie
/// within 1.5e-3 of δ̂ at μ = 0.715, and a step of 0.1 went from one side of
/// the S to the other with δ̂ falling but slopes both positive: the curve was
/// taken for single-valued (`wearopt asperity` put the cusp at 0.7093), or
/// no node bracketed its jump.
fn hides_turns(start: f64, end: f64, change: f64) -> bool {
    if start * end <= 0.0 {
        return false;
    }
    // The derivative a + b t + c t² on t ∈ [0, 1]: start at 0, end at 1, and
    // `change` its integral.
    let (a, c) = (start, 3.0 * (start + end) - 6.0 * change);
    let b = end - start - c;
    let vertex = -b / (2.0 * c);
    if !(c != 0.0 && vertex > 0.0 && vertex < 1.0) {
        return false;
    }
    let least = a + vertex * (b + c * vertex);
    least * start < 0.0
}

/// The equilibria of the Lennard-Jones sphere at the apex gaps `gaps` (over
/// Z0, in decreasing order, the first at least 1.5), each the first along the
/// path from the far field: the solver's points as an independent solution
/// tabulates them.
pub fn lennard_jones_at_apex_gaps(
    tabor: f64,
    gaps: &[f64],
    settings: SphereSettings,
) -> Result<Vec<SpherePoint>, CurveError> {
    let sphere = Sphere::new(tabor, settings);
    let last = gaps.iter().copied().fold(f64::INFINITY, f64::min);
    let first = gaps.iter().copied().fold(1.5, f64::max);
    let from = sphere.z0 * (1.0 - first) - 0.1;
    let windows = trace_until(&sphere, from, from + 4.0, |q| q.apex_gap < last)?;
    gaps.iter()
        .map(|&g| {
            let w = windows
                .iter()
                .find(|w| (w.start.point.apex_gap - g) * (w.end.point.apex_gap - g) <= 0.0)
                .ok_or(CurveError::NotConverged(g))?;
            let state = root(&sphere, w, |s| s.point.apex_gap - g)?.0;
            finish(&sphere, &state, Hold::ApexGap)
        })
        .collect()
}

/// The point `state` makes, extrapolated to the converged solution where the
/// sphere's settings ask for it.
fn finish(sphere: &Sphere, state: &SphereState, hold: Hold) -> Result<SpherePoint, CurveError> {
    if sphere.settings.extrapolate {
        Ok(sphere.extrapolated(state, hold)?.0)
    } else {
        Ok(state.point)
    }
}

/// How the rows of a solved Lennard-Jones curve are computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum RowAccuracy {
    /// Each row solved again on three nested meshes and extrapolated, as the
    /// marks are ([`Sphere::extrapolated`], docs/model.md §11 *Accuracy*);
    /// [`ROWS_ERROR`] states what is left.
    Converged,
    /// The trace's own mesh (`wearopt asperity --fast`), within
    /// [`CURVE_ERROR`]'s second and third figures.
    Fast,
}

impl RowAccuracy {
    /// The word in reports (`rows_accuracy`).
    pub fn as_str(self) -> &'static str {
        match self {
            RowAccuracy::Converged => "converged",
            RowAccuracy::Fast => "fast",
        }
    }
}

/// What converged rows are good to: relative to the load (or absolute where
/// |P̂| < 1e-3, near P̂ = 0), measured against the independent solution of
/// `scripts/reference_lennard_jones.py` (`tests/all/asperity.rs`,
/// `converged_rows_match_the_independent_points`).
pub const ROWS_ERROR: (f64, f64) = (1e-5, 1e-8);

/// What the marks are good to, absolute in Maugis units, against the
/// independent solution at μ = 0.05 … 10 (`tests/all/asperity.rs`,
/// `matches_the_independent_solution`; measured 2.2e-7, 1.9e-8 and 1.04e-5):
/// the pull-off's load, the jump in (load and interference), the jump out's
/// load (its interference within 3e-8). [`CURVE_ERROR`]'s first figure is
/// the largest.
pub const MARKS_ERROR: (f64, f64, f64) = (3e-7, 2e-8, 2e-5);

/// The interference (Maugis units) at or below which every solved
/// Lennard-Jones curve's trace starts (or −2ẑ0 where that is further out),
/// whatever rows are asked for: the jumps lie above −1 at every μ, and one
/// trace from one start gives the same marks for every range (rows asked
/// for below it come from a second trace that ends there).
pub const TRACE_FROM: f64 = -2.0;

/// The interference the trace passes on the contact branch, its load rising
/// and its apex in repulsion, before the marks are read from it: past the
/// pull-off and the jump out at every μ (both below −0.2), whatever `to`.
pub const MARKS_TO: f64 = 0.5;

/// The trace's step in δ̂ out of a stretching mesh (or 0.02 ẑ0 where larger).
const TRACE_STEP: f64 = 0.05;

/// The Lennard-Jones curve at Tabor parameter μ over interferences
/// `from..=to` (`points` evenly spaced, one row per branch that reaches each),
/// its rows on the trace's mesh ([`RowAccuracy::Fast`]).
pub fn lennard_jones_curve(
    tabor: f64,
    from: f64,
    to: f64,
    points: usize,
    settings: SphereSettings,
) -> Result<AsperityCurve, CurveError> {
    lennard_jones_curve_with(
        tabor,
        (from, to, points),
        settings,
        RowAccuracy::Fast,
        &|_, _| {},
    )
}

/// One row before its load is read: the state the trace found at it.
struct RowState {
    interference: f64,
    branch: Branch,
    state: SphereState,
}

/// The states of `windows` at interference `target`: each crossing once (a
/// window owns its end, the first its start too), with its window and
/// arclength.
fn crossings(
    sphere: &Sphere,
    windows: &[Window],
    target: f64,
) -> Result<Vec<(usize, f64, SphereState)>, CurveError> {
    let mut out = Vec::new();
    for (k, w) in windows.iter().enumerate() {
        let (da, db) = (
            w.start.point.interference - target,
            w.end.point.interference - target,
        );
        let crosses = (da > 0.0) != (db > 0.0) || db == 0.0 || (k == 0 && da == 0.0);
        if !crosses || (da == 0.0 && k > 0) {
            continue;
        }
        let (state, at) = if db == 0.0 {
            (w.end.clone(), w.length)
        } else if da == 0.0 {
            (w.start.clone(), 0.0)
        } else {
            root(sphere, w, |s| s.point.interference - target)?
        };
        out.push((k, at, state));
    }
    Ok(out)
}

/// The converged point at interference `target` near the trace's `state`:
/// extrapolated holding δ̂ ([`Sphere::extrapolated_at`]); where that solve
/// fails or lands on another branch (δ̂ turns within the discretisation's
/// error of the row), holding what a turn is found in and moved to `target`
/// along the path's slope dP̂/dδ̂.
fn converged_row(
    sphere: &Sphere,
    state: &SphereState,
    target: f64,
) -> Result<SpherePoint, CurveError> {
    let near = |p: &SpherePoint| {
        (p.load - state.point.load).abs() <= 1e-2 * (1.0 + state.point.load.abs())
            && (p.contact_radius - state.point.contact_radius).abs()
                <= 1e-2 * (1.0 + state.point.contact_radius)
    };
    if let Ok((p, _)) = sphere.extrapolated_point(state, target, Hold::Interference) {
        if near(&p) {
            return Ok(p);
        }
    }

    let (p, _) = sphere.extrapolated(state, state.turn_hold())?;
    let slope = p.load_slope / p.interference_slope;
    let shift = target - p.interference;
    if !(slope * shift).is_finite() || !near(&p) {
        return Err(CurveError::NotConverged(state.point.apex_gap));
    }
    Ok(SpherePoint {
        interference: target,
        load: p.load + slope * shift,
        ..p
    })
}

/// [`lennard_jones_curve`] with the rows computed as `rows_accuracy` says,
/// calling `progress(done, total)` as converged points (rows and marks)
/// finish. The trace starts at [`TRACE_FROM`] and passes [`MARKS_TO`]
/// whatever the range, and the marks are read from that part of it alone:
/// they are the same for every `from`, `to` and `points`.
pub fn lennard_jones_curve_with(
    tabor: f64,
    (from, to, points): (f64, f64, usize),
    settings: SphereSettings,
    rows_accuracy: RowAccuracy,
    progress: &dyn Fn(usize, usize),
) -> Result<AsperityCurve, CurveError> {
    curve_at(
        tabor,
        &targets(from, to, points),
        settings,
        rows_accuracy,
        progress,
    )
}

/// [`lennard_jones_curve_with`] with its rows at the interferences `at`
/// (any order, not empty) instead of an even grid: what an independent
/// solution's points are checked at.
pub fn lennard_jones_rows_at(
    tabor: f64,
    at: &[f64],
    settings: SphereSettings,
    rows_accuracy: RowAccuracy,
) -> Result<AsperityCurve, CurveError> {
    curve_at(tabor, at, settings, rows_accuracy, &|_, _| {})
}

fn curve_at(
    tabor: f64,
    at: &[f64],
    settings: SphereSettings,
    rows_accuracy: RowAccuracy,
    progress: &dyn Fn(usize, usize),
) -> Result<AsperityCurve, CurveError> {
    let from = at.iter().copied().fold(f64::INFINITY, f64::min);
    let to = at.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let sphere = Sphere::new(tabor, settings);
    let z0 = sphere.z0;
    let plan = TracePlan {
        from: TRACE_FROM.min(-2.0 * z0),
        tau_d: TRACE_STEP.max(0.02 * z0),
        largest: 1.0 + 1.3 * (MARKS_TO + 1.0).sqrt(),
    };
    // Past `end` on the contact branch: the apex in repulsion (its gap below
    // Z0) — above μ ≈ 4 the approach branch turns four times, and between its
    // turns δ̂ and P̂ both rise again before any contact.
    let past = |q: &SpherePoint, end: f64| {
        q.interference >= end
            && q.interference_slope > 0.0
            && q.load_slope > 0.0
            && q.apex_gap < SPLIT_GAP
    };
    let mut marks_end = 0;
    let windows = trace_planned(&sphere, plan, |q, n| {
        if marks_end == 0 && past(q, MARKS_TO) {
            marks_end = n;
        }
        marks_end > 0 && past(q, to)
    })?;
    let marked = &windows[..marks_end];
    let start = windows[0].start.point.interference;
    // Rows asked for further out: a second trace, from below `from` to the
    // first's start (single-valued there, on the approach branch).
    let outer = if from < start {
        trace_until(&sphere, from, start, |q| q.interference >= start)?
    } else {
        Vec::new()
    };
    // Turning points of δ̂ along the path (the jumps), refined.
    let slope = |s: &SphereState| s.point.interference_slope;
    let mut turns = Vec::new();
    for (k, w) in marked.iter().enumerate() {
        if (slope(&w.start) > 0.0) != (slope(&w.end) > 0.0) {
            let (state, at) = root(&sphere, w, slope)?;
            turns.push((k, at, state));
        }
    }
    let pull_off = deepest_minimum(&sphere, marked)?;
    let s_shaped = turns.len() >= 2;
    // Branches: the segments of monotone δ̂ between the turning points (a
    // point at arclength `at` in window k has passed the turns before it).
    let unturned = |p: &SpherePoint| {
        if s_shaped || p.contact_radius <= 0.0 {
            Branch::Approach
        } else {
            Branch::Contact
        }
    };
    let branch_after = |k: usize, at: f64, p: &SpherePoint| {
        let passed = turns
            .iter()
            .filter(|t| t.0 < k || (t.0 == k && t.1 < at))
            .count();
        if s_shaped {
            match passed {
                0 => Branch::Approach,
                n if n >= turns.len() => Branch::Contact,
                _ => Branch::Unstable,
            }
        } else {
            unturned(p)
        }
    };
    let mut found = Vec::new();
    for &target in at {
        if target < start {
            for (_, _, state) in crossings(&sphere, &outer, target)? {
                found.push(RowState {
                    interference: target,
                    branch: unturned(&state.point),
                    state,
                });
            }
        } else {
            for (k, at, state) in crossings(&sphere, &windows, target)? {
                found.push(RowState {
                    interference: target,
                    branch: branch_after(k, at, &state.point),
                    state,
                });
            }
        }
    }
    found.sort_by(|a, b| {
        a.interference
            .total_cmp(&b.interference)
            .then(a.branch.cmp(&b.branch))
    });
    // A target between one step's end and the next's regraded start is found
    // in both: the branch holds one point per interference.
    found.dedup_by(|a, b| a.interference == b.interference && a.branch == b.branch);
    let marks_total = if sphere.settings.extrapolate {
        1 + 2 * usize::from(s_shaped)
    } else {
        0
    };
    let converging = rows_accuracy == RowAccuracy::Converged;
    let total = marks_total + if converging { found.len() } else { 0 };
    let done = std::cell::Cell::new(0);
    let tick = || {
        done.set(done.get() + 1);
        progress(done.get(), total);
    };
    progress(0, total);
    let mut rows = Vec::with_capacity(found.len());
    for r in &found {
        let p = if converging {
            let p = converged_row(&sphere, &r.state, r.interference)?;
            tick();
            p
        } else {
            r.state.point
        };
        rows.push(CurvePoint {
            interference: r.interference,
            load: p.load,
            contact_radius: p.contact_radius,
            branch: r.branch,
        });
    }
    // The steps' ends and the turns between them (each turn ends the branch
    // before it: a plot's branches then meet at the jumps, where the
    // unstable branch drawn from the last step's end before the turn had
    // reached up the approach branch by as much as a step); the outer
    // trace's first.
    let outer_path = outer
        .iter()
        .map(|w| w.end.point)
        .filter(|p| p.interference < start)
        .map(|p| CurvePoint {
            interference: p.interference,
            load: p.load,
            contact_radius: p.contact_radius,
            branch: unturned(&p),
        });
    // Between them, the points of each piece's Hermite interpolant
    // ([`drawn_between`]): straight chords cut the sharp turns of the
    // unstable branch (at μ = 3 they cut a load minimum by about 0.01, drawn as a kink).
    let path = outer_path
        .chain(
            windows
                .iter()
                .enumerate()
                .flat_map(|(k, w)| {
                    let knots: Vec<(f64, SpherePoint)> = std::iter::once((0.0, w.start.point))
                        .chain(turns.iter().filter(|t| t.0 == k).map(|t| (t.1, t.2.point)))
                        .chain(std::iter::once((w.length, w.end.point)))
                        .collect();
                    knots
                        .windows(2)
                        .flat_map(|pair| drawn_between(pair[0], pair[1]))
                        .map(move |(at, p)| (k, at, p))
                        .collect::<Vec<_>>()
                })
                .map(|(k, at, p)| CurvePoint {
                    interference: p.interference,
                    load: p.load,
                    contact_radius: p.contact_radius,
                    branch: branch_after(k, at, &p),
                }),
        )
        .collect();
    // The marks extrapolated to the converged solution where the settings
    // ask, each at the converged extremum (the trace's place for it is off
    // by the discretisation's error: by 2.7e-3 in δ̂ for the pull-off at
    // μ = 1, which moved the load there by 7.6e-6).
    let mark = |state: &SphereState,
                hold: Hold,
                quantity: fn(&SpherePoint) -> f64|
     -> Result<CurveMark, CurveError> {
        let p = if sphere.settings.extrapolate {
            let p = sphere.extrapolated_extremum(state, hold, quantity)?.0;
            tick();
            p
        } else {
            state.point
        };
        Ok(CurveMark {
            interference: p.interference,
            load: p.load,
        })
    };
    let turn = |state: &SphereState| mark(state, state.turn_hold(), |p| p.interference);
    let (jump_in, jump_out) = if s_shaped {
        (
            Some(turn(&turns[0].2)?),
            Some(turn(&turns[turns.len() - 1].2)?),
        )
    } else {
        (None, None)
    };
    Ok(AsperityCurve {
        law: CurveLaw::LennardJones,
        tabor,
        points: rows,
        pull_off: mark(&pull_off, Hold::Interference, |p| p.load)?,
        jump_in,
        jump_out,
        path,
    })
}

/// How many pieces a plot's path draws each stretch of a trace step in.
const DRAWN_PIECES: usize = 6;

/// The points a plot draws from one solved state of a trace step to the next
/// (arclengths `a` < `b` from the step's start), the second included: the
/// cubic Hermite interpolant of δ̂ and P̂ in the arclength through both, with
/// their slopes along the path (a drawing between solutions, exact at them;
/// â linear, it only names the branch). A turn of δ̂ is a knot, its slope
/// zero there, so the jumps are drawn as the folds they are.
fn drawn_between(
    (a, p): (f64, SpherePoint),
    (b, q): (f64, SpherePoint),
) -> impl Iterator<Item = (f64, SpherePoint)> {
    let h = b - a;
    (1..=DRAWN_PIECES).map(move |j| {
        if j == DRAWN_PIECES {
            return (b, q);
        }
        let t = j as f64 / DRAWN_PIECES as f64;
        let (t2, t3) = (t * t, t * t * t);
        let (h00, h10, h01, h11) = (
            2.0 * t3 - 3.0 * t2 + 1.0,
            t3 - 2.0 * t2 + t,
            -2.0 * t3 + 3.0 * t2,
            t3 - t2,
        );
        let cubic =
            |x0: f64, d0: f64, x1: f64, d1: f64| h00 * x0 + h10 * h * d0 + h01 * x1 + h11 * h * d1;
        (
            a + t * h,
            SpherePoint {
                interference: cubic(
                    p.interference,
                    p.interference_slope,
                    q.interference,
                    q.interference_slope,
                ),
                load: cubic(p.load, p.load_slope, q.load, q.load_slope),
                contact_radius: (1.0 - t) * p.contact_radius + t * q.contact_radius,
                ..p
            },
        )
    })
}

/// A window of `windows` (one `usable`) over which `f` changes sign; where `f`
/// changes sign only between one window's end and the next one's regraded start
/// (the regrade moves a state by up to its tolerance), the earlier window
/// lengthened on its own mesh until it brackets the root.
fn bracket(
    sphere: &Sphere,
    windows: &[Window],
    f: impl Fn(&SphereState) -> f64,
    usable: impl Fn(&Window) -> bool,
) -> Result<Window, CurveError> {
    if let Some(w) = windows
        .iter()
        .find(|w| f(&w.start) * f(&w.end) <= 0.0 && usable(w))
    {
        return Ok(Window {
            start: w.start.clone(),
            length: w.length,
            end: w.end.clone(),
        });
    }
    let k = windows
        .windows(2)
        .position(|pair| f(&pair[0].end) * f(&pair[1].start) <= 0.0)
        .ok_or(CurveError::NotConverged(f64::NAN))?;
    let w = &windows[k];
    let mut length = w.length;
    for _ in 0..20 {
        length *= 1.25;
        let end = sphere.step(&w.start, length)?;
        if f(&w.start) * f(&end) <= 0.0 {
            return Ok(Window {
                start: w.start.clone(),
                length,
                end,
            });
        }
    }
    Err(CurveError::NotConverged(w.end.point.apex_gap))
}

/// The apex gap (over Z0) at which a single-valued curve's samples change from
/// the approach part (followed in the apex gap) to the contact part (followed
/// in the interference): past the steep rise where contact forms.
pub const SPLIT_GAP: f64 = 1.0;

/// A Lennard-Jones curve sampled the way the rough-surface law follows it
/// (docs/model.md §11): the approach branch up to the jump into contact (or,
/// where the curve is single-valued, up to [`SPLIT_GAP`]) at chosen apex gaps,
/// and the contact branch from there on at chosen interferences.
#[derive(Debug, Clone)]
pub struct LoadingSamples {
    /// μ.
    pub tabor: f64,
    /// The apex gap (over Z0) where the approach part ends.
    pub end_gap: f64,
    /// The interference δ̂ where the contact part starts (the jump-in's, or the
    /// split's).
    pub switch: f64,
    /// True where the curve is S-shaped: the load jumps at `switch`.
    pub jumps: bool,
    /// The approach branch at the apex gaps asked for.
    pub approach: Vec<SpherePoint>,
    /// The contact branch at the interferences asked for.
    pub contact: Vec<SpherePoint>,
    /// One sphere's pull-off, the deepest minimum of P̂ along the path (at
    /// the converged extremum where the settings extrapolate): on the
    /// contact part, or, above μ ≈ 6, on the retraction neck below `switch`
    /// that the loading curve leaves out.
    pub pull_off: SpherePoint,
}

/// Samples the Lennard-Jones curve of Tabor parameter μ for a table: the
/// approach branch at the apex gaps `approach_gaps(end_gap)` returns (each at
/// least `end_gap`; gaps beyond the traced range are solved directly from the
/// far field) and the contact branch at the interferences `contact_at(switch)`
/// returns (each between `switch` and `to`).
pub fn lennard_jones_loading(
    tabor: f64,
    approach_gaps: impl Fn(f64) -> Vec<f64>,
    contact_at: impl Fn(f64) -> Vec<f64>,
    to: f64,
    settings: SphereSettings,
) -> Result<LoadingSamples, CurveError> {
    let sphere = Sphere::new(tabor, settings);
    let z0 = sphere.z0;
    // From apex gap 3 (μ ≤ 5; the table's curves there were written so), or
    // from δ̂ = −1 above, where the approach branch turns (the jump in) at
    // apex gaps beyond 3 (about 3.4 at μ = 5, growing with μ): a trace
    // started inside the S-shape finds a later turn for the jump in (at
    // μ = 6.4 apex gap 1.9, the curve's switch 0.03 off and the non-contact
    // share of P̄ up to 3 % off).
    let from = if tabor > STRETCH_ABOVE {
        -1.0
    } else {
        z0 * (1.0 - 3.0)
    };
    let windows = trace(&sphere, from, to)?;
    let slope = |s: &SphereState| s.point.interference_slope;
    let turning: Vec<usize> = windows
        .iter()
        .enumerate()
        .filter(|(_, w)| (slope(&w.start) > 0.0) != (slope(&w.end) > 0.0))
        .map(|(k, _)| k)
        .collect();
    let jumps = turning.len() >= 2;
    // The end of the approach part: the first turn, or the split gap; the
    // contact part starts in the window after the last turn (or the split).
    let (end_state, approach_windows, contact_from) = if jumps {
        let k = turning[0];
        let (state, _) = root(&sphere, &windows[k], slope)?;
        (state, k, turning[turning.len() - 1])
    } else {
        let k = windows
            .iter()
            .position(|w| w.end.point.apex_gap <= SPLIT_GAP)
            .ok_or(CurveError::NotConverged(SPLIT_GAP))?;
        let (state, _) = root(&sphere, &windows[k], |s| s.point.apex_gap - SPLIT_GAP)?;
        (state, k, k)
    };
    // Where the curve jumps, its converged turn (the load there is not
    // stationary along the path: the trace's turn would carry its error).
    let end_point = if jumps && sphere.settings.extrapolate {
        sphere.extrapolated_turn(&end_state)?.0
    } else {
        finish(&sphere, &end_state, Hold::ApexGap)?
    };
    let end_gap = end_point.apex_gap;
    let switch = end_point.interference;
    let first_gap = windows[0].start.point.apex_gap;
    let approach = approach_gaps(end_gap)
        .into_iter()
        .map(|g| {
            if g == end_gap {
                return Ok(end_point);
            }
            if g >= first_gap {
                return finish(&sphere, &sphere.far(g)?, Hold::ApexGap);
            }
            let f = |s: &SphereState| s.point.apex_gap - g;
            let w = bracket(&sphere, &windows[..=approach_windows], f, |_| true)?;
            finish(&sphere, &root(&sphere, &w, f)?.0, Hold::ApexGap)
        })
        .collect::<Result<Vec<_>, CurveError>>()?;
    // Where the curve jumps, the contact part from the jump out on: the window
    // it lies in cut there (just above the cusp the whole S-shape lies in one
    // or two windows, and a node's δ̂ was found on the unstable branch before
    // the turn, whose solve at fixed δ̂ on finer meshes did not converge).
    let contact_windows = if jumps {
        let w = &windows[contact_from];
        let (turn, at) = root(&sphere, w, slope)?;
        let length = w.length - at;
        let end = sphere.step(&turn, length)?;
        std::iter::once(Window {
            start: turn,
            length,
            end,
        })
        .chain(windows[contact_from + 1..].iter().cloned())
        .collect()
    } else {
        windows[contact_from..].to_vec()
    };
    let contact = contact_at(switch)
        .into_iter()
        .map(|d| {
            if d == switch && !jumps {
                return Ok(end_point);
            }
            let f = |s: &SphereState| s.point.interference - d;
            let w = bracket(&sphere, &contact_windows, f, |w| slope(&w.end) > 0.0)?;
            finish(&sphere, &root(&sphere, &w, f)?.0, Hold::Interference)
        })
        .collect::<Result<Vec<_>, CurveError>>()?;
    let deepest = deepest_minimum(&sphere, &windows)?;
    let pull_off = if sphere.settings.extrapolate {
        sphere
            .extrapolated_extremum(&deepest, Hold::Interference, |p| p.load)?
            .0
    } else {
        deepest.point
    };
    Ok(LoadingSamples {
        tabor,
        end_gap,
        switch,
        jumps,
        approach,
        contact,
        pull_off,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn jkr_closed_forms() {
        let curve = jkr_curve(-1.0, 1.0, 5);
        assert!((curve.jump_out.unwrap().load + 5.0 / 6.0).abs() < 1e-14);
        assert!((curve.pull_off.load + 1.5).abs() < 1e-15);
    }

    /// −1.2 + 3.2 · 3/8 is 2.2e-16 in floating point: the grid's zero is zero.
    #[test]
    fn a_grid_through_zero_hits_it() {
        let t = targets(-1.2, 2.0, 9);
        assert_eq!(t[3], 0.0);
        assert_eq!(t[8], 2.0);
        assert!((t[4] - 0.4).abs() < 1e-15);
    }
}
