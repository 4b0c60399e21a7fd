//! The Lennard-Jones law above its solved table (docs/model.md §11 *Above the
//! table*): closed-form limit curves, JKR's contact branch from the sphere's
//! jump in with the rigid sphere's approach, against JKR's closed form, against
//! the solved sphere where both exist (μ = 22.36), between themselves, and
//! against JKR's law where it takes over.

use wearopt::accuracy::lennard_jones::reference_load_of;
use wearopt::model::lennard_jones::rough::{critical_interference, RoughLaw};
use wearopt::model::lennard_jones::spacing;
use wearopt::model::lennard_jones::table::{
    bradley, curves, jkr_sphere, limit_curve, limit_jump_in, solved_curves, solved_range,
    tabor_range, Curve, JumpIn, LIMIT_END_ERROR, LIMIT_ERROR, LIMIT_STEPS,
};
use wearopt::model::{find_pull_off, AsperityLaw, Coefficients, Model, Quadrature};

/// JKR's sphere in Maugis units (Maugis 1992, his λ → ∞): at zero
/// interference â³ = 8/3 and P̂ = −4/3; its pull-off P̂ = −3/2 at â³ = 3/2,
/// δ̂ = −0.43679; the stable branch ends at â = 6^{-1/3}, δ̂ = −0.90856
/// (closed forms of δ̂ = â² − (2/3)(6â)^{1/2}, P̂ = â³ − (6â³)^{1/2}).
#[test]
fn jkr_sphere_is_the_closed_form() {
    let (p, a) = jkr_sphere(0.0);
    assert!((p + 4.0 / 3.0).abs() < 1e-14 && (a.powi(3) - 8.0 / 3.0).abs() < 1e-13);
    let a = 1.5f64.cbrt();
    let d = a * a - 2.0 / 3.0 * (6.0 * a).sqrt();
    assert!((d + 0.436_790).abs() < 1e-6, "{d}");
    let (p, b) = jkr_sphere(d);
    assert!((p + 1.5).abs() < 1e-14 && (b - a).abs() < 1e-12);
    let narrowest = 6f64.powf(-1.0 / 3.0);
    let end = narrowest * narrowest - 2.0 / 3.0 * (6.0 * narrowest).sqrt();
    assert!((end + 0.908_560).abs() < 1e-6, "{end}");
    for d in [end + 1e-9, -0.5, 0.3, 7.0, 1e3, 1e8] {
        let (p, a) = jkr_sphere(d);
        assert!(((a * a - 2.0 / 3.0 * (6.0 * a).sqrt() - d) / d.abs().max(1.0)).abs() < 1e-14);
        assert!((p - (a.powi(3) - (6.0 * a.powi(3)).sqrt())).abs() <= 1e-15 * p.abs().max(1.0));
    }
}

