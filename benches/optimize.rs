//! Speed of whole design studies (issue: the five-variable micro-gear study,
//! median ≤ 10 ms on one thread).
//!
//! Run: `cargo bench -p wearopt-benches --bench optimize`

use std::hint::black_box;
use std::path::Path;

use criterion::{criterion_group, criterion_main, Criterion};
use wearopt::optimize::{optimize, Study};

fn studies(c: &mut Criterion) {
    let one_thread = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    let mut g = c.benchmark_group("optimize (one thread)");
    g.sample_size(20);
    for name in ["micro-gear-study", "micro-gear", "switch-study"] {
        let p = wearopt::problem::load(Path::new(&format!(
            "{}/../problems/{name}.toml",
            env!("CARGO_MANIFEST_DIR")
        )))
        .expect("shipped study loads");
        let study = Study {
            scene: &p.scene,
            design: &p.study.design,
            objective: p.study.objective,
            constraints: &p.study.constraints,
            settings: &p.study.optimizer,
        };
        g.bench_function(name, |b| {
            b.iter(|| one_thread.install(|| black_box(optimize(black_box(&study)).unwrap())))
        });
    }
    g.finish();
}

criterion_group!(benches, studies);
criterion_main!(benches);
