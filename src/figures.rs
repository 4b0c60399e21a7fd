//! The paper's figures 1–4 (§4): non-dimensional wear volume V̄ against
//! non-dimensional load P̄, the least-squares line through each curve, and a
//! verdict on each claim §4 makes about them. Computation only, no I/O;
//! [`crate::report::figures`] words the claims and renders the CSV, SVG and
//! text/JSON report, and the CLI (`wearopt figures`) writes them.
//!
//! # How a curve is drawn
//!
//! For one pair (θ, λ) the loads are `points` evenly spaced values of P̄ in
//! `[load_min, load_max]` (compressive). Each load is solved for its separation h by
//! docs/model.md §4's rule (the largest root: the state reached by loading from far
//! apart, which is the falling branch of P̄(h) below the pull-off minimum), reusing
//! one [`landscape`] per curve, and V̄ = Ā(h) (eq. 16). The load written is P̄(h)
//! at the solved h, not the target, so every (P̄, V̄) pair is one model evaluation.
//! Evenly spaced loads weight the least-squares fit uniformly across the range the
//! figure draws.
//!
//! Curves are computed in parallel (rayon) but each is a pure function of its
//! inputs and results are collected in order, so the output does not depend on the
//! thread count.

use rayon::prelude::*;
use serde::Serialize;

use crate::model::{landscape, solve_separation_with, Coefficients, Model, SeparationOutcome};

/// The elastic adhesion index at which adhesion stops mattering (Fuller–Tabor; docs/model.md §2).
pub const THETA_TRANSITION: f64 = 10.0;
/// The plastic adhesion index at which adhesion stops mattering (Johnson; docs/model.md §2).
pub const LAMBDA_TRANSITION: f64 = 0.125;

/// The smallest coefficient of determination for which a curve counts as linear (claim 1).
pub const LINEAR_R_SQUARED: f64 = 0.99;
/// The largest max/min slope ratio for which slopes count as "more or less the same" (claim 3).
pub const EQUAL_SLOPE_RATIO: f64 = 1.10;

/// The largest number of points per curve (20 curves, one separation solve each).
pub const MAX_POINTS: usize = 10_000;

/// What to compute. Defaults in [`FigureSettings::default`]; check with
/// [`FigureSettings::validate`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FigureSettings {
    /// Points per curve, 3 to [`MAX_POINTS`].
    pub points: usize,
    /// Smallest non-dimensional load P̄ drawn, > 0 (compressive).
    pub load_min: f64,
    /// Largest non-dimensional load P̄ drawn, > `load_min`, finite.
    pub load_max: f64,
}

impl Default for FigureSettings {
    fn default() -> Self {
        FigureSettings {
            points: 51,
            load_min: 0.05,
            load_max: 5.0,
        }
    }
}

/// A setting outside its accepted range.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FigureError {
    /// Too few or too many points.
    #[error("points = {0}: must lie in 3..={MAX_POINTS} (a least-squares line needs 3 points to say anything)")]
    Points(usize),
    /// The load range is empty, not compressive or not finite.
    #[error("load range [{min}, {max}]: need 0 < load_min < load_max < inf (compressive loads, e.g. 0.05 to 5)")]
    LoadRange {
        /// The smallest load given.
        min: f64,
        /// The largest load given.
        max: f64,
    },
}

impl FigureSettings {
    /// Checks every field; the error names the field and the accepted range.
    pub fn validate(&self) -> Result<(), FigureError> {
        if !(3..=MAX_POINTS).contains(&self.points) {
            return Err(FigureError::Points(self.points));
        }
        let (min, max) = (self.load_min, self.load_max);
        // Written positively so that NaN fails.
        if min > 0.0 && max > min && max.is_finite() {
            Ok(())
        } else {
            Err(FigureError::LoadRange { min, max })
        }
    }

    /// The target loads: `points` evenly spaced values from `load_min` to `load_max`.
    pub fn loads(&self) -> Vec<f64> {
        let n = self.points;
        (0..n)
            .map(|i| {
                if i + 1 == n {
                    self.load_max
                } else {
                    self.load_min + (self.load_max - self.load_min) * (i as f64) / ((n - 1) as f64)
                }
            })
            .collect()
    }
}

