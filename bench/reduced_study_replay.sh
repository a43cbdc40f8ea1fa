#!/usr/bin/env bash
# Behaviour kept: rerun evidence rows of the reduced study (evidence/manifest.tsv, their own commands) and compare
# each new report with the archived one to the printed digit: the model-scale resistance and its CI as report.md
# prints them (4 decimals), the full-scale resistance and FSICR's R_CH (0.1 kN).
#   bash bench/reduced_study_replay.sh [ID ...]     (default: base_am base_drag base_both, 0.75 s runs on jbc_bench)
# The commands write under runs/replay-study/ instead of runs/study-short/. Exit 1 when a number differs.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
cd "$here"
export PATH="$here/build/bin:$PATH"
ids=("$@")
[ ${#ids[@]} -gt 0 ] || ids=(base_am base_drag base_both)
bad=0
for id in "${ids[@]}"; do
  row="$(awk -F'\t' -v id="$id" '$1 == id { print; exit }' evidence/manifest.tsv)"
  [ -n "$row" ] || { echo "$id: no such row in evidence/manifest.tsv" >&2; exit 2; }
  run_dir="$(cut -f9 <<<"$row")"
  cmd="$(cut -f10 <<<"$row" | sed 's#runs/study-short#runs/replay-study#g')"
  out="$(grep -o -- '--out [^ ]*' <<<"$cmd" | cut -d' ' -f2)"
  rm -rf "$out"
  echo "== $id: $cmd" >&2
  bash -c "$cmd" > "runs/replay-$id.log" 2>&1 || { echo "$id: the command failed (runs/replay-$id.log)"; bad=1; continue; }
  /usr/bin/python3 - "evidence/$run_dir/report.json" "$out/report.json" "$id" <<'PY' || bad=1
import json, sys
old, new = (json.load(open(p)) for p in sys.argv[1:3])
def printed(r):
    m = r.get("resistance_model_N") or {}
    return (f"{m.get('mean', float('nan')):.4f} ± {m.get('ci95', float('nan')):.4f} N",
            f"{r.get('resistance_full_kN') or float('nan'):.1f} kN",
            f"R_CH {((r.get('fsicr') or {}).get('R_CH_kN')) or float('nan'):.1f} kN")
a, b = printed(old), printed(new)
print(f"{sys.argv[3]}: archived {' | '.join(a)}; now {' | '.join(b)}: {'same' if a == b else 'DIFFERENT'}")
sys.exit(0 if a == b else 1)
PY
done
exit $bad
