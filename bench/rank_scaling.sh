#!/usr/bin/env bash
# Wall time per step and per-rank load of a case's LIGGGHTS scene at several rank counts and processor grids, from
# LIGGGHTS' own loop time, its breakdown (pair, neighbour, communication, the rest: fixes and waiting) and its
# end-of-run statistics (pieces, ghosts and neighbour pairs per rank: mean and max / mean). Timings need a machine
# with as many cores as ranks; the load is the decomposition's and can be read oversubscribed (bench/rank_load.sh).
#   bash bench/rank_scaling.sh [CASE_DIR] [RANKS ...]          (default: cases/jbc_ia_5kn, 1 2 4 8 16)
# Environment:
#   STEPS (200)          steps timed per run (the atoms are sorted spatially first, as the runner's
#                        `atom_modify sort` has them after its first 1000 steps)
#   GRIDS ("1 * 1")      processor grids, separated by ';' (LIGGGHTS' `processors` arguments; the runner writes
#                        "1 * 1"); a grid with more than one domain along x gets a box centred on the ice along x,
#                        so that its halves hold equal shares of the channel
#   HULL_X_M             start the hull there (a variant derived with brash-case derive, same packing): e.g. 3
#                        puts the JBC model's bow 10 m into the paper channel's ice
#   HULL (1)             0: the scene without the hull (its mesh and contacts), the ice alone
#   REPEAT (1)           times each grid and rank count is run, interleaved (1 rank only once)
#   CONCURRENT ("")      rank counts n at which to also run n independent 1-rank copies of a 1/n-wide slice of the
#                        channel at once, against one alone: the slowdown is the machine's, not MPI's
#   SCENE                a scene folder already written by `brash-liggghts-run --prepare-only`
#   BRASH_BIN (build/bin), BRASH_MPI_LAUNCHER ("mpirun"), MPI_ARGS (more launcher arguments), KEEP (keep the runs)
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
bin="${BRASH_BIN:-$here/build/bin}"
case_dir="${1:-$here/cases/jbc_ia_5kn}"
[ $# -gt 0 ] && shift
ranks=("$@")
[ ${#ranks[@]} -gt 0 ] || ranks=(1 2 4 8 16)
steps="${STEPS:-200}"
launcher="${BRASH_MPI_LAUNCHER:-mpirun}"
IFS=';' read -r -a grids <<< "${GRIDS:-1 * 1}"
work="$(mktemp -d)"
trap '[ -n "${KEEP:-}" ] || rm -rf "$work"' EXIT

scene="${SCENE:-}"
if [ -z "$scene" ]; then
  # every piece integrated from the packing (the scene these timings are of; the paper case's settled bed would
  # first be made, ~25 min on one rank)
  sets=(--set ice.settle=false --set speedups.farfield=false --set speedups.moving_window=false)
  # pieces the hull now overlaps are inside it at the start: the hull penetration guard is off
  [ -z "${HULL_X_M:-}" ] || sets+=(--set "hull.start_x_m=$HULL_X_M" --set guards.max_hull_penetration_d=0)
  "$bin/brash-case" derive "$case_dir" "${sets[@]}" --out "$work/case" > /dev/null
  case_dir="$work/case"
  "$bin/brash-liggghts-run" "$case_dir" --prepare-only --np 2 --out "$work/prep" > /dev/null
  scene="$work/prep"
fi

# packing.data with its atoms in bins of 5 cm (z, then y, then x), ids kept: the order the runner's periodic sort
# gives, without waiting 1000 steps for it
awk -v b=0.05 '
  /^Atoms/ { print; atoms = 1; next }
  atoms && NF == 7 { printf "%d %d %d %s\n", int(($7 + 10) / b), int(($6 + 10) / b), int(($5 + 100) / b), $0 > "/dev/stderr"; next }
  { print }' "$scene/packing.data" > "$work/head.data" 2> "$work/atoms.keyed"
sort -n -k1,1 -k2,2 -k3,3 "$work/atoms.keyed" | cut -d' ' -f4- > "$work/atoms.sorted"
n_atoms=$(wc -l < "$work/atoms.sorted")
ice_xlo=$(awk '{ if (NR == 1 || $5 < m) m = $5 } END { print m }' "$work/atoms.sorted")
ice_xhi=$(awk '{ if (NR == 1 || $5 > m) m = $5 } END { print m }' "$work/atoms.sorted")

# head.data holds the header and an empty Atoms section; write packing.data with box xlo/xhi as given
write_data() {  # out xlo xhi [atoms file]
  awk -v lo="$2" -v hi="$3" '$3 == "xlo" && $4 == "xhi" && lo != "" { $1 = lo; $2 = hi } { print }' \
    "$work/head.data" > "$1"
  cat "${4:-$work/atoms.sorted}" >> "$1"
}

# the runner's script, timed: no outputs, STEPS steps, the grid given
write_input() {  # out grid
  grep -vE '^(dump|dump_modify|restart|write_restart|processors|fix hf) ' "$scene/in.lmp" |
    sed -E "s/^run [0-9]+/run $steps/; s/^read_data .*/processors $2\nread_data packing.data/" > "${1/#-//dev/stdout}"
}

# the script without the hull (fixes hull, hullwall, mv; the guard's hull check; f_hull in thermo)
without_hull() {
  grep -vE '^fix (hull|hullwall|mv) ' | sed -E "s/ hull [^ ]+( [^ ]+){6} max_penetration [^ ]+//; s/ f_hull\[1\]//"
}

# "Loop time of 12.3 on 4 procs for 200 steps with 417415 atoms"; "Pair  time (%) = 8.1 (65.9)"
loop_time() { awk '/^Loop time of/ { print $4; exit }' "$1"; }
# "Nlocal:    52176.9 ave 53000 max 51000 min" -> "52176.9 53000"
stat() { awk -v key="$1:" '$1 == key { print $2, $4; exit }' "$2"; }
share() { awk -v k="$1" '$1 == k && $2 == "time" { gsub(/[()]/, "", $6); print $6; exit }' "$2"; }

box_xlo=$(awk '$3 == "xlo" { print $1 }' "$work/head.data")
box_xhi=$(awk '$3 == "xlo" { print $2 }' "$work/head.data")
echo "scene: $n_atoms pieces, box x $box_xlo..$box_xhi m, ice x $ice_xlo..$ice_xhi m, $steps steps per run, $(nproc) cores"
echo
echo "| grid | ranks | per step [ms] | speed-up | efficiency | pair % | neigh % | comm % | other % | pieces per rank | max / mean | ghosts / pieces | pairs per rank | max / mean |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
t1=""
for rep in $(seq 1 "${REPEAT:-1}"); do
for grid in "${grids[@]}"; do
  for np in "${ranks[@]}"; do
    [ "$rep" -gt 1 ] && [ "$np" = 1 ] && continue
    d="$work/run-${grid// /}-$np"
    d="${d//\*/x}"
    px=$(awk '{ print $1 }' <<< "$grid")
    [ "$px" = "*" ] || [ "$np" -ge "$px" ] || continue
    mkdir -p "$d"
    cp "$scene"/*.stl "$d/"
    write_input "$d/in.lmp" "$grid"
    if [ "${HULL:-1}" = 0 ]; then without_hull < "$d/in.lmp" > "$d/in.nohull" && mv "$d/in.nohull" "$d/in.lmp"; fi
    if [ "$px" != "1" ] && [ "$np" -gt 1 ]; then
      # centre the box's x range on the ice, keeping all of the runner's box
      centre=$(awk -v a="$ice_xlo" -v b="$ice_xhi" 'BEGIN { print 0.5 * (a + b) }')
      half=$(awk -v c="$centre" -v lo="$box_xlo" -v hi="$box_xhi" 'BEGIN { h = c - lo; if (hi - c > h) h = hi - c; print h }')
      write_data "$d/packing.data" "$(awk -v c="$centre" -v h="$half" 'BEGIN { printf "%.9g", c - h }')" \
        "$(awk -v c="$centre" -v h="$half" 'BEGIN { printf "%.9g", c + h }')"
    else
      write_data "$d/packing.data" "" ""
    fi
    # shellcheck disable=SC2086
    if ! (cd "$d" && $launcher ${MPI_ARGS:-} -np "$np" "$bin/brash-liggghts" -in in.lmp -log none) > "$d/screen.txt" 2>&1; then
      echo "| $grid | $np | failed: $(grep -m1 -E 'ERROR|error' "$d/screen.txt" || tail -1 "$d/screen.txt") |"
      continue
    fi
    t=$(loop_time "$d/screen.txt")
    [ "$np" = 1 ] && [ -z "$t1" ] && t1="$t"
    awk -v g="$grid" -v np="$np" -v t="$t" -v t1="$t1" -v s="$steps" -v pa="$(share Pair "$d/screen.txt")" \
      -v ne="$(share Neigh "$d/screen.txt")" -v co="$(share Comm "$d/screen.txt")" \
      -v ot="$(share Other "$d/screen.txt")" -v lo="$(stat Nlocal "$d/screen.txt")" \
      -v gh="$(stat Nghost "$d/screen.txt")" -v ne2="$(stat Neighs "$d/screen.txt")" 'BEGIN {
      split(lo, nl, " "); split(gh, ng, " "); split(ne2, np2, " ")
      su = (t1 == "") ? "" : sprintf("%.2f", t1 / t); ef = (t1 == "") ? "" : sprintf("%.0f %%", 100 * t1 / t / np)
      printf "| %s | %d | %.1f | %s | %s | %.1f | %.1f | %.1f | %.1f | %.0f | %.3f | %.2f | %.0f | %.3f |\n", g, np, 1000 * t / s,
        su, ef, pa, ne, co, ot, nl[1], nl[2] / nl[1], ng[1] / nl[1], np2[1], np2[2] / np2[1] }'
  done
done
done

# independent 1-rank runs of a slice of the channel 1/n of its width wide about y = 0, its box as wide as a
# rank's subdomain with its ghost layers (5 cm each side, about two piece diameters): the work and memory one of n ranks has, without MPI. n at once against
# one alone: the slowdown is the machine's (shared memory bandwidth and caches, clock), not the decomposition's.
slice_data() {  # n out
  awk -v h="$(awk -v n="$1" 'BEGIN { print 1.125 / n }')" '$6 * $6 < h * h' "$work/atoms.sorted" > "$2.atoms"
  awk -v c="$(wc -l < "$2.atoms")" -v lo="$(awk -v n="$1" 'BEGIN { print -1.125 / n - 0.05 }')" \
    '/atoms$/ && !done { $1 = c; done = 1 } $3 == "ylo" { $1 = lo; $2 = -lo } { print }' "$work/head.data" > "$2"
  cat "$2.atoms" >> "$2"
}
run_slice() {  # dir label
  # shellcheck disable=SC2086
  (cd "$1" && $launcher ${MPI_ARGS:-} --bind-to none -np 1 "$bin/brash-liggghts" -in in.lmp -log none) > "$1/$2.txt" 2>&1
  loop_time "$1/$2.txt"
}
for n in ${CONCURRENT:-}; do
  slice_data "$n" "$work/slice-$n.data"
  for k in $(seq 1 "$n"); do
    d="$work/slice-$n-$k"
    mkdir -p "$d"
    # without the hull: its mesh must lie inside the box, which is now a slice (at t = 0 it is not in the ice)
    write_input - "1 1 1" | without_hull | sed -E "s/^run [0-9]+/run $((steps * 2))/" > "$d/in.lmp"
    cp "$work/slice-$n.data" "$d/packing.data"
  done
  alone=$(run_slice "$work/slice-$n-1" alone)
  for k in $(seq 1 "$n"); do run_slice "$work/slice-$n-$k" together > "$work/slice-$n-$k/t" & done
  wait
  together=$(cat "$work"/slice-"$n"-*/t | awk '{ s += $1; if ($1 > m) m = $1 } END { printf "%.2f %.2f", s / NR, m }')
  awk -v a="$alone" -v n="$n" -v t="$together" -v p="$(wc -l < "$work/slice-$n.data.atoms")" -v s="$((steps * 2))" 'BEGIN {
    split(t, x, " ")
    printf "independent 1-rank runs of a 1/%d slice (%d pieces, %d steps): one alone %.2f s; %d at once: mean %.2f s, slowest %.2f s; slowdown %.2fx (mean), %.2fx (slowest)\n", n, p, s, a, n, x[1], x[2], x[1] / a, x[2] / a }'
done
