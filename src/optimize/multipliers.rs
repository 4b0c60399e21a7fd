//! Lagrange multipliers and the KKT residual of a point of a
//! [`super::NonlinearProgram`], in the problem's own coordinates.

use nalgebra::{DMatrix, DVector};

/// The KKT measures at a point with row multipliers λ ≥ 0.
#[derive(Debug, Clone, PartialEq)]
pub struct Kkt {
    /// The KKT residual: the largest of `stationarity`, `complementarity`, `violation`.
    pub residual: f64,
    /// ‖∇f + Σλ_j∇g_j - μ_lower + μ_upper‖∞ / max(1, ‖∇f‖∞).
    pub stationarity: f64,
    /// max_j |λ_j g_j| / max(1, |f|), or max_j |λ_j g_j| alone where f is a
    /// logarithm ([`KktData::logarithmic`]).
    pub complementarity: f64,
    /// max(0, max_j g_j, bound violations).
    pub violation: f64,
    /// μ ≥ 0 of the lower bounds (nonzero only where x_i = lower_i).
    pub lower: Vec<f64>,
    /// μ ≥ 0 of the upper bounds (nonzero only where x_i = upper_i).
    pub upper: Vec<f64>,
}

/// What the KKT residual is measured from.
pub struct KktData<'a> {
    /// The point.
    pub x: &'a [f64],
    /// Its bounds.
    pub lower: &'a [f64],
    /// Its bounds.
    pub upper: &'a [f64],
    /// f(x).
    pub objective: f64,
    /// g(x).
    pub rows: &'a [f64],
    /// ∇f(x).
    pub gradient: &'a [f64],
    /// ∇g_j(x).
    pub jacobian: &'a [Vec<f64>],
    /// f is the logarithm of a positive quantity
    /// ([`super::NonlinearProgram::logarithmic_objective`]): λ_j g_j, the
    /// change of f a row's slack would buy, is already relative and unit-free.
    pub logarithmic: bool,
}

/// The KKT residual (see [`Kkt`]). The bound multipliers are those that
/// minimise it: a bound holding exactly (x_i on it) absorbs the component of
/// the Lagrangian gradient that pushes against it.
pub fn kkt(d: &KktData, multipliers: &[f64]) -> Kkt {
    let n = d.x.len();
    let mut lower = vec![0.0; n];
    let mut upper = vec![0.0; n];
    let mut worst = 0.0f64;
    let mut violation = 0.0f64;
    for i in 0..n {
        let mut r = d.gradient[i];
        for (j, l) in multipliers.iter().enumerate() {
            r += l * d.jacobian[j][i];
        }
        if d.x[i] <= d.lower[i] && r > 0.0 {
            lower[i] = r;
        } else if d.x[i] >= d.upper[i] && r < 0.0 {
            upper[i] = -r;
        } else {
            worst = worst.max(r.abs());
        }
        violation = violation.max(d.lower[i] - d.x[i]).max(d.x[i] - d.upper[i]);
    }
    let gnorm = d.gradient.iter().fold(0.0f64, |m, g| m.max(g.abs()));
    let stationarity = worst / gnorm.max(1.0);
    let mut comp = 0.0f64;
    for (j, &g) in d.rows.iter().enumerate() {
        violation = violation.max(g);
        comp = comp.max((multipliers[j] * g).abs());
    }
    let complementarity = if d.logarithmic {
        comp
    } else {
        comp / d.objective.abs().max(1.0)
    };
    Kkt {
        residual: stationarity.max(complementarity).max(violation),
        stationarity,
        complementarity,
        violation: violation.max(0.0),
        lower,
        upper,
    }
}

/// Least-squares multipliers: λ ≥ 0 on the rows with g_j ≥ -`active`
/// (others 0) and μ ≥ 0 on the bounds that hold, minimising
/// ‖∇f + Σλ_j∇g_j - μ_lower + μ_upper‖₂ (Lawson–Hanson NNLS).
pub fn least_squares(d: &KktData, active: f64) -> Vec<f64> {
    let n = d.x.len();
    let act: Vec<usize> = (0..d.rows.len())
        .filter(|&j| d.rows[j] >= -active)
        .collect();
    let mut out = vec![0.0; d.rows.len()];
    if act.is_empty() {
        return out;
    }
    let mut columns: Vec<Vec<f64>> = act.iter().map(|&j| d.jacobian[j].clone()).collect();
    for i in 0..n {
        let sign = if d.x[i] <= d.lower[i] {
            -1.0
        } else if d.x[i] >= d.upper[i] {
            1.0
        } else {
            continue;
        };
        let mut e = vec![0.0; n];
        e[i] = sign;
        columns.push(e);
    }
    let a = DMatrix::from_fn(n, columns.len(), |i, k| columns[k][i]);
    let b = DVector::from_iterator(n, d.gradient.iter().map(|g| -g));
    let z = nnls(&a, &b);
    for (k, &j) in act.iter().enumerate() {
        out[j] = z[k];
    }
    out
}

