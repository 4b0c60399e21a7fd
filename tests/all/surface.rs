//! The scan analysis (SURFACES.md §2–§6b) against values computed here, independently of
//! the code under test: direct sums on small maps, closed forms of sampled sines, the
//! ISO 16610-61 transmission, and the summit statistics of Gaussian random surfaces.

use wearopt::surface::filter::gaussian_cutoff;
use wearopt::surface::psd::Psd;
use wearopt::surface::synthetic::{random_surface, Spectrum};
use wearopt::surface::{
    analyse, level, HeightMap, Levelling, Moments, Parameters, Settings, SummitCount, SurfaceError,
    Warning,
};

const PI: f64 = std::f64::consts::PI;

/// Relative difference.
fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// A 6 × 5 map with two missing points, heights in metres.
fn small_map() -> HeightMap {
    let nx = 6;
    let ny = 5;
    let mut h = Vec::new();
    for j in 0..ny {
        for i in 0..nx {
            // Arbitrary but fixed values with structure in both directions.
            let v = ((i * 7 + j * 13) % 11) as f64 - 5.0 + 0.3 * (i * j) as f64;
            h.push(v * 1e-9);
        }
    }
    h[2 * nx + 3] = f64::NAN;
    h[4 * nx] = f64::NAN;
    HeightMap::new(nx, ny, 2e-8, 3e-8, h).unwrap()
}

#[test]
fn moments_of_a_small_map_with_missing_points_by_direct_sums() {
    let map = small_map();
    let (nx, ny, dx, dy) = (6usize, 5usize, 2e-8, 3e-8);
    let h = |i: usize, j: usize| map.at(i, j);
    // Levelling "none" subtracts the mean of the valid points.
    let valid: Vec<f64> = map
        .heights()
        .iter()
        .copied()
        .filter(|x| !x.is_nan())
        .collect();
    assert_eq!(valid.len(), 28);
    let mean = valid.iter().sum::<f64>() / 28.0;
    let m0 = valid.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / 28.0;
    let mut sx = (0.0, 0);
    let mut sy = (0.0, 0);
    let mut sxx = (0.0, 0);
    let mut syy = (0.0, 0);
    for j in 0..ny {
        for i in 0..nx {
            if i + 1 < nx && !h(i, j).is_nan() && !h(i + 1, j).is_nan() {
                sx.0 += ((h(i + 1, j) - h(i, j)) / dx).powi(2);
                sx.1 += 1;
            }
            if j + 1 < ny && !h(i, j).is_nan() && !h(i, j + 1).is_nan() {
                sy.0 += ((h(i, j + 1) - h(i, j)) / dy).powi(2);
                sy.1 += 1;
            }
            if i >= 1
                && i + 1 < nx
                && [h(i - 1, j), h(i, j), h(i + 1, j)]
                    .iter()
                    .all(|x| !x.is_nan())
            {
                sxx.0 += ((h(i + 1, j) - 2.0 * h(i, j) + h(i - 1, j)) / (dx * dx)).powi(2);
                sxx.1 += 1;
            }
            if j >= 1
                && j + 1 < ny
                && [h(i, j - 1), h(i, j), h(i, j + 1)]
                    .iter()
                    .all(|x| !x.is_nan())
            {
                syy.0 += ((h(i, j + 1) - 2.0 * h(i, j) + h(i, j - 1)) / (dy * dy)).powi(2);
                syy.1 += 1;
            }
        }
    }
    // Counts by hand. Missing (3, 2) and (0, 4). Pairs along x: 6·5 − 5 = 25, less 2 in
    // row 2 and 1 in row 4: 22. Pairs along y: 6·4 = 24 less 2 + 1: 21. Triples along x:
    // 4·5 = 20 less 3 + 1: 16. Triples along y: 6·3 = 18 less 3 + 1: 14.
    assert_eq!((sx.1, sy.1, sxx.1, syy.1), (22, 21, 16, 14));
    let levelled = level(&map, Levelling::None).unwrap();
    let m = Moments::of(&levelled);
    let (m2x, m2y) = (sx.0 / sx.1 as f64, sy.0 / sy.1 as f64);
    let (m4x, m4y) = (sxx.0 / sxx.1 as f64, syy.0 / syy.1 as f64);
    assert!(rel(m.m0, m0) < 1e-12);
    assert!(rel(m.m2_x, m2x) < 1e-12);
    assert!(rel(m.m2_y.unwrap(), m2y) < 1e-12);
    assert!(rel(m.m4_x, m4x) < 1e-12);
    assert!(rel(m.m4_y.unwrap(), m4y) < 1e-12);
    assert!(rel(m.m2, 0.5 * (m2x + m2y)) < 1e-12);
    assert!(rel(m.m4, 0.5 * (m4x + m4y)) < 1e-12);
}

