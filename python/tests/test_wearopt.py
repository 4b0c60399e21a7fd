"""The Python package against the command line: identical numbers on the shipped
problems, numpy broadcasting and dtypes, bad input, concurrent calls, sweeps
and the Dask and Slurm examples.

The command line is found as $WEAROPT_BIN, else target/debug/wearopt or
target/release/wearopt of the repository (scripts/test-all builds it first).
"""

from __future__ import annotations

import concurrent.futures
import csv
import io
import json
import re
import os
import shutil
import stat
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import wearopt

ROOT = Path(__file__).resolve().parents[2]
PROBLEMS = sorted((ROOT / "problems").glob("*.toml"))


def _binary() -> str:
    env = os.environ.get("WEAROPT_BIN")
    if env:
        return env
    for profile in ("debug", "release"):
        p = ROOT / "target" / profile / "wearopt"
        if p.exists():
            return str(p)
    found = shutil.which("wearopt")
    if found:
        return found
    pytest.skip("no wearopt binary: run `cargo build` first (scripts/test-all does)")


def cli(*args: str, ok=(0, 1)) -> subprocess.CompletedProcess:
    env = {k: v for k, v in os.environ.items() if not k.startswith("SLURM_")}
    r = subprocess.run([_binary(), *args], cwd=ROOT, capture_output=True, text=True, env=env)
    assert r.returncode in ok, (args, r.returncode, r.stderr)
    return r


def cli_json_beside(args, call):
    """The command's JSON and `call()`'s result, the command run beside the call
    rather than before it: the same answers (neither depends on the number of
    threads) in about half the wall time where each keeps one core busy."""
    env = {k: v for k, v in os.environ.items() if not k.startswith("SLURM_")}
    command = subprocess.Popen(
        [_binary(), *args, "--format", "json"],
        cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env,
    )
    try:
        got = call()
    finally:
        out, err = command.communicate()
    assert command.returncode in (0, 1), (args, command.returncode, err)
    return json.loads(out), got


@pytest.fixture(autouse=True)
def _in_root(monkeypatch):
    # Problem paths as the command line sees them (relative to the repository).
    monkeypatch.chdir(ROOT)


def rel(p: Path) -> str:
    return str(p.relative_to(ROOT))


def without_timing(v):
    """Drops wall-clock keys, the only values that differ between two runs."""
    if isinstance(v, dict):
        return {k: without_timing(x) for k, x in v.items() if "time" not in k or "limit" in k}
    if isinstance(v, list):
        return [without_timing(x) for x in v]
    return v


def test_shipped_problems_are_there():
    assert len(PROBLEMS) >= 5


@pytest.mark.parametrize("path", PROBLEMS, ids=lambda p: p.stem)
def test_evaluate_equals_cli_json(path):
    expected = json.loads(cli("eval", rel(path), "--format", "json").stdout)
    assert wearopt.evaluate(rel(path)) == expected
    assert wearopt.evaluate(Path(rel(path))) == expected  # a pathlib.Path works too


def has_section(path: Path, name: str) -> bool:
    return any(line.strip().startswith(f"[{name}]") for line in path.read_text().splitlines())


# A front file whose study is another file's, word for word (checked by
# test_a_front_file_shares_its_study): its `optimize` is that file's, so it is
# not run again here (a robust study costs seconds); its front is
# test_probability_front_equals_cli_json's.
SAME_STUDY_AS = {"micro-gear-robust-front": "micro-gear-robust"}

# Python's optimize on a robust study is compared on micro-gear-robust (seconds
# each); the adhesion front's own robust study, σ's box widened, adds nothing
# to that comparison, and its front is test_robust_adhesion_front_equals_cli_json's.
COVERED_ELSEWHERE = {"micro-gear-robust-adhesion-front"}

STUDIES = [
    p
    for p in PROBLEMS
    if has_section(p, "design")
    and has_section(p, "objective")
    and p.stem not in SAME_STUDY_AS
    and p.stem not in COVERED_ELSEWHERE
]


def test_a_front_file_shares_its_study():
    tomllib = pytest.importorskip("tomllib")  # Python ≥ 3.11

    for front, study in SAME_STUDY_AS.items():
        a = tomllib.loads((ROOT / "problems" / f"{front}.toml").read_text())
        b = tomllib.loads((ROOT / "problems" / f"{study}.toml").read_text())
        for d in (a, b):
            d.pop("name", None)
            d.pop("pareto", None)
        assert a == b, f"{front}.toml's study is no longer {study}.toml's"


@pytest.mark.parametrize("path", STUDIES, ids=lambda p: p.stem)
def test_optimize_equals_cli_json(path):
    expected, got = cli_json_beside(["optimize", rel(path)], lambda: wearopt.optimize(rel(path)))
    assert got.get("status") != "time_limit"
    assert without_timing(got) == without_timing(expected)


def test_optimize_outside_its_laws_regime_says_so_like_the_cli():
    # The hub's study under the paper's JKR law ends at φ0 = 0.0161, outside JKR's
    # regime (φ0 ≥ 3): `law_regime` names the law that holds and the re-run, and
    # Python's dict equals the command line's JSON (tests/all/law_regime.rs holds
    # the numbers).
    jkr = "tests/data/micro-gear-study-jkr.toml"
    expected = json.loads(cli("optimize", jkr, "--format", "json").stdout)
    got = wearopt.optimize(jkr)
    assert without_timing(got) == without_timing(expected)
    assert got["status"] == "optimal"
    assert got["law_regime"]["law"] == "jkr"
    assert got["law_regime"]["law_that_holds"] == "lennard_jones"
    assert got["law_regime"]["tabor_parameter"] < 0.3
    assert 'adhesion_model = "lennard_jones"' in got["law_regime"]["rerun"]
    # The shipped study holds its law at its optimum.
    assert "law_regime" not in wearopt.optimize("problems/micro-gear-study.toml")


def test_dir_is_the_public_api():
    # No helper import (json, numpy as np, os, typing's Any, Dict, …) leaks into
    # dir(wearopt): every name without a leading underscore is public.
    public = set(wearopt.__all__) | {"Problem"}
    leaked = [n for n in dir(wearopt) if not n.startswith("_") and n not in public]
    assert leaked == []
    assert set(wearopt.__all__) <= set(dir(wearopt))
    for name in ("Any", "Dict", "json", "np", "os", "numbers", "annotations"):
        assert not hasattr(wearopt, name), name


# A front against a probability (`[pareto] event`) is a robust optimum per level:
# its shipped example is too slow for this loop and has a test of its own below.
FRONTS = [p for p in PROBLEMS if has_section(p, "pareto") and "\nevent = " not in p.read_text()]


@pytest.mark.parametrize("path", FRONTS, ids=lambda p: p.stem)
def test_pareto_equals_cli_json(path):
    expected = json.loads(cli("pareto", rel(path), "--points", "4", "--format", "json").stdout)
    assert without_timing(wearopt.pareto(rel(path), points=4)) == without_timing(expected)


