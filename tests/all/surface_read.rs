//! The height-map readers against files written by another program (numpy, Python's
//! zipfile, by hand from the published formats: scripts/make_scans.py), malformed files of
//! each kind, arbitrary bytes, and the CLI's refusals (exit code 2).

use crate::common::wearopt;

use std::path::Path;

use proptest::prelude::*;
use wearopt::surface::read::{self, read_bytes, Format, Overrides, ReadError};

const DIR: &str = "tests/data/scans";

fn path(name: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(DIR).join(name)
}

/// The grid every test file holds: h[j][i] = (10 j + i) nm, 5 × 4, (i = 2, j = 1) missing.
fn check_grid(name: &str, overrides: Overrides, pixel: (f64, f64)) {
    let map = read::load(&path(name), &overrides).unwrap_or_else(|e| panic!("{name}: {e}"));
    assert_eq!((map.nx(), map.ny()), (5, 4), "{name}");
    assert!(
        (map.pixel_size_x() - pixel.0).abs() < 1e-12 * pixel.0
            && (map.pixel_size_y() - pixel.1).abs() < 1e-12 * pixel.1,
        "{name}: pixel {} × {}",
        map.pixel_size_x(),
        map.pixel_size_y()
    );
    for j in 0..4 {
        for i in 0..5 {
            let h = map.at(i, j);
            if (i, j) == (2, 1) {
                assert!(h.is_nan(), "{name}: ({i}, {j}) should be missing, is {h}");
            } else {
                let expected = (10 * j + i) as f64 * 1e-9;
                assert!(
                    (h - expected).abs() <= 1e-6 * 1e-9,
                    "{name}: ({i}, {j}) = {h}, expected {expected}"
                );
            }
        }
    }
}

#[test]
fn every_reader_reads_the_grid_with_its_units() {
    let none = Overrides::default();
    // GSF: XReal 5 um over 5 points, YReal 2 um over 4 points (real length / n), ZUnits nm.
    check_grid("grid.gsf", none, (1e-6, 0.5e-6));
    // X3P: doubles in metres with NaN; int16 with Increment 1 nm, Offset 5 nm and a
    // valid-points mask; int32 with Increment 0.1 nm and a mask; inline float32 DataList.
    for name in [
        "grid-D.x3p",
        "grid-I-mask.x3p",
        "grid-L.x3p",
        "grid-F-inline.x3p",
    ] {
        check_grid(name, none, (1e-6, 0.5e-6));
    }
    // ASCII with Gwyddion's header: Width 5 µm, Height 2 µm, Value units nm.
    check_grid("grid-gwyddion.txt", none, (1e-6, 0.5e-6));
    // NumPy (written by numpy): the user supplies pixel size and unit.
    let user = Overrides {
        pixel_size: Some(2e-8),
        height_unit: Some(1e-9),
        ..Overrides::default()
    };
    for name in [
        "grid.npy",
        "grid-fortran.npy",
        "grid-be-f4.npy",
        "grid-bare.txt",
    ] {
        check_grid(name, user, (2e-8, 2e-8));
    }
    // Overrides win over the file.
    check_grid(
        "grid.gsf",
        Overrides {
            pixel_size: Some(2e-8),
            height_unit: None,
            ..Overrides::default()
        },
        (2e-8, 2e-8),
    );
}

#[test]
fn files_without_units_need_them_from_the_user() {
    for (name, needs) in [
        ("grid.npy", "--pixel-size"),
        ("grid-bare.txt", "--pixel-size"),
        ("grid-no-units.gsf", "--pixel-size"),
    ] {
        let e = read::load(&path(name), &Overrides::default()).unwrap_err();
        assert!(matches!(e, ReadError::NoPixelSize { .. }), "{name}: {e}");
        assert!(e.to_string().contains(needs), "{e}");
    }
    let with_pixel = Overrides {
        pixel_size: Some(1e-8),
        height_unit: None,
        ..Overrides::default()
    };
    for name in ["grid.npy", "grid-bare.txt", "grid-no-units.gsf"] {
        let e = read::load(&path(name), &with_pixel).unwrap_err();
        assert!(matches!(e, ReadError::NoHeightUnit { .. }), "{name}: {e}");
        assert!(e.to_string().contains("--height-unit"), "{e}");
    }
}

