//! The JKR asperity law (docs/model.md §3, the paper's): JKR elastic asperities
//! on the loading branch, plastic junctions beyond Δc; surface forces act only
//! inside contacts. Its integrals are the closed-form contact machinery of
//! `integrals.rs` (the elastic quadrature in s = Δ1^{1/4}) with the scene's
//! coefficients as they are.

use super::asperity_law::{Law, Prepared};
use super::coefficients::Coefficients;
use super::law::{AsperityLaw, AttractionKind, TRANSITION_TABOR};
use super::warnings::Warning;

/// The JKR law's entry in the registry.
pub struct Jkr;

impl Law for Jkr {
    fn name(&self) -> &'static str {
        "jkr"
    }
    fn label(&self) -> &'static str {
        "JKR"
    }
    fn attraction_refused(&self) -> &'static str {
        " (the default)"
    }
    fn section(&self) -> &'static str {
        "docs/model.md §3"
    }
    fn valid_tabor(&self) -> (f64, f64) {
        (TRANSITION_TABOR.1, f64::INFINITY)
    }
    fn description(&self, _attraction: AttractionKind) -> &'static str {
        "JKR (adhesion inside contacts only; adhesion_model = \"jkr\")"
    }
    fn closed_form_pull_off(&self) -> Option<f64> {
        Some(1.5)
    }
    fn with_range(&self, _attraction: AttractionKind, _range: f64) -> AsperityLaw {
        AsperityLaw::Jkr
    }
    fn prepare(&self, law: AsperityLaw, coefficients: &Coefficients) -> Prepared {
        Prepared::closed_form(law, *coefficients, 0.0)
    }
    fn separation_scale(&self, _law: AsperityLaw, c: &Coefficients) -> f64 {
        (1.5 / (c.c_d.cbrt() * c.c_a)).clamp(0.5, 1e6)
    }
    fn outside_regime(&self, tabor: f64) -> Option<Warning> {
        (tabor < self.valid_tabor().0).then_some(Warning::OutsideJkrRegime {
            tabor_parameter: tabor,
        })
    }
}