#[test]
fn moments_of_a_profile_are_the_x_ones() {
    let h: Vec<f64> = [0.0, 2.0, 1.0, 4.0, 3.0, f64::NAN, 1.0, 0.0]
        .iter()
        .map(|x| x * 1e-9)
        .collect();
    let map = HeightMap::new(8, 1, 1e-8, 1e-8, h.clone()).unwrap();
    assert!(map.is_profile());
    let m = Moments::of(&level(&map, Levelling::None).unwrap());
    // Pairs (0,1) (1,2) (2,3) (3,4) (6,7); triples centred at 1, 2, 3.
    let d = |a: f64, b: f64| (b - a) * 1e-9 / 1e-8;
    let m2 = [d(0., 2.), d(2., 1.), d(1., 4.), d(4., 3.), d(1., 0.)]
        .iter()
        .map(|x| x * x)
        .sum::<f64>()
        / 5.0;
    let dd = |a: f64, b: f64, c: f64| (a - 2.0 * b + c) * 1e-9 / 1e-16;
    let m4 = [dd(0., 2., 1.), dd(2., 1., 4.), dd(1., 4., 3.)]
        .iter()
        .map(|x| x * x)
        .sum::<f64>()
        / 3.0;
    assert!(rel(m.m2, m2) < 1e-12 && m.m2_y.is_none());
    assert!(rel(m.m4, m4) < 1e-12 && m.m4_y.is_none());
    // A column is stored as the same profile.
    let col = HeightMap::new(1, 8, 1e-8, 1e-8, h).unwrap();
    assert_eq!(Moments::of(&level(&col, Levelling::None).unwrap()), m);
}

/// A sine along x, constant along y: n = periods·P + 1 points of P samples per period.
fn sine(periods: usize, per: usize, ny: usize, amplitude: f64, dx: f64) -> (HeightMap, f64) {
    let n = periods * per + 1;
    let k = 2.0 * PI / (per as f64 * dx);
    let mut h = Vec::new();
    for _ in 0..ny {
        for i in 0..n {
            h.push(amplitude * (k * i as f64 * dx).sin());
        }
    }
    (HeightMap::new(n, ny, dx, dx, h).unwrap(), k)
}

