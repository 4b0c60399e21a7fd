#!/usr/bin/env bash
# Writes src/model/lennard_jones/table.txt, the Lennard-Jones loading curves the
# rough-surface law reads (docs/model.md §11), from the sphere solver (each node
# extrapolated from three nested meshes to the converged solution), and checks
# the result against the converged solver between its nodes.
#
#   scripts/lennard_jones_table.sh            # the grid: μ = 9.91e-5 … 5, 230 steps (49 per decade),
#                                             # then to 22.4 in 12 (18.4 per decade)
#   scripts/lennard_jones_table.sh check      # only the check of the committed table
#   scripts/lennard_jones_table.sh check 0.01 1.95   # of the curves at those μ
#   scripts/lennard_jones_table.sh between    # tests/data/lennard_jones_between.txt
#   scripts/lennard_jones_table.sh far        # tests/data/lennard_jones_far.txt
#   scripts/lennard_jones_table.sh far-below  # tests/data/lennard_jones_far_below.txt
#   scripts/lennard_jones_table.sh between-below  # tests/data/lennard_jones_between_below.txt
#   scripts/lennard_jones_table.sh cusp       # tests/data/lennard_jones_above_cusp.txt
#
# Takes about four and a half hours on one core to write (release build; 17–103 s a
# curve up to μ = 5, 4–23 minutes above); the check took two hours for the
# first table's 34 curves.
# `between` writes seventeen curves the table does not hold, at the geometric
# midpoints between eleven pairs of its curves (where the interpolation in μ
# errs most; three of them beside the cusp), at μ = 0.696, 0.72875, 0.73, 0.735
# and 0.745 beside the cusp and at the shipped hub's μ, which tests/all/lennard_jones_rough.rs
# measures that interpolation against (about 45 minutes, 23 of them at μ = 21). `far` writes eight
# curves of the table (μ = 0.01, three around 0.041 where the tail's
# departure from the squeezed gap changes sign, 0.105, 0.918, 4.14 and 5.66) with contact
# parts two to eight times as far as the table's (to δ̂ = 1808, 880 and 400),
# which the same tests measure the table's tail against (about 40 minutes, 8 of them at
# μ = 4.14, 18 at 5.66). The contact
# parts reach δ̂ = 50, or 16 ẑ0 where that is further (μ < 0.18: `GRID=0..160`
# in the environment writes only those 160 curves; `GRID=0..98` the 98 below
# μ = 0.01, written on 2026-12-03 in 40 minutes on two processes, GRID=0..49 and
# GRID=49..98, 40–55 s a curve).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --example lennard_jones_table
bin=target/release/examples/lennard_jones_table
table=src/model/lennard_jones/table.txt
if [[ "${1:-}" == between ]]; then
    # μ_i = 0.01 · 500^{i/132} at i = 23.5, 51.5, 79.5, 88.5, 89.5, 92.5,
    # 107.5, 127.5 (88.5 and 89.5 below the cusp, 92.5 above it), the hub's
    # (problems/micro-gear.toml: `wearopt eval --format json`'s
    # tabor_parameter), and beside the cusp μ = 0.696 (below it, beyond the
    # last single-valued curve) and 0.72875, 0.73, 0.735, 0.745 (above it,
    # next to the first S-shaped one, 0.7275, which the generator writes at
    # refinement 2; within μ = 0.70 … 0.725 the generator's
    # loading trace does not converge: at 0.7241 it stalls at apex gap 1.33).
    # Above 5: the geometric midpoints 5 · 20^{i/24} at i = 0.5, 5.5 and
    # 11.5, next to the table's switch of spacing, in the middle and between
    # its last two curves (where the six-curve stencil is most one-sided).
    mus=$(python3 -c 'print(" ".join(repr(m) for m in sorted([0.37421544616518193, 0.696, 0.72875, 0.73, 0.735, 0.745] + [0.01 * 500 ** (i / 132) for i in (23.5, 51.5, 79.5, 88.5, 89.5, 92.5, 107.5, 127.5)] + [5 * 20 ** (i / 24) for i in (0.5, 5.5, 11.5)])))')
    # shellcheck disable=SC2086
    "$bin" 1 $mus > tests/data/lennard_jones_between.txt.new
    mv tests/data/lennard_jones_between.txt.new tests/data/lennard_jones_between.txt
    exit 0
