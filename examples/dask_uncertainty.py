"""A study of a scene under scatter spread over a Dask cluster through the Python package.

Each task computes one shard of the study's samples
(``wearopt.uncertainty(..., shard=(i, n))``, a JSON-serialisable dict), and
``wearopt.merge`` joins the parts into exactly the document of one unsharded run
(``wearopt.uncertainty(problem, method, samples)``). The same code runs on a laptop
(a LocalCluster, as below) or on any Dask cluster whose workers have the package
installed (``pip install ./python``). Reliability is sequential and does not shard.

    python examples/dask_uncertainty.py problems/micro-gear-scatter.toml sobol 16384 > sobol.json
"""

from __future__ import annotations

import json
import sys
from typing import Optional

import wearopt


def dask_uncertainty(client, problem: str, method: str, samples: int, shards: int,
                     seed: Optional[int] = None) -> dict:
    """The study's document (as :func:`wearopt.uncertainty` returns it), computed
    shard by shard on the client's workers."""
    futures = [
        client.submit(wearopt.uncertainty, problem, method, samples, seed, (i, shards),
                      pure=True, key=f"wearopt-uncertainty-{method}-{seed}-{i}-of-{shards}")
        for i in range(shards)
    ]
    return wearopt.merge(client.gather(futures), samples=samples)


def _plain(value):
    """The document with its numpy arrays as lists (for json.dumps)."""
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    return value.tolist() if hasattr(value, "tolist") else value


def main(argv: Optional[list] = None) -> int:
    from dask.distributed import Client, LocalCluster

    args = sys.argv[1:] if argv is None else argv
    if len(args) < 3:
        print("usage: python examples/dask_uncertainty.py PROBLEM.toml METHOD SAMPLES [SHARDS] [WORKERS]",
              file=sys.stderr)
        return 2
    problem, method, samples = args[0], args[1], int(args[2])
    shards = int(args[3]) if len(args) > 3 else 16
    workers = int(args[4]) if len(args) > 4 else 2
    # One thread per worker process: the package parallelises each shard itself.
    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True) as cluster, \
            Client(cluster) as client:
        doc = dask_uncertainty(client, problem, method, samples, shards)
    json.dump(_plain(doc), sys.stdout, indent=1)
    sys.stdout.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
