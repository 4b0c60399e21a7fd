//! What a newcomer tripped over (issue 56): a unit forgotten on the command line,
//! one quantity in two spellings, caveats lost in HTML and JSON, small
//! inconsistencies between commands.

use crate::common;
use crate::common::wearopt;

const MAP: &str = "problems/scans/self-affine.gsf";

fn stderr_of(args: &[&str], code: i32) -> String {
    String::from_utf8(common::stderr(wearopt().args(args), code)).unwrap()
}

/// `--modulus 150` was E* = 150 Pa: a run to the iteration limit, exit 0. A bare
/// number is read in SI only where plausible; otherwise refused with the guess.
#[test]
fn a_bare_number_out_of_its_plausible_range_is_refused_with_a_guess() {
    let e = stderr_of(
        &["contact", MAP, "--modulus", "150", "--pressure", "50MPa"],
        2,
    );
    assert!(e.contains("--modulus \"150\""), "{e}");
    assert!(e.contains("did you mean \"150 GPa\""), "{e}");
    assert!(e.contains("1 MPa – 2 TPa"), "{e}");
    // Every dimensional flag of every command.
    for (args, flag) in [
        (
            vec!["contact", MAP, "--modulus", "150GPa", "--pressure", "50"],
            "--pressure \"50\"",
        ),
        (
            vec![
                "contact",
                MAP,
                "--modulus",
                "150GPa",
                "--pressure",
                "50MPa",
                "--hardness",
                "12",
            ],
            "--hardness \"12\"",
        ),
        (
            vec![
                "contact",
                MAP,
                "--modulus",
                "150GPa",
                "--pressure",
                "50MPa",
                "--work-of-adhesion",
                "50",
                "--adhesion-range",
                "1nm",
            ],
            "--work-of-adhesion \"50\"",
        ),
        (
            vec![
                "contact",
                MAP,
                "--modulus",
                "150GPa",
                "--pressure",
                "50MPa",
                "--work-of-adhesion",
                "50mJ/m^2",
                "--adhesion-range",
                "1",
            ],
            "--adhesion-range \"1\"",
        ),
        (
            vec![
                "contact",
                MAP,
                "--modulus",
                "150GPa",
                "--pressure",
                "50MPa",
                "--pixel-size",
                "20",
            ],
            "--pixel-size \"20\"",
        ),
        (
            vec!["roughness", MAP, "--pixel-size", "20"],
            "--pixel-size \"20\"",
        ),
        (
            vec!["roughness", MAP, "--cutoff", "100"],
            "--cutoff \"100\"",
        ),
        (
            vec![
                "fit-adhesion",
                "problems/ando-friction.csv",
                "--radius",
                "0.3",
            ],
            "--radius \"0.3\"",
        ),
        (
            vec![
                "fit-adhesion",
                "problems/ando-friction.csv",
                "--radius",
                "0.3mm",
                "--modulus",
                "100",
            ],
            "--modulus \"100\"",
        ),
        (
            vec![
                "fit-adhesion",
                "problems/ando-friction.csv",
                "--radius",
                "0.3mm",
                "--quoted-gamma",
                "100",
            ],
            "--quoted-gamma \"100\"",
        ),
        (
            vec![
                "fit-adhesion",
                "problems/ando-friction.csv",
                "--radius",
                "0.3mm",
                "--quoted-bond-strength",
                "65",
            ],
            "--quoted-bond-strength \"65\"",
        ),
    ] {
        let e = stderr_of(&args, 2);
        assert!(e.contains(flag), "{args:?}: {e}");
        assert!(e.contains("did you mean"), "{args:?}: {e}");
    }
    // Plausible bare numbers are SI, as before.
    common::stdout(wearopt().args(["roughness", MAP, "--cutoff", "1e-7"]), 0);
}

/// A row that is not a solution is no usable result: exit 1, as the README says.
#[test]
fn a_contact_row_that_is_not_a_solution_exits_1() {
    // A unit written out is taken as meant: 150 Pa runs to the iteration limit.
    let out = common::stdout(
        wearopt().args(["contact", MAP, "--modulus", "150 Pa", "--pressure", "50MPa"]),
        1,
    );
    let text = String::from_utf8(out).unwrap();
    assert!(text.contains("not a solution"), "{text}");
}