/// Which index a figure varies across its curves.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Varied {
    /// θ varies, λ is fixed.
    Theta,
    /// λ varies, θ is fixed.
    Lambda,
}

/// One of the paper's figures: which curves it draws.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FigureSpec {
    /// The paper's figure number, 1 to 4.
    pub number: u8,
    /// The index held fixed and the one varied.
    pub varied: Varied,
    /// The fixed index's value.
    pub fixed: f64,
    /// The varied index's values, ascending.
    pub values: Vec<f64>,
}

impl FigureSpec {
    /// (θ, λ) of each curve, in the order of `values`.
    pub fn curves(&self) -> Vec<(f64, f64)> {
        self.values
            .iter()
            .map(|&v| match self.varied {
                Varied::Theta => (v, self.fixed),
                Varied::Lambda => (self.fixed, v),
            })
            .collect()
    }

    /// The caption, as the paper words it.
    pub fn caption(&self) -> String {
        match self.varied {
            Varied::Theta => format!(
                "Fig. {}: wear volume against load at λ = {} and varying θ",
                self.number, self.fixed
            ),
            Varied::Lambda => format!(
                "Fig. {}: wear volume against load at θ = {} and varying λ",
                self.number, self.fixed
            ),
        }
    }
}

/// θ values of figures 1 and 2: they bracket the transition θ = 10.
pub const THETAS: [f64; 5] = [2.0, 5.0, 10.0, 25.0, 100.0];
/// λ values of figures 3 and 4: they bracket the transition λ = 0.125.
pub const LAMBDAS: [f64; 5] = [0.01, 0.05, 0.125, 0.5, 5.0];

/// The paper's four figures: λ = 0.1 and λ = 5 with θ varied, θ = 10 and θ = 25
/// with λ varied (the paper's fixed values; the varied values are ours, chosen to
/// bracket the transitions, since the paper's plots are not in the transcript).
pub fn paper_figures() -> Vec<FigureSpec> {
    vec![
        FigureSpec {
            number: 1,
            varied: Varied::Theta,
            fixed: 0.1,
            values: THETAS.to_vec(),
        },
        FigureSpec {
            number: 2,
            varied: Varied::Theta,
            fixed: 5.0,
            values: THETAS.to_vec(),
        },
        FigureSpec {
            number: 3,
            varied: Varied::Lambda,
            fixed: 10.0,
            values: LAMBDAS.to_vec(),
        },
        FigureSpec {
            number: 4,
            varied: Varied::Lambda,
            fixed: 25.0,
            values: LAMBDAS.to_vec(),
        },
    ]
}

/// A straight line fitted by ordinary least squares, y ≈ slope·x + intercept.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LinearFit {
    /// dy/dx.
    pub slope: f64,
    /// y at x = 0.
    pub intercept: f64,
    /// Coefficient of determination, 1 - SS_res/SS_tot = S_xy²/(S_xx S_yy);
    /// 1 when every y is equal (a horizontal line fits exactly).
    pub r_squared: f64,
    /// Points used.
    pub n: usize,
}

/// The least-squares line through (x, y) pairs (centred two-pass sums, so no
/// cancellation from large means). None with fewer than 2 points, if any value is
/// not finite, or if every x is equal.
pub fn least_squares(points: &[(f64, f64)]) -> Option<LinearFit> {
    let n = points.len();
    if n < 2 || points.iter().any(|(x, y)| !x.is_finite() || !y.is_finite()) {
        return None;
    }
    let nf = n as f64;
    let mean_x = points.iter().map(|p| p.0).sum::<f64>() / nf;
    let mean_y = points.iter().map(|p| p.1).sum::<f64>() / nf;
    let (mut sxx, mut sxy, mut syy) = (0.0, 0.0, 0.0);
    for &(x, y) in points {
        let (dx, dy) = (x - mean_x, y - mean_y);
        sxx += dx * dx;
        sxy += dx * dy;
        syy += dy * dy;
    }
    if sxx == 0.0 {
        return None;
    }
    let slope = sxy / sxx;
    let r_squared = if syy == 0.0 {
        1.0
    } else {
        (sxy * sxy / (sxx * syy)).min(1.0)
    };
    Some(LinearFit {
        slope,
        intercept: mean_y - slope * mean_x,
        r_squared,
        n,
    })
}

