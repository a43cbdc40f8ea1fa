#!/usr/bin/env bash
# Benchmark on the paper scene itself: 1,000 steps from a restart file of a paper-case run directory
# (brash-liggghts-run cases/jbc_ia_5kn ...; needs restart/a.restart or b.restart), timed in one sitting:
#   far field on, 2 ranks  |  far field on, 1 rank  (parallel efficiency)  |  far field off, 2 ranks (its speed-up);
# a run without the far field (the paper case's default since session 6) is timed on 2 and 1 ranks only.
# The run's own in.lmp is used with dumps, restart and force output removed; "off" drops fix brash/farfield,
# deletes group idle and its neighbour exclusion (every piece integrated, every pair computed).
#   bash bench/paper_scene.sh RUN_DIR [STEPS]        (skipped with a message when RUN_DIR has no restart)
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
bin="${BRASH_BIN:-$here/build/bin}"
run_dir="${1:-$here/runs/paper-liggghts-added_mass}"
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
sed -e 's|^read_data packing.data|read_restart start.restart|' -e '/^fix hf /d' -e '/^dump/d' -e '/^restart /d' \
    -e '/^write_restart/d' -e "s/^run .*/run $steps/" "$run_dir/in.lmp" > "$work/in_on.lmp"
sed -e '/^fix farfield/d' -e 's/^group idle subtract all all/group idle delete/' \
    -e 's/^neigh_modify delay 0 exclude group idle idle/neigh_modify delay 0/' "$work/in_on.lmp" > "$work/in_off.lmp"
cd "$work"
loop() {  # $1 input, $2 ranks -> loop time [s]
  if [ "$2" = 1 ]; then "$bin/brash-liggghts" -in "$1" -log "log_$1_$2.txt" > /dev/null 2>&1
  else mpirun --allow-run-as-root --oversubscribe -np "$2" "$bin/brash-liggghts" -in "$1" -log "log_$1_$2.txt" > /dev/null 2>&1; fi
  awk '/^Loop time of/ {print $4; exit}' "log_$1_$2.txt"
}
# The far field is off in the paper case since session 6: then the run's own scene is measured on 1 and 2 ranks only.
has_ff=0; grep -q '^fix farfield' in_on.lmp && has_ff=1
label="far field on, "; [ "$has_ff" = 1 ] || label="run's scene,  "
t_on2=$(loop in_on.lmp 2); t_on1=$(loop in_on.lmp 1); t_off2=0
[ "$has_ff" = 1 ] && t_off2=$(loop in_off.lmp 2)
atoms=$(awk '/^Loop time of/ {print $12; exit}' log_in_on.lmp_2.txt)
echo "== paper scene from $(basename "$restart") of $run_dir ($atoms spheres, $steps steps)"
awk -v a="$t_on2" -v b="$t_on1" -v c="$t_off2" -v l="$label" 'BEGIN {
  printf "%s2 ranks: %.1f s\n", l, a;
  printf "%s1 rank : %.1f s   parallel efficiency 2 ranks: %.0f %%\n", l, b, 100 * b / (2 * a);
  if (c > 0) printf "far field off, 2 ranks: %.1f s   far-field speed-up: %.2fx\n", c, c / a;
  else print "(far field off in this run: no far-field comparison)";
}'
