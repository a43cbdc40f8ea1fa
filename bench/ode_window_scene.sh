#!/usr/bin/env bash
# brash-ode's seconds per step on the paper case's scene during its window: the pieces of the LIGGGHTS paper run
# (`both`, the case's defaults; docs/performance.md "The paper case on 2 cores" has its command) as its particle
# dumps hold them at T = 15 s (the window's start) and 25 s (its early stop), positions and velocities, with the hull
# where it was then (bench-ode --scene-from; the pieces held out ahead by the moving window at their packing position,
# at rest). Each setting runs STEPS steps of dt 1e-3 s on one core, one after the
# other in one sitting:
#   all        every piece integrated
#   farfield   the case's far field window (speedups.farfield: true): idle beyond 0.3 m ahead of the bow and 1.0 m
#              behind the stern, woken by the force rule (1e-3 of a piece's weight: brash-ode refuses the
#              neighbour-speed wake), membership every 20 ODE steps
#   beside     farfield, and ice more than SIDE_M beyond the hull's half beam idles too once slower than 5 mm/s
#              (speedups.farfield_beside_m; the ice between the hull and the channel walls)
# A scene from a soft-contact run starts with a contact surface layer as deep as its largest overlap (as the settled
# bed does). Prints seconds per step, pieces awake and contacts at the end, and the ratios to `all`.
#   bash bench/ode_window_scene.sh [RUN_DIR (runs/paper-liggghts-both-window)] [STEPS (20)]   (~10 min)
# env SIDE_M (0.1). Skipped with a message when bench-ode was not built or RUN_DIR has no particle dumps.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
bin="${BRASH_BIN:-$here/build/bin}"
run="${1:-$here/runs/paper-liggghts-both-window}"
steps="${2:-20}"
side_m="${SIDE_M:-0.1}"
dt=1e-3
if [ ! -x "$bin/bench-ode" ]; then
  echo "ode_window_scene: skipped: no $bin/bench-ode (built with BRASH_WITH_ODE=ON)"
  exit 0
fi
if [ ! -f "$run/particles/index.csv" ]; then
  echo "ode_window_scene: skipped: no $run/particles/index.csv (the paper run's dumps; its command is in docs/performance.md)"
  exit 0
fi
work="$(mktemp -d /tmp/brash-odewindow-XXXX)"
trap 'rm -rf "$work"' EXIT
# the case the run ran, every piece of it integrated unless a setting culls (brash-ode runs no moving window; the
# scene is the dump, not the case's bed; its far field is the force rule's)
"$bin/brash-case" derive "$run/case.yaml" --out "$work/case" --set ice.settle=false --set speedups.farfield=false \
  --set speedups.moving_window=false --set speedups.farfield_wake_by=force > /dev/null
# the dump at model time T: its file name from the run's particles/index.csv (step,t_s,file,...)
dump_at() { awk -F, -v t="$1" 'NR > 1 && $2 + 0 == t + 0 { print $3 }' "$run/particles/index.csv"; }

# membership every 20 ODE steps: farfield_every_steps counts the case's (DEM) steps
every="$(/usr/bin/python3 -c "print(round(20 * $dt / $("$bin/brash-case" get "$work/case" run.timestep_s)))")"
farfield="--set speedups.farfield=true --set speedups.farfield_ahead_m=0.3 --set speedups.farfield_behind_m=1.0"
farfield+=" --set speedups.farfield_every_steps=$every"
declare -A opts=([all]=""
                 [farfield]="$farfield"
                 [beside]="$farfield --set speedups.farfield_beside_m=$side_m")
for t in 15 25; do
  duration="$(/usr/bin/python3 -c "print($t + $steps * $dt)")"  # the model time to reach, STEPS steps after T
  file="$(dump_at "$t")"
  [ -n "$file" ] || { echo "ode_window_scene: no dump at t = $t s in $run/particles/index.csv"; exit 1; }
  declare -A per_step=()
  for setting in all farfield beside; do
    log="$work/$setting-$t.log"
    # shellcheck disable=SC2086
    "$bin/bench-ode" "$work/case" --scene-from "$run/particles/$file" --scene-time "$t" --dt "$dt" \
      --duration "$duration" --model both --restart-every 0 --out "$work/run-$setting-$t" ${opts[$setting]} \
      > "$log" 2>&1 || { tail -5 "$log"; exit 1; }
    rm -rf "${work:?}/run-$setting-$t"
    # bench-ode's summary: wall per simulated second; the last progress line: awake and contacts
    read -r s awake contacts <<< "$(/usr/bin/python3 - "$log" "$dt" <<'EOF'
import re, sys
text, dt = open(sys.argv[1]).read(), float(sys.argv[2])
wall = float(re.search(r"([0-9.]+) s wall per simulated s", text)[1])
last = re.findall(r"awake ([0-9]+)  contacts ([0-9]+)", text)[-1]
print(f"{wall * dt:.3f} {last[0]} {last[1]}")
EOF
)"
    per_step[$setting]="$s"
    printf 't = %s s  %-9s %6s s per step  awake %7s  contacts %7s  (%s)\n' "$t" "$setting" "$s" "$awake" "$contacts" \
      "${opts[$setting]:-every piece}"
  done
  /usr/bin/python3 -c "import sys; a,f,b=map(float,sys.argv[1:]); \
print(f't = $t s  per step: farfield {a/f:.2f}x, beside {a/b:.2f}x on all')" \
    "${per_step[all]}" "${per_step[farfield]}" "${per_step[beside]}"
  unset per_step
done
