//! The physics of docs/model.md: coefficients and indices; the asperity laws
//! ([`law`]: JKR §3, DMT with van der Waals or Dugdale attraction of the
//! asperities out of contact §7, and the self-consistent Lennard-Jones sphere
//! §11, [`lennard_jones`]; each an [`asperity_law`] found through the registry);
//! the capillary term of a meniscus in humid air (§10, [`capillary`],
//! [`environment`]); the load and area integrals, the separation solve, the
//! work of separation ([`work`]); the wear laws ([`wear_law`]: Archard §3 and the
//! stress-assisted law §12, behind one registry) and whether junctions smooth or
//! make debris (§13, [`debris`]); sensitivities; and the dimensional layer that
//! ties them to a [`Scene`], with the scene's parameters and the evaluation's
//! outputs each in one table ([`SceneParameter`], [`Quantity`]).
//! No I/O, no printing, no English: outcomes are values ([`Status`], [`Warning`],
//! [`Note`]) that the report stage words.
//!
//! Internals are crate-private: the DMT attraction quadrature (`dmt`), the
//! Gaussian special functions (`special`), and the modules behind the public
//! names (`jkr`, `material`, `parameter`, `registry`).

pub mod asperity;
pub mod asperity_curve;
pub mod asperity_law;
pub mod capillary;
pub mod coefficients;
pub mod debris;
pub(crate) mod dmt;
pub mod environment;
pub mod gauss;
pub mod integrals;
mod jkr;
pub mod law;
pub mod lennard_jones;
pub mod load_curve;
mod material;
mod parameter;
pub mod quadrature;
pub mod quantity;
mod registry;
pub mod scaled;
mod scene;
pub mod sensitivity;
pub mod separation;
pub(crate) mod special;
pub mod warnings;
pub mod wear;
pub mod wear_law;
pub mod work;

pub use capillary::Capillary;
pub use coefficients::{Coefficients, DomainError, Transition};
pub use environment::{Environment, HumidityRange, Liquid, Meniscus};
pub use integrals::{Integrals, Model};
pub use law::{AdhesionModel, AsperityLaw, Attraction, AttractionKind};
pub use load_curve::{load_curve, LoadCurve};
pub use material::Material;
pub use parameter::SceneParameter;
pub use quadrature::Quadrature;
pub use quantity::{Quantity, Role};
pub use scaled::Scaled;
pub use scene::{Cantilever, InputError, Requirements, Scene, WearArea};
pub use sensitivity::{sensitivities, Sensitivity, SensitivityGap};
pub use separation::{
    find_pull_off, landscape, landscape_from, pull_off_of, solve_separation, solve_separation_at,
    solve_separation_from, solve_separation_with, CriticalPoint, Landscape, PullOff,
    SeparationOutcome,
};
pub use warnings::{Note, Warning};
pub use wear::{
    equivalent_modulus, evaluate, evaluate_from, evaluate_with_other, Evaluation,
    EvaluationOptions, Indices, OtherModel, Regime, SearchHints, Status, Stiction, StictionVerdict,
};
pub use wear_law::{WearLaw, WearModel};
