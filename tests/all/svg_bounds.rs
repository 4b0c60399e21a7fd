//! Every text and marker of every plot lies inside the SVG's view box: titles are not
//! cut off, markers on the axes are drawn whole, legends fit. Text extents are
//! estimated with the plots' own glyph advance (`svg::TEXT_EM`, bold 10 % wider), so the
//! check is as strict as the layout's own assumption.

use std::collections::HashMap;

use assert_cmd::Command;
use wearopt::report::svg::{bar_chart, log_bar_chart, Axis, LinePlot, Marker, Series, TEXT_EM};

fn attrs(tag: &str) -> HashMap<String, String> {
    let mut out = HashMap::new();
    let mut rest = tag;
    while let Some(eq) = rest.find("=\"") {
        let name = rest[..eq].rsplit(' ').next().unwrap_or("").to_string();
        let tail = &rest[eq + 2..];
        let end = tail.find('"').unwrap();
        out.insert(name, tail[..end].to_string());
        rest = &tail[end + 1..];
    }
    out
}

fn num(a: &HashMap<String, String>, k: &str) -> f64 {
    a.get(k)
        .unwrap_or_else(|| panic!("no {k} in {a:?}"))
        .parse()
        .unwrap()
}

/// Checks one SVG document; returns how many texts and markers it checked.
fn check(svg: &str) -> (usize, usize) {
    let root = &svg[svg.find("<svg").unwrap()..];
    let root_attrs = attrs(&root[..root.find('>').unwrap()]);
    let vb: Vec<f64> = root_attrs["viewBox"]
        .split(' ')
        .map(|v| v.parse().unwrap())
        .collect();
    let (w, h) = (vb[2], vb[3]);
    let inside = |x: f64, y: f64, what: &str| {
        assert!(
            (-0.01..=w + 0.01).contains(&x) && (-0.01..=h + 0.01).contains(&y),
            "{what}: ({x:.1}, {y:.1}) outside 0 0 {w} {h}"
        );
    };
    let default_size = num(&root_attrs, "font-size");
    let mut texts = 0;
    let mut rest = root;
    while let Some(i) = rest.find("<text ") {
        let tag_end = rest[i..].find('>').unwrap() + i;
        let a = attrs(&rest[i..tag_end]);
        let close = rest[tag_end..].find("</text>").unwrap() + tag_end;
        let content = rest[tag_end + 1..close]
            .replace("&lt;", "<")
            .replace("&gt;", ">")
            .replace("&amp;", "&")
            .replace("&quot;", "\"")
            .replace("&apos;", "'");
        let size = a
            .get("font-size")
            .map_or(default_size, |s| s.parse().unwrap());
        let bold = a.get("font-weight").is_some_and(|b| b == "bold");
        let width = TEXT_EM * size * content.chars().count() as f64 * if bold { 1.1 } else { 1.0 };
        let (x, y) = (num(&a, "x"), num(&a, "y"));
        let (x0, x1) = match a.get("text-anchor").map(String::as_str) {
            Some("middle") => (x - width / 2.0, x + width / 2.0),
            Some("end") => (x - width, x),
            _ => (x, x + width),
        };
        if a.get("transform")
            .is_some_and(|t| t.starts_with("rotate(-90"))
        {
            // Rotated about (x, y): the text runs vertically, centred on y.
            inside(x - 0.8 * size, y - width / 2.0, &content);
            inside(x + 0.25 * size, y + width / 2.0, &content);
        } else {
            inside(x0, y - 0.8 * size, &content);
            inside(x1, y + 0.25 * size, &content);
        }
        texts += 1;
        rest = &rest[close..];
    }
    let mut markers = 0;
    for (open, kind) in [
        ("<circle ", "circle"),
        ("<polygon ", "polygon"),
        ("<rect ", "rect"),
        ("<path ", "path"),
    ] {
        let mut rest = root;
        while let Some(i) = rest.find(open) {
            let end = rest[i..].find('>').unwrap() + i;
            let tag = &rest[i..end];
            let a = attrs(tag);
            match kind {
                "circle" => {
                    let (cx, cy, r) = (num(&a, "cx"), num(&a, "cy"), num(&a, "r"));
                    inside(cx - r, cy - r, tag);
                    inside(cx + r, cy + r, tag);
                }
                // The white background (width="100%") has no position.
                "rect" if !a.contains_key("x") => {}
                "rect" => {
                    let (x, y) = (num(&a, "x"), num(&a, "y"));
                    inside(x, y, tag);
                    inside(x + num(&a, "width"), y + num(&a, "height"), tag);
                }
                _ => {
                    let coords = a.get("points").or_else(|| a.get("d")).unwrap();
                    let flat: Vec<f64> = coords
                        .split([' ', ',', 'M', 'L'])
                        .filter(|s| !s.is_empty())
                        .map(|s| s.parse().unwrap())
                        .collect();
                    for p in flat.chunks(2) {
                        inside(p[0], p[1], tag);
                    }
                }
            }
            markers += 1;
            rest = &rest[end..];
        }
    }
    (texts, markers)
}

