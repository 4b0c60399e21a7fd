"""The cluster examples for `wearopt uncertainty`: examples/dask_uncertainty.py on a
two-process LocalCluster and examples/slurm/uncertainty.sbatch task by task with
Slurm's variables give exactly the unsharded study."""

from __future__ import annotations

import os
import stat
import subprocess
import sys
from pathlib import Path

import pytest

import wearopt
from test_wearopt import _binary, _same, cli

ROOT = Path(__file__).resolve().parents[2]
SCATTER = "problems/micro-gear-scatter.toml"


def test_dask_uncertainty_on_a_local_cluster_gives_the_serial_result():
    distributed = pytest.importorskip("dask.distributed")
    sys.path.insert(0, str(ROOT / "examples"))
    try:
        import dask_uncertainty
    finally:
        sys.path.pop(0)
    serial = wearopt.uncertainty(str(ROOT / SCATTER), "sampling", samples=128)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        doc = dask_uncertainty.dask_uncertainty(client, str(ROOT / SCATTER), "sampling", 128,
                                                shards=5)
    assert _same(doc, serial)


def test_slurm_uncertainty_example_runs_as_a_job_array(tmp_path):
    """Tasks in any order, one resubmitted (it skips its complete part), one lost and
    rerun alone; the merge step the last task hands to `sbatch` writes the unsharded
    run's report byte for byte."""
    fake = tmp_path / "bin"
    fake.mkdir()
    sbatch = fake / "sbatch"
    sbatch.write_text('#!/bin/bash\nfor a in "$@"; do last="$a"; done\n'
                      'echo "$last" > "$FAKE_SBATCH_CMD"\n')
    sbatch.chmod(sbatch.stat().st_mode | stat.S_IEXEC)
    out = tmp_path / "parts"
    script = str(ROOT / "examples/slurm/uncertainty.sbatch")
    env = {k: v for k, v in os.environ.items() if not k.startswith("SLURM_")}
    env.update(PATH=f"{fake}:{env['PATH']}", PROBLEM=str(ROOT / SCATTER), METHOD="sampling",
               SAMPLES="64", SHARDS="3", OUT=str(out), WEAROPT=_binary(), FORMAT="json",
               FAKE_SBATCH_CMD=str(tmp_path / "merge.sh"))

    def task(i, count="3", low="0", high="2"):
        env.update(SLURM_ARRAY_TASK_ID=str(i), SLURM_ARRAY_TASK_COUNT=count,
                   SLURM_ARRAY_TASK_MIN=low, SLURM_ARRAY_TASK_MAX=high,
                   SLURM_ARRAY_JOB_ID="1234")
        r = subprocess.run(["bash", script], cwd=tmp_path, env=env, capture_output=True,
                           text=True)
        assert r.returncode == 0, r.stderr
        return r.stderr

    for i in (2, 0, 1):
        assert "skipped" not in task(i)
    assert "skipped" in task(2)  # a resubmission keeps the complete part
    good = (out / "part-1.json").read_text()
    (out / "part-1.json").unlink()
    task(1, count="1", low="1", high="1")  # `sbatch --array=1`
    assert (out / "part-1.json").read_text() == good
    merged = subprocess.run(["bash", "-c", (tmp_path / "merge.sh").read_text()], cwd=tmp_path,
                            env=env, capture_output=True, text=True)
    assert merged.returncode == 0, merged.stderr
    expected = cli("uncertainty", str(ROOT / SCATTER), "--method", "sampling", "--samples", "64",
                   "--format", "json").stdout
    assert (tmp_path / "uncertainty.json").read_text() == expected