/// Lawson–Hanson non-negative least squares: min ‖Az - b‖₂ over z ≥ 0.
pub fn nnls(a: &DMatrix<f64>, b: &DVector<f64>) -> DVector<f64> {
    let k = a.ncols();
    let mut z = DVector::zeros(k);
    let mut passive = vec![false; k];
    let scale = a.iter().fold(0.0f64, |m, v| m.max(v.abs())) * b.amax().max(1e-300);
    let tol = 1e-13 * scale.max(1e-300) * (k as f64 + 1.0);
    for _ in 0..3 * k + 3 {
        let w = a.transpose() * (b - a * &z);
        let candidate = (0..k)
            .filter(|&j| !passive[j] && w[j] > tol)
            .max_by(|&i, &j| w[i].total_cmp(&w[j]));
        let Some(t) = candidate else { break };
        passive[t] = true;
        for _ in 0..3 * k + 3 {
            let idx: Vec<usize> = (0..k).filter(|&j| passive[j]).collect();
            let ap = DMatrix::from_fn(a.nrows(), idx.len(), |i, c| a[(i, idx[c])]);
            let Ok(sp) = ap.svd(true, true).solve(b, 1e-14) else {
                return z;
            };
            let mut s = DVector::zeros(k);
            for (c, &j) in idx.iter().enumerate() {
                s[j] = sp[c];
            }
            if idx.iter().all(|&j| s[j] > 0.0) {
                z = s;
                break;
            }
            let alpha = idx
                .iter()
                .filter(|&&j| s[j] <= 0.0)
                .map(|&j| z[j] / (z[j] - s[j]))
                .fold(f64::INFINITY, f64::min);
            z = &z + (s - &z) * alpha;
            for &j in &idx {
                if z[j] <= 1e-15 * (1.0 + z.amax()) {
                    passive[j] = false;
                    z[j] = 0.0;
                }
            }
        }
    }
    z.map(|v| v.max(0.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// min ‖z - (1, -1)‖ over z ≥ 0 with A = I: z = (1, 0) (closed form).
    #[test]
    fn nnls_projects_onto_the_orthant() {
        let a = DMatrix::identity(2, 2);
        let b = DVector::from_vec(vec![1.0, -1.0]);
        let z = nnls(&a, &b);
        assert!((z[0] - 1.0).abs() < 1e-15 && z[1] == 0.0, "{z}");
    }

    /// min x² s.t. 1 - x ≤ 0 at x = 1: ∇f = 2, ∇g = -1, λ = 2 (closed form), residual 0.
    #[test]
    fn multiplier_of_an_active_row() {
        let jac = vec![vec![-1.0]];
        let d = KktData {
            x: &[1.0],
            lower: &[-10.0],
            upper: &[10.0],
            objective: 1.0,
            rows: &[0.0],
            gradient: &[2.0],
            jacobian: &jac,
            logarithmic: false,
        };
        let l = least_squares(&d, 1e-6);
        assert!((l[0] - 2.0).abs() < 1e-14);
        assert!(kkt(&d, &l).residual < 1e-14);
        // Without the multiplier the residual is the relative gradient, 2/2 = 1.
        assert_eq!(kkt(&d, &[0.0]).residual, 1.0);
    }

    /// A row with slack 1e-6 and multiplier 2 at f = ln(1e-18) = −41.4: the
    /// objective could fall by λ|g| = 2e-6 of itself. For a logarithmic f
    /// that is the complementarity, in any unit (f shifted by 41.4 or not);
    /// for another f it is taken against max(1, |f|).
    #[test]
    fn complementarity_of_a_logarithm_is_unit_free() {
        let jac = vec![vec![-1.0]];
        let at = |objective: f64, logarithmic: bool| {
            let d = KktData {
                x: &[1.0],
                lower: &[-10.0],
                upper: &[10.0],
                objective,
                rows: &[-1e-6],
                gradient: &[2.0],
                jacobian: &jac,
                logarithmic,
            };
            kkt(&d, &[2.0]).complementarity
        };
        let f = 1e-18f64.ln();
        assert_eq!(at(f, true), 2e-6);
        assert_eq!(at(f - f, true), 2e-6);
        assert_eq!(at(f, false), 2e-6 / f.abs());
        assert_eq!(at(0.5, false), 2e-6);
    }
}
