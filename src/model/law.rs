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
//!   table (solved to μ = 22.4, its closed-form limit curves above), valid for
//!   every Tabor parameter; outside them (μ < 9.91e-5, μ > 3.58e6) the closed-form
//!   laws stand in.
//!
//! Each law's module implements `asperity_law::Law`: its entry in the registry (names,
//! options, where it is exact, its words) and what the model asks of it —
//! (a) the coefficients its contact integrals use or its own integrals,
//! (b) the elastic–plastic transition, (c) an optional non-contact load.
//! [`AdhesionModel::law`] is the registry. The separation and pull-off searches
//! only see P̄, P̄', P̄'' and the sign of the load jump.

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
}
