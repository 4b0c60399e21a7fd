//! wearopt: adhesive wear of rough micro-contacts.
//!
//! Data flows one way, from a problem file or a scan to a document and its
//! renderings. The modules stand on floors, and each imports only modules on the
//! floors below it (`docs/architecture.md` draws the house):
//!
//! 1. [`units`]: dimensions, reading and writing quantities. Imports nothing.
//! 2. [`model`]: the physics of the rough-surface adhesion model (`docs/model.md`):
//!    coefficients, indices, the asperity laws, the load and area integrals, the
//!    separation solve, Archard wear. No I/O. [`surface`]: height maps to σ, R and N.
//!    [`contact`]: the FFT boundary-element solver on a map (imports [`surface`]'s
//!    synthetic maps in its tests only).
//! 3. [`optimize`]: the constrained design search (SQP on clarabel subproblems,
//!    argmin-driven, multistart with rayon); [`accuracy`] and [`figures`].
//! 4. [`sweep`]: design-space sampling; [`uq`]: uncertainty quantification
//!    (Sobol′ and Morris sensitivity, sampling statistics, FORM/SORM reliability)
//!    on any model closure; [`problem`]: the TOML problem-file schema,
//!    the material catalogue and validation with precise errors; [`calibrate`].
//! 5. [`app`]: one function per command, typed options in, a typed document out,
//!    for the command line and the Python package alike.
//! 6. [`report`]: renders a document in a format (text, JSON, CSV, SVG, HTML).

#![warn(missing_docs)]

pub mod accuracy;
pub mod app;
pub mod calibrate;
pub mod contact;
pub mod figures;
pub mod model;
pub mod optimize;
pub mod problem;
pub mod report;
pub mod surface;
pub mod sweep;
pub mod units;
pub mod uq;
pub mod wear_fit;
