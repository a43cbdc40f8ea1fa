#!/usr/bin/env bash
# Benchmark: YADE particle-steps/s with and without the brash fluid adapter (PyRunner + brash_yade), on
# the quick case's scene (same packing, hull band, side walls, contacts as the LIGGGHTS benchmark).
# Paired windows of N steps (fluid on / off), 3 repetitions in one YADE process, 1 thread.
#   bench/yade.sh [CASE_DIR]      env: BENCH_YADE_STEPS (default 200), BRASH_BIN (default build/bin)
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
bin="${BRASH_BIN:-$here/build/bin}"
case_dir="${1:-$here/cases/jbc_narrow}"
steps="${BENCH_YADE_STEPS:-200}"
if [ ! -x "$bin/brash-yade-run" ]; then
  echo "bench/yade.sh: $bin/brash-yade-run not built (needs the Debian packages yade and pybind11-dev); skipped"
  exit 0
fi
work="$(mktemp -d /tmp/brash-bench-yade-XXXX)"
trap 'rm -rf "$work"' EXIT
"$bin/brash-yade-run" "$case_dir" --duration 1 --out "$work/scene" --prepare-only >/dev/null 2>&1
# brash-yade-run in bench mode: builds the scene, runs the paired windows, prints BENCH lines.
export BRASH_YADE_BENCH_STEPS="$steps"
"$bin/brash-yade-run" "$case_dir" --duration 1 --out "$work/scene" --no-post >/dev/null 2>&1 || true
grep '^BENCH' "$work/scene/log.txt" || { echo "bench/yade.sh: no result, see the log:" >&2; tail -20 "$work/scene/log.txt" >&2; exit 1; }
# Against LIGGGHTS on the same case and the same stretch of time (the first N steps), 1 rank.
dt=$("$bin/brash-case" get "$work/scene/case.yaml" run.timestep_s)
dur=$(awk -v n="$steps" -v dt="$dt" 'BEGIN{printf "%.6g", n*dt}')
if "$bin/brash-liggghts-run" "$case_dir" --np 1 --duration "$dur" --no-post --out "$work/lig" >/dev/null 2>&1; then
  read -r ps lt < <(jq -r '"\(.particle_steps) \(.loop_time_s)"' "$work/lig/meta.json")
  awk -v n="$steps" -v ps="$ps" -v lt="$lt" 'BEGIN {
    printf "BENCH liggghts 1 rank, same case, same %s steps: %.3g particle-steps/s (loop %.2f s)\n", n, ps / lt, lt }'
else
  echo "bench/yade.sh: the LIGGGHTS comparison run failed (see $work/lig/log.txt)"
fi