def test_probability_front_equals_cli_json(tmp_path):
    """`wearopt.pareto` on a front against P(event) returns the CLI's document:
    the shipped robust hub, its p95 and stiction left out for speed, two levels
    of P(plasticity_index > 1)."""
    text = (ROOT / "problems" / "micro-gear-robust.toml").read_text()
    text = text.replace('statistic = "p95"', "").replace("samples = 256", "")
    text = text.replace('event = "stiction"\nprobability_max = 1e-3\n', "")
    text = text.replace("[[constraint]]                  # at most 1 hub in 1000 stuck to its pin\n", "")
    text = text.replace(
        "[optimizer]",
        '[pareto]\nevent = { quantity = "plasticity_index", above = 1.0 }\n'
        "points = 2\nprobability_max = 1e-2\nprobability_min = 1e-3\n\n[optimizer]",
    )
    path = tmp_path / "front.toml"
    path.write_text(text)
    expected = json.loads(cli("pareto", str(path), "--format", "json").stdout)
    got = wearopt.pareto(str(path))
    assert got["front_measure"] == "probability"
    assert [p["level"] for p in got["points"]] == [1e-2, 1e-3]
    assert without_timing(got) == without_timing(expected)
    with pytest.raises(ValueError, match="adhesion"):
        wearopt.pareto(str(path), adhesion="pull_off_force")


def test_robust_adhesion_front_equals_cli_json(tmp_path):
    """`wearopt.pareto` on a robust study against an adhesion measure returns the
    CLI's document: the shipped robust hub, its p95 and stiction left out for
    speed, two levels of the pull-off force under P(plasticity_index > 1) <= 1e-3."""
    text = (ROOT / "problems" / "micro-gear-robust.toml").read_text()
    text = text.replace('statistic = "p95"', "").replace("samples = 256", "")
    text = text.replace('event = "stiction"\nprobability_max = 1e-3\n', "")
    text = text.replace("[[constraint]]                  # at most 1 hub in 1000 stuck to its pin\n", "")
    text = text.replace("[optimizer]", '[pareto]\nadhesion = "pull_off_force"\npoints = 2\n\n[optimizer]')
    # The DMT law's pull-off is cheap; the chance constraint (on ψ) does not depend on the law.
    text = text.replace('adhesion_model = "lennard_jones"', 'adhesion_model = "dmt"')
    path = tmp_path / "front.toml"
    path.write_text(text)
    expected = json.loads(cli("pareto", str(path), "--format", "json").stdout)
    got = wearopt.pareto(str(path))
    assert got["front_measure"] == "adhesion"
    assert got["adhesion_measure"] == "pull_off_force"
    assert len(got["points"]) == 2
    assert got["points"][0]["target"] == pytest.approx(got["robust_optimum"]["adhesion"], rel=1e-12)
    assert without_timing(got) == without_timing(expected)


def test_dict_problem_equals_its_file():
    tomllib = pytest.importorskip("tomllib")
    path = ROOT / "problems" / "micro-gear.toml"
    d = tomllib.loads(path.read_text())
    d.setdefault("name", "micro-gear")
    from_dict, from_file = wearopt.evaluate(d), wearopt.evaluate(rel(path))
    for key in ("status", "wear_rate", "real_area", "pull_off_force", "separation", "sensitivities"):
        assert from_dict[key] == from_file[key], key


def test_lennard_jones_above_its_solved_table_is_noted_and_continuous():
    """The hub under the Lennard-Jones law with Z0 shrunk (μ ∝ 1/Z0): above the
    solved table (μ = 22.4) the limit curves serve, noted, no stand-in; far above
    them (μ > 3.6e6) JKR stands in; the pull-off falls with μ toward JKR's
    without a jump (from 5.99 µN at μ = 0.374)."""
    tomllib = pytest.importorskip("tomllib")
    d = tomllib.loads((ROOT / "problems" / "micro-gear.toml").read_text())
    pulls = []
    for z0, kinds, stand_in in [("0.003 nm", {"lennard_jones_limit_curves"}, None),
                                ("0.001 nm", {"lennard_jones_limit_curves"}, None),
                                ("1e-8 nm", {"lennard_jones_stand_in"}, "jkr")]:
        d["interface"]["interatomic_distance"] = z0
        r = wearopt.evaluate(d)
        assert kinds <= {n["kind"] for n in r["note_details"]}, z0
        assert r.get("stand_in_model") == stand_in
        pulls.append(r["pull_off_force"])
    assert pulls[0] > pulls[1] > pulls[2] > 0


def test_lennard_jones_below_a_hundredth_is_solved_and_continuous():
    """A stiff pair with a low γ (μ ∝ γ^{2/3}): across μ = 0.01, where the stand-in
    took over until 2026-12-03 and the real area jumped by 24 %, the law's own
    curves serve and γ 2 % apart moves the real area by 0.08 %; below the table
    (μ < 9.91e-5) DMT stands in, noted."""
    def scene(gamma):
        return {
            "name": "stiff, low adhesion",
            "contact": {"load": "100 uN", "nominal_area": "1000 um^2",
                        "sliding_distance": "1 m", "wear_coefficient": 1e-6},
            "bodies": {"a": {"youngs_modulus": "200 GPa", "poisson_ratio": 0.0},
                       "b": {"youngs_modulus": "200 GPa", "poisson_ratio": 0.0}},
            "interface": {"hardness": "10 GPa", "work_of_adhesion": f"{gamma} J/m^2",
                          "interatomic_distance": "0.3 nm", "adhesion_model": "lennard_jones"},
            "roughness": {"sigma": "1 nm", "asperity_radius": "1 um",
                          "asperity_density": "10 um^-2"},
        }
    below, above = wearopt.evaluate(scene(0.000515)), wearopt.evaluate(scene(0.000525))
    assert below["tabor_parameter"] < 0.01 < above["tabor_parameter"]
    assert below.get("stand_in_model") is None and above.get("stand_in_model") is None
    assert abs(below["real_area"] / above["real_area"] - 1) < 2e-3
    far = wearopt.evaluate(scene(5e-7))
    assert far["tabor_parameter"] < 9.91e-5
    assert far["stand_in_model"] == "dmt"
    assert "lennard_jones_stand_in" in {n["kind"] for n in far["note_details"]}


def _cli_curve(theta: str, lam: str, lo: float, hi: float, n: int, extra=()):
    out = cli("curve", "--theta", theta, "--lambda", lam, "--from", repr(lo), "--to", repr(hi),
              "--points", str(n), *extra).stdout
    rows = list(csv.DictReader(io.StringIO(out)))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


@pytest.mark.parametrize("theta,lam", [("10", "0.125"), ("0.5", "0.01"), ("inf", "inf"), ("1000", "inf")])
def test_curve_equals_cli_columns(theta, lam):
    lo, hi, n = -2.0, 4.0, 61
    expected = _cli_curve(theta, lam, lo, hi, n)
    h = lo + (hi - lo) * np.arange(n) / (n - 1)  # the command line's spacing, bit for bit
    got = wearopt.curve(float(theta), float(lam), h)
    assert set(got) == set(expected)
    for k in expected:
        np.testing.assert_array_equal(got[k], expected[k], err_msg=k)