/// The law's curves: the solver's to μ_top = 22.36, then [`LIMIT_STEPS`]
/// closed-form curves in steps of 20^{1/12} to 20⁴ μ_top. Each is JKR's sphere
/// on its contact part (to its panels' interpolation, 1e-12; the tail beyond
/// δ̂ = 50, the squeezed-gap Hertz load, within 2e-6; the contact radius
/// there JKR's own), from the switch
/// [`JumpIn`] through the last two solved curves, and Bradley's rigid sphere before it
/// (the approach part's end is at δ̂_s); its pull-off JKR's, on the neck.
#[test]
fn the_limit_curves_are_jkr_from_the_jump_in() {
    let (all, solved) = (curves(), solved_curves());
    assert_eq!(all.len(), solved.len() + LIMIT_STEPS);
    let top = solved.last().unwrap();
    let jump_in = limit_jump_in();
    assert!(solved.iter().all(|c| !c.limit) && all[solved.len()..].iter().all(|c| c.limit));
    assert_eq!(solved_range().1, top.tabor);
    assert!((tabor_range().1 / (top.tabor * 20f64.powi(4)) - 1.0).abs() < 1e-12);
    for w in all[solved.len() - 1..].windows(2) {
        assert!((w[1].tabor / w[0].tabor / 20f64.powf(1.0 / 12.0) - 1.0).abs() < 1e-12);
    }
    for c in [
        &all[solved.len()],
        &all[solved.len() + 20],
        all.last().unwrap(),
    ] {
        assert!(c.jumps);
        assert!((c.switch / jump_in.at(c.tabor) - 1.0).abs() < 1e-14);
        let end = c.approach(c.tau_end());
        assert!((end.interference / c.switch - 1.0).abs() < 1e-12);
        for tau in [0.2 * c.tau_end(), 0.7 * c.tau_end(), c.tau_end()] {
            let rigid = bradley(tau).0;
            assert!((c.approach(tau).load - rigid).abs() <= 1e-13 * rigid.abs().max(1e-300));
        }
        for step in [0.0, 1e-3, 0.01, 0.1, 0.5, 1.0, 3.0, 10.0, 30.0, 49.0] {
            let d = c.switch + step;
            let (p, a) = jkr_sphere(d);
            assert!(
                (c.load(d) - p).abs() < 1e-12 * p.abs().max(1.0),
                "μ {} δ̂ {d}",
                c.tabor
            );
            assert!(
                (c.contact_area(d).0 - a).abs() < 1e-12 * a,
                "μ {} δ̂ {d}",
                c.tabor
            );
        }
        for d in [60.0, 400.0, 1e4] {
            let (p, a) = jkr_sphere(d);
            assert!((c.load(d) / p - 1.0).abs() < 2e-6, "μ {} δ̂ {d}", c.tabor);
            let ((radius, slope), (inner, _)) = c.contact_area_slope(d);
            assert!((radius - a).abs() < 1e-13 * a && inner == c.load(d));
            let e = 1e-4 * d;
            let central = (jkr_sphere(d + e).1 - jkr_sphere(d - e).1) / (2.0 * e);
            assert!((central / slope - 1.0).abs() < 1e-7, "{central} vs {slope}");
        }
        let (d, p) = c.pull_off();
        assert!((p + 1.5).abs() < 1e-15 && (d + 0.436_790).abs() < 1e-6);
    }
}

/// The jump in above the solved table, δ̂_s = −(C μ^{-4/7} − D μ^{-1}) through
/// the last two solved curves (μ = 19.7, 22.4), against the solver's own
/// switch: on the solved curves from μ = 10.6 (measured 5.2e-6 there, 1.9e-7
/// at 17.4), at the curve written between the last two (21.0; 1.9e-8) and
/// at the one above the table (31.6; 5.5e-7). The μ^{-1/2} from the last
/// curve alone (until 2026-11-28) was 0.96 % too deep at 31.6; the first
/// term alone, C μ^{-4/7}, is 16 % off at 10.6.
#[test]
fn the_jump_in_follows_the_solved_curves() {
    let solved = solved_curves();
    let jump_in = limit_jump_in();
    assert!((jump_in.leading - 1.4915).abs() < 1e-4 && (jump_in.offset - 0.5648).abs() < 1e-4);
    let off = |c: &Curve| (jump_in.at(c.tabor) / c.switch - 1.0).abs();
    let below = solved
        .iter()
        .filter(|c| c.tabor > 10.0)
        .map(off)
        .fold(0.0, f64::max);
    let between = committed("lennard_jones_between.txt")
        .iter()
        .filter(|c| c.tabor > 20.0)
        .map(off)
        .fold(0.0, f64::max);
    let c = &committed("lennard_jones_above.txt")[0];
    let above = off(c);
    println!(
        "jump in: {below:.2e} on the curves above 10, {between:.2e} at 21.0, {above:.2e} at 31.6"
    );
    assert!(below < 6e-6 && between < 5e-8 && above < 7e-7);
    let old = top_switch_rule(solved.last().unwrap(), c.tabor);
    assert!((old / c.switch - 1.0 - 9.6e-3).abs() < 1e-4);
    let at = solved.iter().find(|c| c.tabor > 10.0).unwrap();
    let leading = jump_in.leading * at.tabor.powf(-4.0 / 7.0) / -at.switch - 1.0;
    assert!((leading - 0.16).abs() < 0.01, "{leading}");
}

use crate::common::committed_curves as committed;
use crate::common::Scope;

/// The switch the limit curves took until 2026-11-28: the last solved
/// curve's δ̂_s μ^{1/2}, held.
fn top_switch_rule(top: &Curve, tabor: f64) -> f64 {
    top.switch * (top.tabor / tabor).sqrt()
}

/// The pull-off of P̄(h) of one curve alone (no plasticity), by the reference
/// quadrature.
fn pull_off(curve: &Curve, ell: f64) -> f64 {
    let c = Coefficients::new(6f64.sqrt() * ell.powf(-0.75), f64::INFINITY);
    deepest(|h| reference_load_of([(curve, 1.0, f64::INFINITY)], ell, c, h).0)
}

