//! The uncertainty engines on cheap closed-form models, so that the numbers are
//! the engines' own cost: FORM + SORM (no sampling) on the 5-D paraboloid
//! g = 3.5 − u5 + Σ_{i≤4} u_i², and the analysis of Sobol′ indices (centring,
//! estimates, intervals over 32 replicates) at N = 2^14, d = 5 on precomputed values;
//! and the reliability-based design of Youn & Choi (2004) by SORA with its
//! verification by importance sampling (`uq::robust`, s = 0.3, β_t = 3, one start).
//! Run with `cargo bench -p wearopt-benches --bench uq`.

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;

use wearopt::uq::distribution::std_normal_cdf;
use wearopt::uq::distribution::Distribution;
use wearopt::uq::model::InputModel;
use wearopt::uq::reliability::{self, ReliabilitySettings};
use wearopt::uq::robust::{self, Outputs, RobustSettings, UncertainProgram};
use wearopt::uq::sobol;

fn form_sorm(c: &mut Criterion) {
    let model =
        InputModel::independent(vec![Distribution::Normal { mean: 0.0, sd: 1.0 }; 5]).unwrap();
    let settings = ReliabilitySettings {
        sampling: false,
        ..Default::default()
    };
    let g = |x: &[f64]| Some(3.5 - x[4] + x[..4].iter().map(|v| v * v).sum::<f64>());
    c.bench_function("FORM (21 starts) + SORM, 5-D paraboloid", |b| {
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
            sobol::points(&model, k, 1 << 14, 1)
                .iter()
                .map(|x| Some(f(x)))
                .collect()
        })
        .collect();
    let mut group = c.benchmark_group("sobol");
    group.sample_size(10);
    group.bench_function("analyze, N = 2^14, d = 5", |b| {
        b.iter(|| black_box(sobol::analyze(d, &values)))
    });
    group.bench_function("points, N = 2^14, d = 5", |b| {
        b.iter(|| {
            for k in 0..1u64 << 14 {
                black_box(sobol::points(&model, k, 1 << 14, 1));
            }
        })
    });
    group.finish();
}

/// Youn & Choi 2004: min d1 + d2, X ~ N(d, 0.3²), three chance constraints.
struct YounChoi;

impl UncertainProgram for YounChoi {
    fn dimension(&self) -> usize {
        2
    }
    fn bounds(&self) -> (Vec<f64>, Vec<f64>) {
        (vec![0.0; 2], vec![10.0; 2])
    }
    fn inputs(&self, d: &[f64]) -> InputModel {
        InputModel::independent(
            d.iter()
                .map(|&mean| Distribution::Normal { mean, sd: 0.3 })
                .collect(),
        )
        .unwrap()
    }
    fn outputs(&self, d: &[f64], x: &[f64]) -> Option<Outputs> {
        let (x1, x2) = (x[0], x[1]);
        Some(Outputs {
            objective: d[0] + d[1],
            limit_states: vec![
                x1 * x1 * x2 / 20.0 - 1.0,
                (x1 + x2 - 5.0).powi(2) / 30.0 + (x1 - x2 - 12.0).powi(2) / 120.0 - 1.0,
                80.0 / (x1 * x1 + 8.0 * x2 + 5.0) - 1.0,
            ],
            constraints: Vec::new(),
        })
    }
}

fn youn_choi(c: &mut Criterion) {
    let settings = RobustSettings {
        targets: vec![std_normal_cdf(-3.0); 3],
        ..RobustSettings::default()
    };
    let mut group = c.benchmark_group("robust");
    group.sample_size(10);
    group.bench_function("Youn & Choi, SORA + verification (CoV 0.02)", |b| {
        b.iter(|| {
            black_box(robust::optimize_robust(
                &YounChoi,
                &[vec![5.0, 5.0]],
                &settings,
            ))
        })
    });
    group.finish();
}

criterion_group!(benches, form_sorm, sobol_analyze, youn_choi);
criterion_main!(benches);
