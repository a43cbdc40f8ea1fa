#!/usr/bin/env bash
# Benchmark: brash-post throughput on a paper-size particle snapshot. One short quick-case run
# gives a valid run directory; brash-post is timed on it twice in the same sitting: with its own small
# snapshots, and with them replaced by one synthetic snapshot of POST_BENCH_ATOMS spheres (default 420,000,
# the paper case; deterministic values, the particles_<step>.csv layout of docs/case_format.md). The
# difference is the cost of reading the snapshot and writing its ParaView file; printed as spheres/s.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
bin="${BRASH_BIN:-$here/build/bin}"
atoms="${POST_BENCH_ATOMS:-420000}"
work="$(mktemp -d /tmp/brash-postbench-XXXX)"
trap 'rm -rf "$work"' EXIT

"$bin/brash-liggghts-run" "$here/cases/jbc_narrow" --duration 0.02 --out "$work/small" --no-post >/dev/null 2>&1 ||
  { echo "bench: the quick-case run for the run layout failed" >&2; exit 1; }
cp -r "$work/small" "$work/big"
rm -f "$work/big/particles/"particles_*.csv
awk -v n="$atoms" 'BEGIN {
  srand(1);
  print "id,x,y,z,radius,vx,vy,vz,submerged_fraction,ca_x,ca_y,ca_z";
  for (i = 1; i <= n; i++)
    printf "%d,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,0.5,0.5,%.6g\n", i, 21 * rand(), 2.25 * rand() - 1.125,
           -0.035 * rand(), 0.0088 + 0.0005 * rand(), 0.1 * rand(), 0.1 * rand(), 0.1 * rand(), rand(), rand();
}' > "$work/big/particles/particles_0000000000.csv"
printf 'step,t_s,file,hull_x_m\n0,0,particles_0000000000.csv,-7.2\n' > "$work/big/particles/index.csv"
size_mb=$(du -m "$work/big/particles/particles_0000000000.csv" | cut -f1)

wall() {  # seconds of wall time of brash-post on run dir $1
  local t0 t1
  t0=$(date +%s.%N)
  "$bin/brash-post" "$1" >/dev/null 2>&1 || { echo "bench: brash-post $1 failed" >&2; exit 1; }
  t1=$(date +%s.%N)
  awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.3f", b - a }'
}
small_atoms=$(($(wc -l < "$(ls "$work/small/particles/"particles_*.csv | head -1)") - 1))
small_files=$(ls "$work/small/particles/"particles_*.csv | wc -l)
t_small=$(wall "$work/small")
t_big=$(wall "$work/big")
[ -f "$work/big/particles.pvd" ] || { echo "bench: no ParaView output for the big snapshot" >&2; exit 1; }
echo "== brash-post throughput (paired wall times, one sitting)"
awk -v ts="$t_small" -v tb="$t_big" -v n="$atoms" -v mb="$size_mb" -v sn="$small_atoms" -v sf="$small_files" 'BEGIN {
  printf "run with its own snapshots (%d x %d spheres): %.2f s\n", sf, sn, ts;
  printf "same run, one snapshot of %d spheres (%d MB CSV): %.2f s\n", n, mb, tb;
  d = tb - ts; if (d <= 0) d = tb;
  printf "paper-size snapshot: %.2f s, %.3g spheres/s (read + ParaView .vtu)\n", d, n / d;
}'
