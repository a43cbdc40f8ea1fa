#!/usr/bin/env bash
# Benchmark: stability map of the engine-independent core (docs/stability.md). One ice sphere integrated by
# brash::core::ReferenceSphere over time step x Ca (0, 0.5, 2, 10) x treatment x density ratio x impact speed,
# the explicit boundary against the theory m_a/m = Ca rho_w s / rho_i = 1, and the paper's settings with
# their time-step margin. Prints Markdown; fails if the paper's settings (Table 1, implicit, dt 5e-5) are
# not stable.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
bin="${BRASH_BIN:-$here/build/bin}"
out="${BRASH_BENCH_OUT:-$(mktemp /tmp/brash-stability-XXXX.md)}"
"$bin/brash-stability-core" "$@" | tee "$out"
echo "(map written to $out)"
if grep -E '^\| table1 \| implicit \|' "$out" | grep -q UNSTABLE; then
  echo "stability_core: the paper's settings are NOT stable" >&2
  exit 1
fi
