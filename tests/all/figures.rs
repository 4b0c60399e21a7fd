//! `wearopt figures` and the library behind it: the least-squares fit against
//! closed forms, the curves against an independent recomputation with the model,
//! the claims' logic, the exact CSV headers, SVG well-formedness (a minimal XML
//! checker written here), the CLI end to end and its exit codes, and output that
//! does not depend on the thread count.

use crate::common;
use crate::common::wearopt;

use std::fs;
use std::path::{Path, PathBuf};

use crate::common::{parse_xml, Element};
use wearopt::figures::{
    assess_claims, compute_curve, compute_figures, least_squares, paper_figures, Curve, Figure,
    FigureSettings, FigureSpec, LinearFit, Varied,
};
use wearopt::model::{Coefficients, Model};
use wearopt::report::svg::{Axis, LinePlot, Marker, Series};

/// A fresh, empty directory for one test.
fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("wearopt-figures-{}-{name}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).expect("temp dir");
    dir
}

/// Least squares by the textbook raw-sum normal equations (Cramer's rule) and
/// r² = 1 - SS_res/SS_tot from the residuals: a different route from the
/// library's centred sums and S_xy²/(S_xx S_yy).
fn reference_fit(points: &[(f64, f64)]) -> (f64, f64, f64) {
    let n = points.len() as f64;
    let sx: f64 = points.iter().map(|p| p.0).sum();
    let sy: f64 = points.iter().map(|p| p.1).sum();
    let sxx: f64 = points.iter().map(|p| p.0 * p.0).sum();
    let sxy: f64 = points.iter().map(|p| p.0 * p.1).sum();
    let slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    let intercept = (sy - slope * sx) / n;
    let mean_y = sy / n;
    let ss_res: f64 = points
        .iter()
        .map(|p| (p.1 - slope * p.0 - intercept).powi(2))
        .sum();
    let ss_tot: f64 = points.iter().map(|p| (p.1 - mean_y).powi(2)).sum();
    (slope, intercept, 1.0 - ss_res / ss_tot)
}

#[test]
fn least_squares_matches_closed_forms() {
    // y = 3x + 1 + e with residuals e orthogonal to 1 and x: the fit is exactly
    // slope 3, intercept 1, and r² = 1 - Σe²/SS_tot = 1 - 4/94.
    let xs = [-2.0, -1.0, 0.0, 1.0, 2.0];
    let es = [1.0, -1.0, 0.0, -1.0, 1.0];
    let pts: Vec<(f64, f64)> = xs
        .iter()
        .zip(es)
        .map(|(&x, e)| (x, 3.0 * x + 1.0 + e))
        .collect();
    let f = least_squares(&pts).unwrap();
    assert!((f.slope - 3.0).abs() < 1e-14, "{f:?}");
    assert!((f.intercept - 1.0).abs() < 1e-14, "{f:?}");
    assert!((f.r_squared - 90.0 / 94.0).abs() < 1e-14, "{f:?}");
    assert_eq!(f.n, 5);

    // A curved, offset set: agrees with the raw-sum route.
    let pts: Vec<(f64, f64)> = (0..40)
        .map(|i| {
            let x = 0.05 + 0.125 * i as f64;
            (x, 0.3 + 1.7 * x.powf(0.85) + 0.01 * (7.0 * x).sin())
        })
        .collect();
    let f = least_squares(&pts).unwrap();
    let (slope, intercept, r2) = reference_fit(&pts);
    assert!((f.slope / slope - 1.0).abs() < 1e-12);
    assert!((f.intercept - intercept).abs() < 1e-12);
    assert!((f.r_squared - r2).abs() < 1e-12);
    assert!(f.r_squared < 1.0);

    // Degenerate inputs.
    assert!(least_squares(&[(1.0, 1.0)]).is_none());
    assert!(least_squares(&[(1.0, 1.0), (1.0, 2.0), (1.0, 3.0)]).is_none());
    assert!(least_squares(&[(1.0, 1.0), (f64::NAN, 2.0)]).is_none());
    assert_eq!(
        least_squares(&[(0.0, 2.0), (1.0, 2.0)]).unwrap().r_squared,
        1.0
    );
}

