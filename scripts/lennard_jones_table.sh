#!/usr/bin/env bash
# Writes src/model/lennard_jones/table.txt, the Lennard-Jones loading curves the
# rough-surface law reads (docs/model.md §11), from the sphere solver (each node
# extrapolated from three nested meshes to the converged solution), and checks
# the result against the converged solver between its nodes.
#
#   scripts/lennard_jones_table.sh            # the grid: μ = 0.01 … 5, 12 per decade
#   scripts/lennard_jones_table.sh check      # only the check of the committed table
#   scripts/lennard_jones_table.sh check 0.01 1.95   # of the curves at those μ
#
# Takes about 25 minutes on one core to write (release build) and two hours to
# check.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --example lennard_jones_table
bin=target/release/examples/lennard_jones_table
table=src/model/lennard_jones/table.txt
if [[ "${1:-}" != check ]]; then
    "$bin" 1 > "$table.new"
    mv "$table.new" "$table"
fi
shift || true
"$bin" check "$table" "$@"
