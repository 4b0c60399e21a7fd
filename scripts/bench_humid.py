#!/usr/bin/env python3
"""Whole `wearopt` commands in humid air against the same files dry, side by side.

Writes the variants of two shipped problems into a temporary folder and times each
pair of commands alternately (so that the machine's drift falls on both), then
prints the medians and their ratio:

* `wearopt eval problems/micro-gear-humid.toml` against the same file without
  `[environment]` and `contact_angle` (its cantilever kept: both compute Γ);
* `wearopt optimize problems/micro-gear-coating-study.toml` (its limits at nine
  humidities, 0–90 %) against the same study at the one humidity 90 %, and against
  it dry (without `[environment]` and the contact-angle variable, which dry air
  does not have).

    cargo build --release && python3 scripts/bench_humid.py [--pairs N]

Only the standard library; the binary is target/release/wearopt.
"""

from __future__ import annotations

import argparse
import re
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
BINARY = ROOT / "target" / "release" / "wearopt"


def without_section(text: str, name: str) -> str:
    """The TOML text without the section `[name]` (up to the next section)."""
    return re.sub(rf"(?ms)^\[{re.escape(name)}\].*?(?=^\[|\Z)", "", text)


def variants(folder: Path) -> dict[str, Path]:
    """The shipped files and their dry or single-humidity variants."""
    humid = (ROOT / "problems" / "micro-gear-humid.toml").read_text()
    study = (ROOT / "problems" / "micro-gear-coating-study.toml").read_text()
    dry = re.sub(r"(?m)^contact_angle = .*$", "", without_section(humid, "environment"))
    study_one = re.sub(
        r"(?m)^relative_humidity = \{.*$", "relative_humidity = 0.9", study
    )
    study_one = re.sub(r"(?m)^humidity_points = .*$", "", study_one)
    study_dry = without_section(study, "environment")
    study_dry = re.sub(r"(?m)^contact_angle = .*$", "", study_dry)
    out = {}
    for name, text in [
        ("humid-dry.toml", dry),
        ("study-one-humidity.toml", study_one),
        ("study-dry.toml", study_dry),
    ]:
        path = folder / name
        path.write_text(text)
        out[name] = path
    return out


def run(args: list[str]) -> float:
    """Seconds one command takes (it must succeed)."""
    start = time.perf_counter()
    subprocess.run([str(BINARY), *args], check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - start


def pair(name: str, base: list[str], other: list[str], pairs: int) -> None:
    """Time `base` and `other` alternately; print the medians and the ratio."""
    a, b = [], []
    for _ in range(pairs):
        a.append(run(base))
        b.append(run(other))
    ma, mb = statistics.median(a), statistics.median(b)
    print(f"{name}: {ma * 1e3:.2f} ms against {mb * 1e3:.2f} ms ({mb / ma:.2f}x), median of {pairs} pairs")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pairs", type=int, default=0, help="pairs per comparison (default 150 for eval, 10 for optimize)")
    pairs = parser.parse_args().pairs
    with tempfile.TemporaryDirectory() as tmp:
        v = variants(Path(tmp))
        humid = str(ROOT / "problems" / "micro-gear-humid.toml")
        study = str(ROOT / "problems" / "micro-gear-coating-study.toml")
        pair("eval: dry file, humid file", ["eval", str(v["humid-dry.toml"])], ["eval", humid], pairs or 150)
        pair(
            "optimize: one humidity (90 %), nine humidities",
            ["optimize", str(v["study-one-humidity.toml"])],
            ["optimize", study],
            pairs or 10,
        )
        pair("optimize: dry study, nine humidities", ["optimize", str(v["study-dry.toml"])], ["optimize", study], pairs or 10)


if __name__ == "__main__":
    main()
