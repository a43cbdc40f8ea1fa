#!/usr/bin/env bash
# The validation check can fail: in a copy of ROOT's evidence and page the check passes, and once the `both`
# paper run's window mean is changed in its report.json it fails.
#   check_validation_catches_change.sh ROOT BIN
set -euo pipefail
root="$1"; bin="$2"
here="$(cd "$(dirname "$0")" && pwd)"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/docs"
cp -r "$root/evidence" "$root/scripts" "$tmp/"
cp -r "$root/docs/validation.md" "$root/docs/validation_figs" "$tmp/docs/"
ln -s "$root/cases" "$tmp/cases"
bash "$here/check_validation_page.sh" "$tmp" "$bin" > /dev/null || { echo "the unchanged copy fails the check"; exit 1; }
report="$tmp/evidence/paper-liggghts-both-20s/report.json"
sed -i 's/"mean": 24\.54/"mean": 25.54/g; s/"resistance_full_kN": 568\./"resistance_full_kN": 591./' "$report"
if cmp -s "$root/evidence/paper-liggghts-both-20s/report.json" "$report"; then echo "the report was not changed"; exit 1; fi
if bash "$here/check_validation_page.sh" "$tmp" "$bin" > /dev/null 2>&1; then
  echo "a changed report was not caught"; exit 1
fi
echo "a changed report is caught"
