#!/bin/sh
# The key table of a Markdown page (the lines from the "case keys: begin" marker to the "case keys: end" marker)
# is what `brash-case keys --markdown` prints. Usage: check_case_keys.sh PAGE BRASH_CASE_EXE
page=$1
exe=$2
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
"$exe" keys --markdown > "$tmp/want.md" || exit 1
sed -n '/^<!-- case keys: begin/,/^<!-- case keys: end -->$/p' "$page" > "$tmp/page.md"
if ! diff -u "$tmp/page.md" "$tmp/want.md"; then
  echo "$page: the key table is not the loader's: run brash-case keys --page $page"
  exit 1
fi