/// The most negative P̄(h) for h in −2 … 8: a scan in h, then golden sections.
fn deepest(f: impl Fn(f64) -> f64) -> f64 {
    let mut best = (0.0, f64::INFINITY);
    for i in 0..=100 {
        let h = -2.0 + 0.1 * i as f64;
        let v = f(h);
        if v < best.1 {
            best = (h, v);
        }
    }
    let (mut a, mut b) = (best.0 - 0.1, best.0 + 0.1);
    for _ in 0..40 {
        let (m1, m2) = (a + 0.382 * (b - a), a + 0.618 * (b - a));
        if f(m1) < f(m2) {
            b = m2;
        } else {
            a = m1;
        }
    }
    f(0.5 * (a + b))
}

/// Where both exist, at the solved table's last curve (μ = 22.36), the limit
/// curve written from its switch stands in for it within what the reports
/// state (`LIMIT_ERROR`): the rough surface's pull-off (ℓ = 1, 3, 10; measured
/// 3.2e-3, 1.03e-2, 9e-5) and P̄ relative to ∫|p| φ̄ (ℓ = 1 … 100, with and
/// without plasticity, h = −1 … 4; measured 2.75e-3) — where JKR's law (the
/// stand-in there until 2026-11-28) missed the pull-off by a third and more.
/// Smaller on the solved curves above than below (the difference falls as μ
/// grows: at μ = 19.7 the pull-off's is 1.2e-2).
#[test]
fn the_limit_curve_stands_in_for_the_sphere_as_stated() {
    limit_curve_stands_in(Scope::Representative);
}

#[test]
#[ignore = "campaign (minutes): cargo test --release --test all -- --ignored limit_curve_stands_in_campaign"]
fn limit_curve_stands_in_campaign() {
    limit_curve_stands_in(Scope::Every);
}

fn limit_curve_stands_in(scope: Scope) {
    let solved = solved_curves();
    let mut worst_by_mu = Vec::new();
    for k in scope.pick(&[solved.len() - 2, solved.len() - 1], &[1]) {
        let own = &solved[k];
        let limit = limit_curve(own.tabor, &JumpIn::through(&solved[k - 1], own));
        let mut pull = 0.0f64;
        for ell in scope.pick(&[1.0, 3.0, 10.0], &[0]) {
            let (a, b) = (pull_off(own, ell), pull_off(&limit, ell));
            println!(
                "μ = {}, ℓ = {ell}: pull-off {a:.6e}, limit curve {:+.3e}",
                own.tabor,
                b / a - 1.0
            );
            pull = pull.max((b / a - 1.0).abs());
        }
        let mut load = 0.0f64;
        for ell in scope.pick(&[1.0f64, 3.0, 10.0, 30.0, 100.0], &[0]) {
            for c_h in scope.pick(&[5.0, f64::INFINITY], &[1]) {
                let c = Coefficients::new(6f64.sqrt() * ell.powf(-0.75), c_h);
                let dc = |k: &Curve| critical_interference(k, c_h * ell.sqrt()) / ell;
                for h in scope.pick(&[-1.0, 0.0, 0.5, 1.0, 2.0, 3.0, 4.0], &[1, 4]) {
                    let (a, size) = reference_load_of([(own, 1.0, dc(own))], ell, c, h);
                    let (b, _) = reference_load_of([(&limit, 1.0, dc(&limit))], ell, c, h);
                    load = load.max((a - b).abs() / size);
                }
            }
        }
        println!(
            "μ = {}: pull-off within {pull:.3e}, P̄ within {load:.3e}",
            own.tabor
        );
        worst_by_mu.push((pull, load));
    }
    let (pull, load) = *worst_by_mu.last().unwrap();
    for (worst, stated) in [(pull, LIMIT_ERROR.0), (load, LIMIT_ERROR.1)] {
        scope.as_stated(worst, stated, 1.05);
    }
    if scope == Scope::Every {
        assert!(worst_by_mu[0].0 > pull && worst_by_mu[0].1 > load);
    }
}

/// Between the limit curves P̄ is interpolated (cubically in 1/μ) within
/// 1.7e-5 of ∫|p| φ̄ of the limit curve at the midpoint (μ = 650; 1.0e-6 at
/// 2.6e5, 3.3e-7 at 3.2e6), ℓ = 0.3 … 100, with and without
/// plasticity, h = −1 … 4.
#[test]
fn the_law_between_limit_curves_is_interpolated_as_stated() {
    between_limit_curves(Scope::Representative);
}