fn bytes(name: &str) -> Vec<u8> {
    std::fs::read(path(name)).unwrap()
}

/// Expects a Malformed error whose reason contains `words`.
fn refused(data: &[u8], format: Format, words: &str) {
    match read_bytes(data, format, "f") {
        Err(e @ ReadError::Malformed { .. }) => {
            assert!(e.to_string().contains(words), "{e} (expected {words:?})")
        }
        other => panic!("expected a refusal containing {words:?}, got {other:?}"),
    }
}

#[test]
fn malformed_gsf() {
    let good = bytes("grid.gsf");
    refused(&good[..good.len() - 3], Format::Gsf, "needs 80 data bytes");
    refused(
        b"Gwyddion Simple Field 2.0\nXRes = 1\n\0\0\0",
        Format::Gsf,
        "first line",
    );
    refused(
        b"Gwyddion Simple Field 1.0\nXRes = 2\n",
        Format::Gsf,
        "no NUL",
    );
    refused(
        b"Gwyddion Simple Field 1.0\nXRes = 0\nYRes = 1\n\0\0",
        Format::Gsf,
        "XRes",
    );
    refused(
        b"Gwyddion Simple Field 1.0\nYRes = 1\n\0\0\0\0",
        Format::Gsf,
        "no XRes",
    );
    refused(
        b"Gwyddion Simple Field 1.0\nXRes = 1\nYRes = 1\nZUnits = V\n\0\0\0\0\0\0\0\0",
        Format::Gsf,
        "ZUnits",
    );
    // Data not at the next multiple of 4 (a stray byte in the padding).
    let text = "Gwyddion Simple Field 1.0\nXRes = 1\nYRes = 1\n";
    let mut b = text.as_bytes().to_vec();
    b.push(0);
    b.extend(std::iter::repeat_n(1u8, 8));
    refused(&b, Format::Gsf, "NUL bytes up to byte");
}

#[test]
fn malformed_x3p() {
    refused(b"not a zip", Format::X3p, "not a zip");
    let good = bytes("grid-D.x3p");
    refused(&good[..good.len() / 2], Format::X3p, "");
    // Rebuild archives with one thing wrong.
    let xml = |data_type: &str, size_x: usize| {
        format!(
            "<?xml version=\"1.0\"?><p:ISO5436_2 xmlns:p=\"http://www.opengps.eu/2008/ISO5436_2\"><Record1><Axes>\
<CX><AxisType>I</AxisType><DataType>D</DataType><Increment>1e-6</Increment><Offset>0</Offset></CX>\
<CY><AxisType>I</AxisType><DataType>D</DataType><Increment>1e-6</Increment><Offset>0</Offset></CY>\
<CZ><AxisType>A</AxisType><DataType>{data_type}</DataType></CZ></Axes></Record1>\
<Record3><MatrixDimension><SizeX>{size_x}</SizeX><SizeY>2</SizeY><SizeZ>1</SizeZ></MatrixDimension>\
<DataLink><PointDataLink>bindata/data.bin</PointDataLink></DataLink></Record3></p:ISO5436_2>"
        )
    };
    let zip = |xml: Option<String>, data: &[u8]| {
        use std::io::Write;
        let mut buf = std::io::Cursor::new(Vec::new());
        let mut z = zip::ZipWriter::new(&mut buf);
        let o = zip::write::SimpleFileOptions::default()
            .compression_method(zip::CompressionMethod::Stored);
        if let Some(x) = xml {
            z.start_file("main.xml", o).unwrap();
            z.write_all(x.as_bytes()).unwrap();
        }
        z.start_file("bindata/data.bin", o).unwrap();
        z.write_all(data).unwrap();
        z.finish().unwrap();
        buf.into_inner()
    };
    let four = [0u8; 32];
    assert!(read_bytes(&zip(Some(xml("D", 2)), &four), Format::X3p, "f").is_ok());
    refused(&zip(Some(xml("D", 3)), &four), Format::X3p, "need 48");
    refused(&zip(Some(xml("Q", 2)), &four), Format::X3p, "DataType");
    refused(&zip(None, &four), Format::X3p, "main.xml");
    refused(
        &zip(Some("<a><b></a>".into()), &four),
        Format::X3p,
        "main.xml",
    );
    refused(
        &zip(
            Some(xml("D", 2).replace(
                "<AxisType>I</AxisType><DataType>D</DataType><Increment>1e-6",
                "<AxisType>A</AxisType><DataType>D</DataType><Increment>1e-6",
            )),
            &four,
        ),
        Format::X3p,
        "incremental",
    );
}

