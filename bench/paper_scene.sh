#!/usr/bin/env bash
# Benchmark on the paper scene itself: 1,000 steps from a restart file of a paper-case run directory
# (brash-liggghts-run cases/jbc_ia_5kn ...; needs restart/a.restart or b.restart), timed in one sitting:
#   far field on, 2 ranks  |  far field on, 1 rank  (parallel efficiency)  |  far field off, 2 ranks (its speed-up);
# a run without the far field (speedups.farfield: false) is timed on 2 and 1 ranks, and with the far field switched
# on (the run's case.yaml with speedups.farfield: true, i.e. its window, with each wake rule of WAKE_RULES, default
# "force neighbour_speed" (speedups.farfield_wake_by); input written by brash-liggghts-run --prepare-only) on 2 ranks:
# what the far field would save on this scene, at this time.
# The run's own in.lmp is used with dumps, restart and force output removed; "off" drops fix brash/farfield,
# deletes group idle and its neighbour exclusion (every piece integrated, every pair computed).
# A run with the far field but not the moving window is also timed with the moving window switched on (its case.yaml
# with speedups.moving_window: true, input from --prepare-only): what the window saves on top of the far field. A run
# made with the moving window is timed as it is only: its restart file holds the window's pieces, not the channel.
# SKIP_1RANK=1 leaves out the 1-rank timing (the slowest).
#   bash bench/paper_scene.sh [RUN_DIR] [STEPS]      (skipped with a message when RUN_DIR has no restart; RUN_DIR
#   defaults to the runs/paper-liggghts-* run with the newest restart file)
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
bin="${BRASH_BIN:-$here/build/bin}"
# default: the paper-case run in runs/ with the newest restart file
newest="$(ls -t "$here"/runs/paper-liggghts-*/restart/[ab].restart 2>/dev/null | head -1 || true)"
run_dir="${1:-${newest:+$(dirname "$(dirname "$newest")")}}"
run_dir="${run_dir:-$here/runs/paper-liggghts-both}"
steps="${2:-1000}"
restart="$(ls -t "$run_dir"/restart/a.restart "$run_dir"/restart/b.restart 2>/dev/null | head -1 || true)"
if [ -z "$restart" ]; then
  echo "paper_scene: skipped: no restart file in $run_dir/restart (run the paper case first)"
  exit 0
fi
work="$(mktemp -d /tmp/brash-paperbench-XXXX)"
trap 'rm -rf "$work"' EXIT
cp "$restart" "$work/start.restart"
cp "$run_dir"/hull*.stl "$work/"
[ ! -f "$run_dir/hull_flow.bin" ] || cp "$run_dir/hull_flow.bin" "$work/"  # the hull flow's table (fluid.hull_flow)
strip() {  # in.lmp -> the same scene from start.restart, without outputs, for $steps steps
  sed -e 's|^read_data packing.data|read_restart start.restart|' -e '/^fix hf /d' -e '/^dump/d' -e '/^restart /d' \
      -e '/^write_restart/d' -e "s/^run .*/run $steps/" "$1"
}
strip "$run_dir/in.lmp" > "$work/in_on.lmp"
sed -e '/^fix farfield/d' -e 's/^group idle subtract all all/group idle delete/' -e 's/ f_farfield\[1\]//' \
    -e 's/^neigh_modify delay 0 exclude group idle idle/neigh_modify delay 0/' "$work/in_on.lmp" > "$work/in_off.lmp"
# A run without the far field: then the run's own scene is measured on 1 and 2 ranks, and the same scene
# with the case's far field switched on, once per wake rule.
has_ff=0; grep -q '^fix farfield' "$work/in_on.lmp" && has_ff=1
has_win=0; grep -q '^fix window' "$work/in_on.lmp" && has_win=1
wake_rules="${WAKE_RULES:-force neighbour_speed}"
prepare() {  # $1 derived case folder, $2 run folder -> the stripped input of that case's scene in $3
  "$bin/brash-liggghts-run" "$1" --np 2 --out "$2" --prepare-only > "$work/prepare.log" 2>&1 ||
    { cat "$work/prepare.log" >&2; exit 1; }
  strip "$2/in.lmp" > "$3"
}
if [ "$has_ff" = 1 ] && [ "$has_win" = 0 ]; then
  "$bin/brash-case" derive "$run_dir/case.yaml" --set speedups.moving_window=true --out "$work/wincase" > /dev/null
  prepare "$work/wincase" "$work/winrun" "$work/in_win.lmp"
