#!/usr/bin/env bash
# Benchmark: brash-ode vs LIGGGHTS on the same case in one sitting (paired: same case, same duration, run one
# after the other, never at the same time). Prints particle-steps/s and wall time per simulated second for both,
# from each run's meta.json (loop time = the time-stepping loop; wall = the whole command incl. setup).
#   bench/ode_vs_liggghts.sh [CASE_DIR]
#   env: BENCH_DURATION (default 0.3 s), BENCH_NP (LIGGGHTS MPI ranks, default 2), BRASH_BIN (default build/bin),
#        BRASH_ODE_BIN (default: brash-ode in BRASH_BIN, else build-ode/bin)
# Note: on cases/jbc_narrow the bow reaches the ice at t = 0.31 s, so the default 0.3 s measures the floating
# bed without hull contacts (the per-step cost of the bed; hull contacts add ~25 % collision work in ODE).
# The time steps differ on purpose (ODE 5e-4 s, LIGGGHTS the case's 1e-4 s): particle-steps/s is the cost of
# one step, wall time per simulated second is what a user waits.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
bin="${BRASH_BIN:-$here/build/bin}"
ode="${BRASH_ODE_BIN:-$bin}"
[ -x "$ode/brash-ode" ] || ode="$here/build-ode/bin"
case_dir="${1:-$here/cases/jbc_narrow}"
dur="${BENCH_DURATION:-0.3}"
np="${BENCH_NP:-2}"
for x in "$ode/brash-ode" "$bin/brash-liggghts-run"; do
  [ -x "$x" ] || { echo "bench/ode_vs_liggghts.sh: $x not built; skipped"; exit 0; }
done
if [ -z "${BRASH_HULL_DIR:-}" ]; then
  for d in "$here/build/hull_meshes" "$here/build-ode/hull_meshes" "$here/build-hull/hull_meshes"; do
    [ -f "$d/jbc_panamax_model.stl" ] && { export BRASH_HULL_DIR="$d"; break; }
  done
fi
work="$(mktemp -d /tmp/brash-bench-ode-lig-XXXX)"
trap 'rm -rf "$work"' EXIT

t0=$(date +%s.%N)
"$ode/brash-ode" "$case_dir" --out "$work/ode" --duration "$dur" --restart-every 0 --no-progress >/dev/null 2>"$work/ode.err" \
  || { echo "brash-ode failed:" >&2; tail -5 "$work/ode.err" >&2; exit 1; }
t1=$(date +%s.%N)
"$bin/brash-liggghts-run" "$case_dir" --out "$work/lig" --duration "$dur" --np "$np" --no-post >/dev/null 2>"$work/lig.err" \
  || { echo "brash-liggghts-run failed:" >&2; tail -5 "$work/lig.err" >&2; exit 1; }
t2=$(date +%s.%N)

python3 - "$work/ode/meta.json" "$work/lig/meta.json" "$dur" "$t0" "$t1" "$t2" <<'PY'
import json, sys
ode, lig = (json.load(open(f)) for f in sys.argv[1:3])
dur, t0, t1, t2 = (float(x) for x in sys.argv[3:7])
w_ode, w_lig = t1 - t0, t2 - t1
print(f"== ODE vs LIGGGHTS, {ode['particles']} spheres, {dur} s simulated, paired in one sitting")
print(f"{'engine':10} {'ranks':>5} {'dt [s]':>8} {'particle-steps':>15} {'particle-steps/s':>17} {'per rank':>10} "
      f"{'loop s/sim s':>13} {'wall s/sim s':>13}")
rows = []
for name, m, wall in (("ode", ode, w_ode), ("liggghts", lig, w_lig)):
    ps, loop, ranks = float(m["particle_steps"]), float(m["loop_time_s"]), int(m.get("ranks", 1))
    rows.append((ps / loop, loop / dur, wall / dur, ranks))
    print(f"{name:10} {ranks:5d} {m['dt_s']:8.1e} {ps:15.4g} {ps / loop:17.4g} {ps / loop / ranks:10.4g} "
          f"{loop / dur:13.1f} {wall / dur:13.1f}")
print(f"ratio ODE/LIGGGHTS: particle-steps/s x{rows[0][0] / rows[1][0]:.2f} (per rank x"
      f"{rows[0][0] / rows[1][0] * rows[1][3] / rows[0][3]:.2f}), wall time per simulated s x{rows[0][2] / rows[1][2]:.2f}")
PY