#[test]
fn malformed_npy_and_ascii() {
    let good = bytes("grid.npy");
    refused(&good[..good.len() - 8], Format::Npy, "data bytes");
    refused(&good[..20], Format::Npy, "header");
    refused(b"\x93NUMPX\x01\x00\x10\x00", Format::Npy, "magic");
    let mut bad = good.clone();
    let at = bad.windows(3).position(|w| w == b"<f8").unwrap();
    bad[at + 1] = b'c';
    refused(&bad, Format::Npy, "not supported");
    let mut bad = good.clone();
    let at = bad.windows(6).position(|w| w == b"(4, 5)").unwrap();
    bad[at..at + 6].copy_from_slice(b"(4, 6)");
    refused(&bad, Format::Npy, "needs 192 data bytes");
    refused(b"1 2 3\n4 5\n", Format::Ascii, "line 2: 2 values");
    refused(b"1 2 x3\n", Format::Ascii, "not a number");
    refused(b"# only a comment\n", Format::Ascii, "no rows");
    refused(b"# Width: 5\n1 2 3\n", Format::Ascii, "Width");
    refused(b"# Value units: V\n1 2 3\n", Format::Ascii, "Value units");
    refused(b"1 inf 3\n", Format::Ascii, "infinite");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    /// Arbitrary bytes never make a reader panic.
    #[test]
    fn arbitrary_bytes_never_panic(data in proptest::collection::vec(any::<u8>(), 0..300)) {
        for f in [Format::Gsf, Format::X3p, Format::Ascii, Format::Npy] {
            let _ = read_bytes(&data, f, "fuzz");
        }
    }

    /// Valid files with bytes changed or cut never make a reader panic, and whatever is
    /// read has as many values as its grid.
    #[test]
    fn damaged_files_never_panic(
        which in 0usize..6,
        edits in proptest::collection::vec((any::<prop::sample::Index>(), any::<u8>()), 0..6),
        cut in any::<prop::sample::Index>(),
    ) {
        let (name, f) = [
            ("grid.gsf", Format::Gsf),
            ("grid-I-mask.x3p", Format::X3p),
            ("grid-F-inline.x3p", Format::X3p),
            ("grid.npy", Format::Npy),
            ("grid-fortran.npy", Format::Npy),
            ("grid-gwyddion.txt", Format::Ascii),
        ][which];
        let mut data = bytes(name);
        for (i, b) in edits {
            let k = i.index(data.len());
            data[k] = b;
        }
        let keep = data.len() - cut.index(data.len() / 4 + 1);
        data.truncate(keep);
        if let Ok(scan) = read_bytes(&data, f, "fuzz") {
            prop_assert_eq!(scan.values.len(), scan.nx * scan.ny);
            let _ = scan.resolve(&Overrides { pixel_size: Some(1e-8), height_unit: Some(1e-9), ..Overrides::default() }, "fuzz");
        }
    }
}

