//! Speed of the contact solver (issue 24): one application of the half-space
//! compliance (a forward and an inverse 2-D real FFT with the Westergaard kernel)
//! on 512² and 1024² maps, and a whole elastic solve of the shipped 256² scan at
//! ~6 % contact, and adhesive solves on it, on one thread. The comparison with Tamaas runs side by side in
//! `scripts/bench_contact.py`.
//!
//! Run: `cargo bench -p wearopt-benches --bench contact`

use std::hint::black_box;
use std::path::Path;

use criterion::{criterion_group, criterion_main, Criterion};
use wearopt::contact::adhesion::Adhesion;
use wearopt::contact::fft::Compliance;
use wearopt::contact::{Settings, Solver};
use wearopt::surface::read::{load, Overrides};
use wearopt::surface::{level, Levelling};

fn contact(c: &mut Criterion) {
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    let mut g = c.benchmark_group("contact (one thread)");
    g.sample_size(20);
    for n in [512usize, 1024] {
        let mut k = Compliance::new(n, n, 1e-8, 1e-8, 1e11);
        let field: Vec<f64> = (0..n * n).map(|i| ((i * 7919) % 1000) as f64).collect();
        let mut out = vec![0.0; n * n];
        g.bench_function(format!("compliance K·p, {n}²"), |b| {
            b.iter(|| one.install(|| k.apply(black_box(&field), &mut out)))
        });
    }
    let root = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."));
    let map = load(
        &root.join("problems/scans/self-affine.gsf"),
        &Overrides::default(),
    )
    .unwrap();
    let map = level(&map, Levelling::Plane).unwrap();
    let mut solver = Solver::new(
        map.nx(),
        map.ny(),
        map.pixel_size_x(),
        map.pixel_size_y(),
        map.heights(),
        150e9,
    )
    .unwrap();
    g.bench_function(
        "elastic solve, shipped 256² scan, 200 MPa (6.3 % contact)",
        |b| b.iter(|| one.install(|| solver.solve(black_box(200e6), &Settings::default(), None))),
    );
    // Adhesion: one solve at a mean gap from the undeformed gaps, and one warm
    // step of a pull-off sweep (the unit of `wearopt contact --work-of-adhesion`).
    let law = Adhesion::new(0.1, 0.5e-9).unwrap();
    let settings = Settings::default();
    g.bench_function(
        "adhesive solve at mean gap 5 nm, shipped 256² scan, γ = 0.1 J/m², ρ = 0.5 nm",
        |b| {
            b.iter(|| {
                one.install(|| solver.adhesive_at_gap(black_box(5e-9), &law, &settings, None))
            })
        },
    );
    let state = solver.adhesive_at_gap(5e-9, &law, &settings, None).unwrap();
    g.bench_function("adhesive warm step (+0.25 nm), same", |b| {
        b.iter(|| {
            one.install(|| {
                solver.adhesive_at_gap(black_box(5.25e-9), &law, &settings, Some(&state.gaps))
            })
        })
    });
    g.finish();
}

criterion_group!(benches, contact);
criterion_main!(benches);
