//! The asperity laws: how one asperity's load depends on its interference.
//!
//! The evaluator ([`super::Model`]) is built from one [`AsperityLaw`]:
//!
//! * [`AsperityLaw::Jkr`] — docs/model.md §3 (`jkr.rs`): JKR elastic asperities
//!   on the loading branch, plastic junctions beyond Δc; surface forces act only
//!   inside contacts. Its integrals are `integrals.rs`'s (elastic quadrature in
//!   s = Δ1^{1/4}).
//! * [`AsperityLaw::Dmt`] — docs/model.md §7 (`dmt.rs`): Hertz contact with the
//!   DMT adhesive offset `-c_0`, Δc = c_h², and attraction of the asperities that
//!   are *not* in contact, by a Dugdale stress of range Δ_h or by van der Waals
//!   forces with equilibrium distance z0.
//! * [`AsperityLaw::LennardJones`] — docs/model.md §11 (`lennard_jones/`): the
//!   self-consistent sphere with a Lennard-Jones surface force, from its loading
//!   table, valid for every Tabor parameter; outside the table (μ < 0.01, μ > 5)
//!   its closed-form limits stand in.
//!
//! Each law's module implements [`Law`]: its entry in the registry (names,
//! options, where it is exact, its words) and what the model asks of it —
//! (a) the coefficients its contact integrals use or its own integrals,
//! (b) the elastic–plastic transition, (c) an optional non-contact load.
//! [`AdhesionModel::law`] is the registry. The separation and pull-off searches
//! only see P̄, P̄', P̄'' and the sign of the load jump.

use super::coefficients::Coefficients;
use super::integrals::Tabulated;
use super::warnings::{Note, Warning};
use serde::Serialize;
use std::sync::Arc;

/// φ0 range where neither limit law is exact (the JKR–DMT transition), and `eval`
/// gives both.
pub const TRANSITION_TABOR: (f64, f64) = (0.3, 3.0);

/// Which asperity law a scene uses (the problem-file key `adhesion_model`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum AdhesionModel {
    /// Johnson–Kendall–Roberts asperities (docs/model.md §3), for φ0 > 3.
    #[default]
    Jkr,
    /// Derjaguin–Muller–Toporov asperities with non-contact attraction (docs/model.md §7), for φ0 < 0.3.
    Dmt,
    /// The self-consistent sphere with a Lennard-Jones surface force (docs/model.md §11),
    /// of which the other two are the limits: for every φ0.
    LennardJones,
}

impl AdhesionModel {
    /// Every asperity law, in the order problem files, options and messages list
    /// them: the registry every name, parser and list of laws reads.
    pub const ALL: [AdhesionModel; 3] = [
        AdhesionModel::Jkr,
        AdhesionModel::Dmt,
        AdhesionModel::LennardJones,
    ];

    /// The law's module: its names, the options it takes, where it is exact,
    /// and its physics. **The registration**: a new law is a variant here and
    /// in [`AsperityLaw`], and one line below.
    pub fn law(self) -> &'static dyn Law {
        match self {
            AdhesionModel::Jkr => &super::jkr::Jkr,
            AdhesionModel::Dmt => &super::dmt::Dmt,
            AdhesionModel::LennardJones => &super::lennard_jones::law::LennardJones,
        }
    }

    /// The word used in problem files and reports.
    pub fn as_str(self) -> &'static str {
        self.law().name()
    }

    /// The law named `name` (as [`AdhesionModel::as_str`] writes it).
    pub fn from_name(name: &str) -> Option<AdhesionModel> {
        Self::ALL.into_iter().find(|m| m.as_str() == name)
    }

    /// The names of every law, in order.
    pub fn names() -> [&'static str; 3] {
        Self::ALL.map(AdhesionModel::as_str)
    }

    /// Whether the law takes an attraction of the asperities out of contact (the
    /// `attraction` key and its range).
    pub fn takes_attraction(self) -> bool {
        self.law().takes_attraction()
    }

    /// The law's name as a report writes it in prose.
    pub fn label(self) -> &'static str {
        self.law().label()
    }

    /// The Tabor parameters φ0 over which the law is exact (closed ends): JKR at
    /// and above the transition, DMT at and below it.
    pub fn valid_tabor(self) -> (f64, f64) {
        self.law().valid_tabor()
    }

    /// The laws exact at φ0 (the registry's order).
    pub fn valid_at(tabor: f64) -> impl Iterator<Item = AdhesionModel> {
        Self::ALL.into_iter().filter(move |m| {
            let (lo, hi) = m.valid_tabor();
            tabor >= lo && tabor <= hi
        })
    }

    /// The law `eval` gives beside this one at φ0: inside the JKR–DMT transition
    /// (ends included) a limit law (JKR or DMT) is answered beside by the law
    /// valid there, the Lennard-Jones sphere. `None` for the Lennard-Jones law
    /// itself and outside the transition (φ0 inside the limit law's validity).
    pub fn bracket(self, tabor: f64) -> Option<AdhesionModel> {
        let inside = tabor >= TRANSITION_TABOR.0 && tabor <= TRANSITION_TABOR.1;
        if !inside || self.law().general() {
            return None;
        }
        Self::ALL.into_iter().find(|m| m.law().general())
    }
}

