//! Writes the Lennard-Jones loading table (src/model/lennard_jones/table.txt)
//! from the sphere solver: `scripts/lennard_jones_table.sh` runs it.
//!
//! Usage: `lennard_jones_table [REFINEMENT] [MU ...]` — the Tabor parameters
//! default to the table's grid (`REACH=R` in the environment: contact parts
//! to δ̂ = R instead of 50 or 16 ẑ0; `GRID=I..J`: the grid's curves I to J − 1); blocks go to stdout in increasing μ, progress
//! to stderr. `lennard_jones_table check FILE [MU ...]` compares a table with
//! the solver between its nodes.

use wearopt::model::asperity_curve::{lennard_jones_loading, CurveError};
use wearopt::model::lennard_jones::table::{
    approach_gaps, breaks_scale, contact_breaks, contact_nodes, write_block, Header,
};
use wearopt::model::lennard_jones::{spacing, SphereSettings};

/// The table's grid: μ from 0.01 to 5, geometric in 132 steps (49 per
/// decade; the first table's 33 steps halved twice, so that the cubic
/// interpolation in μ between its curves errs about 16 times less each time),
/// but for one: at step 91, μ = 0.7255, 4 % above the cusp (0.6972), the
/// curve at μ = 0.7275 stands in (until 2026-11-29 the loading trace did not
/// converge at 0.7255, nor at 0.700 … 0.7253: it stepped over the narrow
/// S-shape whole, and sought the first contact nodes on its unstable branch).
/// Then on from 5 in steps of 20^{1/24} (18.4 per decade) to 5√20 = 22.4, a
/// sparser grid because these curves cost more to write (4 minutes at
/// μ = 5.3, 23 at 21): between them P̄, interpolated from six curves, is
/// within 1e-6 of the solver's (`tests/all/lennard_jones_rough.rs`, against
/// curves between them; 3.7e-5 from four on half the curves). Above 22.4
/// the law's closed-form limit curves continue (`table::limit_curve`).
/// Below 0.01 the same geometric steps go on for [`BELOW`] more, to
/// μ = 9.91e-5: there the DMT stand-in takes over, beyond any physical pair
/// (μ = 1e-4 needs γ = 0.03 mJ/m² on 10 nm diamond summits).
fn grid() -> Vec<f64> {
    let (lo, hi, steps) = (0.01f64, 5.0f64, 132);
    let (top, top_steps) = (5.0 * 20f64.sqrt(), 12);
    (-BELOW..=steps)
        .map(|i| {
            if i == 91 {
                FIRST_S_SHAPED
            } else {
                lo * (hi / lo).powf(i as f64 / steps as f64)
            }
        })
        .chain((1..=top_steps).map(|i| hi * (top / hi).powf(i as f64 / top_steps as f64)))
        .collect()
}

/// The grid's steps below μ = 0.01 (two decades of 49).
const BELOW: i32 = 98;

/// The grid's first S-shaped curve, standing in for step 91.
const FIRST_S_SHAPED: f64 = 0.7275;

/// The refinement a curve is written at: the run's, but twice it at
/// [`FIRST_S_SHAPED`], next to the cusp, where the trace's mesh moves the
/// jumps by a good part of the S-shape's width. There the curve at refinement 1 was 4.3e-6 of ∫|p| φ̄ off its own at 2
/// (rough-surface P̄, ℓ = 1 … 100, h = −1 … 4; at μ = 0.73 the two agree
/// within 8e-9; at 0.7275 refinement 3, 36 CPU-minutes, agrees with 2
/// within 4.9e-10), and P̄ interpolated beside the cusp was 2.7e-6 off the
/// solver's at μ = 0.735, 2.7e-6 at 0.73; from the curve at refinement 2,
/// 2.1e-7 and 9.6e-8, as between the table's other curves.
fn refinement_of(mu: f64, refinement: f64) -> f64 {
    if mu == FIRST_S_SHAPED {
        2.0 * refinement
    } else {
        refinement
    }
}

