"""What the testers found in the Python package (issue 57, item 6): NumPy's
scalars are numbers, as Python's are."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import wearopt

ROOT = Path(__file__).resolve().parents[2]
STUDY = str(ROOT / "problems" / "micro-gear-study.toml")


@pytest.mark.parametrize("scalar", [np.float32, np.float64, np.int32, np.int64])
def test_asperity_takes_numpy_scalars(scalar):
    # np.float32(1) raised TypeError; the curve is the one of the Python numbers
    # (JKR: a closed form, so the comparison is exact).
    want = wearopt.asperity(2.0, -1.0, 0.5, 4, "jkr")
    got = wearopt.asperity(scalar(2), scalar(-1), np.float32(0.5), np.int64(4), "jkr")
    assert got == want


def test_sweep_takes_numpy_integers():
    # wearopt.sweep(path, np.int64(10)) raised TypeError.
    want = wearopt.sweep(STUDY, 4, seed=1, shard=(1, 2))
    got = wearopt.sweep(STUDY, np.int64(4), seed=np.int32(1), shard=(np.int64(1), np.int64(2)))
    assert got == want
    with pytest.raises(TypeError, match="samples must be an int"):
        wearopt.sweep(STUDY, np.float64(4))
    with pytest.raises(TypeError, match="samples must be an int"):
        wearopt.sweep(STUDY, np.bool_(True))


def test_humidity_and_pareto_take_numpy_integers():
    hub = str(ROOT / "problems" / "micro-gear-humid.toml")
    want = wearopt.humidity(hub, 0.0, 0.9, 3)
    assert wearopt.humidity(hub, np.float32(0.0), np.float64(0.9), np.int64(3)) == want


def test_ctrl_c_interrupts_a_contact_solve():
    # Ctrl-C during wearopt.contact arrived only when the call returned. The
    # interrupt (what Ctrl-C does: _thread.interrupt_main) comes 0.3 s into a
    # call that takes several seconds, and must be raised well before its end.
    import _thread
    import threading
    import time

    rng = np.random.default_rng(57)
    args = dict(pixel_size="20 nm", height_unit="nm", modulus="150 GPa",
                pressures=[f"{p} MPa" for p in (20, 40, 60, 80, 100, 120)])
    # A map large enough that the call lasts over 1.5 s on this machine (a
    # release build on two free cores solves 512 x 512 in about 1 s), timed
    # after a small call has paid the one-time costs (the FFT plans, the thread
    # pool): a first call timed long and a second one over before the interrupt
    # came made this test fail on a busy machine.
    wearopt.contact(rng.normal(size=(64, 64)), **args)
    for n in (512, 1024, 2048):
        heights = rng.normal(size=(n, n))
        start = time.monotonic()
        wearopt.contact(heights, **args)
        whole = time.monotonic() - start
        if whole > 1.5:
            break
    assert whole > 1.5, f"the call takes {whole:.2f} s: too short to tell"
    timer = threading.Timer(0.3, _thread.interrupt_main)
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        wearopt.contact(heights, **args)
    interrupted = time.monotonic() - start
    timer.join()
    assert interrupted < 0.3 + 0.5 * whole, f"{interrupted:.2f} s of {whole:.2f} s"
