#!/usr/bin/env bash
# The validation page is what evidence/ makes: generate it from ROOT's evidence/ into the docs/ folder of a
# temporary tree that links ROOT's evidence/, cases/ and scripts/ (so that the page's relative links are the same)
# and compare it, and its figures' data, with ROOT/docs/validation.md (exit 1 and the diff when they differ).
#   check_validation_page.sh ROOT BIN
set -euo pipefail
root="$1"; bin="$2"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/docs"
for d in evidence cases scripts; do ln -s "$(cd "$root" && pwd)/$d" "$tmp/$d"; done
BRASH_BIN="$bin" "$tmp/scripts/brash-validation" "$tmp/docs/validation.md" > "$tmp/log" 2>&1 || { cat "$tmp/log"; exit 1; }
status=0
diff -u "$root/docs/validation.md" "$tmp/docs/validation.md" || status=1
for f in "$tmp"/docs/validation_figs/*.dat; do
  diff -u "$root/docs/validation_figs/$(basename "$f")" "$f" || status=1
done
[ "$status" = 0 ] || echo "docs/validation.md is not what evidence/ makes: run make validation" >&2
exit $status