def test_curve_hardness_coefficient_equals_cli():
    expected = _cli_curve("inf", "inf", 0.0, 3.0, 4, ("--hardness-coefficient", "2.5"))
    got = wearopt.curve(np.inf, np.inf, np.arange(4.0), hardness_coefficient=2.5)
    for k in expected:
        np.testing.assert_array_equal(got[k], expected[k], err_msg=k)


def test_curve_broadcasts_like_numpy():
    theta = np.array([[1.0], [10.0], [100.0]])  # (3, 1)
    h = np.array([-1.0, 0.0, 1.0, 2.0])  # (4,)
    got = wearopt.curve(theta, 0.5, h)
    for k, v in got.items():
        assert v.shape == (3, 4), k
        assert v.dtype == np.float64
    for i in range(3):
        for j in range(4):
            one = wearopt.curve(theta[i, 0], 0.5, h[j])
            assert one["load"].shape == ()
            assert got["load"][i, j] == one["load"]
            assert got["area"][i, j] == one["area"]
    np.testing.assert_array_equal(got["h"], np.broadcast_to(h, (3, 4)))
    # Empty input, empty output of the broadcast shape.
    assert wearopt.curve(1.0, 1.0, np.empty((0, 2)))["load"].shape == (0, 2)
    # Non-contiguous and Fortran-ordered input.
    hf = np.asfortranarray(np.linspace(0, 1, 6).reshape(2, 3))
    np.testing.assert_array_equal(wearopt.curve(1.0, 1.0, hf)["load"],
                                  wearopt.curve(1.0, 1.0, np.ascontiguousarray(hf))["load"])
    with pytest.raises(ValueError):
        wearopt.curve(np.ones(2), 1.0, np.ones(3))


def test_curve_dtypes():
    ref = wearopt.curve(10.0, 1.0, np.array([0.0, 1.0, 2.0]))["load"]
    np.testing.assert_array_equal(wearopt.curve(10, 1, np.array([0, 1, 2]))["load"], ref)
    np.testing.assert_array_equal(
        wearopt.curve(np.float32(10), 1, np.array([0, 1, 2], dtype=np.int16))["load"], ref)
    np.testing.assert_array_equal(wearopt.curve(10.0, 1.0, [0, 1, 2])["load"], ref)
    for bad in (np.array([1 + 2j]), np.array(["1"]), np.array([object()]), np.array([True])):
        with pytest.raises(TypeError):
            wearopt.curve(10.0, 1.0, bad)


@pytest.mark.parametrize(
    "args,cli_args",
    [
        ((-1.0, 1.0, 0.0), ["--theta", "-1", "--lambda", "1"]),
        ((1.0, 0.0, 0.0), ["--theta", "1", "--lambda", "0"]),
        ((np.nan, 1.0, 0.0), ["--theta", "NaN", "--lambda", "1"]),
    ],
)
def test_curve_bad_input_has_the_cli_message(args, cli_args):
    r = cli("curve", *cli_args, "--from", "0", "--to", "1", "--points", "2", ok=(2,))
    message = r.stderr.strip().removeprefix("Error: ")
    with pytest.raises(ValueError) as e:
        wearopt.curve(*args)
    assert str(e.value) == keywords(message)
    assert "--" not in str(e.value)
    with pytest.raises(ValueError, match=r"\(element 1\)"):
        wearopt.curve(*(np.array([good, bad]) for good, bad in zip((1.0, 1.0, 0.0), args)))


def test_curve_dmt_equals_cli_columns():
    expected = _cli_curve("10", "1", -1.0, 3.0, 9, ("--adhesion-model", "dmt", "--attraction",
                                                   "dugdale", "--attraction-range", "0.1"))
    h = -1.0 + 4.0 * np.arange(9) / 8
    got = wearopt.curve(10.0, 1.0, h, adhesion_model="dmt", attraction="dugdale",
                        attraction_range=0.1)
    for k in expected:
        np.testing.assert_array_equal(got[k], expected[k], err_msg=k)


def test_curve_lennard_jones_equals_cli_columns():
    expected = _cli_curve("184.2", "1.309e5", -1.0, 4.0, 11,
                          ("--adhesion-model", "lennard_jones", "--attraction-range", "0.1"))
    h = -1.0 + 5.0 * np.arange(11) / 10
    got = wearopt.curve(184.2, 1.309e5, h, adhesion_model="lennard_jones", attraction_range=0.1)
    for k in expected:
        np.testing.assert_array_equal(got[k], expected[k], err_msg=k)
    # Attracted summits pull (docs/model.md §11): the non-contact load is < 0.
    assert (got["noncontact_load"] < 0).all()


def test_curve_other_laws_are_refused_plainly():
    with pytest.raises(ValueError,
                       match='^adhesion_model="magic": expected "jkr", "dmt" or "lennard_jones"$'):
        wearopt.curve(1.0, 1.0, 0.0, adhesion_model="magic")
    with pytest.raises(ValueError, match='^adhesion_model="lennard_jones" needs attraction_range: '):
        wearopt.curve(1.0, 1.0, 0.0, adhesion_model="lennard_jones")
    with pytest.raises(ValueError, match="^attraction applies to adhesion_model=\"dmt\" only: "):
        wearopt.curve(1.0, 1.0, 0.0, adhesion_model="lennard_jones", attraction="dugdale",
                      attraction_range=0.1)
    with pytest.raises(ValueError, match='^adhesion_model="dmt" needs attraction_range: '):
        wearopt.curve(1.0, 1.0, 0.0, adhesion_model="dmt")
    with pytest.raises(ValueError, match='^attraction="lj": expected "van_der_waals" or "dugdale"$'):
        wearopt.curve(1.0, 1.0, 0.0, adhesion_model="dmt", attraction="lj", attraction_range=0.1)
    with pytest.raises(ValueError, match="^attraction and attraction_range apply to "):
        wearopt.curve(1.0, 1.0, 0.0, attraction_range=0.1)


def keywords(message):
    """A command-line message in Python's words: `--pixel-size "x"` is `pixel_size="x"`."""
    return re.sub(r'--([a-z-]+) ("[^"]*"|\S+)', lambda m: f"{m[1].replace('-', '_')}={m[2]}", message)


BAD = sorted((ROOT / "tests" / "bad_input").glob("*.toml"))


@pytest.mark.parametrize("path", BAD, ids=lambda p: p.stem)
def test_bad_problem_raises_the_cli_message(path):
    r = cli("eval", rel(path), ok=(2,))
    message = r.stderr.strip().removeprefix("Error: ")
    with pytest.raises(ValueError) as e:
        wearopt.evaluate(rel(path))
    assert str(e.value) == message


