"""A design-space sweep spread over a Dask cluster through the Python package.

Each task computes one shard of the sweep (``wearopt.sweep(..., shard=(i, n))``),
the shards come back as text, and ``wearopt.merge`` joins them into exactly the
output of one unsharded run (``wearopt sweep FILE --samples N``). The same code
runs on a laptop (a LocalCluster, as below) or on any Dask cluster whose workers
have the package installed (``pip install ./python``).

    python examples/dask_sweep.py problems/micro-gear-study.toml 100000 > sweep.csv
"""

from __future__ import annotations

import sys
from typing import Optional

import wearopt


def dask_sweep(client, problem: str, samples: int, shards: int, method: str = "sobol",
               seed: int = 0, format: str = "csv") -> str:
    """The sweep's text, computed shard by shard on the client's workers."""
    futures = [
        client.submit(wearopt.sweep, problem, samples, method, seed, (i, shards), format,
                      pure=True, key=f"wearopt-sweep-{seed}-{i}-of-{shards}")
        for i in range(shards)
    ]
    return wearopt.merge(client.gather(futures), samples=samples)


def main(argv: Optional[list] = None) -> int:
    from dask.distributed import Client, LocalCluster

    args = sys.argv[1:] if argv is None else argv
    if len(args) < 2:
        print("usage: python examples/dask_sweep.py PROBLEM.toml SAMPLES [SHARDS] [WORKERS]",
              file=sys.stderr)
        return 2
    problem, samples = args[0], int(args[1])
    shards = int(args[2]) if len(args) > 2 else 16
    workers = int(args[3]) if len(args) > 3 else 2
    # One thread per worker process: the package parallelises each shard itself.
    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True) as cluster, \
            Client(cluster) as client:
        sys.stdout.write(dask_sweep(client, problem, samples, shards))
    return 0


if __name__ == "__main__":
    sys.exit(main())
