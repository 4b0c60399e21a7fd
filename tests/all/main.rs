//! The integration tests, as modules of one test binary (one build and one link
//! instead of one per file; `cargo test` runs them all, `cargo test --test all
//! MODULE::` one file's). Test data lives in `tests/data/` and `tests/bad_input/`.

mod common;

mod accuracy;
mod app;
mod asperity;
mod calibrate;
mod capillary;
mod cli;
mod contact;
mod debris;
mod dmt;
mod dmt_reference;
mod dmt_studies;
mod dmt_weak;
mod embed;
mod figures;
mod fit_wear;
mod hock_schittkowski;
mod html;
mod law_regime;
mod lennard_jones_law;
mod lennard_jones_limit;
mod lennard_jones_rough;
mod lennard_jones_table;
mod materials;
mod model_invariants;
mod newcomer;
mod optimize;
mod optimize_contracts;
mod optimize_regressions;
mod pareto;
mod pareto_regressions;
mod problem_files;
mod reference;
mod reports;
mod robust;
mod robust_design;
mod robust_pareto;
mod search_cost;
mod stability;
mod stress_assisted_wear;
mod surface;
mod surface_problem;
mod surface_read;
mod svg_bounds;
mod sweep;
mod testers;
mod uncertainty;
mod uq;