/// δ̂_max: the contact part reaches 50 beyond contact, or 16 ẑ0 where that
/// is further (μ < 0.18: there the contact at δ̂ = 50 is still narrow against
/// the attraction's reach, and the tail, which follows the gap a Hertz
/// pressure squeezes, fits the curve's shift well only once it is wide: with
/// 4 ẑ0, until 2026-11-28, the tail moved P̄ by up to 2.3e-6 around μ = 0.037,
/// where its departure from the squeezed gap changes sign; with 8 ẑ0 by
/// 6.6e-7, with 16 ẑ0 by 1.5e-7).
fn reach_of(mu: f64) -> f64 {
    50f64.max(16.0 * spacing(mu))
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.first().map(String::as_str) == Some("check") {
        // `check plain FILE`: against the trace's own mesh, not extrapolated.
        let plain = args.get(1).map(String::as_str) == Some("plain");
        let args = &args[usize::from(plain)..];
        let only: Vec<f64> = args[2..].iter().map(|a| a.parse().expect("MU")).collect();
        return check(&args[1], &only, plain);
    }
    // `plain`: the trace's own mesh, without the extrapolation.
    let plain = args.first().map(String::as_str) == Some("plain");
    let args = &args[usize::from(plain)..];
    let refinement: f64 = args.first().map_or(1.0, |a| a.parse().expect("REFINEMENT"));
    let mus: Vec<f64> = if args.len() > 1 {
        args[1..].iter().map(|a| a.parse().expect("MU")).collect()
    } else if let Ok(range) = std::env::var("GRID") {
        // `GRID=I..J`: the grid's curves I to J − 1 (a block of the table
        // written again, e.g. where the reach changed).
        let (i, j) = range.split_once("..").expect("GRID=I..J");
        grid()[i.parse().expect("I")..j.parse().expect("J")].to_vec()
    } else {
        grid()
    };
    let settings = SphereSettings {
        refinement,
        extrapolate: !plain,
    };
    println!(
        "# Lennard-Jones loading curves (docs/model.md §11), refinement {refinement}{}:",
        if plain { "" } else { ", extrapolated" }
    );
    println!(
        "# written by scripts/lennard_jones_table.sh; read by src/model/lennard_jones/table.rs"
    );
    for mu in mus {
        let start = std::time::Instant::now();
        // `REACH=R` in the environment: a contact part to δ̂ = R instead (to
        // measure the tail beyond the table's reach against the solver).
        let reach = std::env::var("REACH")
            .ok()
            .and_then(|r| r.parse().ok())
            .unwrap_or_else(|| reach_of(mu));
        let (samples, to) = with_shorter_reach(mu, reach, 0.93, 0.6 * reach, |to| {
            lennard_jones_loading(
                mu,
                approach_gaps,
                |switch| contact_nodes(&contact_breaks(switch, to, breaks_scale(mu))),
                to,
                SphereSettings {
                    refinement: refinement_of(mu, refinement),
                    ..settings
                },
            )
        })
        .unwrap_or_else(|e| panic!("μ = {mu}: {e:?}"));
        let loads: Vec<f64> = samples.approach.iter().map(|p| p.load).collect();
        let openings: Vec<f64> = samples
            .approach
            .iter()
            .map(|p| p.interference / spacing(mu) - 1.0 + p.apex_gap)
            .collect();
        let breaks = contact_breaks(samples.switch, to, breaks_scale(mu));
        let column = |f: fn(&wearopt::model::lennard_jones::SpherePoint) -> f64| -> Vec<f64> {
            samples.contact.iter().map(f).collect()
        };
        let contact = column(|p| p.load);
        let radius = column(|p| p.contact_radius);
        let inner = column(|p| p.inner_load);
        print!(
            "{}",
            write_block(
                Header {
                    tabor: mu,
                    end_gap: samples.end_gap,
                    switch: samples.switch,
                    jumps: samples.jumps,
                    // One sphere's pull-off, where the loading curve leaves
                    // it out (on the retraction neck below the jump in; a
                    // single-valued curve is the whole path, its minimum on
                    // it on either side of the split).
                    neck_pull_off: (samples.jumps
                        && samples.pull_off.interference < samples.switch)
                        .then_some((samples.pull_off.interference, samples.pull_off.load)),
                },
                (&loads, &openings),
                &breaks,
                [&contact, &radius, &inner]
            )
        );
        eprintln!(
            "μ = {mu:.5}: switch {:.6} (jumps: {}), pull-off {:.7} at {:.5}, {:.1} s",
            samples.switch,
            samples.jumps,
            samples.pull_off.load,
            samples.pull_off.interference,
            start.elapsed().as_secs_f64()
        );
    }
}

