#!/usr/bin/env bash
# The speed sweep on the quick case (cases/jbc_quick, its 7 m channel): SPEEDS x MODELS LIGGGHTS runs at the same
# bow travel as the case's own 11 s at 0.482 m/s (duration 11 s x 0.482 / U, rounded to the 0.008 s output
# interval), window its last 40 %: the stem ends ~1.9 m from the far end at every speed, and the window starts
# after 6.6 s-at-0.482 m/s of travel (the slower the ship, the longer the ice ahead of the bow takes to settle: at
# 0.3 m/s the last 50 % still drifted with drag, the last 40 % did not). The contact band reaches 0.3 m below the
# waterline at every speed (the case's 0.2 m held the ice up to 0.482 m/s, deepest piece bottom 0.175 m; at
# 0.7 m/s pieces reached 0.204 m, at 1.0 m/s one passed under the band into the hull and the guard stopped the run).
#   bash bench/quick_speed_sweep.sh [WORK_DIR]   (default runs/quick-speed; env SPEEDS, MODELS, JOBS)
# Runs JOBS (default 2) single-rank runs at a time, slowest first (~25 min on 2 cores); a run directory that
# already holds a report is kept. WORK_DIR/<case>_<model>.cmd holds the commands that made each run (the study's
# manifest lists them). Each run's report says whether its window has a blocking plateau and is
# stationary; brash-study-report fits R = a U^n over the sweep.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
bin="${BRASH_BIN:-$here/build/bin}"
work="$(mkdir -p "${1:-$here/runs/quick-speed}" && cd "${1:-$here/runs/quick-speed}" && pwd)"
speeds="${SPEEDS:-0.2 0.3 0.482 0.7 1.0}"
models="${MODELS:-both drag}"
mkdir -p "$work/cases"
: > "$work/jobs.txt"
for u in $speeds; do
  dur=$(awk -v u="$u" 'BEGIN { printf "%.3f", int(11.0 * 0.482 / u / 0.008 + 0.5) * 0.008 }')
  w0=$(awk -v d="$dur" 'BEGIN { printf "%.3f", 0.6 * d }')
  name="quick_u$u"
  new=(new "$name" --cases-dir "$work/cases" --template cases/jbc_quick/case.yaml --speed "$u" --duration "$dur"
       --window "$w0" "$dur" --band 0.3 0.1 --force)
  (cd "$here" && "$bin/brash-case" "${new[@]}") > "$work/cases/$name.log"
  echo "brash-case ${new[*]} && brash-pack $work/cases/$name" > "$work/cases/$name.cmd"
  for m in $models; do echo "$u $name $m" >> "$work/jobs.txt"; done
done
# the packing once per case folder before the runs start (two runs of one case would both write it)
for u in $speeds; do "$bin/brash-pack" "$work/cases/quick_u$u" > "$work/cases/quick_u$u.pack.log"; done
run_one() {
  local name="$2" model="$3" out="$work/$2_$3"
  echo "$(cat "$work/cases/$name.cmd") && brash-liggghts-run $work/cases/$name --np 1 --model $model --out $out" \
    > "$out.cmd"
  [ -f "$out/report.json" ] && return 0
  rm -rf "$out"
  "$bin/brash-liggghts-run" "$work/cases/$name" --np 1 --model "$model" --out "$out" > "$out.log" 2>&1 ||
    echo "quick_speed_sweep: $name $model failed (see $out.log)" >&2
}
export -f run_one
export work bin
sort -n "$work/jobs.txt" | xargs -P "${JOBS:-2}" -L 1 bash -c 'run_one "$@"' _
for f in "$work"/quick_u*/report.json; do echo "$f"; done
