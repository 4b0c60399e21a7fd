//! What the rough-surface model asks of an asperity law: the trait [`Law`] each
//! law's module implements (`jkr.rs`, `dmt.rs`, `lennard_jones/law.rs`), what
//! it gives the model at one scene's coefficients ([`Prepared`]), and the
//! integrals of a law that takes its own ([`Tabulated`]). The registry that
//! lists the laws is `registry.rs`; their names are `law.rs`'s.

use super::coefficients::{Coefficients, Transition};
use super::law::{AsperityLaw, Attraction, AttractionKind};
use super::warnings::{Note, Warning};
use std::sync::Arc;

/// One asperity law as its own module gives it: the registry's entry (names,
/// the options it takes, where it is exact, a report's words for it) and what
/// the rough-surface model asks of it. Each law implements it on a unit struct
/// (`jkr.rs`, `dmt.rs`, `lennard_jones/law.rs`); `AdhesionModel::law`
/// (`registry.rs`) lists them. Nothing outside the law's module and that line names a law.
pub trait Law: Sync {
    /// The word used in problem files, options and reports (`adhesion_model`).
    fn name(&self) -> &'static str;
    /// The law's short name in prose ("JKR").
    fn label(&self) -> &'static str;
    /// Where docs/model.md states it ("docs/model.md §3").
    fn section(&self) -> &'static str;
    /// Its name where a report names it in full ("Lennard-Jones sphere").
    fn title(&self) -> &'static str {
        self.label()
    }
    /// Whether it takes an attraction of its asperities out of contact (the
    /// `attraction` key, a kind and a range).
    fn takes_attraction(&self) -> bool {
        false
    }
    /// Whether it needs a range of its own (z0 = Z0/σ) without taking an
    /// attraction (`curve`'s `--attraction-range`).
    fn has_own_range(&self) -> bool {
        false
    }
    /// What its range means, for a message that asks for it ("z0 = Z0/σ, …").
    fn range_meaning(&self) -> &'static str {
        ""
    }
    /// Why the law refuses the `attraction` key, after `adhesion_model is
    /// "NAME"` (ignored where it takes one).
    fn attraction_refused(&self) -> &'static str {
        ""
    }
    /// The Tabor parameters φ0 over which the law is exact (closed ends).
    fn valid_tabor(&self) -> (f64, f64);
    /// True for a law that holds through the JKR–DMT transition: `eval` gives it
    /// beside the limit laws there.
    fn general(&self) -> bool {
        false
    }
    /// A report's description of the law, `{z0}` (Z0/σ), `{hamaker}` (J) and
    /// `{dugdale_range}` (h0/σ) standing for the scene's numbers.
    fn description(&self, attraction: AttractionKind) -> &'static str;
    /// The Hamaker constant of its attraction over π Z0² γ (None: no power-law
    /// attraction out of contact).
    fn hamaker_factor(&self, _attraction: AttractionKind) -> Option<f64> {
        None
    }
    /// Whether asperities out of contact carry load under it.
    fn attracts_out_of_contact(&self) -> bool {
        false
    }
    /// One asperity's pull-off over πγR where it is a closed form (None: the
    /// law's own, from its curve).
    fn closed_form_pull_off(&self) -> Option<f64>;

    /// The law of a scene, its range (z0 = Z0/σ, or under an attraction that
    /// attraction's own) already non-dimensional.
    fn with_range(&self, attraction: AttractionKind, range: f64) -> AsperityLaw;
    /// What the model takes its integrals from at these coefficients.
    fn prepare(&self, law: AsperityLaw, coefficients: &Coefficients) -> Prepared;
    /// The attraction of asperities out of contact that the model adds in
    /// closed form (docs/model.md §7), if the law has one.
    fn closed_form_attraction(&self, _law: AsperityLaw) -> Option<Attraction> {
        None
    }
    /// A first guess of the separation of the load's minimum (the separation
    /// search's scale), for a law with adhesion.
    fn separation_scale(&self, law: AsperityLaw, coefficients: &Coefficients) -> f64;
    /// The warning for a scene outside the law's regime at φ0 (with adhesion).
    fn outside_regime(&self, _tabor: f64) -> Option<Warning> {
        None
    }
    /// The note a scene gets where a closed form (`stand_in`) stands in for the
    /// law.
    fn stand_in_note(&self, _stand_in: AsperityLaw, _tabor: f64) -> Option<Note> {
        None
    }
    /// The note a scene gets where the law's own numbers come from a stated
    /// approximation of it (not a stand-in law) at φ0.
    fn approximation_note(&self, _law: AsperityLaw, _tabor: f64) -> Option<Note> {
        None
    }
}

/// What a [`Law`] gives the model at one scene's coefficients.
#[derive(Debug, Clone)]
pub struct Prepared {
    /// The law whose integrals are taken: the scene's, or a closed form that
    /// stands in for it.
    pub effective: AsperityLaw,
    /// The coefficients of the contact integrals.
    pub contact: Coefficients,
    /// The constant subtracted from the elastic asperity load (DMT's c_0).
    pub elastic_offset: f64,
    /// A law that integrates its own elastic and non-contact shares (from a
    /// table of its single-asperity curve); None for the closed-form contacts.
    pub tabulated: Option<Arc<dyn Tabulated>>,
}

impl Prepared {
    /// The closed-form contacts of `law` at these coefficients.
    pub fn closed_form(law: AsperityLaw, contact: Coefficients, elastic_offset: f64) -> Self {
        Prepared {
            effective: law,
            contact,
            elastic_offset,
            tabulated: None,
        }
    }
}

/// The non-contact and contact shares of P̄ and their first two
/// h-derivatives, each a mantissa: the value is `m e^{-exponent}`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Shares {
    /// ∫_{Δ<0} p φ̄ dΔ, and its h-derivatives.
    pub noncontact: [f64; 3],
    /// The scale of `noncontact`: κ(−h) = max(−h, 0)²/2.
    pub noncontact_exponent: f64,
    /// ∫_0^{Δc} p φ̄ dΔ (elastic contacts), and its h-derivatives.
    pub elastic: [f64; 3],
    /// The scale of `elastic`: κ(h) = max(h, 0)²/2.
    pub elastic_exponent: f64,
}

/// A law that integrates its own elastic and non-contact shares over the
/// summit heights (the Lennard-Jones law, from the table of its single-asperity
/// curve): the model adds the plastic junctions of each of its curves, the
/// area, the counts and the capillary load.
pub trait Tabulated: Send + Sync + std::fmt::Debug {
    /// The elastic and non-contact shares at h.
    fn shares(&self, h: f64) -> Shares;
    /// Each curve's Δc with its weight, the plastic junctions beyond which the
    /// model adds in closed form.
    fn plastic_junctions(&self, visit: &mut dyn FnMut(f64, f64));
    /// ∫ p(Δ) T_0(h0 + Δ) dΔ, T_0(u) = ∫_u^∞ e^{−x²/2} dx, over the elastic and
    /// non-contact shares: their part of the work of separation from h0 with
    /// the integrals exchanged (`model::work`); None where the law cannot
    /// (the work is then a quadrature over h).
    fn solid_work(&self, h0: f64) -> Option<f64>;
    /// The elastic–plastic transition at these coefficients.
    fn transition(&self, coefficients: &Coefficients) -> Transition;
    /// One asperity's pull-off in units of πγR (> 0).
    fn asperity_pull_off(&self) -> f64;
    /// The law's own type (for its module's accessors).
    fn as_any(&self) -> &dyn std::any::Any;
}
