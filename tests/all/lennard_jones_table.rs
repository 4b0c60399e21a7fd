//! The Lennard-Jones loading table (src/model/lennard_jones/table.txt) against
//! the solver it was written from, at points it was not built from, and
//! against the closed-form limits at its ends.

use wearopt::model::asperity_curve::lennard_jones_loading;
use wearopt::model::lennard_jones::table::{
    lobatto, solved_curves, APPROACH_DEGREE, AT_HUNDREDTH, HUNDREDTH,
};
use wearopt::model::lennard_jones::SphereSettings;

use crate::common::Scope;

/// The committed table covers μ = 9.91e-5 … 5√20 = 22.4, with its curve at
/// μ = 0.01 at `AT_HUNDREDTH` (`wearopt asperity` solves μ = 1e-3 … 100,
/// `asperity_curve::SOLVED_TABOR`, the table's generator below that too;
/// outside the table the law's
/// closed-form stand-ins are within the error `wearopt accuracy` states),
/// with a grid dense enough to interpolate between (at most 1/24 decade
/// apart up to μ = 5; above, steps of 20^{1/24}, 18.4 a decade, where six
/// curves serve a stencil and the interpolation's error is stated apart) and
/// in order.
#[test]
fn the_table_covers_its_grid() {
    let c = solved_curves();
    assert!(c.len() >= 60, "{} curves", c.len());
    assert!((c[0].tabor / (0.01 * 500f64.powf(-98.0 / 132.0)) - 1.0).abs() < 1e-12);
    assert_eq!(c[AT_HUNDREDTH].tabor, HUNDREDTH);
    assert!((c[c.len() - 1].tabor - 5.0 * 20f64.sqrt()).abs() < 1e-9);
    assert!(c.iter().any(|curve| curve.tabor == 5.0));
    for w in c.windows(2) {
        let ratio = w[1].tabor / w[0].tabor;
        let widest = if w[1].tabor <= 5.0 {
            10f64.powf(1.0 / 24.0)
        } else {
            20f64.powf(1.0 / 24.0)
        };
        assert!(ratio > 1.0 && ratio <= widest + 1e-9, "{ratio}");
    }
    // S-shaped from the cusp (MODEL.md §8: μ about 0.7) up, single-valued below.
    let first = c.iter().position(|curve| curve.jumps).unwrap();
    assert!(c[first..].iter().all(|curve| curve.jumps));
    assert!(c[first].tabor > 0.6 && c[first - 1].tabor < 1.0);
}

/// The cusp the interpolation in μ keeps its stencils to one side of
/// (`CUSP_TABOR`) is the converged solution's: δ̂ against the apex gap G (the
/// path's regular parameter), each point extrapolated on three meshes, rises
/// monotonically towards the flat 5e-4 of μ below it (its least slope
/// −dδ̂/dG, measured +4.8e-4) and turns back 5e-4 above it (−4.8e-4); the
/// sphere's trace on its own mesh, as `wearopt asperity` runs it, finds no
/// jumps 1e-3 below and jumps 2e-3 above (its cusp lies within 3e-4 above
/// the converged one). It lies between the table's last single-valued curve
/// and its first S-shaped one.
#[test]
fn the_cusp_lies_between_the_tables_kinds_of_curve() {
    cusp_between_kinds(Scope::Representative);
}

#[test]
#[ignore = "campaign (minutes): cargo test --release --test all -- --ignored cusp_between_kinds_campaign"]
fn cusp_between_kinds_campaign() {
    cusp_between_kinds(Scope::Every);
}

/// The curves on either side of the cusp are single-valued and S-shaped; in
/// the campaign the least slope −dδ̂/dG changes sign across it too.
fn cusp_between_kinds(scope: Scope) {
    use wearopt::model::asperity_curve::{asperity_curve, lennard_jones_at_apex_gaps, CurveLaw};
    use wearopt::model::lennard_jones::rough::CUSP_TABOR;
    use wearopt::model::lennard_jones::SphereSettings;
    let c = solved_curves();
    let first = c.iter().position(|curve| curve.jumps).unwrap();
    assert!(c[first - 1].tabor < CUSP_TABOR && CUSP_TABOR < c[first].tabor);
    // The least slope −dδ̂/dG over G = 1.27 … 1.235, where the S-shape opens
    // (the steepest point lies at G = 1.253).
    let extrapolated = SphereSettings {
        refinement: 1.0,
        extrapolate: true,
    };
    let gaps: Vec<f64> = (0..=35).map(|i| 1.27 - 1e-3 * i as f64).collect();
    let least_slope = |mu: f64| {
        let points = lennard_jones_at_apex_gaps(mu, &gaps, extrapolated).unwrap();
        points
            .windows(2)
            .map(|w| (w[1].interference - w[0].interference) / (w[0].apex_gap - w[1].apex_gap))
            .fold(f64::INFINITY, f64::min)
    };
    if scope == Scope::Every {
        let (below, above) = (
            least_slope(CUSP_TABOR - 5e-4),
            least_slope(CUSP_TABOR + 5e-4),
        );
        assert!(below > 2e-4 && below < 1e-3, "{below:e}");
        assert!(above < -2e-4 && above > -1e-3, "{above:e}");
    }
    for (mu, s_shaped) in [(CUSP_TABOR - 1e-3, false), (CUSP_TABOR + 2e-3, true)] {
        let (curve, _) = asperity_curve(CurveLaw::LennardJones, mu, -1.2, 1.0, 3).unwrap();
        assert_eq!(curve.jump_in.is_some(), s_shaped, "μ = {mu}");
    }
}

