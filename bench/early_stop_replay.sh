#!/usr/bin/env bash
# The early-stop rule before (trend test `halves`) and after (`slope`, brash/stats/early_stop.hpp) replayed on every
# archived record long enough for a check: the paper runs and the reduced cases' runs in evidence/ (complete, or
# stopped early: those are replayed on the window they asked for, to their record's end). One row per run and
# threshold: where each rule stops, the window mean at the stop and the slope rule's estimate of the full window's
# mean against the full window's, and why the slope rule held or did not (docs/performance.md "Early stop").
# Below the table: each record's window about its fitted line (the surrogates of tests/stats/test_early_stop.cpp are
# matched to the paper runs').
#   bash bench/early_stop_replay.sh [REL_CI (0.01,0.05)] [RUNS: paper | reduced | all (all)]
# paper: evidence/paper-*; reduced: the reduced cases' runs (evidence/quick-*, evidence/study/*).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
bin="${BRASH_BIN:-$here/build/bin}"
rel="${1:-0.01,0.05}"
which="${2:-all}"
case "$which" in
  paper) globs=("$here"/evidence/paper-*/) ;;
  reduced) globs=("$here"/evidence/quick-*/ "$here"/evidence/study/*/) ;;
  all) globs=("$here"/evidence/paper-*/ "$here"/evidence/quick-*/ "$here"/evidence/study/*/) ;;
  *) echo "usage: $0 [REL_CI] [paper|reduced|all]" >&2; exit 2 ;;
esac
tmp="$(mktemp)"; trap 'rm -f "$tmp"' EXIT
shopt -s nullglob
runs=()
for d in "${globs[@]}"; do
  d="${d%/}"
  [ -f "$d/hull_force.csv" ] && [ "$(jq -r .status "$d/meta.json")" = complete ] && runs+=("$d")
done
"$bin/brash-post" early-stop "${runs[@]}" --rel-ci "$rel" --trend halves,slope > "$tmp"
# brash-post's columns: run, window, record to, full window, rel_ci, trend test, stops at, saved, window mean at
# the stop, estimate, why. A run whose windows allow no check (fewer than 64 samples by 40 % of the window) is left
# out.
awk -F'|' '
  function trim(s) { gsub(/^ +| +$/, "", s); return s }
  BEGIN { print "| run | window [s] | full window [N] | rel_ci | before (halves): stops at [s] | its mean at the stop [N] | after (slope): stops at [s] | window mean at the stop [N] | the estimate it reports [N] | why (slope rule) |"
          print "|---|---|---|---|---|---|---|---|---|---|" }
  /^\| run / || /^\|---/ || !/^\| / { next }
  { run = trim($2); key = run "|" trim($6) }
  trim($7) == "halves" { hstop[key] = trim($8); hmean[key] = trim($10); next }
  trim($7) == "slope" && trim($12) != "no check" {
    printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", run, trim($3), trim($5) == "— (record ends first)" ? "— (record stops at " trim($4) " s)" : trim($5),
           trim($6), hstop[key], hmean[key], trim($8), trim($10), trim($11), trim($12)
  }' "$tmp"
# the paper records' windows: what the surrogates are matched to
if grep -q '^- paper-' "$tmp"; then
  echo
  grep -E '^The records' "$tmp"
  echo
  grep -E '^- paper-' "$tmp"
fi
