//! wearopt: adhesive wear of rough micro-contacts.
//!
//! Data flows one way, from a problem file to a report:
//!
//! * [`model`]: the physics of the rough-surface adhesion model (shared `MODEL.md`):
//!   coefficients, indices, one asperity, the load and area integrals, the
//!   separation solve, Archard wear. No I/O.
//! * [`problem`]: the TOML problem-file schema, units, the material catalogue and
//!   validation with precise errors.
//! * [`report`]: rendering results as text, JSON and CSV.

pub mod model;
pub mod problem;
pub mod report;