/// Where the curve is single-valued, the approach part's end and the contact
/// part's start are one solver point (the split): the table is continuous
/// there. Where it jumps, both parts start from the jump's interference.
#[test]
fn the_parts_meet_at_the_switch() {
    for c in solved_curves() {
        let end = c.approach(c.tau_end());
        assert!(
            (end.interference - c.switch).abs() < 1e-9 * (1.0 + c.switch.abs()),
            "μ = {}: {} vs {}",
            c.tabor,
            end.interference,
            c.switch
        );
        if !c.jumps {
            let (load, _) = c.contact(c.switch);
            assert!((end.load - load).abs() < 1e-9, "μ = {}", c.tabor);
        } else {
            // Under displacement control the load jumps towards the flat.
            assert!(c.contact(c.switch).0 < end.load, "μ = {}", c.tabor);
        }
    }
}

/// Far from the flat every sphere is rigid: the approach part tends to
/// Bradley's P̂ = (2/3)[G⁻⁸ − 4G⁻²] at apex gap G (docs/model.md §11), the
/// elastic opening vanishing faster than the load.
#[test]
fn the_far_field_is_bradleys() {
    for c in solved_curves() {
        for g in [30.0f64, 300.0] {
            let p = c.approach(g.powf(-0.5));
            let bradley = 2.0 / 3.0 * (g.powi(-8) - 4.0 * g.powi(-2));
            let rel = (p.load - bradley).abs() / bradley.abs();
            // The elastic correction is of order μ^{3/2} G^{-1/2} (and ≤ 1 %).
            assert!(rel < 2e-2, "μ = {} G = {g}: {rel:e}", c.tabor);
            assert!(p.load < 0.0);
        }
    }
    // μ = 0.01 is rigid to 1e-3 already near the flat.
    let c = &solved_curves()[AT_HUNDREDTH];
    let g = 2.0f64;
    let bradley = 2.0 / 3.0 * (g.powi(-8) - 4.0 * g.powi(-2));
    assert!((c.approach(g.powf(-0.5)).load / bradley - 1.0).abs() < 1e-3);
}

/// At the top of the table the contact part is within the measured distance
/// of JKR (0.17 % in the pull-off at μ = 22.4, 1.6 % at 5):
/// the load at δ̂ = 1, 5, 20 within 3 % of 1 + |P̂| of JKR's loading curve.
#[test]
fn the_top_of_the_table_is_near_jkr() {
    let c = solved_curves().last().unwrap();
    for d in [1.0f64, 5.0, 20.0] {
        // JKR's â from δ̂ = â² − (2/3)√(6â) by Newton, then P̂ = â³ − √(6â³).
        let mut a = d.sqrt() + 1.0;
        for _ in 0..50 {
            let f = a * a - 2.0 / 3.0 * (6.0 * a).sqrt() - d;
            let df = 2.0 * a - (6.0f64).sqrt() / (3.0 * a.sqrt());
            a -= f / df;
        }
        let jkr = a.powi(3) - (6.0 * a.powi(3)).sqrt();
        let (p, _) = c.contact(d);
        assert!(
            (p - jkr).abs() < 0.03 * (1.0 + jkr.abs()),
            "δ̂ = {d}: {p} vs {jkr}"
        );
    }
}

/// The table against the converged solver (each point extrapolated from
/// three nested meshes, docs/model.md §11 *Accuracy*) at points it was not
/// built from (midpoints between its nodes), at μ = 0.0176 and 1.11 (one
/// each side of the cusp): P̂ within APPROACH_BAR on the approach part and
/// CONTACT_BAR on the contact part, relative (absolute below |P̂| = 1e-3);
/// the whole table: `lennard_jones_table check`, README.
const APPROACH_BAR: f64 = 1e-6;
const CONTACT_BAR: f64 = 1e-6;
const SWITCH_BAR: f64 = 1e-9;

