"""The Python package's results on the shipped problems, one file each, for
scripts/outputs (which compares them byte for byte before and after a change)."""

import json
import pathlib
import re
import sys

import numpy as np
import wearopt

out = pathlib.Path(sys.argv[1])
out.mkdir(parents=True, exist_ok=True)


def timeless(value):
    """The value without its wall-clock times (they differ from run to run)."""
    if isinstance(value, dict):
        return {k: timeless(v) for k, v in value.items() if k != "time_seconds"}
    if isinstance(value, list):
        return [timeless(v) for v in value]
    return value


def dump(name, value):
    value = timeless(value)
    (out / name).write_text(json.dumps(value, indent=1, sort_keys=True, default=repr) + "\n")


def error(name, call):
    try:
        call()
    except ValueError as e:
        (out / name).write_text(f"ValueError: {e}\n")


for f in sorted(pathlib.Path("problems").glob("*.toml")):
    dump(f"evaluate-{f.stem}.json", wearopt.evaluate(str(f)))
    text = f.read_text()
    if re.search(r"^\[design\]", text, re.M):
        dump(f"optimize-{f.stem}.json", wearopt.optimize(str(f)))
    if re.search(r"^\[pareto\]", text, re.M):
        dump(f"pareto-{f.stem}.json", wearopt.pareto(str(f), points=5))
error("pareto-no-section.txt", lambda: wearopt.pareto("problems/gold-switch.toml"))
error("pareto-points.txt", lambda: wearopt.pareto("problems/micro-gear.toml", points=0))

c = wearopt.curve([[1.0], [10.0]], 0.125, np.linspace(-2, 4, 13))
dump("curve-jkr.json", {k: np.asarray(v).tolist() for k, v in c.items()})
c = wearopt.curve(10.0, 1.0, np.linspace(-1, 3, 9), adhesion_model="dmt", attraction_range=0.1)
dump("curve-dmt.json", {k: np.asarray(v).tolist() for k, v in c.items()})
error("curve-bad.txt", lambda: wearopt.curve(-1.0, 1.0, 0.0))

dump("roughness-gsf.json", wearopt.roughness("problems/scans/self-affine.gsf"))
dump("roughness-npy.json", wearopt.roughness("problems/scans/self-affine-nm.npy",
                                             pixel_size="20 nm", height_unit="nm", level="none"))
error("roughness-npy-missing.txt", lambda: wearopt.roughness("problems/scans/self-affine-nm.npy"))

dump("contact.json", wearopt.contact("problems/scans/self-affine.gsf", modulus="150 GPa",
                                     pressures=["50 MPa", "200 MPa"], hardness="12 GPa"))
error("contact-bad.txt", lambda: wearopt.contact("problems/scans/self-affine.gsf",
                                                 modulus="150 GPa", pressures="0 MPa"))

s = wearopt.sweep("problems/micro-gear-study.toml", 16)
(out / "sweep.csv").write_text(s)
parts = [wearopt.sweep("problems/micro-gear-study.toml", 16, shard=(i, 2), format="json") for i in range(2)]
(out / "merge.json").write_text(wearopt.merge(parts))
error("sweep-bad-method.txt", lambda: wearopt.sweep("problems/micro-gear-study.toml", 4, method="x"))