/// Ā(h) = e^{-h²/2} - h √(π/2) erfc(h/√2) (docs/model.md §4), by puruspe's erfc.
fn area_closed_form(h: f64) -> f64 {
    (-h * h / 2.0).exp()
        - h * (std::f64::consts::PI / 2.0).sqrt() * puruspe::erfc(h / std::f64::consts::SQRT_2)
}

/// The loading-branch separation for a compressive target, found without the
/// library's solver: step left from h = 6 (where P̄ is ≈ 0 < target) by 1/64
/// until P̄ ≥ target, then bisect. This is the largest root, docs/model.md §4.
fn loading_separation(model: &Model, target: f64) -> f64 {
    let load = |h: f64| model.at(h).load().value();
    let mut hi = 6.0;
    assert!(load(hi) < target);
    let mut lo = hi - 1.0 / 64.0;
    while load(lo) < target {
        hi = lo;
        lo -= 1.0 / 64.0;
        assert!(lo > -50.0, "no root for {target}");
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if load(mid) < target {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    0.5 * (lo + hi)
}

#[test]
fn curve_slopes_match_an_independent_recomputation() {
    let settings = FigureSettings {
        points: 21,
        ..FigureSettings::default()
    };
    // A positive plastic jump, two negative ones (θ = 10, λ = 0.125 sits on both
    // transitions), and a nearly elastic-adhesive curve.
    for (theta, lambda) in [(2.0, 5.0), (10.0, 0.125), (100.0, 0.1), (25.0, 0.01)] {
        let curve = compute_curve(theta, lambda, &settings);
        assert_eq!(curve.points.len(), settings.points);
        assert_eq!(curve.failed, 0);
        let model = Model::new(Coefficients::from_indices(theta, lambda));
        let pts: Vec<(f64, f64)> = settings
            .loads()
            .into_iter()
            .map(|target| {
                let h = loading_separation(&model, target);
                let load = model.at(h).load().value();
                assert!((load / target - 1.0).abs() < 1e-9, "θ={theta} λ={lambda}");
                (load, area_closed_form(h))
            })
            .collect();
        for (p, q) in curve.points.iter().zip(&pts) {
            assert!(
                (p.load - q.0).abs() < 1e-9 * q.0,
                "θ={theta} λ={lambda}: {p:?} vs {q:?}"
            );
            assert!(
                (p.wear_volume - q.1).abs() < 1e-9 * q.1,
                "θ={theta} λ={lambda}: {p:?} vs {q:?}"
            );
        }
        let (slope, intercept, r2) = reference_fit(&pts);
        let fit = curve.fit.unwrap();
        assert!(
            (fit.slope / slope - 1.0).abs() < 1e-8,
            "θ={theta} λ={lambda}: slope {} vs {slope}",
            fit.slope
        );
        assert!((fit.intercept - intercept).abs() < 1e-8);
        assert!((fit.r_squared - r2).abs() < 1e-8);
        // V̄ grows with P̄ along the loading branch.
        assert!(curve
            .points
            .windows(2)
            .all(|w| w[1].wear_volume > w[0].wear_volume));
    }
}

fn synthetic_figure(
    number: u8,
    varied: Varied,
    fixed: f64,
    values: &[f64],
    slopes: &[f64],
) -> Figure {
    let spec = FigureSpec {
        number,
        varied,
        fixed,
        values: values.to_vec(),
    };
    let curves = spec
        .curves()
        .into_iter()
        .zip(slopes)
        .map(|((theta, lambda), &slope)| Curve {
            theta,
            lambda,
            points: Vec::new(),
            failed: 0,
            fit: Some(LinearFit {
                slope,
                intercept: 0.0,
                r_squared: 0.999,
                n: 3,
            }),
            pull_off_load: None,
            plastic_jump: 0.0,
        })
        .collect();
    Figure { spec, curves }
}

#[test]
fn claims_follow_their_criteria() {
    let v = [1.0, 2.0, 3.0];
    let paper_like = vec![
        synthetic_figure(1, Varied::Theta, 0.1, &v, &[3.0, 2.0, 1.0]),
        synthetic_figure(2, Varied::Theta, 5.0, &v, &[1.0, 1.05, 1.02]),
        synthetic_figure(3, Varied::Lambda, 10.0, &v, &[2.0, 1.5, 1.2]),
        synthetic_figure(4, Varied::Lambda, 25.0, &v, &[2.5, 1.5, 1.0]),
    ];
    let claims = assess_claims(&paper_like);
    let ids: Vec<&str> = claims.iter().map(|c| c.id).collect();
    assert_eq!(
        ids,
        [
            "linear",
            "low_lambda_low_theta_wears_more",
            "high_lambda_theta_insensitive",
            "low_lambda_wears_more"
        ]
    );
    assert!(claims.iter().all(|c| c.holds == Some(true)), "{claims:#?}");

    let mut contrary = paper_like.clone();
    contrary[0] = synthetic_figure(1, Varied::Theta, 0.1, &v, &[1.0, 2.0, 3.0]);
    contrary[1] = synthetic_figure(2, Varied::Theta, 5.0, &v, &[1.0, 1.2, 1.0]);
    contrary[3] = synthetic_figure(4, Varied::Lambda, 25.0, &v, &[2.5, 1.0, 1.5]);
    contrary[2].curves[1].fit.as_mut().unwrap().r_squared = 0.95;
    let claims = assess_claims(&contrary);
    assert!(claims.iter().all(|c| c.holds == Some(false)), "{claims:#?}");
    let words = |i: usize| wearopt::report::figures::evidence(&claims[i].evidence);
    assert!(words(0).contains("0.950000"), "{}", words(0));
    assert!(words(2).contains("1.2000"), "{}", words(2));
    assert!(words(3).contains("2 → 3"), "{}", words(3));

    let claims = assess_claims(&paper_like[..1]);
    assert_eq!(claims[2].holds, None);
    assert_eq!(claims[3].holds, None);
}

#[test]
fn the_result_does_not_depend_on_the_thread_count() {
    let settings = FigureSettings {
        points: 9,
        ..FigureSettings::default()
    };
    let run = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| compute_figures(&paper_figures(), &settings))
    };
    let one = run(1);
    assert_eq!(one, run(3));
    assert_eq!(one.len(), 4);
    for (f, spec) in one.iter().zip(paper_figures()) {
        assert_eq!(f.spec, spec);
        assert_eq!(f.curves.len(), spec.values.len());
        for (c, (theta, lambda)) in f.curves.iter().zip(spec.curves()) {
            assert_eq!((c.theta, c.lambda), (theta, lambda));
        }
    }
}

