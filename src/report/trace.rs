//! The optimiser's per-iteration trace as CSV: error against run time (`optimize
//! --trace`), for one optimum or every optimised material of a ranking.

use super::number;
use crate::optimize::Optimum;

/// The per-iteration trace of every start: error against run time.
pub fn trace_csv(o: &Optimum) -> String {
    let mut out = String::from(
        "start,iteration,time_s,objective,ln_objective,kkt_residual,constraint_violation\n",
    );
    for s in &o.start_outcomes {
        for r in &s.trace {
            out.push_str(&format!(
                "{},{},{},{},{},{},{}\n",
                s.index,
                r.iteration,
                number(r.time),
                number(r.objective.exp()),
                number(r.objective),
                number(r.kkt_residual),
                number(r.violation)
            ));
        }
    }
    out
}
