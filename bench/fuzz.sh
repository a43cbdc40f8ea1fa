#!/usr/bin/env bash
# Benchmark: libFuzzer on every parser (tests/fuzz: case YAML, packing CSV, STL binary+ASCII, fix
# brash/guard arguments), FUZZ_SECONDS (default 60) each, 1 worker (2-core machine). Builds tests/fuzz with
# clang into build/fuzz. Fails if any target finds a crash, sanitizer report, foreign exception, leak,
# timeout or out-of-memory; the reproducer is kept in build/fuzz/findings/<target>/.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
seconds="${FUZZ_SECONDS:-60}"
build="${BRASH_FUZZ_BUILD:-$here/build/fuzz}"
command -v clang++ >/dev/null || { echo "fuzz: clang++ not found (make deps installs clang, libclang-rt-14-dev)" >&2; exit 1; }
cmake -S "$here/tests/fuzz" -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++ >/dev/null
cmake --build "$build" -j1 >/dev/null
status=0
for t in case packing stl guard_args; do
  corpus="$build/corpus/$t"; findings="$build/findings/$t"
  mkdir -p "$corpus" "$findings"
  cp -n "$here/tests/fuzz/corpus/$t/"* "$corpus/" 2>/dev/null || true
  log="$build/fuzz_$t.log"
  # -rss_limit_mb / -timeout: memory blow-ups and hangs are findings too. detect_leaks: leaks are findings.
  if "$build/fuzz_$t" "$corpus" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
       -artifact_prefix="$findings/" -print_final_stats=1 >"$log" 2>&1; then
    runs=$(awk '/stat::number_of_executed_units/{print $2}' "$log")
    cov=$(grep -Eo 'cov: [0-9]+' "$log" | tail -1 | awk '{print $2}')
    echo "fuzz_$t: ${seconds} s, ${runs:-?} inputs, coverage ${cov:-?} edges, corpus $(ls "$corpus" | wc -l) files: 0 findings"
  else
    status=1
    echo "fuzz_$t: FINDING (see $log and $findings/):" >&2
    grep -E 'ERROR|SUMMARY|terminate|what\(\)' "$log" | head -5 >&2
  fi
done
exit $status