/// One asperity law as its own module gives it: the registry's entry (names,
/// the options it takes, where it is exact, a report's words for it) and what
/// the rough-surface model asks of it. Each law implements it on a unit struct
/// (`jkr.rs`, `dmt.rs`, `lennard_jones/law.rs`); [`AdhesionModel::law`] lists
/// them. Nothing outside the law's module and that line names a law.
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

/// How non-contacting asperities are attracted under DMT (the key `attraction`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum AttractionKind {
    /// Van der Waals: a power-law force -A R / (6 (g + Z0)²), A = 12π Z0² γ.
    #[default]
    VanDerWaals,
    /// Dugdale: a constant stress σ0 = 1.03 γ/Z0 over a range h0 = Z0/1.03.
    Dugdale,
}

impl AttractionKind {
    /// Every attraction, in the order problem files and messages list them.
    pub const ALL: [AttractionKind; 2] = [AttractionKind::VanDerWaals, AttractionKind::Dugdale];

    /// The word used in problem files and reports.
    pub fn as_str(self) -> &'static str {
        match self {
            AttractionKind::VanDerWaals => "van_der_waals",
            AttractionKind::Dugdale => "dugdale",
        }
    }

    /// The attraction named `name` (as [`AttractionKind::as_str`] writes it).
    pub fn from_name(name: &str) -> Option<AttractionKind> {
        Self::ALL.into_iter().find(|m| m.as_str() == name)
    }

    /// The names of every attraction, in order.
    pub fn names() -> [&'static str; 2] {
        Self::ALL.map(AttractionKind::as_str)
    }

    /// The attraction's name in prose.
    pub fn label(self) -> &'static str {
        match self {
            AttractionKind::VanDerWaals => "van der Waals",
            AttractionKind::Dugdale => "Dugdale",
        }
    }

    /// The non-dimensional range of the attraction for an interatomic distance
    /// Z0 and roughness σ: z0 = Z0/σ (van der Waals) or Δ_h = Z0/(1.03 σ) (Dugdale).
    pub fn range(self, interatomic_distance: f64, sigma: f64) -> f64 {
        match self {
            AttractionKind::VanDerWaals => interatomic_distance / sigma,
            AttractionKind::Dugdale => interatomic_distance / (DUGDALE_STRESS_FACTOR * sigma),
        }
    }
}

/// σ0 = 1.03 γ/Z0: the Dugdale stress that matches the Lennard-Jones peak
/// (Maugis 1992; Johnson & Greenwood 1997), so h0 = γ/σ0 = Z0/1.03.
pub const DUGDALE_STRESS_FACTOR: f64 = 1.03;

/// The attraction of non-contacting asperities, non-dimensional.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Attraction {
    /// p(Δ) = -c_0 (z0/(z0 - Δ))² for Δ < 0.
    VanDerWaals {
        /// z0 = Z0/σ > 0.
        range: f64,
    },
    /// p(Δ) = -c_0 (1 + Δ/Δ_h) for -Δ_h ≤ Δ < 0, 0 below.
    Dugdale {
        /// Δ_h = h0/σ > 0.
        range: f64,
    },
}

impl Attraction {
    /// From the kind and its non-dimensional range.
    pub fn new(kind: AttractionKind, range: f64) -> Self {
        match kind {
            AttractionKind::VanDerWaals => Attraction::VanDerWaals { range },
            AttractionKind::Dugdale => Attraction::Dugdale { range },
        }
    }