#[test]
#[ignore = "campaign (minutes): cargo test --release --test all -- --ignored between_limit_curves_campaign"]
fn between_limit_curves_campaign() {
    between_limit_curves(Scope::Every);
}

fn between_limit_curves(scope: Scope) {
    let all = curves();
    let n = solved_curves().len();
    let jump_in = limit_jump_in();
    let cases = [(n + 12, 1.7e-5), (n + 36, 1.05e-6), (all.len() - 2, 3.3e-7)];
    for (k, stated) in scope.pick(&cases, &[0]) {
        let mu = (all[k].tabor * all[k + 1].tabor).sqrt();
        let own = limit_curve(mu, &jump_in);
        let mut worst = 0.0f64;
        for ell in scope.pick(&[0.3f64, 1.0, 3.0, 10.0, 30.0, 100.0], &[1]) {
            for c_h in scope.pick(&[5.0, f64::INFINITY], &[0]) {
                let c = Coefficients::new(6f64.sqrt() * ell.powf(-0.75), c_h);
                let law = RoughLaw::new(c.c_0, c.c_h, spacing(mu) / ell).unwrap();
                let dc = critical_interference(&own, c_h * ell.sqrt()) / ell;
                for h in scope.pick(&[-1.0, 0.0, 0.5, 1.0, 2.0, 3.0, 4.0], &[1, 4]) {
                    let (a, size) = reference_load_of(law.curves(), ell, c, h);
                    let (b, _) = reference_load_of([(&own, 1.0, dc)], ell, c, h);
                    worst = worst.max((a - b).abs() / size);
                }
            }
        }
        println!("μ = {mu:.4e}: P̄ within {worst:.2e}");
        scope.as_stated(worst, stated, 1.1);
    }
}

/// Where the limit curves end (μ = 3.58e6) JKR's law takes over: the rough
/// surface's pull-off under it within `LIMIT_END_ERROR` of the last limit
/// curve's where adhesion is strong (ℓ = 0.3, 1, 3; measured 3.1e-4, 7.3e-4,
/// 2.9e-3); where it is weak (ℓ = 10) JKR's is far smaller, both below 1e-18
/// of the load scale. At the solved table's end JKR's law was 1.7 and 7.4
/// times smaller (ℓ = 1, 3).
#[test]
fn jkr_takes_over_where_the_limit_curves_end() {
    let pull = |mu: f64, ell: f64, law: Option<()>| {
        let c = Coefficients::new(6f64.sqrt() * ell.powf(-0.75), f64::INFINITY);
        let law = match law {
            Some(()) => AsperityLaw::LennardJones {
                range: spacing(mu) / ell,
            },
            None => AsperityLaw::Jkr,
        };
        let model = Model::with_law(c, law, Quadrature::default());
        find_pull_off(&model).unwrap().load.value()
    };
    let top = tabor_range().1;
    let mut worst = 0.0f64;
    for ell in [0.3, 1.0, 3.0] {
        let (lj, jkr) = (pull(top, ell, Some(())), pull(top, ell, None));
        println!("ℓ = {ell}: {lj:.6e} against JKR's {jkr:.6e}");
        worst = worst.max((jkr / lj - 1.0).abs());
    }
    assert!(
        (0.5 * LIMIT_END_ERROR..=1.05 * LIMIT_END_ERROR).contains(&worst),
        "{worst:e}"
    );
    let (lj, jkr) = (pull(top, 10.0, Some(())), pull(top, 10.0, None));
    println!("ℓ = 10: {lj:.3e} against JKR's {jkr:.3e}");
    assert!(
        jkr.abs() < 1e-6 * lj.abs() && lj.abs() < 1e-18,
        "{lj:e} {jkr:e}"
    );
    let solved = solved_range().1;
    for (ell, ratio) in [(1.0, 1.68), (3.0, 7.4)] {
        let r = pull(solved, ell, Some(())) / pull(solved, ell, None);
        assert!((r / ratio - 1.0).abs() < 0.01, "ℓ {ell}: {r}");
    }
}