#[test]
fn sampled_sine_moments_match_their_closed_forms() {
    // h_i = A sin(k i Δ), i = 0..mP (P samples per period, m periods).
    // m0: the mean is exactly 0 (whole periods plus sin 2πm = 0), so m0 = (A²/2) mP/(mP+1).
    // Forward differences (2A/Δ) sin(kΔ/2) cos(k x_i + kΔ/2) over mP whole periods:
    //   m2 = (2A/Δ)² sin²(kΔ/2) / 2.
    // Second differences −(4A/Δ²) sin²(kΔ/2) sin(k x_i), centres i = 1..mP−1:
    //   m4 = (4A/Δ²)² sin⁴(kΔ/2) (mP/2)/(mP−1).
    // As kΔ → 0 these tend to A²k²/2 and A²k⁴/2.
    let (a, dx) = (3e-9, 1e-8);
    for &(periods, per) in &[(8usize, 16usize), (5, 50), (20, 7)] {
        let (map, k) = sine(periods, per, 1, a, dx);
        let m = Moments::of(&level(&map, Levelling::None).unwrap());
        let mp = (periods * per) as f64;
        let s = (k * dx / 2.0).sin();
        let m0 = a * a / 2.0 * mp / (mp + 1.0);
        let m2 = (2.0 * a / dx).powi(2) * s * s / 2.0;
        let m4 = (4.0 * a / (dx * dx)).powi(2) * s.powi(4) * (mp / 2.0) / (mp - 1.0);
        assert!(rel(m.m0, m0) < 1e-12, "m0 {} vs {}", m.m0, m0);
        assert!(rel(m.m2, m2) < 1e-12, "m2 {} vs {}", m.m2, m2);
        assert!(rel(m.m4, m4) < 1e-12, "m4 {} vs {}", m.m4, m4);
        // Continuum limits to O((kΔ)²).
        let kd2 = (k * dx).powi(2);
        assert!(rel(m.m2, a * a * k * k / 2.0) < kd2);
        assert!(rel(m.m4, a * a * k.powi(4) / 2.0) < kd2);
    }
    // On a map (constant along y) the y moments are 0 and the combined ones halve.
    let (map, _) = sine(8, 16, 4, a, dx);
    let m = Moments::of(&level(&map, Levelling::None).unwrap());
    assert_eq!((m.m2_y, m.m4_y), (Some(0.0), Some(0.0)));
    assert!(rel(m.m2, m.m2_x / 2.0) < 1e-15);
    assert!(m.anisotropy_ratio().is_infinite());
}

#[test]
fn a_single_wavelength_is_refused_as_inconsistent() {
    // α of a sine is 1 (m0 m4 = m2²), below the 1.5 of any isotropic Gaussian surface.
    let (map, _) = sine(8, 16, 1, 1e-9, 1e-8);
    match analyse(&map, &Settings::default()) {
        Err(SurfaceError::InconsistentMoments { alpha }) => assert!((alpha - 1.0).abs() < 0.05),
        other => panic!("{other:?}"),
    }
    let flat = HeightMap::new(4, 4, 1e-8, 1e-8, vec![1e-9; 16]).unwrap();
    assert!(matches!(
        analyse(&flat, &Settings::default()),
        Err(SurfaceError::Unresolved { .. })
    ));
}

/// Maps that are not surfaces are refused: a constant map (it was read as
/// R = 1.8e9 m) and a tilted plane stored in single precision (its levelled
/// "roughness" is the float32 rounding, 6e-8 of the heights). A random surface
/// on the same offset is analysed.
#[test]
fn a_constant_map_or_a_plane_is_refused() {
    let n = 64;
    let constant = HeightMap::new(n, n, 1e-8, 1e-8, vec![3.7e-6; n * n]).unwrap();
    let plane: Vec<f64> = (0..n * n)
        .map(|k| (2e-6 + 1e-9 * (k % n) as f64 + 3e-10 * (k / n) as f64) as f32 as f64)
        .collect();
    let plane = HeightMap::new(n, n, 1e-8, 1e-8, plane).unwrap();
    for map in [&constant, &plane] {
        match analyse(map, &Settings::default()) {
            Err(e @ SurfaceError::Unresolved { .. }) => {
                assert!(e.to_string().contains("a constant map or a plane"), "{e}")
            }
            other => panic!("{other:?}"),
        }
    }
    let rough = random_surface(
        n,
        1e-8,
        Spectrum::Gaussian {
            correlation_length: 5e-8,
        },
        1e-9,
        3,
    )
    .unwrap();
    let offset: Vec<f64> = rough.heights().iter().map(|h| h + 2e-6).collect();
    let rough = HeightMap::new(n, n, 1e-8, 1e-8, offset).unwrap();
    assert!(analyse(&rough, &Settings::default()).is_ok());
}