    /// Which kind.
    pub fn kind(self) -> AttractionKind {
        match self {
            Attraction::VanDerWaals { .. } => AttractionKind::VanDerWaals,
            Attraction::Dugdale { .. } => AttractionKind::Dugdale,
        }
    }

    /// z0 or Δ_h.
    pub fn range(self) -> f64 {
        match self {
            Attraction::VanDerWaals { range } | Attraction::Dugdale { range } => range,
        }
    }
}

/// The asperity law a [`super::Model`] is built from.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum AsperityLaw {
    /// docs/model.md §3 (the paper's law).
    #[default]
    Jkr,
    /// docs/model.md §7.
    Dmt(Attraction),
    /// docs/model.md §11: the Lennard-Jones sphere, with z0 = Z0/σ.
    LennardJones {
        /// z0 = Z0/σ > 0.
        range: f64,
    },
}

impl AsperityLaw {
    /// The law's name.
    pub fn adhesion_model(self) -> AdhesionModel {
        match self {
            AsperityLaw::Jkr => AdhesionModel::Jkr,
            AsperityLaw::Dmt(_) => AdhesionModel::Dmt,
            AsperityLaw::LennardJones { .. } => AdhesionModel::LennardJones,
        }
    }

    /// The law's module.
    pub fn law(self) -> &'static dyn Law {
        self.adhesion_model().law()
    }

    /// The reach of its attraction out of contact (z0 or Δ_h; 0 under JKR).
    pub fn range(self) -> f64 {
        match self {
            AsperityLaw::Jkr => 0.0,
            AsperityLaw::Dmt(a) => a.range(),
            AsperityLaw::LennardJones { range } => range,
        }
    }

    /// Its attraction's kind (van der Waals where it takes none).
    pub fn attraction_kind(self) -> AttractionKind {
        match self {
            AsperityLaw::Dmt(a) => a.kind(),
            _ => AttractionKind::VanDerWaals,
        }
    }

    /// The law for a scene's choice, with its attraction range from Z0 and σ.
    pub fn of(
        model: AdhesionModel,
        attraction: AttractionKind,
        interatomic_distance: f64,
        sigma: f64,
    ) -> Self {
        let law = model.law();
        let range = if law.takes_attraction() {
            attraction.range(interatomic_distance, sigma)
        } else {
            interatomic_distance / sigma
        };
        law.with_range(attraction, range)
    }
}

#[cfg(test)]
mod registry_tests {
    use super::*;

    #[test]
    fn names_round_trip_and_the_transition_is_bracketed() {
        for m in AdhesionModel::ALL {
            assert_eq!(AdhesionModel::from_name(m.as_str()), Some(m));
        }
        assert_eq!(AdhesionModel::from_name("lj"), None);
        for a in AttractionKind::ALL {
            assert_eq!(AttractionKind::from_name(a.as_str()), Some(a));
        }
        // Inside the transition (ends included) each limit law is answered by
        // the Lennard-Jones law, which needs nothing beside it.
        for phi in [0.3, 1.0, 3.0] {
            for m in [AdhesionModel::Jkr, AdhesionModel::Dmt] {
                assert_eq!(m.bracket(phi), Some(AdhesionModel::LennardJones));
            }
            assert_eq!(AdhesionModel::LennardJones.bracket(phi), None);
        }
        // The laws exact in each regime: the limit law and the general one.
        let valid = |phi: f64| AdhesionModel::valid_at(phi).collect::<Vec<_>>();
        use AdhesionModel::{Dmt, Jkr, LennardJones};
        assert_eq!(valid(0.1), [Dmt, LennardJones]);
        assert_eq!(valid(1.0), [LennardJones]);
        assert_eq!(valid(10.0), [Jkr, LennardJones]);
        // Each law's entry agrees with its configured law's.
        for m in AdhesionModel::ALL {
            let law = m.law().with_range(AttractionKind::Dugdale, 0.25);
            assert_eq!(law.adhesion_model(), m);
            let takes_range = m.takes_attraction() || m.law().has_own_range();
            assert_eq!(law.range(), if takes_range { 0.25 } else { 0.0 });
        }
        // Well inside a law's validity nothing brackets it.
        assert_eq!(AdhesionModel::Jkr.bracket(100.0), None);
        assert_eq!(AdhesionModel::Dmt.bracket(0.01), None);
    }
}