/// On a limit curve the plastic rule (docs/model.md §11: P̂_in/â² reaches
/// c_h ℓ^{1/2}) is §3's JKR rule exactly: with P̂_in = P̂ = â³ − (6â³)^{1/2}
/// and t = â^{1/2} it is the cubic t³ − c_h t − √6 = 0, Δc = t⁴ − (2/3)√6 t
/// (ℓ = 1) — within 1e-10 on the panels, and within 1e-6 beyond δ̂ = 50,
/// where the load is the tail's (c_h = 30: Δc = 918).
#[test]
fn the_plastic_rule_on_a_limit_curve_is_jkrs() {
    let c = &curves()[solved_curves().len() + 10];
    for (c_h, tolerance) in [(3.0f64, 1e-10), (6.0, 1e-10), (30.0, 1e-6)] {
        let c_a = 6f64.sqrt();
        let mut t = c_h.sqrt() + 1.0;
        for _ in 0..60 {
            t -= (t * t * t - c_h * t - c_a) / (3.0 * t * t - c_h);
        }
        let jkr = t.powi(4) - 2.0 / 3.0 * c_a * t;
        let dc = critical_interference(c, c_h);
        println!("c_h = {c_h}: Δc = {dc} against JKR's {jkr}");
        assert!((dc / jkr - 1.0).abs() < tolerance, "{dc} vs {jkr}");
    }
}

/// The law above the solved table against a curve the solver wrote there and
/// the table does not hold (μ = √1000 = 31.6, `tests/data/lennard_jones_above.txt`):
/// what the law serves (the last solved curve and the limit curves, weighted)
/// within `LIMIT_CHECK` — the rough surface's pull-off (ℓ = 1 … 100; measured
/// 2.0e-3, 6.7e-3, 5.2e-5 at ℓ = 1, 3, 10) and P̄ relative to ∫|p| φ̄ (ℓ = 1 …
/// 100, with and without plasticity, h = −1 … 4; measured 1.42e-3; with the
/// jump in held at μ^{-1/2}, until 2026-11-28, 5.9e-3 and 3.5e-3).
#[test]
fn the_law_above_the_table_against_a_solved_curve_there() {
    above_the_table(Scope::Representative);
}

#[test]
#[ignore = "campaign (minutes): cargo test --release --test all -- --ignored above_the_table_campaign"]
fn above_the_table_campaign() {
    above_the_table(Scope::Every);
}

fn above_the_table(scope: Scope) {
    use wearopt::model::lennard_jones::table::LIMIT_CHECK;
    let own = committed("lennard_jones_above.txt").remove(0);
    let mu = own.tabor;
    assert!((mu / LIMIT_CHECK.0 - 1.0).abs() < 1e-3 && mu > solved_range().1);
    let (mut pull, mut load) = (0.0f64, 0.0f64);
    for ell in scope.pick(&[1.0f64, 3.0, 10.0, 30.0, 100.0], &[0]) {
        for c_h in scope.pick(&[5.0, f64::INFINITY], &[1]) {
            let c = Coefficients::new(6f64.sqrt() * ell.powf(-0.75), c_h);
            let law = RoughLaw::new(c.c_0, c.c_h, spacing(mu) / ell).unwrap();
            let dc = critical_interference(&own, c_h * ell.sqrt()) / ell;
            for h in scope.pick(&[-1.0, 0.0, 0.5, 1.0, 2.0, 3.0, 4.0], &[1, 4]) {
                let (a, size) = reference_load_of(law.curves(), ell, c, h);
                let (b, _) = reference_load_of([(&own, 1.0, dc)], ell, c, h);
                load = load.max((a - b).abs() / size);
            }
        }
        let c = Coefficients::new(6f64.sqrt() * ell.powf(-0.75), f64::INFINITY);
        let law = RoughLaw::new(c.c_0, c.c_h, spacing(mu) / ell).unwrap();
        let served = served_pull_off(&law, ell);
        let solved = pull_off(&own, ell);
        println!(
            "ℓ = {ell}: pull-off {solved:.6e}, the law {:+.3e}",
            served / solved - 1.0
        );
        pull = pull.max((served / solved - 1.0).abs());
    }
    println!("pull-off within {pull:.3e}, P̄ within {load:.3e}");
    for (worst, stated) in [(pull, LIMIT_CHECK.1), (load, LIMIT_CHECK.2)] {
        scope.as_stated(worst, stated, 1.05);
    }
}

/// [`pull_off`] of what a law serves (its curves, weighted).
fn served_pull_off(law: &RoughLaw, ell: f64) -> f64 {
    let c = Coefficients::new(6f64.sqrt() * ell.powf(-0.75), f64::INFINITY);
    deepest(|h| reference_load_of(law.curves(), ell, c, h).0)
}