#[test]
fn the_xml_checker_rejects_malformed_documents() {
    assert!(parse_xml("<svg><g></g></svg>").is_ok());
    for bad in [
        "<svg><g></svg>",
        "<svg>",
        "<svg a=1></svg>",
        "<svg>&bogus;</svg>",
        "<svg a=\"<\"></svg>",
        "<svg></svg><svg></svg>",
        "<svg a=\"1\" a=\"2\"></svg>",
    ] {
        assert!(parse_xml(bad).is_err(), "{bad}");
    }
}

fn count<'a>(elements: &'a [Element], name: &str, class: Option<&str>) -> Vec<&'a Element> {
    elements
        .iter()
        .filter(|e| {
            e.name == name
                && class.is_none_or(|c| e.attributes.get("class").is_some_and(|x| x == c))
        })
        .collect()
}

#[test]
fn the_svg_exporter_escapes_text_and_handles_log_axes() {
    let svg = LinePlot::new(
        "Front <A & B>",
        Axis::log("wear rate").with_unit("m³/m"),
        Axis::log("load").with_unit("µN"),
    )
    .with_series(
        Series::new(
            "\"design\" 'a'",
            vec![(1e-18, 1.0), (1e-17, 10.0), (0.0, 5.0), (1e-16, 100.0)],
        )
        .without_line()
        .with_marker(Marker::Diamond),
    )
    .with_series(Series::new("b", vec![(1e-18, 2.0), (1e-16, 3.0)]).with_marker(Marker::Cross))
    .to_svg();
    let el = parse_xml(&svg).unwrap_or_else(|e| panic!("{e}\n{svg}"));
    assert_eq!(el[0].name, "svg");
    assert!(svg.contains("Front &lt;A &amp; B&gt;"));
    assert!(svg.contains("wear rate (m³/m)") && svg.contains("load (µN)"));
    assert!(svg.contains("&quot;design&quot; &apos;a&apos;"));
    let series = count(&el, "g", Some("series"));
    assert_eq!(series.len(), 2);
    // The scatter has no line, and its point at x = 0 is not drawable on a log axis.
    assert_eq!(count(&el, "polyline", None).len(), 1);
    // 3 diamonds in the plot + 1 in the legend.
    let diamonds = svg.matches("<polygon").count();
    assert_eq!(diamonds, 4);
    assert!(svg.contains(">1e-18</text>") && svg.contains(">1e-16</text>"));
    // An empty plot still renders.
    parse_xml(&LinePlot::new("empty", Axis::linear("x"), Axis::linear("y")).to_svg()).unwrap();
}

