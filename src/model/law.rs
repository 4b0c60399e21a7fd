//! The asperity laws: how one asperity's load depends on its interference.
//!
//! The evaluator ([`super::Model`]) is built from one [`AsperityLaw`]:
//!
//! * [`AsperityLaw::Jkr`] — docs/model.md §3: JKR elastic asperities on the loading
//!   branch, plastic junctions beyond Δc; surface forces act only inside contacts.
//!   Its integrals live in `integrals.rs` (elastic quadrature in s = Δ1^{1/4}).
//! * [`AsperityLaw::Dmt`] — docs/model.md §7: Hertz contact with the DMT adhesive
//!   offset `-c_0`, Δc = c_h², and attraction of the asperities that are *not* in
//!   contact, by a Dugdale stress of range Δ_h or by van der Waals forces with
//!   equilibrium distance z0. Its non-contact term lives in `dmt.rs`.
//!
//! A law contributes (a) the coefficients its contact integrals use, (b) the
//! elastic–plastic transition, and (c) an optional non-contact load.
//!
//! * [`AsperityLaw::LennardJones`] — docs/model.md §11: the self-consistent
//!   sphere with a Lennard-Jones surface force, from its loading table
//!   (`lennard_jones/`), valid for every Tabor parameter; outside the table
//!   (μ < 0.01, μ > 5) its closed-form limits stand in.
//!
//! The separation and pull-off searches only see P̄, P̄', P̄'' and the sign of
//! the load jump.

use serde::Serialize;

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

    /// The word used in problem files and reports.
    pub fn as_str(self) -> &'static str {
        match self {
            AdhesionModel::Jkr => "jkr",
            AdhesionModel::Dmt => "dmt",
            AdhesionModel::LennardJones => "lennard_jones",
        }
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
        match self {
            AdhesionModel::Jkr | AdhesionModel::LennardJones => false,
            AdhesionModel::Dmt => true,
        }
    }

    /// The law's name as a report writes it in prose.
    pub fn label(self) -> &'static str {
        match self {
            AdhesionModel::Jkr => "JKR",
            AdhesionModel::Dmt => "DMT",
            AdhesionModel::LennardJones => "Lennard-Jones",
        }
    }

    /// The Tabor parameters φ0 over which the law is exact (closed ends): JKR at
    /// and above the transition, DMT at and below it.
    pub fn valid_tabor(self) -> (f64, f64) {
        match self {
            AdhesionModel::Jkr => (TRANSITION_TABOR.1, f64::INFINITY),
            AdhesionModel::Dmt => (0.0, TRANSITION_TABOR.0),
            AdhesionModel::LennardJones => (0.0, f64::INFINITY),
        }
    }

    /// The law `eval` gives beside this one at φ0: inside the JKR–DMT transition
    /// (ends included) a limit law (JKR or DMT) is answered beside by the law
    /// valid there, the Lennard-Jones sphere. `None` for the Lennard-Jones law
    /// itself and outside the transition (φ0 inside the limit law's validity).
    pub fn bracket(self, tabor: f64) -> Option<AdhesionModel> {
        let inside = tabor >= TRANSITION_TABOR.0 && tabor <= TRANSITION_TABOR.1;
        let general = AdhesionModel::LennardJones;
        (inside && self != general).then_some(general)
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

    /// The law for a scene's choice, with its attraction range from Z0 and σ.
    pub fn of(
        model: AdhesionModel,
        attraction: AttractionKind,
        interatomic_distance: f64,
        sigma: f64,
    ) -> Self {
        match model {
            AdhesionModel::Jkr => AsperityLaw::Jkr,
            AdhesionModel::Dmt => AsperityLaw::Dmt(Attraction::new(
                attraction,
                attraction.range(interatomic_distance, sigma),
            )),
            AdhesionModel::LennardJones => AsperityLaw::LennardJones {
                range: interatomic_distance / sigma,
            },
        }
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
        // Well inside a law's validity nothing brackets it.
        assert_eq!(AdhesionModel::Jkr.bracket(100.0), None);
        assert_eq!(AdhesionModel::Dmt.bracket(0.01), None);
    }
}
