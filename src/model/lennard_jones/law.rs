//! The Lennard-Jones law's entry in the registry (docs/model.md §11): the
//! self-consistent sphere from its loading table, valid for every Tabor
//! parameter: the solver's curves from μ = 9.91e-5 to 22.4, then closed-form
//! limit curves (JKR's contact branch from the sphere's jump in) to 3.6e6;
//! outside them the closed-form laws stand in, JKR above and DMT with van der
//! Waals attraction below.

use super::rough::{self, Grid, RoughLaw, Shares};
use crate::model::asperity_law::{Law, Prepared, Tabulated};
use crate::model::coefficients::{Coefficients, Transition};
use crate::model::dmt::Dmt;
use crate::model::jkr::Jkr;
use crate::model::law::{AdhesionModel, AsperityLaw, Attraction, AttractionKind};
use crate::model::warnings::Note;
use std::sync::Arc;

/// The Lennard-Jones law's entry in the registry.
pub struct LennardJones;

impl Law for LennardJones {
    fn name(&self) -> &'static str {
        "lennard_jones"
    }
    fn label(&self) -> &'static str {
        "Lennard-Jones"
    }
    fn title(&self) -> &'static str {
        "Lennard-Jones sphere"
    }
    fn has_own_range(&self) -> bool {
        true
    }
    fn range_meaning(&self) -> &'static str {
        "z0 = Z0/σ, the Lennard-Jones force's equilibrium spacing over the roughness"
    }
    fn attraction_refused(&self) -> &'static str {
        ", whose attraction is its own (the Lennard-Jones force, range interatomic_distance)"
    }
    fn section(&self) -> &'static str {
        "docs/model.md §11"
    }
    fn valid_tabor(&self) -> (f64, f64) {
        (0.0, f64::INFINITY)
    }
    fn general(&self) -> bool {
        true
    }
    fn description(&self, _attraction: AttractionKind) -> &'static str {
        "Lennard-Jones sphere (self-consistent, for every Tabor parameter; attraction of asperities not in contact with range z0 = Z0/σ = {z0}, Hamaker constant A = 16π Z0² γ = {hamaker} J)"
    }
    fn hamaker_factor(&self, _attraction: AttractionKind) -> Option<f64> {
        Some(16.0)
    }
    fn attracts_out_of_contact(&self) -> bool {
        true
    }
    fn closed_form_pull_off(&self) -> Option<f64> {
        None
    }
    fn with_range(&self, _attraction: AttractionKind, range: f64) -> AsperityLaw {
        AsperityLaw::LennardJones { range }
    }
    fn prepare(&self, law: AsperityLaw, c: &Coefficients) -> Prepared {
        let range = law.range();
        // Without adhesion every law is Hertz's (and JKR's path is exact).
        if !c.has_adhesion() {
            return Jkr.prepare(AsperityLaw::Jkr, c);
        }
        match RoughLaw::new(c.c_0, c.c_h, range) {
            Some(table) => Prepared {
                effective: law,
                contact: *c,
                elastic_offset: 0.0,
                tabulated: Some(Arc::new(table.grid())),
            },
            None => {
                if rough::tabor(c.c_0, range) > 1.0 {
                    Jkr.prepare(AsperityLaw::Jkr, c)
                } else {
                    Dmt.prepare(AsperityLaw::Dmt(Attraction::VanDerWaals { range }), c)
                }
            }
        }
    }
    fn separation_scale(&self, law: AsperityLaw, _c: &Coefficients) -> f64 {
        1.0 + law.range().min(1e3)
    }
    fn approximation_note(&self, _law: AsperityLaw, tabor: f64) -> Option<Note> {
        (tabor > super::table::solved_range().1).then_some(Note::LennardJonesLimitCurves {
            tabor_parameter: tabor,
            pull_off_error: super::table::LIMIT_ERROR.0,
        })
    }
    fn stand_in_note(&self, stand_in: AsperityLaw, tabor: f64) -> Option<Note> {
        let stand_in = stand_in.adhesion_model();
        Some(Note::LennardJonesStandIn {
            tabor_parameter: tabor,
            stand_in,
            pull_off_error: rough::stand_in_pull_off_error(stand_in == AdhesionModel::Jkr),
        })
    }
}

impl Tabulated for Grid {
    fn shares(&self, h: f64) -> Shares {
        Grid::shares(self, h)
    }
    fn solid_work(&self, h0: f64) -> Option<f64> {
        Grid::solid_work(self, h0)
    }
    fn plastic_junctions(&self, visit: &mut dyn FnMut(f64, f64)) {
        for (dc, weight) in self.law().critical_interferences() {
            visit(dc, weight);
        }
    }
    /// Δc and the load jump J = (c_p Δc − c_0) − p(Δc) of its curves, Δc
    /// interpolated as the integrals are, J the most negative (the separation
    /// search looks for extra minima wherever one curve's jump is negative).
    fn transition(&self, c: &Coefficients) -> Transition {
        let mut dc = 0.0;
        let mut jump = f64::INFINITY;
        for (critical, weight, load) in self.law().transitions() {
            dc += weight * critical;
            if critical.is_finite() {
                jump = jump.min(c.c_p * critical - c.c_0 - load);
            }
        }
        Transition {
            t: dc.sqrt().sqrt(),
            critical_interference: if dc.is_nan() { f64::INFINITY } else { dc },
            jump: if jump.is_finite() { jump } else { 0.0 },
        }
    }
    fn asperity_pull_off(&self) -> f64 {
        -self.law().asperity_pull_off()
    }
    fn as_any(&self) -> &dyn std::any::Any {
        self
    }
}

/// The Lennard-Jones table among a model's own integrals (`Model::tabulated`;
/// None under the other laws, and under this one where a closed form stands in).
pub fn table_of(tabulated: Option<&dyn Tabulated>) -> Option<&RoughLaw> {
    tabulated
        .and_then(|t| t.as_any().downcast_ref::<Grid>())
        .map(Grid::law)
}