/// One point of a curve.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CurvePoint {
    /// The separation h = d/σ the load was solved for.
    pub separation: f64,
    /// P̄(h).
    pub load: f64,
    /// V̄ = Ā(h) (eq. 16).
    pub wear_volume: f64,
}

/// V̄ against P̄ for one (θ, λ).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Curve {
    /// Elastic adhesion index.
    pub theta: f64,
    /// Plastic adhesion index.
    pub lambda: f64,
    /// The points whose separation solve converged, in ascending load.
    pub points: Vec<CurvePoint>,
    /// Target loads whose solve did not converge (not expected; counted, not hidden).
    pub failed: usize,
    /// The least-squares line V̄ ≈ slope·P̄ + intercept through `points`.
    pub fit: Option<LinearFit>,
    /// The pull-off load of the rough surface (most negative P̄; None without adhesion).
    pub pull_off_load: Option<f64>,
    /// The plastic load jump J (docs/model.md §3); negative means P̄(h) may have a
    /// compressive local maximum and minimum.
    pub plastic_jump: f64,
}

/// Computes one curve (see the module docs).
pub fn compute_curve(theta: f64, lambda: f64, settings: &FigureSettings) -> Curve {
    let model = Model::new(Coefficients::from_indices(theta, lambda));
    let land = landscape(&model);
    let pull_off = crate::model::pull_off_of(&land);
    let mut points = Vec::with_capacity(settings.points);
    let mut failed = 0;
    for target in settings.loads() {
        match solve_separation_with(&model, target, Some(&land)) {
            SeparationOutcome::Contact { separation, .. } => {
                let at = model.at(separation);
                points.push(CurvePoint {
                    separation,
                    load: at.load().value(),
                    wear_volume: at.area().value(),
                });
            }
            SeparationOutcome::Separated { .. } | SeparationOutcome::NotConverged { .. } => {
                failed += 1
            }
        }
    }
    let pairs: Vec<(f64, f64)> = points.iter().map(|p| (p.load, p.wear_volume)).collect();
    Curve {
        theta,
        lambda,
        fit: least_squares(&pairs),
        points,
        failed,
        pull_off_load: pull_off.map(|p| p.load.value()),
        plastic_jump: model.transition.jump,
    }
}

/// A computed figure.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Figure {
    /// What it draws.
    pub spec: FigureSpec,
    /// One curve per value of the varied index, in the order of `spec.values`.
    pub curves: Vec<Curve>,
}

impl Figure {
    /// The fitted slopes in curve order (NaN where a curve has no fit).
    pub fn slopes(&self) -> Vec<f64> {
        self.curves
            .iter()
            .map(|c| c.fit.map_or(f64::NAN, |f| f.slope))
            .collect()
    }
}

/// Computes every curve of every figure, curves in parallel; the result is
/// identical whatever the thread count.
pub fn compute_figures(specs: &[FigureSpec], settings: &FigureSettings) -> Vec<Figure> {
    let jobs: Vec<(usize, f64, f64)> = specs
        .iter()
        .enumerate()
        .flat_map(|(i, s)| s.curves().into_iter().map(move |(t, l)| (i, t, l)))
        .collect();
    let curves: Vec<Curve> = jobs
        .par_iter()
        .map(|&(_, theta, lambda)| compute_curve(theta, lambda, settings))
        .collect();
    let mut figures: Vec<Figure> = specs
        .iter()
        .map(|s| Figure {
            spec: s.clone(),
            curves: Vec::with_capacity(s.values.len()),
        })
        .collect();
    for (&(i, _, _), curve) in jobs.iter().zip(curves) {
        figures[i].curves.push(curve);
    }
    figures
}