/// Every other row missing: no valid pair along y. Its moments were counted as
/// zero slope (m2 halved, R off by √2, the warning blaming anisotropy); now x
/// stands for both, and the warning says so. On a random surface the result
/// equals the x-only moments of the full map's rows kept.
#[test]
fn a_direction_without_pairs_is_left_out_and_said() {
    let n = 64;
    let rough = random_surface(
        n,
        1e-8,
        Spectrum::Gaussian {
            correlation_length: 5e-8,
        },
        1e-9,
        4,
    )
    .unwrap();
    let holes: Vec<f64> = rough
        .heights()
        .iter()
        .enumerate()
        .map(|(k, &h)| if (k / n) % 2 == 1 { f64::NAN } else { h })
        .collect();
    let map = HeightMap::new(n, n, 1e-8, 1e-8, holes).unwrap();
    let settings = Settings {
        level: Levelling::None,
        cutoff: None,
    };
    let r = analyse(&map, &settings).unwrap();
    let m = Moments::of(&map);
    assert_eq!(m.only_along, Some("x"));
    assert_eq!(m.m2, m.m2_x);
    assert_eq!(m.m4, m.m4_x);
    assert!(r.warnings.iter().any(|w| matches!(
        w,
        Warning::OneDirection {
            used: "x",
            missing: "y"
        }
    )));
    assert!(!r
        .warnings
        .iter()
        .any(|w| matches!(w, Warning::Anisotropy { .. })));
}

#[test]
fn mccool_formulas_as_written() {
    let m = Moments {
        m0: 4e-18,
        m2: 1e-3,
        m4: 2e12,
        m2_x: 1e-3,
        m2_y: Some(1e-3),
        m4_x: 2e12,
        m4_y: Some(2e12),
        only_along: None,
    };
    let p = Parameters::from_moments(&m).unwrap();
    let alpha = 4e-18 * 2e12 / 1e-6;
    assert!(rel(p.bandwidth, alpha) < 1e-15);
    assert!(rel(p.summit_density, 2e12 / (6.0 * PI * 3f64.sqrt() * 1e-3)) < 1e-15);
    assert!(rel(p.summit_radius, 0.375 * (PI / 2e12).sqrt()) < 1e-15);
    assert!(rel(p.summit_sigma, ((1.0 - 0.8968 / alpha) * 4e-18).sqrt()) < 1e-15);
    assert!(rel(p.mean_summit_height, 4.0 * 2e-9 / (PI * alpha).sqrt()) < 1e-15);
    // SURFACES.md §7: ηRσ = 0.0204 √α (to the rounding of its constants, for α ≫ 1).
    let expected = 1.0 / (6.0 * PI * 3f64.sqrt())
        * 0.375
        * PI.sqrt()
        * (1.0 - 0.8968 / alpha).sqrt()
        * alpha.sqrt();
    assert!(rel(p.gw_product(), expected) < 1e-14);
    // §7's 0.0204 √α leaves out the factor (1 − 0.8968/α)^½ of σ_s (0.94 at α = 8).
    let factor = (1.0 - 0.8968 / alpha).sqrt();
    assert!(rel(p.gw_product() / factor, 0.0204 * alpha.sqrt()) < 0.01);
}

/// A Gaussian random surface resolved well above the pixel scale.
fn gaussian_surface(n: usize, seed: u64) -> HeightMap {
    random_surface(
        n,
        1e-8,
        Spectrum::SelfAffine {
            hurst: 0.8,
            rolloff: 2.0 * PI / (n as f64 * 1e-8 / 16.0),
            cutoff: 2.0 * PI / (12.0 * 1e-8),
        },
        2e-9,
        seed,
    )
    .unwrap()
}

#[test]
fn mccool_against_counted_summits_of_a_gaussian_random_surface() {
    // Nayak's summit density m4/(6π√3 m2) holds for any isotropic Gaussian surface; the
    // spread and radius formulas are McCool's approximations for large α. On a surface
    // resolved with at least 12 pixels per shortest wavelength, the 8-neighbour count
    // reproduces the density, the spread and the mean summit height within 5 % (seed 42:
    // 0.1 %, 0.5 %, 1.4 %) and the radius within 25 % (15 %: the mean of 1/κ exceeds
    // 1/mean κ, and McCool's R is the large-α form).
    let map = gaussian_surface(512, 42);
    let r = analyse(&map, &Settings::default()).unwrap();
    let s = r.summits.unwrap();
    let p = r.parameters;
    assert!(s.count > 500, "{}", s.count);
    assert!(
        rel(s.density, p.summit_density) < 0.05,
        "density {} vs {}",
        s.density,
        p.summit_density
    );
    assert!(
        rel(s.sigma.unwrap(), p.summit_sigma) < 0.05,
        "sigma {:?} vs {}",
        s.sigma,
        p.summit_sigma
    );
    assert!(
        rel(s.mean_radius.unwrap(), p.summit_radius) < 0.25,
        "radius {:?} vs {}",
        s.mean_radius,
        p.summit_radius
    );
    assert!(rel(s.mean_height.unwrap(), p.mean_summit_height) < 0.05);
    assert!(!r
        .warnings
        .iter()
        .any(|w| matches!(w, Warning::CountingDisagrees { .. })));
    assert!(!r
        .warnings
        .iter()
        .any(|w| matches!(w, Warning::Anisotropy { .. })));
}