def test_bad_arguments():
    with pytest.raises(TypeError):
        wearopt.evaluate(42)
    with pytest.raises(ValueError, match="no such|cannot read"):
        wearopt.evaluate("problems/does-not-exist.toml")
    with pytest.raises(ValueError, match="^<problem dict>: "):
        wearopt.evaluate({"contact": {"load": "10 uQ"}})
    with pytest.raises(ValueError):
        wearopt.evaluate({"contact": {"load": None}})
    with pytest.raises(ValueError, match="^points=1: must lie in 2..=200$"):
        wearopt.pareto("problems/micro-gear.toml", points=1)
    with pytest.raises(ValueError, match="no \\[pareto\\] section"):
        wearopt.pareto("problems/gold-switch.toml")
    with pytest.raises(ValueError, match="no \\[design\\] variables"):
        wearopt.optimize("problems/gold-switch.toml")
    with pytest.raises(ValueError, match="must be m\\^5"):
        wearopt.sweep("problems/micro-gear-study.toml", 10, method="grid")
    with pytest.raises(ValueError, match="^shard=3/3: "):
        wearopt.sweep("problems/micro-gear-study.toml", 10, shard=(3, 3))
    with pytest.raises(TypeError):
        wearopt.sweep("problems/micro-gear-study.toml", 10.0)


def test_outcomes_are_statuses_not_exceptions():
    r = wearopt.optimize("problems/infeasible-study.toml")
    assert r["status"] == "infeasible"
    d = {"contact": {"load": "-1 N", "nominal_area": "100 um^2", "sliding_distance": "1 m",
                     "wear_coefficient": 1e-4},
         "bodies": {"a": {"material": "polysilicon"}, "b": {"material": "polysilicon"}},
         "interface": {"work_of_adhesion": "0.1 J/m^2"},
         "roughness": {"sigma": "5 nm", "asperity_radius": "1 um", "asperity_density": "10 um^-2"}}
    assert wearopt.evaluate(d)["status"] == "separated"


def test_concurrent_calls_from_threads_agree_with_serial_ones():
    h = np.linspace(-2, 4, 20001)
    jobs = [
        lambda: wearopt.evaluate("problems/micro-gear.toml"),
        lambda: wearopt.evaluate("problems/gold-switch.toml"),
        lambda: wearopt.curve(10.0, 0.125, h)["load"].tolist(),
        lambda: wearopt.curve(0.5, 0.01, h)["area"].tolist(),
        lambda: wearopt.sweep("problems/micro-gear-study.toml", 300, method="lhs", seed=4),
        lambda: without_timing(wearopt.optimize("problems/micro-gear-study.toml")),
    ]
    serial = [job() for job in jobs]
    with concurrent.futures.ThreadPoolExecutor(max_workers=8) as pool:
        futures = [(i, pool.submit(jobs[i])) for _ in range(3) for i in range(len(jobs))]
        for i, f in futures:
            assert f.result() == serial[i], i


def test_sweep_equals_cli_and_merges_byte_for_byte():
    study = "problems/micro-gear-study.toml"
    for fmt in ("csv", "json"):
        expected = cli("sweep", study, "--samples", "40", "--method", "lhs", "--seed", "9",
                       "--format", fmt).stdout
        assert wearopt.sweep(study, 40, method="lhs", seed=9, format=fmt) == expected
        parts = [wearopt.sweep(study, 40, "lhs", 9, (i, 6), fmt) for i in range(6)]
        assert wearopt.merge(reversed(parts), samples=40) == expected
    with pytest.raises(ValueError, match="missing"):
        wearopt.merge(parts[:3] + parts[4:])


def _same(a, b) -> bool:
    """Deep equality of two documents (numpy arrays compared element-wise)."""
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(_same(a[k], b[k]) for k in a)
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return np.array_equal(np.asarray(a), np.asarray(b))
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b))
    return a == b


def test_uncertainty_shards_merge_into_the_unsharded_run(tmp_path):
    scatter = "problems/micro-gear-scatter.toml"
    for method in ("sobol", "sampling", "morris"):
        expected = cli("uncertainty", scatter, "--method", method, "--samples", "64",
                       "--format", "json").stdout
        whole = wearopt.uncertainty(scatter, method, samples=64)
        parts = [wearopt.uncertainty(scatter, method, samples=64, shard=(i, 3)) for i in range(3)]
        assert [p["wearopt"] for p in parts] == ["uncertainty part"] * 3
        assert parts[0]["fingerprint"] == whole["fingerprint"]
        # The dicts, in any order; and the command line's parts, as texts.
        assert _same(wearopt.merge(reversed(parts), samples=64), whole)
        texts = [cli("uncertainty", scatter, "--method", method, "--samples", "64",
                     "--shard", f"{i}/3").stdout for i in range(3)]
        assert _same(wearopt.merge([texts[2], texts[0], texts[1]]), whole)
        # Python's parts, written as JSON, merge on the command line.
        paths = []
        for i, p in enumerate(parts):
            path = tmp_path / f"{method}-{i}.json"
            path.write_text(json.dumps(p))
            paths.append(str(path))
        assert cli("merge", paths[1], paths[2], paths[0], "--format", "json").stdout == expected
    with pytest.raises(ValueError, match="missing"):
        wearopt.merge(parts[:2])
    foreign = wearopt.uncertainty(scatter, "morris", samples=64, seed=5, shard=(1, 3))
    with pytest.raises(ValueError, match=foreign["fingerprint"]):
        wearopt.merge([parts[0], foreign, parts[2]])
    with pytest.raises(ValueError, match="cannot be sharded"):
        wearopt.uncertainty(scatter, "reliability", shard=(0, 2))
    with pytest.raises(TypeError, match="shard"):
        wearopt.uncertainty(scatter, "sampling", shard=3)


def test_uncertainty_shards_of_a_dict_problem():
    tomllib = pytest.importorskip("tomllib")
    problem = tomllib.loads((ROOT / "problems/micro-gear-scatter.toml").read_text())
    whole = wearopt.uncertainty(problem, "sampling", samples=64)
    parts = [wearopt.uncertainty(problem, "sampling", samples=64, shard=(i, 2)) for i in range(2)]
    assert _same(wearopt.merge(parts), whole)


def test_dask_example_on_a_local_cluster_gives_the_serial_result():
    distributed = pytest.importorskip("dask.distributed")
    sys.path.insert(0, str(ROOT / "examples"))
    try:
        import dask_sweep
    finally:
        sys.path.pop(0)
    study = "problems/micro-gear-study.toml"
    serial = wearopt.sweep(study, 500)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        assert len(client.scheduler_info()["workers"]) == 2
        assert dask_sweep.dask_sweep(client, str(ROOT / study), 500, shards=7) == serial


