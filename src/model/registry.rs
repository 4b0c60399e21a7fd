//! The registry of asperity laws: the one place that lists them
//! ([`AdhesionModel::law`]), and what is read from it — names, parsing, the
//! options a law takes, where it is exact, which law answers another in the
//! JKR–DMT transition.

use super::asperity_law::Law;
use super::law::{AdhesionModel, AsperityLaw, AttractionKind, TRANSITION_TABOR};

impl AdhesionModel {
    /// Every asperity law, in the order problem files, options and messages list
    /// them: the registry every name, parser and list of laws reads.
    pub const ALL: [AdhesionModel; 3] = [
        AdhesionModel::Jkr,
        AdhesionModel::Dmt,
        AdhesionModel::LennardJones,
    ];

    /// The law's module: its names, the options it takes, where it is exact,
    /// and its physics. **The registration**: a new law is a variant of
    /// `AdhesionModel` and of [`AsperityLaw`] (`law.rs`), and one line here.
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

    /// The law that takes an attraction (the `attraction` key: DMT).
    pub fn taking_attraction() -> AdhesionModel {
        Self::ALL
            .into_iter()
            .find(|m| m.takes_attraction())
            .unwrap_or_default()
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

impl AsperityLaw {
    /// The law's module.
    pub fn law(self) -> &'static dyn Law {
        self.adhesion_model().law()
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
mod tests {
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
