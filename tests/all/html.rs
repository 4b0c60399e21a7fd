//! `--format html` pages as pages: each parses (it is well-formed XHTML-compatible
//! markup after the doctype), holds every plot it promises, has no URL at all, and —
//! where a headless Chromium is installed — renders without a console error.

use crate::common;

use crate::common::parse_xml;
use assert_cmd::Command;

fn page(args: &[&str]) -> String {
    let out = Command::cargo_bin("wearopt")
        .unwrap()
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.code().is_some_and(|c| c <= 1),
        "{args:?}: {out:?}"
    );
    String::from_utf8(out.stdout).unwrap()
}

fn check_page(html: &str, figures: &[&str]) {
    let body = html
        .strip_prefix("<!DOCTYPE html>\n")
        .unwrap_or_else(|| panic!("no doctype: {}", &html[..80.min(html.len())]));
    let el = parse_xml(body).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(el[0].name, "html");
    for id in figures {
        let fig = el
            .iter()
            .position(|e| {
                e.name == "figure" && e.attributes.get("id").map(String::as_str) == Some(id)
            })
            .unwrap_or_else(|| panic!("no figure {id}"));
        assert_eq!(el[fig + 1].name, "svg", "figure {id} has no inline plot");
    }
    assert_eq!(
        el.iter().filter(|e| e.name == "svg").count(),
        figures.len(),
        "plots"
    );
    // No URL of any kind: not even the SVG namespace or a link.
    assert!(!html.contains("http:") && !html.contains("https:") && !html.contains("//"));
    assert!(!el
        .iter()
        .any(|e| matches!(e.name.as_str(), "a" | "link" | "script" | "img")));
    assert!(el.iter().any(|e| e.name == "table"));
}

/// Renders the page in headless Chromium where one is installed and checks that it
/// logs no error; skipped (with a note on stderr) where none is.
fn renders_in_chromium(html: &str, name: &str) {
    let Some(browser) = ["chromium", "chromium-browser", "google-chrome"]
        .into_iter()
        .find(|b| {
            std::process::Command::new(b)
                .arg("--version")
                .output()
                .is_ok_and(|o| o.status.success())
        })
    else {
        eprintln!("no headless browser installed: page {name} checked as markup only");
        return;
    };
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let file = dir.join(format!("{name}.html"));
    std::fs::write(&file, html).unwrap();
    let out = std::process::Command::new(browser)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-background-networking",
            "--no-first-run",
            "--disable-component-update",
            "--disable-sync",
            "--enable-logging=stderr",
            "--v=0",
            "--dump-dom",
        ])
        .arg(&file)
        .output()
        .unwrap();
    let dom = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{browser} failed on {name}");
    // The browser's DOM holds the same plots, so it parsed them as SVG.
    assert_eq!(
        dom.matches("<svg").count(),
        html.matches("<svg").count(),
        "{name}: the browser lost plots"
    );
    let log = String::from_utf8_lossy(&out.stderr);
    assert!(
        !log.lines()
            .any(|l| l.contains("CONSOLE") && l.contains("ERROR")),
        "{name}: {log}"
    );
}

#[test]
fn eval_page() {
    let html = page(&["eval", "problems/micro-gear.toml", "--format", "html"]);
    // The hub's pull-off (6 µN) is a dot on the 10 mN curve: the tensile part is
    // drawn again, enlarged, the pull-off labelled.
    check_page(
        &html,
        &[
            "load-separation",
            "load-separation-tension",
            "sensitivities",
        ],
    );
    assert!(html.contains("pull-off 5.999 µN at d = 11.55 nm"));
    assert!(html.contains("0.6404 µm²"));
    renders_in_chromium(&html, "eval");
}

#[test]
fn optimize_page() {
    let html = page(&[
        "optimize",
        "tests/data/micro-gear-study-jkr.toml",
        "--format",
        "html",
    ]);
    check_page(&html, &["convergence", "load-separation"]);
    renders_in_chromium(&html, "optimize");
}

/// The header cells of every table of a page, in order, one Vec per table.
fn table_headers(html: &str) -> Vec<Vec<String>> {
    html.split("<table>")
        .skip(1)
        .map(|t| {
            let head = &t[..t.find("</tr>").unwrap()];
            head.split("<th>")
                .skip(1)
                .map(|c| c[..c.find("</th>").unwrap()].to_string())
                .collect()
        })
        .collect()
}

/// The rows (cell texts) of the table whose first header cell is `first`.
fn table_rows(html: &str, first: &str) -> Vec<Vec<String>> {
    let t = html
        .split("<table>")
        .skip(1)
        .find(|t| t.starts_with(&format!("\n<tr><th>{first}</th>")))
        .unwrap_or_else(|| panic!("no table starting with {first}"));
    let t = &t[..t.find("</table>").unwrap()];
    t.split("<tr>")
        .skip(2)
        .map(|r| {
            r.split("<td")
                .skip(1)
                .map(|c| {
                    let c = &c[c.find('>').unwrap() + 1..];
                    c[..c.find("</td>").unwrap()].to_string()
                })
                .collect()
        })
        .collect()
}