#[test]
fn line_plot_with_long_title_and_markers_on_the_axes() {
    let svg = LinePlot::new(
        "A long title that a Pareto study gives its plot: wear rate against pull-off force (trade-off) of a latching gold micro-relay",
        Axis::log("pull-off force").with_unit("N"),
        Axis::linear("wear rate").with_unit("µm³/m"),
    )
    // Points on all four edges of the plot area (the data range is fitted to them).
    .with_series(Series::new("Pareto front (pull-off ≤ 1 fN drawn at it, a long name)", vec![(1e-15, 0.0), (1e-5, 10.0)]).with_marker(Marker::Circle))
    .with_series(Series::new("knee", vec![(1e-15, 10.0), (1e-5, 0.0)]).without_line().with_marker(Marker::Diamond))
    .with_series(Series::new("baseline", vec![(1e-10, 0.0)]).without_line().with_marker(Marker::Square))
    .with_series(Series::new("infeasible", vec![(1e-10, 10.0)]).without_line().with_marker(Marker::Triangle))
    .with_series(Series::new("dominated", vec![(1e-15, 5.0)]).without_line().with_marker(Marker::Cross))
    .to_svg();
    let (texts, markers) = check(&svg);
    assert!(texts >= 10 && markers >= 12, "{texts} {markers}");
}

#[test]
fn bar_chart_fits() {
    let bars: Vec<(String, f64)> = [
        ("youngs_modulus", -1.014),
        ("hardness", 0.0),
        ("work_of_adhesion", 0.07),
        ("asperity_radius", 0.56),
        ("sigma", f64::NAN),
    ]
    .iter()
    .map(|(n, v)| (n.to_string(), *v))
    .collect();
    let (texts, markers) = check(&bar_chart(
        "Elasticities of the wear rate",
        "d ln(wear rate) / d ln x",
        &bars,
    ));
    assert_eq!(texts, 2 + 2 * bars.len());
    assert!(markers >= 4);
}

#[test]
fn log_bar_chart_fits() {
    let bars: Vec<(String, f64, String)> = [
        ("1. silicon carbide", 8.6e-18),
        ("2. a material with a long name", 1.2e-17),
        ("3. nickel", 7.3e-15),
        ("excluded (no result)", f64::NAN),
        ("zero", 0.0),
    ]
    .iter()
    .map(|(n, v)| (n.to_string(), *v, format!("{v:e} m³/m")))
    .collect();
    let svg = log_bar_chart(
        "Wear rate of each material",
        "wear rate (m³/m), log scale",
        &bars,
    );
    let (texts, markers) = check(&svg);
    // Title, axis label, a name and a value per bar, and decade labels 1e-18 … 1e-14.
    assert_eq!(texts, 2 + 2 * bars.len() + 5, "{svg}");
    assert_eq!(svg.matches("<rect class=\"bar\"").count(), 3);
    assert!(markers >= 3);
    for d in ["1e-18", "1e-14"] {
        assert!(svg.contains(&format!(">{d}</text>")), "{d}: {svg}");
    }
    // Bars grow with the value: the nickel bar is the longest.
    let widths: Vec<f64> = svg
        .lines()
        .filter(|l| l.starts_with("<rect class=\"bar\""))
        .map(|l| num(&attrs(l), "width"))
        .collect();
    assert!(widths[0] < widths[1] && widths[1] < widths[2], "{widths:?}");
    // No drawable value: still a well-formed chart.
    check(&log_bar_chart(
        "t",
        "x",
        &[("a".into(), f64::NAN, "—".into())],
    ));
}

