#!/usr/bin/env bash
# Per-rank load of a case's LIGGGHTS scene (pieces, ghosts and neighbour pairs per rank, as mean and max / mean) at
# several rank counts and processor grids, after one step: bench/rank_scaling.sh with STEPS=1, oversubscribed where
# the machine has fewer cores (the decomposition, not the speed, is measured; the time columns mean nothing here).
#   bash bench/rank_load.sh [CASE_DIR] [RANKS ...]      (default: cases/jbc_ia_5kn, 2 4 8 16)
# Environment: as bench/rank_scaling.sh (GRIDS, HULL_X_M: the hull started there, e.g. HULL_X_M=3 puts the JBC
# model's bow 10 m into the paper channel's ice, so the hull's mesh and the ice it pushes weigh on the ranks
# that hold them).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
case_dir="${1:-$here/cases/jbc_ia_5kn}"
[ $# -gt 0 ] && shift
[ $# -gt 0 ] || set -- 2 4 8 16
args="--oversubscribe"
[ "$(id -u)" != 0 ] || args="$args --allow-run-as-root"
STEPS=1 MPI_ARGS="${MPI_ARGS:-$args}" exec bash "$here/bench/rank_scaling.sh" "$case_dir" "$@"
