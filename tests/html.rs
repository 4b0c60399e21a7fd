//! `--format html` pages as pages: each parses (it is well-formed XHTML-compatible
//! markup after the doctype), holds every plot it promises, has no URL at all, and —
//! where a headless Chromium is installed — renders without a console error.

mod common;

use assert_cmd::Command;
use common::parse_xml;

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
    check_page(&html, &["load-separation", "sensitivities"]);
    assert!(html.contains("0.5702 µm²"));
    renders_in_chromium(&html, "eval");
}

#[test]
fn optimize_page() {
    let html = page(&[
        "optimize",
        "problems/micro-gear-study.toml",
        "--format",
        "html",
    ]);
    check_page(&html, &["convergence", "load-separation"]);
    renders_in_chromium(&html, "optimize");
}

#[test]
fn pareto_page() {
    let html = page(&[
        "pareto",
        "problems/latch-pareto.toml",
        "--points",
        "6",
        "--format",
        "html",
    ]);
    check_page(&html, &["front"]);
    assert!(html.contains("knee"));
    renders_in_chromium(&html, "pareto");
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
        &["load-separation", "sensitivities"],
    );
}
