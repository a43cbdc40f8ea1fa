#!/usr/bin/env bash
# brash-ode's seconds per step on the paper scene (cases/jbc_ia_5kn, 417,415 spheres, dt 1e-3 s as in the ODE paper
# runs), before and after, one after the other in one sitting on one core:
#   before: --sphere-order packing --iterations 20   (the bodies in the packing's random order; from the 8th
#           iteration on ODE 0.16 shuffles the contact rows every 8 iterations)
#   after:  --sphere-order spatial --iterations 8    (bodies in a spatial order; no shuffle)
# Each runs from the fresh bed with the bow entering the ice for DURATION_S of model time; the seconds per step
# are read off the progress lines (model time, elapsed wall time, contacts) over the stretch where the scene has
# at least CONTACTS contacts, and over the first stretch (the fresh bed). Prints the ratio before / after.
#   bash bench/ode_paper_scene.sh [DURATION_S] [CONTACTS]        (defaults 0.2 s, 400000; ~30 min)
# Skipped with a message when bench-ode was not built (BRASH_WITH_ODE=OFF).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
bin="${BRASH_BIN:-$here/build/bin}"
duration="${1:-0.2}"
contacts="${2:-400000}"
case_dir="${CASE:-$here/cases/jbc_ia_5kn}"
dt=1e-3
if [ ! -x "$bin/bench-ode" ]; then
  echo "ode_paper_scene: skipped: no $bin/bench-ode (built with BRASH_WITH_ODE=ON)"
  exit 0
fi
"$bin/brash-pack" "$case_dir" > /dev/null  # the packing (generated/, reused when present)
work="$(mktemp -d /tmp/brash-odescene-XXXX)"
trap 'rm -rf "$work"' EXIT
# ODE starts from the packing with every piece integrated (the paper case's settled bed and far field are LIGGGHTS')
# (the derived case uses the base's packing)
"$bin/brash-case" derive "$case_dir" --out "$work/case" --set ice.settle=false --set speedups.farfield=false --set speedups.moving_window=false > /dev/null
case_dir="$work/case"

# Seconds per step from the progress lines of LOG: over the lines with >= CONTACTS contacts, and over the first ones.
per_step() {
  /usr/bin/python3 - "$1" "$contacts" "$dt" <<'EOF'
import re, sys
log, c_min, dt = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
pts = [(float(m[1]), float(m[2]), int(m[3])) for m in
       re.finditer(r"t = ([0-9.]+) / [0-9.]+ s .*?elapsed ([0-9.]+) s .*?contacts ([0-9]+)", open(log).read())]
if len(pts) < 3:
    sys.exit(f"ode_paper_scene: too few progress lines in {log}")
def rate(a, b):
    return (b[1] - a[1]) / ((b[0] - a[0]) / dt)
deep = [p for p in pts if p[2] >= c_min]
fresh = rate(pts[0], pts[min(2, len(pts) - 1)])
if len(deep) < 2:
    print(f"{fresh:.3f} nan {pts[-1][2]} {pts[0][0]:.3f} {pts[-1][0]:.3f}")
else:
    print(f"{fresh:.3f} {rate(deep[0], deep[-1]):.3f} {deep[-1][2]} {deep[0][0]:.3f} {deep[-1][0]:.3f}")
EOF
}

declare -A opts=([before]="--sphere-order packing --iterations 20" [after]="--sphere-order spatial --iterations 8")
declare -A result
for side in before after; do
  log="$work/$side.log"
  # shellcheck disable=SC2086
  "$bin/bench-ode" "$case_dir" --dt "$dt" --duration "$duration" --model both --restart-every 0 \
    --out "$work/$side" ${opts[$side]} > "$log" 2>&1 || { tail -5 "$log"; exit 1; }
  result[$side]="$(per_step "$log")"
  rm -rf "${work:?}/$side"
  read -r fresh deep n t0 t1 <<< "${result[$side]}"
  printf '%-6s (%s): %s s per step on the fresh bed, %s s per step at >= %s contacts (t = %s-%s s, %s at the end)\n' \
    "$side" "${opts[$side]}" "$fresh" "$deep" "$contacts" "$t0" "$t1" "$n"
  # where the whole run's time went (bench-ode's summary line)
  grep -o '(fluid [0-9.]* / collide [0-9.]* / quickstep [0-9.]* s)' "$log" | sed 's/^/       whole run: /' || true
done
read -r fb db _ <<< "${result[before]}"
read -r fa da _ <<< "${result[after]}"
/usr/bin/python3 -c "import sys; fb,db,fa,da=map(float,sys.argv[1:]); \
print(f'ODE paper scene, seconds per step before / after: fresh bed {fb/fa:.2f}x, at >= $contacts contacts {db/da:.2f}x')" \
  "$fb" "$db" "$fa" "$da"
