#!/usr/bin/env bash
# Benchmark: the cost of a LIGGGHTS step in the hull's panel flow, with the coupling of earlier versions (the drag alone,
# a regular table: fluid.hull_flow_coupling drag_regular_table) and with today's (the table valid up to the hull,
# the water's acceleration: full), on the same scene. Prints ratios measured in this one run:
#   instructions: callgrind over N steps of each (independent of the machine's load);
#   time:         the loop time of M steps of each, alternately, R times each (best of R).
# Usage: bash bench/hull_flow_cost.sh [CASE_DIR]   (default cases/jbc_narrow; its panel flow table is computed
# once and cached in the case's generated/ folder). BENCH_CALLGRIND_STEPS (50), BENCH_TIME_STEPS (1000; 0 skips),
# BENCH_REPEATS (3).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
bin="${BRASH_BIN:-$here/build/bin}"
case_dir="${1:-$here/cases/jbc_narrow}"
steps_cg="${BENCH_CALLGRIND_STEPS:-50}"
steps_t="${BENCH_TIME_STEPS:-1000}"
repeats="${BENCH_REPEATS:-3}"
work="$(mktemp -d /tmp/brash-bench-XXXX)"
trap 'rm -rf "$work"' EXIT

couplings=(drag_regular_table full)
for c in "${couplings[@]}"; do
  "$bin/brash-liggghts-run" "$case_dir" --duration 0.2 --set fluid.hull_flow=panel --set fluid.model=both \
    --set "fluid.hull_flow_coupling=$c" --out "$work/$c" --prepare-only >/dev/null
  [ -f "$work/$c/in.lmp" ] || { echo "bench: could not prepare the scene of $case_dir ($c)" >&2; exit 1; }
done
mk_input() {  # $1 = scene, $2 = steps
  sed -e "s/^run .*/run $2/" -e '/^write_restart/d' -e '/^restart /d' -e '/^dump /d' -e '/^dump_modify/d' \
    "$work/$1/in.lmp"
}
atoms=$(awk '/ atoms$/{print $1; exit}' "$work/full/packing.data")

echo "== a step in the panel flow: coupling drag_regular_table (before) against full (now), $atoms spheres, 1 rank"
ir() { callgrind_annotate "$1" 2>/dev/null | awk '/PROGRAM TOTALS/ && !n++ {gsub(",","",$1); print $1}'; }
fix_ir() {
  callgrind_annotate --inclusive=yes "$1" 2>/dev/null |
    awk '/FixIceFluid::post_force/ && !n++ {gsub(",","",$1); print $1}'
}
for c in "${couplings[@]}"; do
  (cd "$work/$c" && mk_input "$c" "$steps_cg" > in_cg.lmp &&
    valgrind --tool=callgrind --callgrind-out-file=cg.out --toggle-collect='LAMMPS_NS::Verlet::run(int)' \
      "$bin/brash-liggghts" -in in_cg.lmp -log none >/dev/null 2>&1)
done
awk -v a="$(ir "$work/drag_regular_table/cg.out")" -v b="$(ir "$work/full/cg.out")" \
    -v fa="$(fix_ir "$work/drag_regular_table/cg.out")" -v fb="$(fix_ir "$work/full/cg.out")" \
    -v n="$atoms" -v s="$steps_cg" 'BEGIN{
  printf "instructions per step    before %.4g  now %.4g  ratio %.4f\n", a/s, b/s, b/a;
  printf "fix icefluid per piece   before %.1f  now %.1f  ratio %.3f (instructions per sphere-step)\n",
         fa/(n*s), fb/(n*s), fb/fa;
}'

if [ "$steps_t" = 0 ]; then exit 0; fi
loop() { awk '/^Loop time of/ && !n++ {print $4}' "$1"; }
for c in "${couplings[@]}"; do (cd "$work/$c" && mk_input "$c" "$steps_t" > in_t.lmp); done
best_before=1e300 best_now=1e300
for ((r = 0; r < repeats; ++r)); do
  for c in "${couplings[@]}"; do
    (cd "$work/$c" && "$bin/brash-liggghts" -in in_t.lmp -log none > t.txt 2>&1)
    t=$(loop "$work/$c/t.txt")
    if [ "$c" = full ]; then best_now=$(awk -v a="$best_now" -v b="$t" 'BEGIN{print (b<a)?b:a}')
    else best_before=$(awk -v a="$best_before" -v b="$t" 'BEGIN{print (b<a)?b:a}'); fi
  done
done
awk -v a="$best_before" -v b="$best_now" -v s="$steps_t" -v r="$repeats" 'BEGIN{
  printf "loop time of %d steps    before %.2f s  now %.2f s  ratio %.3f (best of %d each, alternately)\n", s, a, b, b/a, r;
}'