fi
if [ "$has_ff" = 0 ]; then
  for rule in $wake_rules; do
    "$bin/brash-case" derive "$run_dir/case.yaml" --set speedups.farfield=true --set "speedups.farfield_wake_by=$rule" \
      --out "$work/ffcase_$rule" > /dev/null
    prepare "$work/ffcase_$rule" "$work/ffrun_$rule" "$work/in_ff_$rule.lmp"
  done
fi
cd "$work"
loop() {  # $1 input, $2 ranks -> loop time [s]
  if [ "$2" = 1 ]; then "$bin/brash-liggghts" -in "$1" -log "log_$1_$2.txt" > /dev/null 2>&1
  else mpirun --allow-run-as-root --oversubscribe -np "$2" "$bin/brash-liggghts" -in "$1" -log "log_$1_$2.txt" > /dev/null 2>&1; fi
  grep -q '^Loop time of' "log_$1_$2.txt" || { echo "paper_scene: $1 on $2 rank(s) did not run:" >&2; tail -5 "log_$1_$2.txt" >&2; exit 1; }
  awk '/^Loop time of/ {print $4; exit}' "log_$1_$2.txt"
}
label="far field on, "; [ "$has_ff" = 1 ] || label="run's scene,  "; [ "$has_win" = 0 ] || label="window + far field, "
t_on2=$(loop in_on.lmp 2); t_on1=0; t_off2=0; t_win2=0
[ "${SKIP_1RANK:-0}" = 1 ] || t_on1=$(loop in_on.lmp 1)
declare -A t_ff2
if [ "$has_win" = 1 ]; then :
elif [ "$has_ff" = 1 ]; then t_off2=$(loop in_off.lmp 2); t_win2=$(loop in_win.lmp 2)
else for rule in $wake_rules; do t_ff2[$rule]=$(loop "in_ff_$rule.lmp" 2); done; fi
atoms=$(awk '/^Loop time of/ {print $12; exit}' log_in_on.lmp_2.txt)
t_restart=$(awk 'h { print $2; exit } $1 == "Step" { h = 1 }' log_in_on.lmp_2.txt)  # thermo: step, model time
echo "== paper scene from $(basename "$restart") (t = $t_restart s) of $run_dir ($atoms spheres, $steps steps)"
awk -v a="$t_on2" -v b="$t_on1" -v c="$t_off2" -v w="$t_win2" -v l="$label" 'BEGIN {
  printf "%s2 ranks: %.1f s\n", l, a;
  if (b > 0) printf "%s1 rank : %.1f s   parallel efficiency 2 ranks: %.0f %%\n", l, b, 100 * b / (2 * a);
  if (c > 0) printf "far field off, 2 ranks: %.1f s   far-field speed-up: %.2fx\n", c, c / a;
  if (w > 0) printf "far field + moving window (case window), 2 ranks: %.1f s   window speed-up: %.2fx, both: %.2fx\n",
                    w, a / w, c / w;
}'
idle_count() {  # thermo's last column (f_farfield[1]) at the first and the last thermo line of log $1
  awk -v n="$atoms" '$1 == "Step" { h = 1; next } h && /^ *[0-9]/ { if (first == "") first = $NF; last = $NF }
    /^Loop time/ { h = 0 } END { printf "  idle pieces: %d (%.0f %%) at the start, %d (%.0f %%) at the end\n",
    first, 100 * first / n, last, 100 * last / n }' "$1"
}
held_count() {  # thermo's second-last column (f_window[1]) at the first thermo line of log $1, and its atoms
  awk '$1 == "Step" { h = 1; next } h && /^ *[0-9]/ { printf "  held out by the window: %d pieces, %d in the scene\n",
    $(NF - 1), $3; exit }' "$1"
}
if [ "$has_win" = 1 ]; then held_count log_in_on.lmp_2.txt; idle_count log_in_on.lmp_2.txt; exit 0; fi
if [ "$has_ff" = 1 ]; then
  idle_count log_in_on.lmp_2.txt
  held_count log_in_win.lmp_2.txt
  exit 0
fi
for rule in $wake_rules; do
  awk -v a="$t_on2" -v f="${t_ff2[$rule]}" -v r="$rule" 'BEGIN {
    printf "far field on (case window, wake by %s), 2 ranks: %.1f s   far-field speed-up: %.2fx\n", r, f, a / f }'
  idle_count "log_in_ff_$rule.lmp_2.txt"
done