fi
if [[ "${1:-}" == cusp ]]; then
    # μ = 0.70, 0.705, 0.71, 0.715 and 0.72, between the cusp (μ_c = 0.6972)
    # and the table's first S-shaped curve (0.7275), at refinement 2 (5
    # minutes each; at refinement 1 the trace's mesh moves the jumps by 5e-4
    # of δ̂, more than the S-shape is wide below μ ≈ 0.707, and the contact
    # nodes next to the jump find no solution on it), 0.70 at 3 (27 minutes:
    # there the S-shape is 9.4e-5 wide).
    {
        echo "# Lennard-Jones loading curves (docs/model.md §11), extrapolated, just above the cusp (μ_c = 0.6972): μ = 0.70 at refinement 3, 0.705, 0.71, 0.715, 0.72 at refinement 2:"
        echo "# written by scripts/lennard_jones_table.sh cusp; read by tests/all/lennard_jones_rough.rs"
        "$bin" 3 0.70 | grep -v '^#'
        "$bin" 2 0.705 0.71 0.715 0.72 | grep -v '^#'
    } > tests/data/lennard_jones_above_cusp.txt.new
    mv tests/data/lennard_jones_above_cusp.txt.new tests/data/lennard_jones_above_cusp.txt
    exit 0
fi
if [[ "${1:-}" == far ]]; then
    # The table's first curve (twice its reach of 16 ẑ0), its 29th, 31st and
    # 33rd (four times their reach of 16 ẑ0, 242 … 200), its 52nd (4.7 times
    # its 86), its 98th and its 129th (eight times the reach of 50), and its
    # 134th, the first above 5, on the stretching mesh (18 minutes).
    {
        echo "# Lennard-Jones loading curves (docs/model.md §11), refinement 1, extrapolated, contact parts to δ̂ = 1808 (32 ẑ0) at μ = 0.01, 880 at 0.0374, 0.0411 and 0.0451, 400 at 0.105, 0.918, 4.14 and 5.66:"
        echo "# written by scripts/lennard_jones_table.sh far; read by tests/all/lennard_jones_rough.rs"
        REACH=1808 "$bin" 1 0.01 | grep -v '^#'
        REACH=880 "$bin" 1 0.03736876876070855 0.04105842385440056 0.045112381951961454 | grep -v '^#'
        REACH=400 "$bin" 1 0.10527787805206623 0.9180942678743859 4.141741928025571 5.664734861651771 | grep -v '^#'
    } > tests/data/lennard_jones_far.txt.new
    mv tests/data/lennard_jones_far.txt.new tests/data/lennard_jones_far.txt
    exit 0
fi
# `below NAME WHAT ARGS…`: tests/data/lennard_jones_NAME.txt, the curves the
# generator writes for ARGS (an environment assignment may lead), headed by WHAT.
below() {
    local name=$1 what=$2 out=tests/data/lennard_jones_$1.txt
    shift 2
    {
        echo "# Lennard-Jones loading curves (docs/model.md §11), refinement 1, extrapolated, $what:"
        echo "# written by scripts/lennard_jones_table.sh ${name//_/-}; read by tests/all/lennard_jones_rough.rs"
        env "$@" | grep -v '^#'
    } > "$out.new"
    mv "$out.new" "$out"
}
if [[ "${1:-}" == between-below ]]; then
    # Two curves at geometric midpoints below μ = 0.01, between the grid's
    # steps −88 and −87 (μ = 1.63e-4) and −58 and −57 (6.67e-4): what the
    # interpolation in μ there is measured against (about 2 minutes).
    # shellcheck disable=SC2046
    below between_below "at two midpoints of the table's grid below μ = 0.01" "$bin" 1 \
        $(python3 -c 'print(" ".join(repr(0.01 * 500 ** (i / 132)) for i in (-87.5, -57.5)))')
    exit 0
fi
if [[ "${1:-}" == far-below ]]; then
    # The table's lowest curve (μ = 9.91e-5) with its contact part twice as
    # far, to δ̂ = 182 400 (32 ẑ0): what the tail there is measured against.
    below far_below "the table's lowest (μ = 9.91e-5) with its contact part to δ̂ = 182 400 (32 ẑ0)" \
        REACH=182400 "$bin" 1 "$(python3 -c 'print(repr(0.01 * 500 ** (-98 / 132)))')"
    exit 0
fi
if [[ "${1:-}" != check ]]; then
    "$bin" 1 > "$table.new"
    mv "$table.new" "$table"
fi
shift || true
"$bin" check "$table" "$@"
