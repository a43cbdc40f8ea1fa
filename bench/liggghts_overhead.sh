#!/usr/bin/env bash
# Benchmark: fix icefluid overhead vs bare LIGGGHTS and particle-steps/s on 1 and 2 ranks, on the
# quick case's scene (same packing, hull band, contacts). Prints ratios measured in this one run.
#   instructions: callgrind, N steps, bare scene (fix icefluid removed) vs the same scene with it;
#                 plus the inclusive share of FixIceFluid::post_force in the run with it.
#   throughput:   loop time of M steps on 1 and 2 ranks (paired, same sitting); BENCH_THROUGHPUT_STEPS=0 skips it.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
bin="${BRASH_BIN:-$here/build/bin}"
case_dir="${1:-$here/cases/jbc_narrow}"
steps_cg="${BENCH_CALLGRIND_STEPS:-100}"
steps_tp="${BENCH_THROUGHPUT_STEPS:-2000}"
work="$(mktemp -d /tmp/brash-bench-XXXX)"
trap 'rm -rf "$work"' EXIT

# Scene files from the runner (inputs only), then the step count is edited.
"$bin/brash-liggghts-run" "$case_dir" --duration 0.2 --out "$work/scene" --prepare-only >/dev/null
scene="$work/scene"
[ -f "$scene/in.lmp" ] || { echo "bench: could not prepare the scene from $case_dir" >&2; exit 1; }
mk_input() {  # $1 = steps, $2 = with|without fix icefluid
  sed -e "s/^run .*/run $1/" -e '/^write_restart/d' -e '/^restart /d' -e '/^dump /d' -e '/^dump_modify/d' \
      "$scene/in.lmp" | { if [ "$2" = without ]; then grep -v '^fix fl ' | sed -e 's/ f_fl\[[0-9]\]//g'; else cat; fi; }
}
cd "$scene"
mk_input "$steps_cg" with > in_with.lmp
mk_input "$steps_cg" without > in_without.lmp
atoms=$(awk '/ atoms$/{print $1; exit}' packing.data)

echo "== fix icefluid overhead (callgrind instructions, $steps_cg steps, $atoms spheres, 1 rank)"
for v in without with; do
  valgrind --tool=callgrind --callgrind-out-file="cg_$v.out" --toggle-collect='LAMMPS_NS::Verlet::run(int)' \
    "$bin/brash-liggghts" -in "in_$v.lmp" -log none >/dev/null 2>&1
done
ir() { callgrind_annotate "$1" 2>/dev/null | awk '/PROGRAM TOTALS/ && !n++ {gsub(",","",$1); print $1}'; }
ir_without=$(ir cg_without.out); ir_with=$(ir cg_with.out)
ir_fix=$(callgrind_annotate --inclusive=yes "cg_with.out" 2>/dev/null | awk '/FixIceFluid::post_force/ && !n++ {gsub(",","",$1); print $1}')
awk -v a="$ir_without" -v b="$ir_with" -v f="${ir_fix:-0}" -v n="$atoms" -v s="$steps_cg" 'BEGIN{
  printf "instructions bare        %.4g\n", a;
  printf "instructions with fix    %.4g\n", b;
  printf "ratio with/bare          %.4f  (the bare run has no buoyancy: its spheres sink, so its contacts differ)\n", b/a;
  printf "post_force inclusive     %.4g = %.2f %% of the run, %.1f instructions per sphere-step\n", f, 100*f/b, f/(n*s);
  printf "plugin overhead          %.2f %% = fix instructions / all other instructions of the same run (goal <= 3 %%)\n", 100*f/(b-f);
}'

if [ "$steps_tp" = 0 ]; then exit 0; fi  # BENCH_THROUGHPUT_STEPS=0: instruction counts only
echo "== throughput ($steps_tp steps)"
mk_input "$steps_tp" with > in_tp.lmp
loop() { awk '/^Loop time of/ && !n++ {print $4}' "$1"; }
"$bin/brash-liggghts" -in in_tp.lmp -log none > tp1.txt 2>&1
mpirun --allow-run-as-root --oversubscribe -np 2 "$bin/brash-liggghts" -in in_tp.lmp -log none > tp2.txt 2>&1
t1=$(loop tp1.txt); t2=$(loop tp2.txt)
awk -v t1="$t1" -v t2="$t2" -v n="$atoms" -v s="$steps_tp" 'BEGIN{
  printf "1 rank : %.3g particle-steps/s (loop %.2f s)\n", n*s/t1, t1;
  printf "2 ranks: %.3g particle-steps/s (loop %.2f s)\n", n*s/t2, t2;
  printf "parallel efficiency 2 ranks: %.0f %%\n", 100*t1/(2*t2);
}'
# Note: LIGGGHTS 3.8 crashes (fprintf to a null screen in InputMeshTri) with "-screen none": screen output
# is redirected to /dev/null instead.