#[test]
fn the_table_matches_the_solver_between_its_nodes() {
    between_its_nodes(Scope::Representative);
}

#[test]
#[ignore = "campaign (minutes): cargo test --release --test all -- --ignored between_its_nodes_campaign"]
fn between_its_nodes_campaign() {
    between_its_nodes(Scope::Every);
}

/// Curve 6 in the default run; 6 and 42 in the campaign.
fn between_its_nodes(scope: Scope) {
    for index in scope.pick(&[AT_HUNDREDTH + 6, AT_HUNDREDTH + 42], &[0]) {
        let c = &solved_curves()[index];
        let taus = lobatto(0.0, c.tau_end(), APPROACH_DEGREE);
        let mid_taus: Vec<f64> = [5usize, 20, 29, 31]
            .iter()
            .map(|&i| 0.5 * (taus[i] + taus[i + 1]))
            .collect();
        let gaps: Vec<f64> = mid_taus.iter().map(|t| 1.0 / (t * t)).collect();
        let ds: Vec<f64> = [0.0037, 0.31, 2.7].iter().map(|x| c.switch + x).collect();
        let samples = lennard_jones_loading(
            c.tabor,
            |_| gaps.clone(),
            |_| ds.clone(),
            c.switch + 3.0,
            SphereSettings {
                extrapolate: true,
                ..Default::default()
            },
        )
        .unwrap();
        assert_eq!(samples.jumps, c.jumps);
        // Traced with other steps (to a nearer end), the switch is the same
        // converged point.
        assert!(
            (samples.switch - c.switch).abs() < SWITCH_BAR,
            "μ = {}: {} vs {}",
            c.tabor,
            samples.switch,
            c.switch
        );
        for (t, p) in mid_taus.iter().zip(&samples.approach) {
            let q = c.approach(*t);
            assert!(
                (q.load - p.load).abs() < APPROACH_BAR * p.load.abs().max(1e-3),
                "μ = {} τ = {t}: {} vs {}",
                c.tabor,
                q.load,
                p.load
            );
        }
        for (d, p) in ds.iter().zip(&samples.contact) {
            let (q, _) = c.contact(*d);
            assert!(
                (q - p.load).abs() < CONTACT_BAR * p.load.abs().max(1e-3),
                "μ = {} δ̂ = {d}: {q} vs {}",
                c.tabor,
                p.load
            );
        }
    }
}

/// The load inside the contact radius is the whole load where the curve is
/// JKR-like (μ = 5: within 5 %) and the Hertz load, above the whole load by
/// about the attraction outside, where it is DMT-like (μ = 0.01).
#[test]
fn the_inner_load_spans_jkr_and_dmt() {
    let top = solved_curves().last().unwrap();
    let (_, inner) = top.contact_area(20.0);
    let (load, _) = top.contact(20.0);
    assert!((inner / load - 1.0).abs() < 0.05, "{inner} vs {load}");
    let bottom = &solved_curves()[AT_HUNDREDTH];
    let (_, inner) = bottom.contact_area(20.0);
    let (load, _) = bottom.contact(20.0);
    assert!(inner > load + 1.0, "{inner} vs {load}");
}

/// δ̂(τ) is inverted on the approach part to rounding, from the far field to
/// just before the switch, in a handful of steps' worth of time.
#[test]
fn the_approach_part_inverts() {
    for c in solved_curves() {
        let points = [-1e4, -30.0, -2.0].map(|x| x * c.z0);
        let near = [c.switch - 0.3, c.switch - 1e-6];
        for d in points.into_iter().chain(near).filter(|&d| d < c.switch) {
            let t = c.tau_at(d);
            let back = c.approach(t).interference;
            assert!(
                (back - d).abs() <= 1e-12 * d.abs().max(1.0),
                "μ = {}: {d} → {t} → {back}",
                c.tabor
            );
        }
    }
}

/// Every curve's numbers are read when first used; every one of the
/// committed table reads whole, the same when read again, and finite.
#[test]
fn every_curve_reads_whole() {
    use wearopt::model::lennard_jones::table::{parse, TABLE};
    let again = parse(TABLE).unwrap();
    assert_eq!(again.len(), solved_curves().len());
    for (a, b) in again.iter().zip(solved_curves()) {
        assert!(a == b, "μ = {}", a.tabor);
        let (load, slope) = a.contact(a.max_interference());
        assert!(load.is_finite() && slope.is_finite());
        assert!(a.approach(0.5 * a.tau_end()).load.is_finite());
    }
}
