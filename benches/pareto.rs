//! A 15-point wear–adhesion front of the micro-gear study (`problems/micro-gear.toml`).
//! Run with `cargo bench --bench pareto`; target median ≤ 0.5 s on two cores.

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::path::Path;

use wearopt::optimize::pareto::{pareto, Silent};
use wearopt::optimize::Study;

fn micro_gear_front(c: &mut Criterion) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("problems/micro-gear.toml");
    let problem = wearopt::problem::load(&path).expect("micro-gear.toml loads");
    let mut spec = problem.study.pareto.expect("micro-gear.toml has [pareto]");
    spec.points = 15;
    let study = Study {
        scene: &problem.scene,
        design: &problem.study.design,
        objective: problem.study.objective,
        constraints: &problem.study.constraints,
        settings: &problem.study.optimizer,
    };
    let mut group = c.benchmark_group("pareto");
    group.sample_size(10);
    group.bench_function("micro-gear front, 15 points", |b| {
        b.iter(|| black_box(pareto(&study, &spec, &Silent).expect("front")))
    });
    group.finish();
}

criterion_group!(benches, micro_gear_front);
criterion_main!(benches);
