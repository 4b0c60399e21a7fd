//! 100 000 designs of the five-variable micro-gear study
//! (`problems/micro-gear-study.toml`), Sobol′ points, each row evaluated (separation,
//! pull-off, constraints) and written as CSV to a sink, as `wearopt sweep` does.
//! Run with `cargo bench -p wearopt-benches --bench sweep`; target median ≤ 3 s on two cores.

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::path::Path;

use wearopt::report::sweep::{self as out, Encoding};
use wearopt::sweep::{Method, Sweep};

fn micro_gear_sweep(c: &mut Criterion) {
    let path = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
        .join("problems/micro-gear-study.toml");
    let problem = wearopt::problem::load(&path).expect("micro-gear-study.toml loads");
    let s = &problem.study;
    let samples = 100_000;
    let sweep = Sweep::new(
        &problem.scene,
        &s.design,
        &s.constraints,
        Method::Sobol,
        samples,
        0,
    )
    .expect("a valid sweep");
    let mut group = c.benchmark_group("sweep");
    group.sample_size(10);
    group.bench_function("micro-gear study, 100 000 designs (CSV)", |b| {
        b.iter(|| {
            let mut bytes = 0usize;
            let mut first = true;
            sweep
                .run(0..samples, |rows| {
                    for r in rows {
                        bytes += out::row(Encoding::Csv, &sweep, r, first).len();
                        first = false;
                    }
                    Ok::<(), ()>(())
                })
                .expect("sink never fails");
            black_box(bytes)
        })
    });
    group.finish();
}

criterion_group!(benches, micro_gear_sweep);
criterion_main!(benches);