#[test]
fn summit_count_by_hand() {
    // A 5 × 5 map with two summits at (1,1) and (3,3), a plateau (not a summit: not
    // strictly higher) at (3,1), a point (2,2) lower than its neighbour (1,1), and a
    // highest point (1,3) that has a missing neighbour.
    #[rustfmt::skip]
    let mut h = vec![
        0., 0., 0., 0., 0.,
        0., 5., 0., 3., 3.,
        0., 0., 1., 0., 0.,
        0., 9., 0., 4., 0.,
        0., 0., 0., 0., 0.,
    ];
    h[4 * 5] = f64::NAN; // (0, 4): a neighbour of (1, 3)
    let h: Vec<f64> = h.iter().map(|x| x * 1e-9).collect();
    let map = HeightMap::new(5, 5, 1e-8, 2e-8, h).unwrap();
    let s = SummitCount::of(&map);
    // Candidates: the 9 interior points less (1,3), whose neighbour is missing.
    assert_eq!((s.count, s.candidates), (2, 8));
    // Summits: (1,1) h = 5 and (3,3) h = 4 nm. Their second differences: the 4 axial
    // neighbours are 0 except (2,2) = 1 nm, which is diagonal to both, so
    // h_xx = −2h/Δx², h_yy = −2h/Δy², κ = h (1/Δx² + 1/Δy²).
    let kappa = |h: f64, dx: f64, dy: f64| 0.5 * (2.0 * h / (dx * dx) + 2.0 * h / (dy * dy));
    let radii: Vec<f64> = [5e-9, 4e-9]
        .iter()
        .map(|&h| 1.0 / kappa(h, 1e-8, 2e-8))
        .collect();
    assert!(rel(s.mean_radius.unwrap(), radii.iter().sum::<f64>() / 2.0) < 1e-12);
    assert!(rel(s.density, 2.0 / (8.0 * 1e-8 * 2e-8)) < 1e-12);
    let mean = 9e-9 / 2.0;
    let var = [5e-9, 4e-9]
        .iter()
        .map(|x: &f64| (x - mean).powi(2))
        .sum::<f64>()
        / 2.0;
    assert!(rel(s.sigma.unwrap(), var.sqrt()) < 1e-12);
}