/// A claim of the paper's §4 and whether the model bears it out. The report stage
/// words it (`report::figures`): what the paper says, the test, and the evidence.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Claim {
    /// A short stable key (`linear`, `low_lambda_low_theta_wears_more`, …).
    pub id: &'static str,
    /// Whether the model satisfies it; None when the figures needed are missing.
    pub holds: Option<bool>,
    /// The numbers that decide it.
    pub evidence: Evidence,
}

/// The curve whose fit is least straight (claim 1).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct WorstFit {
    /// Its figure.
    pub figure: u8,
    /// Its θ.
    pub theta: f64,
    /// Its λ.
    pub lambda: f64,
    /// Its r², None when no line could be fitted.
    pub r_squared: Option<f64>,
}

/// A figure's slopes in the order of its varied index (claims 2 to 4).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Slopes {
    /// The figure.
    pub figure: u8,
    /// The index varied across its curves.
    pub varied: Varied,
    /// The varied index's values.
    pub values: Vec<f64>,
    /// The least-squares slope of each curve (NaN where none was fitted).
    pub slopes: Vec<f64>,
    /// The slopes fall strictly as the index grows (all finite).
    pub falls: bool,
    /// Adjacent values (v_i, v_i+1) where the slope does not fall.
    pub breaks: Vec<(f64, f64)>,
}

/// A figure's slopes, or the number of a figure that was not computed.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum FigureSlopes {
    /// The figure was computed.
    Computed(Slopes),
    /// The figure of this number was not among those computed.
    Missing(u8),
}

/// What decides a claim.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Evidence {
    /// Claim 1: the least straight curve, and how many fall below the threshold.
    Linearity {
        /// The curve with the smallest r² (None: no curves).
        worst: Option<WorstFit>,
        /// Curves below [`LINEAR_R_SQUARED`] (or without a fit).
        below: usize,
        /// Curves in all.
        curves: usize,
    },
    /// Claims 2 and 4: the slopes of each figure named, in order.
    Ordering {
        /// One entry per figure the claim looks at.
        figures: Vec<FigureSlopes>,
    },
    /// Claim 3: figure 2's slopes and their max/min ratio.
    EqualSlopes {
        /// Figure 2's slopes.
        figure: FigureSlopes,
        /// max/min of the slopes (NaN when the figure is missing).
        ratio: f64,
    },
}

/// True when the slopes fall strictly as the varied index grows (all finite).
fn strictly_decreasing(slopes: &[f64]) -> bool {
    slopes.iter().all(|s| s.is_finite()) && slopes.windows(2).all(|w| w[1] < w[0])
}

fn find(figures: &[Figure], number: u8) -> Option<&Figure> {
    figures.iter().find(|f| f.spec.number == number)
}

/// Figure `number`'s slopes, in order, with where they fail to fall.
fn slopes_of(figures: &[Figure], number: u8) -> FigureSlopes {
    let Some(fig) = find(figures, number) else {
        return FigureSlopes::Missing(number);
    };
    let s = fig.slopes();
    let v = &fig.spec.values;
    FigureSlopes::Computed(Slopes {
        figure: number,
        varied: fig.spec.varied,
        values: v.clone(),
        falls: strictly_decreasing(&s),
        breaks: (1..s.len())
            .filter(|&i| s[i].is_nan() || s[i - 1].is_nan() || s[i] >= s[i - 1])
            .map(|i| (v[i - 1], v[i]))
            .collect(),
        slopes: s,
    })
}