fn read(path: &Path) -> String {
    fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

#[test]
fn cli_writes_the_figures_and_reports_the_claims() {
    let dir = temp_dir("cli");
    let out = dir.join("nested/figs");
    let points = 11;
    let output = common::stdout(
        wearopt()
            .args(["figures", "--points", "11", "--out"])
            .arg(&out),
        0,
    );
    let text = String::from_utf8(output).unwrap();

    let names: Vec<String> = (1..=4)
        .flat_map(|i| [format!("figure{i}.csv"), format!("figure{i}.svg")])
        .chain(["slopes.csv".to_string()])
        .collect();
    for name in &names {
        let path = out.join(name);
        assert!(path.is_file(), "{name} missing");
        assert!(
            text.contains(&path.display().to_string()),
            "report does not name {name}"
        );
    }
    for (i, claim) in ["(1)", "(2)", "(3)", "(4)"].iter().enumerate() {
        let line = text
            .lines()
            .find(|l| l.trim_start().starts_with(claim))
            .unwrap_or_else(|| panic!("no claim line {}\n{text}", i + 1));
        assert!(
            line.contains("HOLDS") || line.contains("DOES NOT HOLD"),
            "{line}"
        );
    }
    assert!(text.contains("r² ≥ 0.99"));

    // Library run with the same settings, for exact comparison.
    let settings = FigureSettings {
        points,
        ..FigureSettings::default()
    };
    let figures = compute_figures(&paper_figures(), &settings);

    for f in &figures {
        let n = f.spec.number;
        let csv = read(&out.join(format!("figure{n}.csv")));
        let mut lines = csv.lines();
        assert_eq!(lines.next(), Some("theta,lambda,load,wear_volume"));
        let rows: Vec<Vec<f64>> = lines
            .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
            .collect();
        assert_eq!(rows.len(), f.spec.values.len() * points);
        for (row, (c, p)) in rows.iter().zip(
            f.curves
                .iter()
                .flat_map(|c| c.points.iter().map(move |p| (c, p))),
        ) {
            assert_eq!(row, &[c.theta, c.lambda, p.load, p.wear_volume]);
        }

        let svg = read(&out.join(format!("figure{n}.svg")));
        let el = parse_xml(&svg).unwrap_or_else(|e| panic!("figure{n}.svg: {e}"));
        assert_eq!(el[0].name, "svg");
        assert_eq!(count(&el, "title", None).len(), 1);
        assert_eq!(count(&el, "text", Some("title")).len(), 1);
        assert_eq!(count(&el, "text", Some("x-label")).len(), 1);
        assert_eq!(count(&el, "text", Some("y-label")).len(), 1);
        assert!(svg.contains(">non-dimensional load P̄</text>"));
        assert!(svg.contains(">non-dimensional wear volume V̄</text>"));
        assert!(svg.contains(&format!("Fig. {n}:")));
        let series = count(&el, "g", Some("series"));
        assert_eq!(series.len(), f.curves.len());
        assert_eq!(count(&el, "g", Some("legend")).len(), 1);
        assert_eq!(count(&el, "g", Some("legend-entry")).len(), f.curves.len());
        assert_eq!(count(&el, "polyline", None).len(), f.curves.len());
        let symbol = match f.spec.varied {
            Varied::Theta => "θ",
            Varied::Lambda => "λ",
        };
        for (s, v) in series.iter().zip(&f.spec.values) {
            assert_eq!(s.attributes["data-name"], format!("{symbol} = {v}"));
        }
    }

    let slopes = read(&out.join("slopes.csv"));
    let mut lines = slopes.lines();
    assert_eq!(lines.next(), Some("figure,theta,lambda,slope,r_squared"));
    let rows: Vec<&str> = lines.collect();
    let expected: Vec<(u8, &Curve)> = figures
        .iter()
        .flat_map(|f| f.curves.iter().map(move |c| (f.spec.number, c)))
        .collect();
    assert_eq!(rows.len(), expected.len());
    for (row, (n, c)) in rows.iter().zip(expected) {
        let cells: Vec<&str> = row.split(',').collect();
        assert_eq!(cells[0], n.to_string());
        let fit = c.fit.unwrap();
        let got: Vec<f64> = cells[1..].iter().map(|x| x.parse().unwrap()).collect();
        assert_eq!(got, [c.theta, c.lambda, fit.slope, fit.r_squared]);
        // And the slope is the least-squares slope of the CSV points themselves.
        let (slope, _, r2) = reference_fit(
            &c.points
                .iter()
                .map(|p| (p.load, p.wear_volume))
                .collect::<Vec<_>>(),
        );
        assert!((fit.slope / slope - 1.0).abs() < 1e-10);
        assert!((fit.r_squared - r2).abs() < 1e-10);
    }
    let _ = fs::remove_dir_all(&dir);
}

#[test]
fn cli_json_report_carries_claims_and_slopes() {
    let dir = temp_dir("json");
    let output = common::stdout(
        wearopt()
            .args(["figures", "--points", "5", "--format", "json", "--out"])
            .arg(&dir),
        0,
    );
    let v: serde_json::Value = serde_json::from_slice(&output).expect("valid JSON");
    assert_eq!(v["claims"].as_array().unwrap().len(), 4);
    for c in v["claims"].as_array().unwrap() {
        assert!(c["holds"].is_boolean(), "{c}");
        assert!(c["evidence"].is_string() && c["criterion"].is_string());
    }
    let curves = v["curves"].as_array().unwrap();
    assert_eq!(curves.len(), 20);
    for c in curves {
        assert!(c["slope"].is_f64() && c["r_squared"].is_f64(), "{c}");
        assert_eq!(c["points"], 5);
    }
    assert_eq!(v["files"].as_array().unwrap().len(), 9);
    assert_eq!(v["settings"]["points"], 5);
    let _ = fs::remove_dir_all(&dir);
}

#[test]
fn cli_output_is_the_same_on_one_thread_and_on_several() {
    let dir = temp_dir("threads");
    let mut outputs = Vec::new();
    for threads in ["1", "4"] {
        let out = dir.join(threads);
        let stdout = common::stdout(
            wearopt()
                .env("RAYON_NUM_THREADS", threads)
                .args(["figures", "--points", "7", "--format", "json", "--out"])
                .arg(&out),
            0,
        );
        let files: Vec<String> = ["figure1.csv", "figure3.svg", "slopes.csv"]
            .iter()
            .map(|f| read(&out.join(f)))
            .collect();
        let mut v: serde_json::Value = serde_json::from_slice(&stdout).unwrap();
        v["files"] = serde_json::Value::Null; // the paths differ by directory
        outputs.push((v, files));
    }
    assert_eq!(outputs[0], outputs[1]);
    let _ = fs::remove_dir_all(&dir);
}

#[test]
fn cli_refuses_bad_arguments_with_exit_code_2() {
    let dir = temp_dir("bad");
    let cases: &[(&[&str], &str)] = &[
        (&["--points", "0"], "--points 0"),
        (&["--points", "2"], "--points 2"),
        (&["--points", "10001"], "--points 10001"),
        (&["--points", "-3"], ""),
        (&["--load-min", "0"], "--load-min 0"),
        (&["--load-min", "-1"], "--load-min -1"),
        (&["--load-max", "0.01"], "--load-max 0.01"),
        (&["--load-max", "inf"], "--load-max inf"),
        (&["--format", "xml"], ""),
    ];
    for (args, message) in cases {
        let assert = wearopt()
            .arg("figures")
            .args(*args)
            .arg("--out")
            .arg(dir.join("unused"))
            .assert()
            .code(2);
        let stderr = String::from_utf8_lossy(&assert.get_output().stderr).to_string();
        assert!(stderr.contains(message), "{args:?}: {stderr}");
    }
    // Nothing is written when the arguments are refused.
    assert!(!dir.join("unused").exists());

    // --out naming an existing file.
    let file = dir.join("a-file");
    fs::write(&file, "x").unwrap();
    let assert = wearopt()
        .args(["figures", "--out"])
        .arg(&file)
        .assert()
        .code(2);
    let stderr = String::from_utf8_lossy(&assert.get_output().stderr).to_string();
    assert!(stderr.contains("--out"), "{stderr}");
    let _ = fs::remove_dir_all(&dir);
}