#[test]
fn cutoff_removes_short_waves_and_relevels_on_the_kept_points() {
    // Two sines along x: λ1 = 64 px passes (transmission exp(−π α² λs²/λ1²) =
    // exp(−ln 2 / 64) = 0.989 at λs = 8 px), the pixel-scale λ2 = 2 px is removed
    // (exp(−16 ln 2) = 1.5e-5 of it remains). 272 points leave 256 = 4 periods of λ1.
    let (n, ny, dx) = (272usize, 40usize, 1e-8);
    let (a1, a2) = (2e-9, 1e-9);
    let (k1, k2) = (2.0 * PI / (64.0 * dx), 2.0 * PI / (2.0 * dx));
    let surface = |tilt: f64| {
        let mut h = Vec::new();
        for j in 0..ny {
            for i in 0..n {
                let x = i as f64 * dx;
                h.push(
                    a1 * (k1 * x).sin()
                        + a2 * (k2 * x + 0.3).sin()
                        + tilt * (x + 0.2 * j as f64 * dx),
                );
            }
        }
        HeightMap::new(n, ny, dx, dx, h).unwrap()
    };
    let cutoff = 8.0 * dx;
    let f = gaussian_cutoff(&surface(0.0), cutoff).unwrap();
    assert_eq!(f.edge_band, (8, 8));
    assert_eq!((f.map.nx(), f.map.ny()), (256, 24));
    let t1 = (-std::f64::consts::LN_2 / 64.0).exp();
    let m = Moments::of(&level(&f.map, Levelling::None).unwrap());
    // Forward differences of A sin: (2A/Δ)² sin²(kΔ/2)/2 on whole periods (255 of the 256
    // pairs: within 1 %).
    let expected_m2x = (2.0 * a1 * t1 / dx * (k1 * dx / 2.0).sin()).powi(2) / 2.0;
    assert!(
        rel(m.m2_x, expected_m2x) < 0.01,
        "{} vs {}",
        m.m2_x,
        expected_m2x
    );
    assert!(m.m2_y.unwrap() < 1e-12 * expected_m2x);
    // With a tilt and plane levelling: the filter keeps a plane as it is (symmetric
    // kernel), and the second levelling is fitted on the kept points, so their residual is
    // orthogonal to 1, x and y there.
    let tilted = surface(1e-3);
    let f = gaussian_cutoff(&level(&tilted, Levelling::Plane).unwrap(), cutoff).unwrap();
    let r = level(&f.map, Levelling::Plane).unwrap();
    let (mut s0, mut sx, mut sy) = (0.0, 0.0, 0.0);
    for j in 0..r.ny() {
        for i in 0..r.nx() {
            let h = r.at(i, j);
            s0 += h;
            sx += h * i as f64;
            sy += h * j as f64;
        }
    }
    let scale = a1 * (r.nx() * r.ny()) as f64;
    assert!(s0.abs() < 1e-12 * scale && sx.abs() < 1e-10 * scale && sy.abs() < 1e-10 * scale);
}

#[test]
fn cutoff_with_missing_points_renormalises_the_kernel() {
    // A constant surface with a hole: the filter of a constant is that constant wherever
    // at least half the kernel weight is valid, and missing where less is.
    let (n, dx) = (41usize, 1.0);
    let mut h = vec![7.0; n * n];
    for j in 15..26 {
        for i in 15..26 {
            h[j * n + i] = f64::NAN;
        }
    }
    let map = HeightMap::new(n, n, dx, dx, h).unwrap();
    let f = gaussian_cutoff(&map, 4.0).unwrap();
    let k = f.map.heights();
    assert!(k
        .iter()
        .filter(|x| !x.is_nan())
        .all(|x| (x - 7.0).abs() < 1e-12));
    // The hole's centre (20, 20) → kept index 16: no valid weight at all.
    assert!(f.map.at(16, 16).is_nan());
    // A point well away from the hole keeps its value.
    assert!((f.map.at(0, 0) - 7.0).abs() < 1e-12);
    // Points inside the hole near its edge get a value (more than half the weight valid
    // only outside the hole's corner region) — and the count of missing shrinks or grows
    // consistently with the half-weight rule computed here independently.
    let w: Vec<f64> = (-4i32..=4)
        .map(|k| (-PI * (k as f64 / ((std::f64::consts::LN_2 / PI).sqrt() * 4.0)).powi(2)).exp())
        .collect();
    let total: f64 = w.iter().sum::<f64>().powi(2);
    for jj in 0..f.map.ny() {
        for ii in 0..f.map.nx() {
            let (i, j) = (ii + 4, jj + 4);
            let mut valid = 0.0;
            for (a, wa) in w.iter().enumerate() {
                for (b, wb) in w.iter().enumerate() {
                    let (x, y) = (i + a - 4, j + b - 4);
                    if !(15..26).contains(&x) || !(15..26).contains(&y) {
                        valid += wa * wb;
                    }
                }
            }
            assert_eq!(f.map.at(ii, jj).is_nan(), valid < 0.5 * total, "({i}, {j})");
        }
    }
}