/// Tests the four claims of §4 against computed figures (by figure number:
/// 1: λ = 0.1, θ varied; 2: λ = 5, θ varied; 3, 4: θ = 10, 25, λ varied).
pub fn assess_claims(figures: &[Figure]) -> Vec<Claim> {
    let mut claims = Vec::new();

    // (1) Linear in load, every curve.
    let fits: Vec<(u8, &Curve, Option<LinearFit>)> = figures
        .iter()
        .flat_map(|f| f.curves.iter().map(move |c| (f.spec.number, c, c.fit)))
        .collect();
    let worst = fits
        .iter()
        .min_by(|a, b| {
            let ra = a.2.map_or(f64::NEG_INFINITY, |f| f.r_squared);
            let rb = b.2.map_or(f64::NEG_INFINITY, |f| f.r_squared);
            ra.total_cmp(&rb)
        })
        .map(|(n, c, f)| WorstFit {
            figure: *n,
            theta: c.theta,
            lambda: c.lambda,
            r_squared: f.map(|f| f.r_squared),
        });
    let below = fits
        .iter()
        .filter(|(_, _, f)| f.is_none_or(|f| f.r_squared < LINEAR_R_SQUARED))
        .count();
    claims.push(Claim {
        id: "linear",
        holds: worst.map(|_| below == 0),
        evidence: Evidence::Linearity {
            worst,
            below,
            curves: fits.len(),
        },
    });

    let order_holds = |f: &FigureSlopes| match f {
        FigureSlopes::Computed(s) => Some(s.falls),
        FigureSlopes::Missing(_) => None,
    };

    // (2) Figure 1: at low λ, lower θ wears more.
    let fig1 = slopes_of(figures, 1);
    claims.push(Claim {
        id: "low_lambda_low_theta_wears_more",
        holds: order_holds(&fig1),
        evidence: Evidence::Ordering {
            figures: vec![fig1],
        },
    });

    // (3) Figure 2: at high λ, slopes nearly equal.
    let fig2 = slopes_of(figures, 2);
    let (holds, ratio) = match &fig2 {
        FigureSlopes::Computed(f) => {
            let s = &f.slopes;
            let max = s.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            let min = s.iter().copied().fold(f64::INFINITY, f64::min);
            let ratio = max / min;
            let ok = s.iter().all(|x| x.is_finite()) && min > 0.0 && ratio <= EQUAL_SLOPE_RATIO;
            (Some(ok), ratio)
        }
        FigureSlopes::Missing(_) => (None, f64::NAN),
    };
    claims.push(Claim {
        id: "high_lambda_theta_insensitive",
        holds,
        evidence: Evidence::EqualSlopes {
            figure: fig2,
            ratio,
        },
    });

    // (4) Figures 3 and 4: lower λ wears more, at both θ.
    let parts: Vec<FigureSlopes> = [3, 4].iter().map(|&n| slopes_of(figures, n)).collect();
    let each: Vec<Option<bool>> = parts.iter().map(order_holds).collect();
    let holds = if each.iter().any(Option::is_none) {
        None
    } else {
        Some(each.iter().all(|h| *h == Some(true)))
    };
    claims.push(Claim {
        id: "low_lambda_wears_more",
        holds,
        evidence: Evidence::Ordering { figures: parts },
    });
    claims
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn least_squares_recovers_an_exact_line() {
        let pts: Vec<(f64, f64)> = (0..7).map(|i| (i as f64, 2.5 * i as f64 - 1.0)).collect();
        let f = least_squares(&pts).unwrap();
        assert!((f.slope - 2.5).abs() < 1e-14);
        assert!((f.intercept + 1.0).abs() < 1e-14);
        assert!((f.r_squared - 1.0).abs() < 1e-14);
        assert!(least_squares(&[(1.0, 2.0), (1.0, 3.0)]).is_none());
    }

    #[test]
    fn settings_refuse_nonsense() {
        let ok = FigureSettings::default();
        assert!(ok.validate().is_ok());
        for bad in [
            FigureSettings { points: 0, ..ok },
            FigureSettings { points: 2, ..ok },
            FigureSettings {
                points: MAX_POINTS + 1,
                ..ok
            },
            FigureSettings {
                load_min: 0.0,
                ..ok
            },
            FigureSettings {
                load_max: 0.01,
                ..ok
            },
            FigureSettings {
                load_max: f64::INFINITY,
                ..ok
            },
            FigureSettings {
                load_min: f64::NAN,
                ..ok
            },
        ] {
            assert!(bad.validate().is_err(), "{bad:?}");
        }
        let loads = ok.loads();
        assert_eq!(loads.len(), ok.points);
        assert_eq!(loads[0], ok.load_min);
        assert_eq!(*loads.last().unwrap(), ok.load_max);
    }
}