def test_slurm_example_runs_as_a_job_array(tmp_path):
    """examples/slurm/sweep.sbatch run task by task with Slurm's variables, with a
    stand-in `sbatch` that runs the merge step it is handed; a failed task rerun
    alone (`--array=1`: Slurm's count 1) computes its own shard's rows."""
    fake = tmp_path / "bin"
    fake.mkdir()
    sbatch = fake / "sbatch"
    sbatch.write_text('#!/bin/bash\nfor a in "$@"; do last="$a"; done\n'
                      'echo "$last" > "$FAKE_SBATCH_CMD"\n')
    sbatch.chmod(sbatch.stat().st_mode | stat.S_IEXEC)
    out = tmp_path / "parts"
    env = {k: v for k, v in os.environ.items() if not k.startswith("SLURM_")}
    env.update(PATH=f"{fake}:{env['PATH']}", PROBLEM=str(ROOT / "problems/micro-gear-study.toml"),
               SAMPLES="50", SHARDS="4", OUT=str(out), WEAROPT=_binary(),
               FAKE_SBATCH_CMD=str(tmp_path / "merge.sh"))
    for task in (2, 0, 3, 1, 2):  # any order; task 2 twice (a resubmission skips)
        env.update(SLURM_ARRAY_TASK_ID=str(task), SLURM_ARRAY_TASK_COUNT="4",
                   SLURM_ARRAY_TASK_MIN="0", SLURM_ARRAY_TASK_MAX="3",
                   SLURM_ARRAY_JOB_ID="1234")
        r = subprocess.run(["bash", str(ROOT / "examples/slurm/sweep.sbatch")], cwd=tmp_path,
                           env=env, capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
    # Task 1 failed (its part lost); rerun as `sbatch --array=1`.
    good = (out / "part-1.csv").read_text()
    (out / "part-1.csv").unlink()
    env.update(SLURM_ARRAY_TASK_ID="1", SLURM_ARRAY_TASK_COUNT="1",
               SLURM_ARRAY_TASK_MIN="1", SLURM_ARRAY_TASK_MAX="1")
    r = subprocess.run(["bash", str(ROOT / "examples/slurm/sweep.sbatch")], cwd=tmp_path,
                       env=env, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert (out / "part-1.csv").read_text() == good
    merged = subprocess.run(["bash", "-c", (tmp_path / "merge.sh").read_text()], cwd=tmp_path,
                            env=env, capture_output=True, text=True)
    assert merged.returncode == 0, merged.stderr
    expected = cli("sweep", "problems/micro-gear-study.toml", "--samples", "50").stdout
    assert (tmp_path / "sweep.csv").read_text() == expected


SCANS = sorted((ROOT / "problems" / "scans").glob("*.*"))
SCAN_OPTIONS = {".npy": ["--pixel-size", "20 nm", "--height-unit", "nm"]}


@pytest.mark.parametrize("path", SCANS, ids=lambda p: p.name)
def test_roughness_equals_cli_json(path):
    extra = SCAN_OPTIONS.get(path.suffix, [])
    for more in ([], ["--cutoff", "100 nm", "--level", "quadratic"]):
        expected = json.loads(cli("roughness", rel(path), *extra, *more, "--format", "json").stdout)
        kwargs = {k.lstrip("-").replace("-", "_"): v for k, v in zip((extra + more)[::2], (extra + more)[1::2])}
        assert wearopt.roughness(rel(path), **kwargs) == expected


def test_roughness_bad_input_has_the_cli_message():
    scan = "problems/scans/self-affine.gsf"
    r = cli("roughness", scan, "--cutoff", "-5 nm", ok=(2,))
    with pytest.raises(ValueError) as e:
        wearopt.roughness(scan, cutoff="-5 nm")
    assert str(e.value) == keywords(r.stderr.strip().removeprefix("Error: "))
    r = cli("roughness", "problems/scans/self-affine-nm.npy", ok=(2,))
    with pytest.raises(ValueError) as e:
        wearopt.roughness("problems/scans/self-affine-nm.npy")
    # The same message, but the way to supply the pixel size is Python's.
    cli_message = r.stderr.strip().removeprefix("Error: ")
    assert str(e.value).split(";")[0] == cli_message.split(";")[0]
    assert "the keyword argument pixel_size=" in str(e.value) and "--" not in str(e.value)
    with pytest.raises(ValueError, match="level"):
        wearopt.roughness(scan, level="cubic")


def test_new_commands_equal_the_cli_json(tmp_path):
    # fit-adhesion, figures and the roughness of an array: the command line's JSON.
    expected = json.loads(cli("fit-adhesion", "problems/ando-friction.csv", "--radius", "0.3mm",
                              "--materials", "steel,silicon", "--format", "json").stdout)
    got = wearopt.fit_adhesion("problems/ando-friction.csv", "0.3mm",
                               materials=["steel", "silicon"])
    # The same document, its notes naming keyword arguments where the command
    # line's name flags ("give mu= to set it or fit_mu=True to fit it").
    notes, cli_notes = got.pop("notes"), expected.pop("notes")
    assert got == expected
    assert notes == [n.replace("--mu", "mu=").replace("--fit-mu", "fit_mu=True")
                     for n in cli_notes]
    assert any("fit_mu=True" in n for n in notes) and not any("--" in n for n in notes)
    expected = json.loads(cli("fit-adhesion", "problems/ando-friction.csv", "--radius", "1 mm",
                              "--fit-mu", "--modulus", "100 GPa", "--format", "json").stdout)
    assert wearopt.fit_adhesion("problems/ando-friction.csv", "1 mm", fit_mu=True,
                                modulus="100 GPa") == expected
    out = tmp_path / "figs"
    expected = json.loads(cli("figures", "--out", str(out), "--points", "7", "--format", "json").stdout)
    cli_files = {p: Path(p).read_text() for p in expected["files"]}
    got = wearopt.figures(out=out, points=7)
    assert got == expected
    assert {p: Path(p).read_text() for p in got["files"]} == cli_files
    z = np.load(ROOT / "problems" / "scans" / "self-affine-nm.npy")
    by_file = wearopt.roughness(rel(ROOT / "problems" / "scans" / "self-affine-nm.npy"),
                                pixel_size="20 nm", height_unit="nm")
    by_array = wearopt.roughness(z, pixel_size="20 nm", height_unit="nm")
    for k in ("summit_sigma", "summit_radius", "summit_density", "rms_height", "m0", "m2", "m4"):
        if k in by_file:
            assert by_array[k] == by_file[k], k


def test_fit_adhesion_quoted_values_name_no_flag():
    c = wearopt.fit_adhesion("problems/ando-friction.csv", "0.3 mm", quoted_gamma="2 mJ/m^2")
    assert c["comparison"]["source"] == "the quoted values"


def test_new_commands_word_errors_as_keywords():
    with pytest.raises(ValueError, match="^radius="):
        wearopt.fit_adhesion("problems/ando-friction.csv", "-1 mm")
    with pytest.raises(ValueError, match="^materials=unobtainium: not in the catalogue"):
        wearopt.fit_adhesion("problems/ando-friction.csv", "1 mm", materials=["unobtainium"])
    with pytest.raises(ValueError, match=r"^mu=0.1, fit_mu=True: give mu \(held fixed\) or fit_mu=True"):
        wearopt.fit_adhesion("problems/ando-friction.csv", "1 mm", mu=0.1, fit_mu=True)
    with pytest.raises(ValueError, match="^points=2: must lie in 3..="):
        wearopt.figures(points=2)
    with pytest.raises(ValueError, match="^pixel_size=None"):
        wearopt.roughness(np.zeros((8, 8)))


def test_accuracy_equals_the_cli_json_but_for_times():
    # Each times its settings on one thread (the times are not compared).
    expected, got = cli_json_beside(
        ["accuracy", "problems/micro-gear.toml"], lambda: wearopt.accuracy("problems/micro-gear.toml")
    )
    timeless = lambda rows: [{k: v for k, v in r.items() if k != "time_per_eval_ns"} for r in rows]
    assert timeless(got["rows"]) == timeless(expected["rows"])
    assert got.keys() == expected.keys()


def test_humidity_equals_cli_json_and_words_errors_as_keywords():
    path = "problems/micro-gear-humid.toml"
    expected = json.loads(
        cli("humidity", path, "--from", "0", "--to", "0.9", "--points", "4", "--format", "json").stdout
    )
    got = wearopt.humidity(path, 0.0, 0.9, 4)
    assert got == expected
    assert [round(p["relative_humidity"], 2) for p in got["points"]] == [0.0, 0.3, 0.6, 0.9]
    assert got["threshold_humidity"] is not None and 0.6 < got["threshold_humidity"] < 0.9
    with pytest.raises(ValueError, match="^from=0.5 is above to=0.2"):
        wearopt.humidity(path, 0.5, 0.2, 4)
    with pytest.raises(ValueError, match=r"^points=1: must lie in 2..="):
        wearopt.humidity(path, 0.0, 0.5, 1)
    with pytest.raises(ValueError, match=r"^to=1: a relative humidity must lie in \[0, 1\)"):
        wearopt.humidity(path, 0.0, 1.0, 4)


def test_humidity_takes_a_fraction_or_a_percentage():
    path = "problems/micro-gear-humid.toml"
    assert wearopt.humidity(path, "0 %", "90 %", 4) == wearopt.humidity(path, 0.0, 0.9, 4)


def test_uncertainty_equals_cli_json():
    path = "problems/micro-gear-scatter.toml"
    for method in ("sampling", "sobol", "reliability"):
        expected = json.loads(
            cli("uncertainty", path, "--method", method, "--samples", "128", "--format", "json").stdout
        )
        got = wearopt.uncertainty(path, method, samples=128)
        assert json.dumps(got, default=lambda a: a.tolist(), sort_keys=True) == json.dumps(
            expected, sort_keys=True
        ), method
    s = wearopt.uncertainty(path, "sampling", samples=128)
    assert isinstance(s["outputs"][0]["p95_interval"], np.ndarray)
    with pytest.raises(ValueError, match="method"):
        wearopt.uncertainty(path, "bogus")


def test_asperity_equals_cli_json_and_words_errors_as_keywords():
    # μ = 1 on the trace's mesh: S-shaped (jumps at δ̂ = −0.92 and −0.98), at a
    # quarter of the cost of μ = 3 (the converged rows are compared in
    # tests/all/asperity.rs).
    expected, got = cli_json_beside(
        ["asperity", "--tabor", "1", "--from", "-1", "--to", "0", "--points", "3", "--fast"],
        lambda: wearopt.asperity(1.0, -1.0, 0.0, 3, fast=True),
    )
    assert got == expected
    assert got["jump_in"]["interference"] > got["jump_out"]["interference"]
    assert [p["branch"] for p in got["points"]][0] == "approach"
    jkr = wearopt.asperity(3.0, -1.0, 0.0, 3, adhesion_model="jkr")
    assert jkr["pull_off"]["load"] == -1.5
    with pytest.raises(ValueError, match=r"^tabor=0: the Tabor parameter"):
        wearopt.asperity(0.0, -1.0, 0.0, 3)
    with pytest.raises(ValueError, match=r"^adhesion_model=maugis: the asperity laws are lennard_jones, jkr, dmt"):
        wearopt.asperity(1.0, -1.0, 0.0, 3, adhesion_model="maugis")
    with pytest.raises(ValueError, match=r"^points=1: must lie in 2..="):
        wearopt.asperity(1.0, -1.0, 0.0, 1)


# μ = 0.21: a sphere whose trace is short (the comparison, not the physics, is tested).
SPHERE = dict(radius="1 um", work_of_adhesion="0.05 J/m^2", modulus="100 GPa", interatomic_distance="0.3 nm")


def test_asperity_sphere_in_si_and_fast_equal_the_cli():
    """The SI keywords and `fast` are the flags: the same JSON, μ from the
    sphere, newtons and metres beside the Maugis units."""
    flags = ["--radius", "1 um", "--work-of-adhesion", "0.05 J/m^2", "--modulus", "100 GPa",
             "--interatomic-distance", "0.3 nm"]
    expected, got = cli_json_beside(
        ["asperity", *flags, "--from", "-1", "--to", "0", "--points", "3", "--fast"],
        lambda: wearopt.asperity(None, -1.0, 0.0, 3, fast=True, **SPHERE),
    )
    assert got == expected
    assert got["rows_accuracy"] == "fast"
    mu = (1e-6 * 0.05**2 / (1e22 * 27e-30)) ** (1 / 3)
    assert abs(got["tabor"] - mu) < 1e-12 * mu
    for p in got["points"]:
        assert abs(p["load_n"] - p["load"] * 3.141592653589793 * 0.05e-6) <= 1e-12 * abs(p["load_n"])
    # A number is read in SI where plausible; a forgotten unit is refused.
    same = wearopt.asperity(None, -1.0, 0.0, 3, fast=True, **dict(SPHERE, radius=1e-6))
    assert same == got
    with pytest.raises(ValueError, match=r"^radius=\"1.0\": .*did you mean"):
        wearopt.asperity(None, -1.0, 0.0, 3, **dict(SPHERE, radius=1))
    with pytest.raises(ValueError, match=r"^tabor=1, radius=.*not both"):
        wearopt.asperity(1.0, -1.0, 0.0, 3, **SPHERE)
    with pytest.raises(TypeError, match="fast must be a bool"):
        wearopt.asperity(1.0, -1.0, 0.0, 3, fast="yes")
    converged = wearopt.asperity(None, -1.0, 0.0, 3, adhesion_model="jkr", **SPHERE)
    assert converged["rows_accuracy"] is None  # a closed form has no mesh


# ---- wearopt.contact: the FFT boundary-element solver on a scan ----------------


def test_contact_equals_cli_json():
    scan = "problems/scans/self-affine.gsf"
    expected = json.loads(
        cli("contact", scan, "--modulus", "150 GPa", "--pressure", "50 MPa,200 MPa",
            "--hardness", "12 GPa", "--format", "json").stdout
    )
    got = wearopt.contact(scan, modulus="150 GPa", pressures=["50 MPa", "200 MPa"], hardness="12 GPa")
    assert got == expected


def test_contact_bad_input_has_the_cli_message():
    scan = "problems/scans/self-affine.gsf"
    r = cli("contact", scan, "--modulus", "150 GPa", "--pressure", "-1 MPa", ok=(2,))
    with pytest.raises(ValueError) as e:
        wearopt.contact(scan, modulus="150 GPa", pressures="-1 MPa")
    assert str(e.value) == keywords(r.stderr.strip().removeprefix("Error: ")).replace(
        "pressure=", "pressures="
    )
    z = np.zeros((8, 8))
    z[2, 3] = np.nan
    with pytest.raises(ValueError, match="1 of 64 points are missing"):
        wearopt.contact(z, pixel_size="10 nm", modulus="100 GPa", pressures=1e6)


def _self_affine(n, seed, hurst=0.8):
    """A self-affine map from Tamaas's own generator (rms 1 nm)."""
    import tamaas as tm

    sg = tm.SurfaceGeneratorFilter2D([n, n])
    sg.random_seed = seed
    sg.spectrum = tm.Isopowerlaw2D()
    sg.spectrum.q0 = 4
    sg.spectrum.q1 = 4
    sg.spectrum.q2 = n // 4
    sg.spectrum.hurst = hurst
    h = np.array(sg.buildSurface())
    return h / np.sqrt(np.mean(h**2)) * 1e-9


@pytest.mark.parametrize("seed,fraction", [(3, 0.03), (11, 0.1)])
def test_contact_matches_tamaas(seed, fraction):
    """Tamaas 2.9's Polonsky–Keer solver (PolonskyKeerRey, pressure primal and
    constraint) on the same periodic map, E* and mean pressure: the same
    contacting pixels (within two), the mean gap within 1e-6 and the pressures
    within 1e-6 of their largest."""
    import tamaas as tm

    n, length, e_star = 128, 1e-6, 100e9
    h = _self_affine(n, seed)
    model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [length, length], [n, n])
    model.E, model.nu = e_star, 0.0
    slope = np.sqrt(np.mean(np.gradient(h, length / n, axis=0) ** 2 + np.gradient(h, length / n, axis=1) ** 2))
    pressure = fraction * e_star * slope / 2  # ~ κ⁻¹ E* h' A/A0 with κ = 2
    tm.PolonskyKeerRey(model, h, 1e-12).solve(pressure)
    traction = np.array(model.traction)
    gap = np.array(model.displacement) - h
    gap -= gap[traction > 0].mean()
    c = wearopt.contact(h, pixel_size=length / n, modulus=e_star, pressures=pressure,
                        level="none", tolerance=1e-12, fields=True)
    point = c["points"][0]
    assert point["status"] == "converged"
    assert abs(int((point["pressure_field"] > 0).sum()) - int((traction > 0).sum())) <= 2
    mean_gap = np.maximum(gap, 0).mean()
    assert abs(point["mean_gap"] / mean_gap - 1) < 1e-6
    assert np.abs(point["pressure_field"] - traction).max() < 1e-6 * traction.max()
    assert abs(point["pressure_field"].mean() / pressure - 1) < 1e-12


def test_adhesive_contact_matches_tamaas():
    """Tamaas 2.9's Rey–Anciaux–Molinari solver (PolonskyKeerRey, gap primal and
    constraint, ExponentialAdhesionFunctional) at a mean gap; wearopt at the
    mean pressure Tamaas found, with the same law, along its approach: the same
    state — the mean gap within 1e-9, the same contacting pixels (within two),
    the net tractions within 1e-9 of the largest (measured: 5e-12)."""
    import tamaas as tm

    n, length, e_star = 128, 1e-6, 100e9
    gamma, rho = 0.05, 0.5e-9  # process zone 50 pixels
    h = _self_affine(n, 3)
    model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [length, length], [n, n])
    model.E, model.nu = e_star, 0.0
    solver = tm.PolonskyKeerRey(model, h, 1e-12, tm.PolonskyKeerRey.gap, tm.PolonskyKeerRey.gap)
    law = tm.ExponentialAdhesionFunctional(h)
    law.parameters = {"rho": rho, "surface_energy": gamma}
    solver.addFunctionalTerm(law)
    solver.solve(1.5e-9)
    traction = np.array(model.traction)
    gap = np.array(model.displacement) - h
    c = wearopt.contact(h, pixel_size=length / n, modulus=e_star, pressures=traction.mean(),
                        level="none", tolerance=1e-12, fields=True,
                        work_of_adhesion=gamma, adhesion_range=rho)
    point = c["points"][0]
    a = point["adhesive"]
    assert a["status"] == "converged"
    assert abs(a["mean_gap"] / 1.5e-9 - 1) < 1e-9
    touching = point["adhesive_gap_field"] <= 0
    assert abs(int(touching.sum()) - int((gap <= 1e-20).sum())) <= 2
    assert np.abs(point["adhesive_pressure_field"] - traction).max() < 1e-9 * np.abs(traction).max()
    # Adhesion pulls the surfaces into more contact than the same load without it.
    assert a["real_area_fraction"] > point["real_area_fraction"]
    assert c["adhesion"]["pull_off_pressure"] < 0