#[test]
fn psd_integrates_to_m0_and_peaks_at_a_sine() {
    // Persson's normalisation on the grid: Σ C δq² = ⟨(w h)²⟩/⟨w²⟩ ≈ m0 for a surface much
    // larger than its correlation length (many modes): within 5 %.
    let map = random_surface(
        256,
        1e-8,
        Spectrum::Gaussian {
            correlation_length: 4e-8,
        },
        3e-9,
        9,
    )
    .unwrap();
    let l = level(&map, Levelling::Plane).unwrap();
    let m0 = Moments::of(&l).m0;
    let psd = Psd::of(&l);
    assert!(
        rel(psd.integral(), m0) < 0.05,
        "{} vs {}",
        psd.integral(),
        m0
    );
    // The continuous form 2π ∫ q C dq by the trapezoid rule on the bins, within 15 %
    // (coarse logarithmic bins).
    let mut trap = 0.0;
    for k in 1..psd.q.len() {
        let (q0, q1) = (psd.q[k - 1], psd.q[k]);
        trap += 0.5 * (q0 * psd.c[k - 1] + q1 * psd.c[k]) * (q1 - q0);
    }
    assert!(
        rel(2.0 * PI * trap, m0) < 0.15,
        "{} vs {}",
        2.0 * PI * trap,
        m0
    );
    // A profile sine: its line PSD peaks in the bin holding k, and ∫ C dq ≈ m0.
    let (sine, k) = sine(32, 16, 1, 1e-9, 1e-8);
    let psd = Psd::of(&sine);
    let top = (0..psd.c.len())
        .max_by(|&a, &b| psd.c[a].total_cmp(&psd.c[b]))
        .unwrap();
    assert!(rel(psd.q[top], k) < 0.15, "{} vs {k}", psd.q[top]);
    assert!(rel(psd.integral(), 0.5e-18) < 0.02, "{}", psd.integral());
}

#[test]
fn same_numbers_on_one_and_two_threads() {
    let map = gaussian_surface(256, 5);
    let s = Settings {
        level: Levelling::Quadratic,
        cutoff: Some(5e-8),
    };
    let run = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| {
                let r = analyse(&map, &s).unwrap();
                let p = Psd::of(&level(&map, Levelling::Quadratic).unwrap());
                (r, p)
            })
    };
    assert_eq!(run(1), run(2));
    assert_eq!(run(1), run(3));
}

#[test]
fn refusals() {
    let mostly_missing = HeightMap::new(4, 4, 1.0, 1.0, {
        let mut v = vec![f64::NAN; 16];
        v[..7].iter_mut().for_each(|x| *x = 1.0);
        v
    })
    .unwrap();
    assert!(matches!(
        analyse(&mostly_missing, &Settings::default()),
        Err(SurfaceError::TooManyMissing {
            valid: 7,
            total: 16
        })
    ));
    let two_rows = HeightMap::new(5, 2, 1.0, 1.0, vec![0.0; 10]).unwrap();
    assert!(matches!(
        analyse(&two_rows, &Settings::default()),
        Err(SurfaceError::TooSmall { .. })
    ));
    assert!(HeightMap::new(2, 2, 1.0, 1.0, vec![0.0; 3]).is_err());
    assert!(HeightMap::new(2, 2, 0.0, 1.0, vec![0.0; 4]).is_err());
    assert!(HeightMap::new(2, 2, 1.0, 1.0, vec![0.0, f64::INFINITY, 0.0, 0.0]).is_err());
    let map = gaussian_surface(64, 1);
    match analyse(
        &map,
        &Settings {
            level: Levelling::Plane,
            cutoff: Some(1e-6),
        },
    ) {
        Err(e @ SurfaceError::CutoffTooLarge { .. }) => {
            assert!(e.to_string().contains("use a cut-off below"), "{e}")
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn anisotropy_is_warned() {
    // Stretch a Gaussian surface along y: sample every row of an isotropic map with a
    // pixel 3 times longer in y than its content → m2_y is 9 times smaller.
    let base = gaussian_surface(256, 3);
    let map = HeightMap::new(256, 256, 1e-8, 3e-8, base.heights().to_vec()).unwrap();
    let r = analyse(&map, &Settings::default()).unwrap();
    assert!(r
        .warnings
        .iter()
        .any(|w| matches!(w, Warning::Anisotropy { ratio } if *ratio > 5.0)));
}