#[test]
fn cli_refuses_bad_files_with_exit_code_2() {
    let dir = std::env::temp_dir().join(format!("wearopt-surface-read-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let truncated = dir.join("truncated.gsf");
    let good = bytes("grid.gsf");
    std::fs::write(&truncated, &good[..good.len() - 4]).unwrap();
    let ragged = dir.join("ragged.txt");
    std::fs::write(&ragged, "1 2 3\n4 5\n").unwrap();
    let notzip = dir.join("bad.x3p");
    std::fs::write(&notzip, "hello").unwrap();
    let unknown = dir.join("scan.xyz1");
    std::fs::write(&unknown, "1").unwrap();
    let cases: Vec<(Vec<String>, &str)> = vec![
        (vec![truncated.display().to_string()], "data bytes"),
        (
            vec![
                ragged.display().to_string(),
                "--pixel-size".into(),
                "1nm".into(),
                "--height-unit".into(),
                "nm".into(),
            ],
            "every row",
        ),
        (vec![notzip.display().to_string()], "not a zip"),
        (
            vec![unknown.display().to_string()],
            "unknown height-map format",
        ),
        (vec![path("grid.npy").display().to_string()], "--pixel-size"),
        (
            vec![
                path("grid.npy").display().to_string(),
                "--pixel-size".into(),
                "10 nm".into(),
            ],
            "--height-unit",
        ),
        (
            vec![
                path("grid-bare.txt").display().to_string(),
                "--pixel-size".into(),
                "10 nm".into(),
            ],
            "--height-unit",
        ),
        (
            vec![
                path("grid.gsf").display().to_string(),
                "--pixel-size".into(),
                "10 GPa".into(),
            ],
            "--pixel-size",
        ),
        (
            vec![
                path("grid.gsf").display().to_string(),
                "--height-unit".into(),
                "parsec".into(),
            ],
            "--height-unit",
        ),
        (
            vec![
                path("grid.gsf").display().to_string(),
                "--cutoff".into(),
                "-1 nm".into(),
            ],
            "--cutoff",
        ),
        (
            vec![
                path("grid.gsf").display().to_string(),
                "--cutoff".into(),
                "3 um".into(),
            ],
            "cut-off",
        ),
        (
            vec![dir.join("missing.gsf").display().to_string()],
            "cannot read",
        ),
    ];
    for (args, words) in cases {
        let out = wearopt()
            .arg("roughness")
            .args(&args)
            .assert()
            .code(2)
            .get_output()
            .clone();
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.starts_with("Error: "), "{args:?}: {err}");
        assert!(err.contains(words), "{args:?}: {err} (expected {words:?})");
        assert!(!err.contains("panicked"), "{err}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// A matrix written with decimal commas (a European locale's export) was read
/// as twice as many columns of near-zero heights; now it is refused (exit 2,
/// the flag named) and, with --decimal-comma, reads as the same map written with
/// points.
#[test]
fn decimal_commas_are_refused_or_read_when_said() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    use wearopt::surface::synthetic::{random_surface, Spectrum};
    let n = 32;
    let map = random_surface(
        n,
        1e-8,
        Spectrum::Gaussian {
            correlation_length: 4e-8,
        },
        1.0,
        5,
    )
    .unwrap();
    let rows: Vec<Vec<String>> = map
        .heights()
        .chunks(n)
        .map(|r| r.iter().map(|h| format!("{h:.6}")).collect())
        .collect();
    let points = dir.join("points.txt");
    let commas = dir.join("commas.txt");
    std::fs::write(
        &points,
        rows.iter()
            .map(|r| r.join(" "))
            .collect::<Vec<_>>()
            .join("\n"),
    )
    .unwrap();
    std::fs::write(
        &commas,
        rows.iter()
            .map(|r| r.join("\t").replace('.', ","))
            .collect::<Vec<_>>()
            .join("\n"),
    )
    .unwrap();
    let run = |file: &std::path::Path, extra: &[&str]| {
        wearopt()
            .args([
                "roughness",
                file.to_str().unwrap(),
                "--pixel-size",
                "10nm",
                "--height-unit",
                "nm",
                "--format",
                "json",
            ])
            .args(extra)
            .output()
            .unwrap()
    };
    let refused = run(&commas, &[]);
    assert_eq!(refused.status.code(), Some(2));
    let err = String::from_utf8(refused.stderr).unwrap();
    assert!(
        err.contains("decimals with commas") && err.contains("--decimal-comma"),
        "{err}"
    );
    let a: serde_json::Value =
        serde_json::from_slice(&run(&commas, &["--decimal-comma"]).stdout).unwrap();
    let b: serde_json::Value = serde_json::from_slice(&run(&points, &[]).stdout).unwrap();
    assert_eq!(a["summit_sigma"], b["summit_sigma"]);
    assert_eq!(a["nx"], serde_json::json!(n));
}
