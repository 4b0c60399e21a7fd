#!/usr/bin/env bash
# Writes src/model/lennard_jones/table.txt, the Lennard-Jones loading curves the
# rough-surface law reads (docs/model.md §11), from the sphere solver (each node
# extrapolated from three nested meshes to the converged solution), and checks
# the result against the converged solver between its nodes.
#
#   scripts/lennard_jones_table.sh            # the grid: μ = 0.01 … 5, 66 steps (24 per decade)
#   scripts/lennard_jones_table.sh check      # only the check of the committed table
#   scripts/lennard_jones_table.sh check 0.01 1.95   # of the curves at those μ
#   scripts/lennard_jones_table.sh between    # tests/data/lennard_jones_between.txt
#   scripts/lennard_jones_table.sh far        # tests/data/lennard_jones_far.txt
#
# Takes about 50 minutes on one core to write (release build; 30–55 s a
# curve); the check took two hours for the first table's 34 curves.
# `between` writes nine curves the table does not hold, at the geometric
# midpoints between seven pairs of its curves (where the interpolation in μ
# errs most; two of them either side of the cusp), at μ = 0.745 beside the
# cusp and at the shipped hub's μ, which tests/all/lennard_jones_rough.rs
# measures that interpolation against (about 8 minutes). `far` writes three
# curves of the table (μ = 0.01, 0.105, 0.918) with contact parts to δ̂ = 150
# instead of 50, which the same tests measure the table's tail beyond δ̂ = 50
# against (about 7 minutes).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --example lennard_jones_table
bin=target/release/examples/lennard_jones_table
table=src/model/lennard_jones/table.txt
if [[ "${1:-}" == between ]]; then
    # μ_i = 0.01 · 500^{i/66} at i = 11.5, 25.5, 39.5, 44.5, 46.5, 53.5, 63.5
    # (44.5 and 46.5 either side of the cusp, each interpolated from curves on
    # both sides of it; near 45.5, at μ = 0.7241, the generator's loading
    # trace stalls at apex gap 1.33), the hub's
    # (problems/micro-gear.toml: `wearopt eval --format json`'s
    # tabor_parameter), and μ = 0.745 on the S-shaped side next to the cusp.
    mus=$(python3 -c 'print(" ".join(repr(m) for m in sorted([0.37421544616518193, 0.745] + [0.01 * 500 ** (i / 66) for i in (11.5, 25.5, 39.5, 44.5, 46.5, 53.5, 63.5)])))')
    # shellcheck disable=SC2086
    "$bin" 1 $mus > tests/data/lennard_jones_between.txt.new
    mv tests/data/lennard_jones_between.txt.new tests/data/lennard_jones_between.txt
    exit 0
fi
if [[ "${1:-}" == far ]]; then
    # The table's first curve, its 14th and its 49th.
    REACH=150 "$bin" 1 0.01 0.10527787805206623 0.9180942678743859 \
        > tests/data/lennard_jones_far.txt.new
    mv tests/data/lennard_jones_far.txt.new tests/data/lennard_jones_far.txt
    exit 0
fi
if [[ "${1:-}" != check ]]; then
    "$bin" 1 > "$table.new"
    mv "$table.new" "$table"
fi
shift || true
"$bin" check "$table" "$@"
