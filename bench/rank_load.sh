#!/usr/bin/env bash
# Per-rank load of a case's LIGGGHTS scene at t = 0, at several rank counts (oversubscribed where the machine has
# fewer cores: the decomposition, not the speed, is measured): pieces, ghosts and neighbour pairs per rank, as
# mean and max / mean, from LIGGGHTS' own end-of-run statistics after one step of the runner's input script.
#   bash bench/rank_load.sh [CASE_DIR] [RANKS ...]      (default: cases/jbc_ia_5kn, 2 4 8 16)
# Environment: BRASH_BIN (build/bin); HULL_X_M: start the hull there instead (a variant derived with brash-case
# derive, same packing): e.g. HULL_X_M=3 puts the JBC model's bow 10 m into the paper channel's ice, so the
# hull's mesh and the ice it pushes weigh on the ranks that hold them.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
bin="${BRASH_BIN:-$here/build/bin}"
case_dir="${1:-$here/cases/jbc_ia_5kn}"
[ $# -gt 0 ] && shift
ranks=("$@")
[ ${#ranks[@]} -gt 0 ] || ranks=(2 4 8 16)
work="$(mktemp -d)"
trap '[ -n "${KEEP:-}" ] || rm -rf "$work"' EXIT
if [ -n "${HULL_X_M:-}" ]; then
  # pieces the hull now overlaps are inside it for the one step measured: the hull penetration guard is off
  "$bin/brash-case" derive "$case_dir" --set "hull.start_x_m=$HULL_X_M" --set guards.max_hull_penetration_d=0 \
    --out "$work/case" > /dev/null
  case_dir="$work/case"
fi
"$bin/brash-liggghts-run" "$case_dir" --prepare-only --np 2 --out "$work/prep" > /dev/null

# "Nlocal:    52176.9 ave 53000 max 51000 min" -> "52176.9 53000"
stat() { awk -v key="$1:" '$1 == key { print $2, $4; exit }' "$2"; }

echo "| ranks | pieces per rank | max / mean | ghosts per rank | ghosts / pieces | neighbour pairs per rank | max / mean | setup + 1 step [s] |"
echo "|---|---|---|---|---|---|---|---|"
for np in "${ranks[@]}"; do
  d="$work/np$np"
  cp -r "$work/prep" "$d"
  # one step of the runner's scene (its processor grid, box and neighbour settings), no outputs
  grep -vE '^(dump|dump_modify|restart|write_restart) ' "$work/prep/in.lmp" | sed -E 's/^run [0-9]+/run 1/' > "$d/in.lmp"
  start=$(date +%s.%N)
  (cd "$d" && mpirun --allow-run-as-root --oversubscribe -np "$np" "$bin/brash-liggghts" -in in.lmp -log none) \
    > "$d/screen.txt" 2>&1 || { echo "| $np | failed: see $d/screen.txt |"; tail -5 "$d/screen.txt"; continue; }
  wall=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')
  read -r la lm < <(stat Nlocal "$d/screen.txt")
  read -r ga gm < <(stat Nghost "$d/screen.txt")
  read -r na nm < <(stat Neighs "$d/screen.txt")
  awk -v np="$np" -v la="$la" -v lm="$lm" -v ga="$ga" -v na="$na" -v nm="$nm" -v w="$wall" 'BEGIN {
    printf "| %d | %.0f | %.3f | %.0f | %.2f | %.0f | %.3f | %.1f |\n", np, la, lm / la, ga, ga / la, na, nm / na, w }'
done
