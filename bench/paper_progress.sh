#!/usr/bin/env bash
# The paper-case runs so far, side by side: mean resistance (-fx of the hull force, model scale) in bins of
# model time, for every runs/paper-<engine>-<model> directory (finished or still running). A finished run is read
# from its hull_force.csv; a LIGGGHTS run still going from its raw force files (every attempt of a run resumed in pieces; a later attempt's row replaces an
# earlier one), an ODE run from hull_force.csv.
#   bash bench/paper_progress.sh [BIN_S (0.5)] [RUNS_DIR (runs)]
# WINDOW="T0 T1" adds a last row: each run's mean over the full bins inside [T0, T1] s (equal-length bins: the
# window mean), with the number of bins, so that runs are compared over the same window (e.g. one still going).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
bin="${BRASH_BIN:-$here/build/bin}"
bin_s="${1:-0.5}"
runs="${2:-$here/runs}"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
cols=()
shopt -s nullglob
# "t fx" rows of a finished run's hull_force.csv
csv_rows() { awk -F, 'NR > 1 && NF >= 4 { print $1, $2 }' "$1"; }
# "t fx" rows on stdin -> "bin mean(-fx) rows" per BIN_S, sorted
bin_rows() {
  awk -v b="$bin_s" '{ k = int($1 / b + 1e-9); s[k] += -$2; n[k]++ }
       END { for (k in s) printf "%d %.3f %d\n", k, s[k] / n[k], n[k] }' | sort -n
}
for d in "$runs"/paper-*/; do
  d="${d%/}"; name="$(basename "$d")"
  raws=("$d"/hull_force*.raw)
  [ ${#raws[@]} -gt 0 ] || [ -f "$d/hull_force.csv" ] || continue
  if [ ${#raws[@]} -gt 0 ] && ! jq -e '.status == "complete"' "$d/meta.json" > /dev/null 2>&1; then
    # parts in attempt order, then the current one; rows keyed by step
    # (printf, not ls: with no part file the glob is empty, and ls would list the working directory)
    parts=("$d"/hull_force.part*.raw)
    files=$( { [ ${#parts[@]} -eq 0 ] || printf '%s\n' "${parts[@]}" | sort -V; }
             [ -f "$d/hull_force.raw" ] && echo "$d/hull_force.raw" || true)
    # (a resumed attempt's first row is its set-up, without contact forces: the earlier value is kept, as the runner does)
    awk 'FNR == 1 { first = -1 } !/^#/ && NF >= 5 { if (first < 0) { first = $1; if ($1 in t) next }
         t[$1] = $2; fx[$1] = $3 } END { for (s in t) print t[s], fx[s] }' $files
  else
    csv_rows "$d/hull_force.csv"
  fi | bin_rows > "$tmp/$name"
  cols+=("$name")
done
# The runs that live on elsewhere: archived by brash-study (evidence/<name>/hull_force.csv, unless the run
# directory is here) and the 40 s paper runs whose directories were lost, kept as their histories
# (evidence/paper_histories_40s.dat: 0.5 s bins of the full-scale resistance in kN, back to model scale N;
# only when BIN_S is a multiple of 0.5 s).
for d in "$here"/evidence/paper-*/; do
  d="${d%/}"; name="$(basename "$d")"
  [ -f "$d/hull_force.csv" ] && [ ! -e "$runs/$name" ] || continue
  csv_rows "$d/hull_force.csv" | bin_rows > "$tmp/$name (archived)"
  cols+=("$name (archived)")
done
hist="$here/evidence/paper_histories_40s.dat"
per=$(awk -v b="$bin_s" 'BEGIN { m = b / 0.5; print (m >= 1 && m == int(m)) ? m : 0 }')
if [ -f "$hist" ] && [ "$per" -gt 0 ]; then
  lambda=$("$bin/brash-case" get "$here/cases/jbc_ia_5kn" ship.scale_lambda)
  while IFS= read -r label; do
    name="${label#\# } (history)"
    # rows of this block: "t_mid kN"; the kN of a 0.5 s bin -> model N, averaged over BIN_S / 0.5 bins
    awk -v L="$label" -v b="$bin_s" -v lam="$lambda" -v per="$per" '
      $0 == L { on = 1; next } /^#/ { on = 0 } on && NF == 2 {
        k = int($1 / b + 1e-9); s[k] += $2 * 1000 / (lam * lam * lam); n[k]++ }
      END { for (k in s) printf "%d %.3f %d\n", k, s[k] / n[k], (n[k] == per ? b / 0.01 : n[k] * 50) }' "$hist" |
      sort -n > "$tmp/$name"
    [ -s "$tmp/$name" ] && cols+=("$name")
  done < <(grep '^# paper-' "$hist")
fi
# (part of make bench: without a paper-case run there is nothing to show, which is not a failure)
[ ${#cols[@]} -gt 0 ] || { echo "paper_progress: no $runs/paper-* directory with a force record: skipped"; exit 0; }
printf '| t [s] |'; for c in "${cols[@]}"; do printf ' %s R [N] |' "$c"; done; echo
printf '|---|'; for c in "${cols[@]}"; do printf -- '---|'; done; echo
# full bins only (a bin still being filled is marked with its sample count)
all_keys=$(cat "$tmp"/* | awk '{ print $1 }' | sort -n -u)
full=$(awk -v b="$bin_s" 'BEGIN { printf "%d", b / 0.01 + 0.5 }')
for k in $all_keys; do
  printf '| %s-%s |' "$(awk -v k="$k" -v b="$bin_s" 'BEGIN { print k * b }')" "$(awk -v k="$k" -v b="$bin_s" 'BEGIN { print (k + 1) * b }')"
  for c in "${cols[@]}"; do
    v=$(awk -v k="$k" -v f="$full" '$1 == k { printf "%s%s", $2, ($3 < f - 1 ? " (" $3 " rows)" : "") }' "$tmp/$c")
    printf ' %s |' "${v:-—}"
  done
  echo
done
if [ -n "${WINDOW:-}" ]; then
  read -r w0 w1 <<< "$WINDOW"
  printf '| mean %s-%s |' "$w0" "$w1"
  for c in "${cols[@]}"; do
    awk -v b="$bin_s" -v f="$full" -v w0="$w0" -v w1="$w1" '
      $1 * b >= w0 - 1e-9 && ($1 + 1) * b <= w1 + 1e-9 && $3 >= f - 1 { s += $2; n++ }
      END { if (n) printf " %.3f (%d bins) |", s / n, n; else printf " — |" }' "$tmp/$c"
  done
  echo
fi
