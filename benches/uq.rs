//! The uncertainty engines on cheap closed-form models, so that the numbers are
//! the engines' own cost: FORM + SORM (no sampling) on the 5-D paraboloid
//! g = 3.5 − u5 + Σ_{i≤4} u_i², and the analysis of Sobol′ indices (centring,
//! estimates, 1000 bootstrap resamples) at N = 2^14, d = 5 on precomputed values.
//! Run with `cargo bench --bench uq`.

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;

use wearopt::uq::distribution::Distribution;
use wearopt::uq::model::InputModel;
use wearopt::uq::reliability::{self, ReliabilitySettings};
use wearopt::uq::sobol;

fn form_sorm(c: &mut Criterion) {
    let model =
        InputModel::independent(vec![Distribution::Normal { mean: 0.0, sd: 1.0 }; 5]).unwrap();
    let settings = ReliabilitySettings {
        sampling: false,
        ..Default::default()
    };
    let g = |x: &[f64]| Some(3.5 - x[4] + x[..4].iter().map(|v| v * v).sum::<f64>());
    c.bench_function("FORM (11 starts) + SORM, 5-D paraboloid", |b| {
        b.iter(|| black_box(reliability::analyze(&model, g, &settings)))
    });
}

fn sobol_analyze(c: &mut Criterion) {
    let d = 5;
    let model =
        InputModel::independent(vec![Distribution::Uniform { min: 0.0, max: 1.0 }; d]).unwrap();
    let f = |x: &[f64]| x[0] + 2.0 * x[1] * x[2] + x[3].sin() + 0.1 * x[4];
    let values: Vec<Vec<Option<f64>>> = (0..1u64 << 14)
        .map(|k| {
            sobol::points(&model, k, 1)
                .iter()
                .map(|x| Some(f(x)))
                .collect()
        })
        .collect();
    let mut group = c.benchmark_group("sobol");
    group.sample_size(10);
    group.bench_function("analyze, N = 2^14, d = 5, 1000 resamples", |b| {
        b.iter(|| black_box(sobol::analyze(d, &values, 1)))
    });
    group.bench_function("points, N = 2^14, d = 5", |b| {
        b.iter(|| {
            for k in 0..1u64 << 14 {
                black_box(sobol::points(&model, k, 1));
            }
        })
    });
    group.finish();
}

criterion_group!(benches, form_sorm, sobol_analyze);
criterion_main!(benches);