/// The plots the commands write: the Pareto front of the shipped latch study, and the
/// plots inside the HTML pages of eval and optimize.
#[test]
fn shipped_plots_fit() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let front = dir.join("bounds-front.svg");
    Command::cargo_bin("wearopt")
        .unwrap()
        .args([
            "pareto",
            "problems/latch-pareto.toml",
            "--points",
            "6",
            "--plot",
        ])
        .arg(&front)
        .assert()
        .success();
    check(&std::fs::read_to_string(&front).unwrap());
    // The hub's page draws its tensile part enlarged too (three plots).
    for (args, plots) in [
        (
            vec!["eval", "problems/micro-gear.toml", "--format", "html"],
            3,
        ),
        (
            vec![
                "optimize",
                "tests/data/micro-gear-study-jkr.toml",
                "--format",
                "html",
            ],
            2,
        ),
    ] {
        let out = Command::cargo_bin("wearopt")
            .unwrap()
            .args(&args)
            .output()
            .unwrap();
        let html = String::from_utf8(out.stdout).unwrap();
        let mut n = 0;
        let mut rest = html.as_str();
        while let Some(i) = rest.find("<svg ") {
            let end = rest[i..].find("</svg>").unwrap() + i + 6;
            check(&rest[i..end]);
            n += 1;
            rest = &rest[end..];
        }
        assert_eq!(n, plots, "{args:?}");
    }
}

/// The SVG elements of class `class` (their opening tags), in order.
fn tags_of<'a>(svg: &'a str, open: &str) -> Vec<&'a str> {
    let mut out = Vec::new();
    let mut rest = svg;
    while let Some(i) = rest.find(open) {
        let end = rest[i..].find('>').unwrap() + i;
        out.push(&rest[i..end]);
        rest = &rest[end..];
    }
    out
}

/// The plot frame (x, y, width, height) of a line plot.
fn frame(svg: &str) -> (f64, f64, f64, f64) {
    let a = attrs(tags_of(svg, "<rect class=\"frame\"")[0]);
    (
        num(&a, "x"),
        num(&a, "y"),
        num(&a, "width"),
        num(&a, "height"),
    )
}

/// The centres of the circle markers of the series named `name`.
fn circles_of(svg: &str, name: &str) -> Vec<(f64, f64)> {
    let start = svg
        .find(&format!("<g class=\"markers\" data-name=\"{name}\">"))
        .unwrap_or_else(|| panic!("no markers of {name:?}"));
    let group = &svg[start..start + svg[start..].find("</g>").unwrap()];
    tags_of(group, "<circle ")
        .into_iter()
        .map(|t| {
            let a = attrs(t);
            (num(&a, "cx"), num(&a, "cy"))
        })
        .collect()
}

/// A label beside a point in a corner of the plot stays inside the view box and
/// the frame, whichever corner.
#[test]
fn labels_stay_inside_the_frame() {
    for at in [(0.0, 0.0), (10.0, 10.0), (0.0, 10.0), (10.0, 0.0)] {
        let svg = LinePlot::new("t", Axis::linear("x"), Axis::linear("y"))
            .with_series(Series::new("s", vec![(0.0, 0.0), (10.0, 10.0)]))
            .with_label(at, "knee: 9.114 µN, 47.02 µm³/m (a long label)", "#007A5A")
            .to_svg();
        check(&svg);
        let (x, y, w, h) = frame(&svg);
        let label = &svg[svg.find("<g class=\"label\">").unwrap()..];
        let a = attrs(tags_of(label, "<text ")[0]);
        let (tx, ty) = (num(&a, "x"), num(&a, "y"));
        assert!(
            tx >= x && tx <= x + w && ty >= y && ty <= y + h,
            "{at:?}: {tx} {ty}"
        );
    }
}

