//! wearopt: adhesive wear of rough micro-contacts.
//!
//! Data flows one way, from a problem file to a report:
//!
//! * [`model`]: the physics of the rough-surface adhesion model (`docs/model.md`):
//!   coefficients, indices, one asperity, the load and area integrals, the
//!   separation solve, Archard wear. No I/O.
//! * [`optimize`]: the constrained design search (SQP on clarabel subproblems,
//!   argmin-driven, multistart with rayon).
//! * [`problem`]: the TOML problem-file schema, units, the material catalogue and
//!   validation with precise errors.
//! * [`report`]: rendering results as text, JSON and CSV.
//! * [`documents`]: the command line's JSON documents (eval, optimize, pareto,
//!   roughness) computed from a problem or a height map, for the CLI and the
//!   Python package alike.

#![warn(missing_docs)]

pub mod accuracy;
pub mod calibrate;
pub mod documents;
pub mod figures;
pub mod model;
pub mod optimize;
pub mod problem;
pub mod report;
pub mod surface;
pub mod sweep;
