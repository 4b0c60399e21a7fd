#!/usr/bin/env python3
"""wearopt's contact solver against Tamaas 2.9, side by side, one thread each.

The same self-affine map (Tamaas's own generator: Hurst 0.8, power between
wavenumbers 4 and n/4 in units of 2π/L, rms 1 nm), the same composite modulus and
mean pressure (about 5 % contact), the same tolerance (1e-10, each solver's own
residual: Tamaas's is the pressure-weighted gap over the contact, as wearopt's
first term), on 512² and 1024² maps. Prints each solver's time, iterations and
real area, the ratio of the times, and how far the answers are apart.

    OMP_NUM_THREADS=1 RAYON_NUM_THREADS=1 target/venv/bin/python scripts/bench_contact.py

Needs the Python package built into the environment (maturin develop --release
for timings) and tamaas==2.9.0. Each timing is the best of `--repeat` runs.
"""

from __future__ import annotations

import argparse
import os
import time

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("RAYON_NUM_THREADS", "1")

import numpy as np  # noqa: E402
import tamaas as tm  # noqa: E402

import wearopt  # noqa: E402


def surface(n: int, seed: int = 1) -> np.ndarray:
    """Self-affine, H = 0.8, power between wavenumbers 4 and n/4 (in units of
    2π/L), rms 1 nm."""
    sg = tm.SurfaceGeneratorFilter2D([n, n])
    sg.random_seed = seed
    sg.spectrum = tm.Isopowerlaw2D()
    sg.spectrum.q0 = 4
    sg.spectrum.q1 = 4
    sg.spectrum.q2 = n // 4
    sg.spectrum.hurst = 0.8
    h = np.array(sg.buildSurface())
    return h / np.sqrt(np.mean(h**2)) * 1e-9


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", default="512,1024")
    ap.add_argument("--repeat", type=int, default=2)
    ap.add_argument("--tolerance", type=float, default=1e-10)
    args = ap.parse_args()
    tm.set_log_level(tm.LogLevel.error)
    length, e_star = 10e-6, 100e9
    print(f"{'map':>6} {'solver':>8} {'time s':>9} {'iterations':>10} {'area %':>9}")
    for n in (int(s) for s in args.sizes.split(",")):
        h = surface(n)
        dx = length / n
        gx, gy = np.gradient(h, dx)
        slope = np.sqrt(np.mean(gx**2 + gy**2))
        pressure = 0.05 * e_star * slope / 2  # ~5 % contact (κ ≈ 2)
        best_t, traction, t_iter = np.inf, None, None
        for _ in range(args.repeat):
            model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [length, length], [n, n])
            model.E, model.nu = e_star, 0.0
            solver = tm.PolonskyKeerRey(model, h, args.tolerance)
            t = time.perf_counter()
            solver.solve(pressure)
            best_t = min(best_t, time.perf_counter() - t)
            traction = np.array(model.traction)
            t_iter = solver.nb_iter if hasattr(solver, "nb_iter") else "-"
        best_w, point = np.inf, None
        for _ in range(args.repeat):
            t = time.perf_counter()
            c = wearopt.contact(h, pixel_size=dx, modulus=e_star, pressures=pressure,
                                level="none", tolerance=args.tolerance, fields=True)
            best_w = min(best_w, time.perf_counter() - t)
            point = c["points"][0]
        area_t = float(np.mean(traction > 0))
        print(f"{n:>5}² {'tamaas':>8} {best_t:>9.3f} {t_iter!s:>10} {100 * area_t:>9.4f}")
        print(f"{n:>5}² {'wearopt':>8} {best_w:>9.3f} {point['iterations']:>10} "
              f"{100 * point['real_area_fraction']:>9.4f}")
        diff = np.abs(point["pressure_field"] - traction).max() / traction.max()
        pixels = int((point["pressure_field"] > 0).sum()) - int((traction > 0).sum())
        print(f"        time ratio wearopt/tamaas {best_w / best_t:.3f}; "
              f"contact pixels differ by {pixels}, pressures by {diff:.1e} of the largest")


if __name__ == "__main__":
    main()
