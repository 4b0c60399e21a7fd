//! Speed of the scan analysis (issue 12): moments and McCool parameters of a 2048 × 2048
//! map (levelling, moments, parameters, summit count) ≤ 100 ms on two cores; reading a
//! 2048² `.gsf` ≤ 50 ms.
//!
//! Run: `cargo bench -p wearopt-benches --bench surface`

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use wearopt::surface::read::{read_bytes, write_gsf, Format, Overrides};
use wearopt::surface::synthetic::{random_surface, Spectrum};
use wearopt::surface::{analyse, psd::Psd, Levelling, Settings};

fn surface(c: &mut Criterion) {
    let n = 2048;
    let pixel = 10e-9;
    let map = random_surface(
        n,
        pixel,
        Spectrum::SelfAffine {
            hurst: 0.8,
            rolloff: 2.0 * std::f64::consts::PI / (n as f64 * pixel / 8.0),
            cutoff: 2.0 * std::f64::consts::PI / (4.0 * pixel),
        },
        5e-9,
        7,
    )
    .expect("synthetic map");
    let gsf = write_gsf(n, n, n as f64 * pixel, n as f64 * pixel, map.heights());
    let two = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .unwrap();
    let mut g = c.benchmark_group("surface 2048² (two threads)");
    g.sample_size(20);
    g.bench_function("analyse (plane level, moments, McCool, summits)", |b| {
        b.iter(|| two.install(|| analyse(black_box(&map), &Settings::default()).unwrap()))
    });
    g.bench_function("read .gsf from memory and resolve", |b| {
        b.iter(|| {
            read_bytes(black_box(&gsf), Format::Gsf, "bench.gsf")
                .unwrap()
                .resolve(&Overrides::default(), "bench.gsf")
                .unwrap()
        })
    });
    g.bench_function("PSD (Hann, radial average)", |b| {
        b.iter(|| {
            two.install(|| {
                let l = wearopt::surface::level(black_box(&map), Levelling::Plane).unwrap();
                Psd::of(&l)
            })
        })
    });
    g.bench_function("analyse with cut-off 8 pixels", |b| {
        let s = Settings {
            level: Levelling::Plane,
            cutoff: Some(8.0 * pixel),
        };
        b.iter(|| two.install(|| analyse(black_box(&map), &s).unwrap()))
    });
    g.finish();
}

criterion_group!(benches, surface);
criterion_main!(benches);
