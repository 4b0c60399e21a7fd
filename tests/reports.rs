//! Reports as a user meets them: units, small defects of the command line, and the
//! numbers a designer decides on. Each test runs the binary on a problem file.

use assert_cmd::Command;

fn wearopt() -> Command {
    Command::cargo_bin("wearopt").unwrap()
}

fn stdout_of(args: &[&str]) -> String {
    let out = wearopt().args(args).output().unwrap();
    String::from_utf8(out.stdout).unwrap()
}

fn stderr_failing(args: &[&str], code: i32) -> String {
    let out = wearopt()
        .args(args)
        .assert()
        .code(code)
        .get_output()
        .clone();
    assert!(out.stdout.is_empty(), "stdout not empty: {:?}", out.stdout);
    String::from_utf8(out.stderr).unwrap()
}

/// The micro-gear hub: A_r = 5.702e-13 m² and wear rate 5.702e-17 m³/m
/// (tests/problem_files.rs pins the SI values); the text says so with the prefix on the
/// length, and the line the contract names stays.
#[test]
fn eval_text_units_are_si() {
    let t = stdout_of(&["eval", "problems/micro-gear.toml"]);
    assert!(t.contains("real area A_r = 0.5702 µm²"), "{t}");
    assert!(t.contains("wear rate V/L = 57.02 µm³/m"), "{t}");
    assert!(t.contains("asperity density N = 10.0 µm⁻²"), "{t}");
    assert!(
        !t.contains("fm²") && !t.contains("am³") && !t.contains(" um"),
        "{t}"
    );
    assert!(t.contains("Richardson"), "{t}");
}

#[test]
fn curve_refuses_negative_indices_in_its_own_words() {
    for (flag, value) in [("--theta", "-1"), ("--lambda", "-2")] {
        let mut args = vec![
            "curve", "--theta", "1", "--lambda", "1", "--from", "0", "--to", "1", "--points", "2",
        ];
        let i = args.iter().position(|a| *a == flag).unwrap();
        args[i + 1] = value;
        let err = stderr_failing(&args, 2);
        assert!(
            err.contains(&format!("{flag} {value}: must be > 0")),
            "{err}"
        );
        assert!(!err.contains("unexpected argument"), "{err}");
    }
}

#[test]
fn json_and_a_csv_trace_never_share_stdout() {
    let err = stderr_failing(
        &[
            "optimize",
            "problems/switch-study.toml",
            "--format",
            "json",
            "--trace",
            "-",
        ],
        2,
    );
    assert!(
        err.contains("--trace -") && err.contains("file name"),
        "{err}"
    );
}