#[test]
fn pareto_page() {
    // Under JKR, whose six-point front has a knee (the Lennard-Jones law's
    // has two designs on it).
    let latch = crate::common::under_law("latch-pareto", "jkr");
    let html = page(&[
        "pareto",
        latch.to_str().unwrap(),
        "--points",
        "6",
        "--format",
        "html",
    ]);
    check_page(&html, &["front"]);
    // Real tables, not the text report in <pre>.
    assert!(!html.contains("<pre>"));
    let headers = table_headers(&html);
    assert_eq!(headers.len(), 3, "{headers:?}");
    // End points, knee and baseline.
    let ends = table_rows(&html, "design");
    let labels: Vec<&str> = ends.iter().map(|r| r[0].as_str()).collect();
    assert!(
        labels[0].starts_with("point 0: the preferred adhesion end"),
        "{labels:?}"
    );
    assert!(labels[1].ends_with(": the far end"), "{labels:?}");
    assert!(labels.iter().any(|l| l.ends_with("the knee")), "{labels:?}");
    assert!(labels.contains(&"least-wear design of the study"));
    assert!(labels.iter().any(|l| l.starts_with("baseline design")));
    // Every point, its design and both constraints of the study at it.
    assert_eq!(
        headers[1],
        [
            "point",
            "pull-off force",
            "wear rate",
            "status",
            "front",
            "hardness",
            "sigma",
            "asperity radius",
            "real area fraction (constraint)",
            "pull off force (constraint)"
        ]
    );
    let points = table_rows(&html, "point");
    // The turn said in words above the plot.
    assert!(html.contains("<p>The front turns at point 5,"), "{html}");
    // Six on the front; the curve turns, and the dominated points past it are
    // listed too.
    assert!(points.len() > 6, "{points:?}");
    assert_eq!(
        points.iter().filter(|r| r[4] != "dominated").count(),
        6,
        "{points:?}"
    );
    for r in &points {
        assert_eq!(r.len(), 10, "{r:?}");
        // The pull-off constraint at a point is the point's own adhesion measure
        // (the sweep computed it; the page re-evaluates the design): same value.
        let measure = common::num(r[1].split(' ').next().unwrap());
        let constraint = common::num(r[9].split(' ').next().unwrap());
        assert_eq!(
            r[1].split(' ').nth(1),
            r[9].split(' ').nth(1),
            "units of {r:?}"
        );
        assert!(
            common::rel(constraint, measure, measure) < 1e-3,
            "{r:?}: the constraint column disagrees with the measure"
        );
        assert!(!r[8].contains("breaks"), "{r:?}");
    }
    assert_eq!(points.iter().filter(|r| r[4] == "knee").count(), 1);
    // The constraints with their limits.
    let cons = table_rows(&html, "constraint");
    assert_eq!(cons.len(), 2);
    assert_eq!(cons[0][0], "real_area_fraction");
    assert_eq!(cons[0][1], "0.0004");
    assert_eq!(cons[1][2], "10 µN");
    renders_in_chromium(&html, "pareto");
}

#[test]
fn materials_page() {
    let html = page(&[
        "optimize",
        "problems/materials-study.toml",
        "--format",
        "html",
    ]);
    check_page(&html, &["ranking"]);
    let ranking = table_rows(&html, "rank");
    // Every material of [design] materials has a row; ranks 1, 2, … first, then the
    // materials that meet no constraint set (rank "—").
    assert_eq!(ranking.len(), 5);
    let ranked = ranking.iter().take_while(|r| r[0] != "—").count();
    assert!(ranked >= 1);
    for (i, r) in ranking.iter().enumerate() {
        let want = if i < ranked {
            (i + 1).to_string()
        } else {
            "—".into()
        };
        assert_eq!(r[0], want, "{r:?}");
    }
    // The page ranks as the JSON report does.
    let json: serde_json::Value = serde_json::from_str(&page(&[
        "optimize",
        "problems/materials-study.toml",
        "--format",
        "json",
    ]))
    .unwrap();
    let names: Vec<&str> = json["ranking"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["material"].as_str().unwrap())
        .collect();
    let page_names: Vec<&str> = ranking.iter().map(|r| r[1].as_str()).collect();
    assert_eq!(page_names, names);
    // One bar per material with a result (all five here), in the same order.
    let bars = html.matches("<rect class=\"bar\"").count();
    assert_eq!(bars, 5);
    assert!(html.contains(&format!("1. {}", names[0])));
    renders_in_chromium(&html, "materials");
}

#[test]
fn materials_page_to_a_file() {
    let file = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("out-materials.html");
    let out = Command::cargo_bin("wearopt")
        .unwrap()
        .args([
            "optimize",
            "problems/materials-study.toml",
            "--format",
            "html",
            "--out",
        ])
        .arg(&file)
        .output()
        .unwrap();
    assert!(out.status.success() && out.stdout.is_empty(), "{out:?}");
    check_page(&std::fs::read_to_string(&file).unwrap(), &["ranking"]);
}

#[test]
fn out_writes_the_page_to_a_file() {
    let file = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("out-eval.html");
    let out = Command::cargo_bin("wearopt")
        .unwrap()
        .args([
            "eval",
            "problems/gold-switch.toml",
            "--format",
            "html",
            "--out",
        ])
        .arg(&file)
        .output()
        .unwrap();
    assert!(out.status.success() && out.stdout.is_empty());
    check_page(
        &std::fs::read_to_string(&file).unwrap(),
        &[
            "load-separation",
            "load-separation-tension",
            "sensitivities",
        ],
    );
}
