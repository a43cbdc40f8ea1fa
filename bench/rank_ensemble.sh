#!/usr/bin/env bash
# A case run as an ensemble of packing seeds, two ways per seed (1 against 2 ranks, or a
# knob against the reference). A contact scene diverges chaotically from
# round-off, so one run per variant is one realisation each and their difference is dominated by run-to-run scatter.
# Here every member is a packing seed (ice.seed); seed s runs as side A and as side B with the same packing (a pair),
# so the pair's difference holds the chaotic scatter and the effect of the change, not the packing's. The result is
# B's effect on side A, (B - A) / A of the ensemble means, with its 95 % confidence interval (delta method, Student
# t; brash/stats/paired.hpp): B makes no difference beyond 1 % when that interval lies inside [-1 %, +1 %].
#   bash bench/rank_ensemble.sh [N_SEEDS (12)] [OUT (runs/rank-ensemble)]
# env: CASE (cases/jbc_narrow), SIDE_A ("1"), SIDE_B ("2"): a side is NP[:section.key=value,...] (MPI ranks, then
# edits of the case, as in bench/speed_vs_error.sh), e.g. SIDE_B="1:run.timestep_s=2.0e-4" for the dt knob; NP
# `ode`, `ode@DT` or `ode@DT@ITERATIONS` runs the side on brash-ode instead (at its default step, or `--dt DT`, and
# `--iterations ITERATIONS` quickstep iterations), then brash-post; ODE_ARGS: more brash-ode options for every ODE
# side (e.g. "--settle 0.2"; the run names do not show them: give such an ensemble its own OUT);
# TOL_PCT (1): the tolerance the CI is tested against (2 % for a speed-up knob). The wall-time ratio A / B of the
# summed runs is printed too (a knob's speed-up; only as fair as the load was alike when the two sides ran).
# Part of make bench (~1 h on a fresh machine; re-prints once the runs exist). 1-rank runs go two at a time (JOBS,
# one per core), others one at a time: ~4-5 min per quick-case pair on a quiet
# 2-core machine. Finished runs are kept and skipped, so the script can be stopped and started again, and N raised
# later. BRASH_BIN (default build/bin) holds the executables.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
n_seeds="${1:-12}"
out="${2:-$here/runs/rank-ensemble}"
bin="${BRASH_BIN:-$here/build/bin}"
case_src="$(cd "${CASE:-$here/cases/jbc_narrow}" && pwd)"
case_base="$(basename "$case_src")"
sides=("${SIDE_A:-1}" "${SIDE_B:-2}")
mkdir -p "$out/cases"
source "$here/bench/case_variant.sh"
np_of() { echo "${1%%:*}"; }
edits_of() { [[ "$1" == *:* ]] && echo "${1#*:}" || true; }
is_ode() { [[ "$(np_of "$1")" == ode* ]]; }
# field N of an ODE side ode[@DT[@ITERATIONS]]: 1 = DT, 2 = ITERATIONS (empty when not given)
ode_field() { local IFS=@ f; read -r -a f <<< "$(np_of "$1")"; echo "${f[$2]:-}"; }
# run name of a side: np<N> or ode[_dt<DT>][_it<N>], plus the edits when there are any (np1-run.timestep_s_2.0e-4);
# a name too long for the seed case's folder <case>_s<N>-<name> (a file name: 255 characters) keeps what fits
# less 17 characters, then a hash of the whole
side_name() {
  local e np dt it name; e="$(edits_of "$1")"; np="$(np_of "$1")"
  if is_ode "$1"; then
    dt="$(ode_field "$1" 1)"; it="$(ode_field "$1" 2)"; np="ode${dt:+_dt$dt}${it:+_it$it}"
  else
    np="np$np"
  fi
  name="$np${e:+-$(printf '%s' "$e" | tr ',=' '__' | tr -cd 'A-Za-z0-9._-')}"
  local fits=$((255 - ${#case_base} - ${#n_seeds} - 3))
  [ "${#name}" -le "$fits" ] || name="${name:0:$((fits - 17))}-$(printf '%s' "$name" | sha256sum | cut -c1-16)"
  echo "$name"
}
# human label of a side, as the table prints it: "2 ranks", "ODE, dt 5e-4 s, 40 iterations", plus the edits
side_label() {
  local e np dt it label; e="$(edits_of "$1")"; np="$(np_of "$1")"
  if is_ode "$1"; then
    dt="$(ode_field "$1" 1)"; it="$(ode_field "$1" 2)"
    label="ODE${dt:+, dt $dt s}${it:+, $it iterations}"
  else
    label="$np rank$([ "$np" = 1 ] || echo s)"
  fi
  echo "$label${e:+, $e}"
}
engines=(brash-liggghts-run); for side in "${sides[@]}"; do is_ode "$side" && engines+=(brash-ode); done
for exe in brash-case brash-pack "${engines[@]}" brash-post; do
  [ -x "$bin/$exe" ] || { echo "rank_ensemble: $bin/$exe not found (build first, or set BRASH_BIN)" >&2; exit 2; }
done
command -v jq > /dev/null || { echo "rank_ensemble: jq not found (make deps installs it)" >&2; exit 2; }
seed_case() { echo "$out/cases/$(basename "$case_src")_s$1"; }
complete() { [ -f "$1/report.json" ] && jq -e '.status == "complete"' "$1/report.json" > /dev/null; }
run_one() {  # seed, side
  local name; name="$(side_name "$2")"
  local run="$out/s$1-$name" case_dir edits
  complete "$run" && return 0
  case_dir="$(seed_case "$1")"; edits="$(edits_of "$2")"
  if [ -n "$edits" ]; then  # the seed's case with the side's edits, on the seed's packing
    case_variant_same_packing "$bin" "$case_dir" "$case_dir-$name" "$edits"
    case_dir="$case_dir-$name"
  fi
  rm -rf "$run"
  echo "== seed $1, $2 -> $run ($(date +%H:%M:%S))"
  if is_ode "$2"; then
    local dt it ode_args=(); dt="$(ode_field "$2" 1)"; it="$(ode_field "$2" 2)"
    [ -n "$dt" ] && ode_args+=(--dt "$dt")
    [ -n "$it" ] && ode_args+=(--iterations "$it")
    read -r -a extra <<< "${ODE_ARGS:-}"
    ode_args+=("${extra[@]}")
    { "$bin/brash-ode" "$case_dir" --out "$run" "${ode_args[@]}" --no-progress && "$bin/brash-post" "$run"; } > "$run.log" 2>&1 ||
      echo "   seed $1, $2 failed (exit $?): see $run.log"
  else
    "$bin/brash-liggghts-run" "$case_dir" --np "$(np_of "$2")" --out "$run" > "$run.log" 2>&1 ||
      echo "   seed $1, $2 failed (exit $?): see $run.log"
  fi
}
for s in $(seq 1 "$n_seeds"); do
  case_dir="$(seed_case "$s")"
  if [ ! -f "$case_dir/generated/packing.csv" ]; then
    "$bin/brash-case" new "$(basename "$case_dir")" --cases-dir "$out/cases" --template "$case_src/case.yaml" \
      --seed "$s" --force > /dev/null
    # the template's hull file is found through BRASH_HULL_DIR / the build's hull_meshes, as for the case itself
    "$bin/brash-pack" "$case_dir" > "$case_dir/pack.log"
  fi
done
for side in "${sides[@]}"; do
  for s in $(seq 1 "$n_seeds"); do
    if { [ "$(np_of "$side")" = 1 ] || is_ode "$side"; } && [ "${JOBS:-2}" -gt 1 ]; then
      run_one "$s" "$side" &
      while [ "$(jobs -rp | wc -l)" -ge "${JOBS:-2}" ]; do wait -n || true; done
    else
      run_one "$s" "$side"
    fi
  done
  wait
done
# the table, the ensemble statement and OUT/ensemble-<A>-vs-<B>.json (read by brash-study-report and
# bench/pareto_plot.sh): the mean paired difference with its Student-t 95 % CI (brash/stats/paired.hpp)
"$bin/brash-post" paired-ensemble "$out" --seeds "$n_seeds" --case "$(basename "$case_src")" \
  --side-a "${sides[0]}" --side-b "${sides[1]}" --name-a "$(side_name "${sides[0]}")" \
  --name-b "$(side_name "${sides[1]}")" --label-a "$(side_label "${sides[0]}")" \
  --label-b "$(side_label "${sides[1]}")" --tol-pct "${TOL_PCT:-1}"
