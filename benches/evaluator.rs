//! Speed of the evaluator (issue: non-dimensional evaluation ≤ 1 µs median,
//! dimensional evaluation with the separation solve ≤ 20 µs median).
//!
//! Run: `cargo bench --bench evaluator`

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use wearopt::model::{evaluate, Coefficients, EvaluationOptions, Model};

fn nondimensional(c: &mut Criterion) {
    let mut g = c.benchmark_group("nondimensional P̄, Ā at one h");
    for &(theta, lambda, h) in &[
        (10.0, 1.0, 1.0),
        (100.0, 5.0, 3.0),
        (0.1, 1e-3, -2.0),
        (1e4, 100.0, 20.0),
    ] {
        let m = Model::new(Coefficients::from_indices(theta, lambda));
        g.bench_function(format!("theta={theta} lambda={lambda} h={h}"), |b| {
            b.iter(|| {
                let at = m.at(black_box(h));
                black_box((at.load(), at.area()))
            })
        });
    }
    let gw = Model::new(Coefficients::new(0.0, f64::INFINITY));
    g.bench_function("greenwood-williamson h=1", |b| {
        b.iter(|| black_box(gw.at(black_box(1.0)).load()))
    });
    g.finish();
}

fn dimensional(c: &mut Criterion) {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/problems/");
    let mut g = c.benchmark_group("dimensional scene evaluation");
    for name in ["micro-gear", "dlc-contact", "gold-switch"] {
        let problem = wearopt::problem::load(std::path::Path::new(&format!("{dir}{name}.toml")))
            .expect("shipped problem loads");
        let solve_only = EvaluationOptions {
            pull_off: false,
            ..EvaluationOptions::default()
        };
        g.bench_function(format!("{name}: separation solve"), |b| {
            b.iter(|| black_box(evaluate(black_box(&problem.scene), &solve_only)))
        });
        g.bench_function(format!("{name}: solve + pull-off"), |b| {
            b.iter(|| {
                black_box(evaluate(
                    black_box(&problem.scene),
                    &EvaluationOptions::default(),
                ))
            })
        });
    }
    g.finish();
}

criterion_group!(benches, nondimensional, dimensional);
criterion_main!(benches);