def test_adhesion_needs_both_parameters_and_a_resolved_range():
    z = _self_affine(32, 5)
    with pytest.raises(ValueError, match="adhesion_range"):
        wearopt.contact(z, pixel_size="20 nm", modulus="100 GPa", pressures=1e7,
                        work_of_adhesion="50 mJ/m^2")
    with pytest.raises(ValueError, match="coarse-grain"):
        wearopt.contact(z, pixel_size="20 nm", modulus="100 GPa", pressures=1e7,
                        work_of_adhesion="50 mJ/m^2", adhesion_range="0.01 nm")
    c = wearopt.contact(z, pixel_size="20 nm", modulus="100 GPa", pressures=1e7,
                        work_of_adhesion="50 mJ/m^2", adhesion_range="0.01 nm",
                        coarse_grain=True)
    assert c["adhesion"]["coarse_grained"] > 1


def test_pareto_without_a_section_takes_the_command_line():
    """A study with no [pareto] section: the front from the keyword arguments,
    the defaults for the rest; without any, the error says how."""
    front = wearopt.pareto("problems/micro-gear-study.toml", points=3,
                           adhesion="elastic_adhesion_index", direction="high")
    assert front["adhesion_measure"] == "elastic_adhesion_index"
    assert front["direction"] == "high"
    assert len(front["front"]) == 3
    with pytest.raises(ValueError, match="--adhesion, --points, --direction"):
        wearopt.pareto("problems/micro-gear-study.toml")
    with pytest.raises(ValueError, match="elastic_adhesion_index"):
        wearopt.pareto("problems/micro-gear-study.toml", adhesion="theta")


