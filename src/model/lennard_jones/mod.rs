//! The Lennard-Jones asperity (docs/model.md §11): an elastic sphere and a flat
//! attracting each other with a Lennard-Jones 9-3 surface force, solved
//! self-consistently, of which JKR (large Tabor parameter μ) and Bradley's rigid
//! sphere with DMT's contact (small μ) are the limits.

pub(crate) mod elliptic;
pub mod law;
pub mod rough;
pub mod sphere;
pub mod table;

pub use sphere::{spacing, Hold, NotConverged, Sphere, SpherePoint, SphereSettings, SphereState};