/// Compares each curve of the table in `path` with the solver at points the
/// table was not built from: the midpoints (in τ, and in δ̂ on each panel)
/// between its nodes, of every curve or of those whose μ is in `only`. Prints
/// the largest differences per curve.
/// `attempt(to)` from reach `start`, retried with the reach shortened by
/// `factor` while it fails and stays above `floor`: where the solver's trace
/// stalls deep in contact, a slightly shorter reach (the trace's steps scale
/// with it) gets through. The result and the reach that gave it.
fn with_shorter_reach<T>(
    mu: f64,
    start: f64,
    factor: f64,
    floor: f64,
    attempt: impl Fn(f64) -> Result<T, CurveError>,
) -> Result<(T, f64), CurveError> {
    let mut to = start;
    loop {
        match attempt(to) {
            Ok(t) => return Ok((t, to)),
            Err(e) if to > floor => {
                eprintln!("μ = {mu}: {e:?} reaching {to}; retrying");
                to *= factor;
            }
            Err(e) => return Err(e),
        }
    }
}

fn check(path: &str, only: &[f64], plain: bool) {
    use wearopt::model::lennard_jones::table::{lobatto, parse, APPROACH_DEGREE, PANEL_DEGREE};
    let text = std::fs::read_to_string(path).expect("read the table");
    let curves = parse(&text).expect("parse the table");
    // `bar`: the largest error against max(1e-6 |P̂|, 1e-9), the accuracy the
    // table is held to (1 = just met), over the approach and contact parts.
    println!("tabor,approach_abs,approach_rel,contact_abs,contact_rel,tail_rel,bar");
    for c in &curves {
        if !only.is_empty() && !only.iter().any(|m| (m / c.tabor - 1.0).abs() < 1e-3) {
            continue;
        }
        let taus = lobatto(0.0, c.tau_end(), APPROACH_DEGREE);
        let mid_taus: Vec<f64> = taus.windows(2).map(|w| 0.5 * (w[0] + w[1])).collect();
        let gaps: Vec<f64> = mid_taus.iter().map(|t| 1.0 / (t * t)).collect();
        let breaks = c.breaks().to_vec();
        let mut mids = Vec::new();
        for pair in breaks.windows(2) {
            let nodes = lobatto(pair[0], pair[1], PANEL_DEGREE);
            mids.extend(nodes.windows(2).map(|w| 0.5 * (w[0] + w[1])));
        }
        // The tail at 1.2 and 1.5 δ̂_max, traced to 1.6 δ̂_max (a shorter reach
        // where the trace stalls, with the tail points it still covers).
        let max = c.max_interference();
        let with_tail = |to: f64| -> Vec<f64> {
            let tail = [1.2, 1.5].map(|f| f * max);
            mids.iter()
                .copied()
                .chain(tail.into_iter().filter(|&d| d < to))
                .collect()
        };
        let traced = with_shorter_reach(c.tabor, 1.6 * max, 0.97, 1.05 * max, |to| {
            lennard_jones_loading(
                c.tabor,
                |_| gaps.clone(),
                |_| with_tail(to),
                to,
                SphereSettings {
                    extrapolate: !plain,
                    ..Default::default()
                },
            )
        });
        let (samples, all) = match traced {
            Ok((samples, to)) => (samples, with_tail(to)),
            Err(e) => {
                // Reported, and the other curves still checked.
                eprintln!("μ = {}: {e:?}: not checked", c.tabor);
                println!("{},unsolved,,,,,", c.tabor);
                continue;
            }
        };
        let (mut aa, mut ar, mut bar) = (0.0f64, 0.0f64, 0.0f64);
        let against = |e: f64, p: f64| e / (1e-6 * p.abs()).max(1e-9);
        for (t, p) in mid_taus.iter().zip(&samples.approach) {
            let q = c.approach(*t);
            let e = (q.load - p.load).abs();
            aa = aa.max(e);
            ar = ar.max(e / p.load.abs().max(1e-300));
            bar = bar.max(against(e, p.load));
            let ed = (q.interference - p.interference).abs();
            aa = aa.max(ed / (1.0 + p.interference.abs()));
        }
        let (mut ca, mut cr, mut tr) = (0.0f64, 0.0f64, 0.0f64);
        for (d, p) in all.iter().zip(&samples.contact) {
            let (q, _) = c.contact(*d);
            let e = (q - p.load).abs();
            if *d > c.max_interference() {
                tr = tr.max(e / p.load.abs());
            } else {
                ca = ca.max(e);
                cr = cr.max(e / p.load.abs().max(1e-300));
                bar = bar.max(against(e, p.load));
            }
        }
        println!(
            "{},{aa:.2e},{ar:.2e},{ca:.2e},{cr:.2e},{tr:.2e},{bar:.2e}",
            c.tabor
        );
    }
}