def test_decimal_comma_scans(tmp_path):
    """An ASCII scan written with decimal commas is refused unless said, and then
    reads as the map written with points — from roughness(), contact() and a
    problem file's [roughness] decimal_comma = true."""
    z = np.load("problems/scans/self-affine-nm.npy")[:64, :64]
    points = tmp_path / "points.txt"
    commas = tmp_path / "commas.txt"
    np.savetxt(points, z, fmt="%.6f")
    commas.write_text(points.read_text().replace(".", ","))
    with pytest.raises(ValueError, match="--decimal-comma"):
        wearopt.roughness(str(commas), pixel_size="20 nm", height_unit="nm")
    a = wearopt.roughness(str(commas), pixel_size="20 nm", height_unit="nm", decimal_comma=True)
    b = wearopt.roughness(str(points), pixel_size="20 nm", height_unit="nm")
    assert a["summit_sigma"] == b["summit_sigma"]
    c = wearopt.contact(str(commas), pixel_size="20 nm", height_unit="nm", modulus="150 GPa",
                        pressures="100 MPa", decimal_comma=True)
    assert c["points"][0]["status"] == "converged"
    scene = open("problems/micro-gear-scan.toml").read()
    import re
    scene = re.sub(r'topography = "[^"]*"', f'topography = "{commas}"\ndecimal_comma = true\n'
                   'pixel_size = "20 nm"\nheight_unit = "nm"', scene)
    problem = tmp_path / "scan.toml"
    problem.write_text(scene)
    r = wearopt.evaluate(str(problem))
    assert r["status"] == "ok"