/// The latch study's front (issue 56 item 4): its points spread over at least half
/// of each axis (they sat in the rightmost 5 % of a four-decade axis), the knee is
/// ringed and labelled, every text inside the view box; the page's tables use
/// words that wrap (no underscores in their headers).
#[test]
fn the_latch_front_fills_its_axes() {
    let out = Command::cargo_bin("wearopt")
        .unwrap()
        .args(["pareto", "problems/latch-pareto.toml", "--format", "html"])
        .output()
        .unwrap();
    assert!(out.status.success());
    let html = String::from_utf8(out.stdout).unwrap();
    let svg = &html[html.find("<svg ").unwrap()..html.find("</svg>").unwrap() + 6];
    check(svg);
    let (_, _, w, h) = frame(svg);
    let front = circles_of(svg, "Pareto front");
    assert!(front.len() >= 10, "{}", front.len());
    let spread = |v: Vec<f64>| {
        v.iter().copied().fold(f64::NEG_INFINITY, f64::max)
            - v.iter().copied().fold(f64::INFINITY, f64::min)
    };
    let across = spread(front.iter().map(|p| p.0).collect()) / w;
    let up = spread(front.iter().map(|p| p.1).collect()) / h;
    assert!(
        across >= 0.5 && up >= 0.5,
        "the front spans {across:.2} × {up:.2} of the axes"
    );
    assert!(
        svg.contains("<g class=\"label\">") && svg.contains(">knee: "),
        "{svg}"
    );
    for th in html.split("<th>").skip(1) {
        let head = &th[..th.find("</th>").unwrap()];
        assert!(!head.contains('_'), "{head}");
    }
}

/// The sweep map (issue 56 item 4): every text inside the view box, and the axis
/// says how many designs it draws at its left edge.
#[test]
fn the_sweep_map_fits_and_counts_its_edge() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let map = dir.join("bounds-sweep-map.svg");
    let rows = dir.join("bounds-sweep-rows.csv");
    let _ = std::fs::remove_file(&rows);
    Command::cargo_bin("wearopt")
        .unwrap()
        .args([
            "sweep",
            "problems/micro-gear-study.toml",
            "--samples",
            "64",
            "--plot",
        ])
        .arg(&map)
        .arg("--out")
        .arg(&rows)
        .assert()
        .success();
    let svg = std::fs::read_to_string(&map).unwrap();
    check(&svg);
    let label = &svg[svg.find("class=\"x-label\"").unwrap()..];
    let label = &label[label.find('>').unwrap() + 1..label.find("</text>").unwrap()];
    assert!(
        !label.contains("left edge") || label.contains(" of 64 below"),
        "{label}"
    );
}

/// A Lennard-Jones curve without jumps (μ = 0.05, issue 56 item 9) is one
/// single-valued curve on the plot, not a "contact branch" far out of contact.
/// Shown on the DMT curve relabelled as a jump-free Lennard-Jones one (what the
/// plot reads is the law and the jumps; the slow solve is not needed).
#[test]
fn a_curve_without_jumps_is_not_called_a_contact_branch() {
    use wearopt::app::asperity::{asperity, AsperityOptions};
    use wearopt::model::asperity_curve::CurveLaw;
    let mut doc = asperity(&AsperityOptions {
        tabor: 0.05,
        from: -2.0,
        to: 1.0,
        points: 31,
        law: CurveLaw::Dmt,
        rows: wearopt::model::asperity_curve::RowAccuracy::Converged,
        sphere: None,
    })
    .unwrap();
    let dmt = wearopt::report::asperity::plot_svg(&doc);
    assert!(dmt.contains("data-name=\"contact branch\""), "{dmt}");
    let curve = doc.curve.as_mut().unwrap();
    assert!(curve.jump_in.is_none() && curve.jump_out.is_none());
    curve.law = CurveLaw::LennardJones;
    doc.options.law = CurveLaw::LennardJones;
    let svg = wearopt::report::asperity::plot_svg(&doc);
    check(&svg);
    assert!(!svg.contains("branch\""), "{svg}");
    assert_eq!(
        svg.matches("data-name=\"single-valued curve (no jumps)\"")
            .count(),
        2
    );
}