@pytest.mark.skipif(shutil.which("chromium") is None or shutil.which("pdftotext") is None,
                    reason="needs chromium and pdftotext (apt install chromium poppler-utils)")
def test_the_widest_pages_print_whole_on_a4(tmp_path):
    """The pages with the widest tables (a front with three design variables and
    two constraints; a materials ranking) printed to A4 by headless Chromium keep
    every table cell in the PDF's text layer (scripts/print_check.py; before the
    print style, 26 and 15 cells of these two pages were cut off)."""
    cli("pareto", "problems/latch-pareto.toml", "--points", "6", "--format", "html",
        "--out", str(tmp_path / "pareto.html"))
    (tmp_path / "materials.html").write_text(
        cli("optimize", "problems/materials-study.toml", "--format", "html").stdout)
    run = subprocess.run([sys.executable, "scripts/print_check.py", str(tmp_path)],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stdout + run.stderr
    assert "2 pages printed to A4, 0 with cells missing" in run.stdout


def test_pareto_over_a_humidity_range_names_its_humidity():
    """A front over a humidity range is measured at one humidity (the
    objective's), which the result names, as the CLI's JSON does."""
    path = "problems/micro-gear-coating-study.toml"
    front = wearopt.pareto(path, points=3)
    assert front["adhesion_humidity"] == 0.9
    expected = json.loads(cli("pareto", path, "--points", "3", "--format", "json").stdout)
    assert without_timing(front) == without_timing(expected)


def test_stress_assisted_wear_from_a_dict_as_from_the_file():
    """``[wear]`` reaches the stress-assisted law (docs/model.md §12) from a dict as from
    problems/silicon-sidewall-wear.toml: the same wear rate and law outputs."""
    from_file = wearopt.evaluate("problems/silicon-sidewall-wear.toml")
    from_dict = wearopt.evaluate({
        "contact": {"load": "800 uN", "nominal_area": "1000 um^2",
                    "sliding_distance": "1 m", "temperature": "300 K"},
        "bodies": {"a": {"material": "single-crystal silicon"},
                   "b": {"material": "single-crystal silicon"}},
        "interface": {"work_of_adhesion": "0.02 J/m^2", "interatomic_distance": "0.3 nm",
                      "adhesion_model": "dmt"},
        "roughness": {"sigma": "3 nm", "asperity_radius": "1 um",
                      "asperity_density": "10 um^-2"},
        "wear": {"law": "stress_assisted", "activation_energy": "0.91 eV",
                 "activation_volume": "0.0067 nm^3", "attempt_frequency": "1e13 Hz",
                 "stress": "normal", "sliding_speed": "38 mm/s"},
    })
    assert from_file["wear_law"] == from_dict["wear_law"] == "stress_assisted"
    for key in ("wear_rate", "effective_wear_coefficient", "log10_effective_wear_coefficient",
                "mean_contact_stress", "saturated_fraction", "apparent_activation_energy"):
        assert from_dict[key] == from_file[key], key


def test_fit_wear_equals_the_cli_and_takes_rows():
    path = "problems/wear-rates.csv"
    expected = json.loads(cli("fit-wear", path, "--format", "json").stdout)
    assert wearopt.fit_wear(path) == expected
    # The same data as columns (a dict, as a DataFrame would give them): the same
    # numbers, from "<rows>" (line numbers count from the header there).
    with open(path) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    columns = {k: [float(r[k]) for r in rows] for k in rows[0]}
    got = wearopt.fit_wear(columns)
    for k in ("activation_volume", "activation_energy", "activation_energy_ev", "ln_prefactor"):
        for q in ("estimate", "standard_error", "lower", "upper"):
            assert got[k][q] == pytest.approx(expected[k][q], rel=1e-12), (k, q)
    assert got["origin"] == "<rows>"
    # One temperature from a keyword argument, rates per metre with a speed.
    one = {"stress_Pa": [1e9, 2e9, 3e9], "rate_m3_per_m": [1e-20, 2e-20, 4e-20]}
    f = wearopt.fit_wear(one, temperature="300 K", speed="1 mm/s")
    assert f["activation_energy"] is None and f["speed"] == 1e-3
    assert any("cannot be identified" in n for n in f["notes"])


def test_fit_wear_words_errors_as_keywords():
    with pytest.raises(ValueError, match="^speed="):
        wearopt.fit_wear({"stress_Pa": [1e9, 2e9, 3e9], "rate_m3_per_m": [1, 2, 3]})
    with pytest.raises(ValueError, match="at least 3 points"):
        wearopt.fit_wear({"stress_Pa": [1e9, 2e9], "rate_m3_per_s": [1, 2]})
    with pytest.raises(ValueError, match="one stress value only"):
        wearopt.fit_wear({"stress_Pa": [1e9] * 3, "rate_m3_per_s": [1, 2, 3]})
    with pytest.raises(ValueError, match="rate_m3_per_s"):
        wearopt.fit_wear({"stress_Pa": [1e9, 2e9, 3e9], "rate_m3_per_s": [1, 0, 3]})
    with pytest.raises(ValueError, match="^temperature="):
        wearopt.fit_wear("problems/wear-rates.csv", temperature=300)


def test_evaluate_reports_the_debris_regime_as_the_cli(tmp_path):
    text = (ROOT / "problems" / "micro-gear.toml").read_text()
    text = text.replace("[interface]\n", '[interface]\nshear_strength = "1 GPa"\n', 1)
    path = tmp_path / "hub-debris.toml"
    path.write_text(text)
    expected = json.loads(cli("eval", str(path), "--format", "json").stdout)
    got = wearopt.evaluate(str(path))
    for k in ("critical_junction_size", "debris_contact_fraction", "debris_area_fraction",
              "wear_mechanism", "debris_shape_factor"):
        assert got[k] == expected[k], k
    # The hub at τ = 1 GPa, its Lennard-Jones junction sizes (docs/model.md §13;
    # the 0.251 and 0.573 were Hertz sizes, the lower bounds).
    assert got["critical_junction_size"] == pytest.approx(78.7e-9, rel=1e-3)
    assert got["debris_contact_fraction"] == pytest.approx(0.414, abs=5e-4)
    assert got["debris_area_fraction"] == pytest.approx(0.761, abs=5e-4)
    assert got["wear_mechanism"] == "debris"
    assert any("archard" in w for w in got["warnings"])
