#!/usr/bin/env bash
# The paper case's bed with no ship: how still is a floating bed at rest, and does the step or the fluid model put
# energy into it? (The far field's wake rule only skips ice at rest: on the paper scene it woke every piece,
# docs/performance.md "The wake rule on the paper scene".) A short channel of the case's ice (LENGTH m), the hull
# parked at the ice edge (ship speed 1e-9 m/s), DURATION s of LIGGGHTS on 1 rank per run, dumps every 0.25 s, then per
# dump the kinetic energy of the pieces that started in the channel's middle half (away from the free ends) and the
# median |vz|, for five variants: the case as it is | half its step | Ca 0.5 on every axis in every state (no
# Table-1 switch on motion reversal) | Ca 0 (buoyancy and gravity only) | the drag model.
#   bash bench/resting_bed.sh [OUT (runs/resting-bed)]
# env: CASE (cases/jbc_ia_5kn), LENGTH (2.0), DURATION (3.0), JOBS (2 runs at a time), BRASH_BIN (build/bin).
# Finished runs are kept and re-printed. ~10 min on 2 cores for the paper case's ice (40,000 pieces).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:-$here/runs/resting-bed}"
bin="${BRASH_BIN:-$here/build/bin}"
case_src="$(cd "${CASE:-$here/cases/jbc_ia_5kn}" && pwd)"
length="${LENGTH:-2.0}" duration="${DURATION:-3.0}" jobs="${JOBS:-2}"
dt="$("$bin/brash-case" get "$case_src" run.timestep_s)"
half_dt="$(awk -v d="$dt" 'BEGIN { printf "%.6g", d / 2 }')"
rho_ice="$("$bin/brash-case" get "$case_src" ice.density_kg_m3)"
# the averaging window inside the shorter run; the shorter channel's own packing (same seed) in the variant's folder
base="channel.length_m=$length,ship.speed_m_s=1.0e-9,run.duration_s=$duration,run.dump_interval_s=0.25"
base="$base,run.window_s=[0.0,$duration],ice.packing_file=generated/packing.csv,ice.settle=false,speedups.farfield=false,speedups.moving_window=false"
variants=(
  "case:"
  "half_dt:run.timestep_s=$half_dt"
  "ca_uniform_0.5:fluid.ca_table=uniform 0.5"
  "ca_zero:fluid.ca_table=zero"
  "drag:fluid.model=drag"
)
mkdir -p "$out"
source "$here/bench/case_variant.sh"
run_variant() {  # name edits
  local dir="$out/$1"
  [ -f "$dir/run/meta.json" ] && jq -e '.status == "complete"' "$dir/run/meta.json" > /dev/null && return 0
  rm -rf "$dir"
  case_variant "$bin" "$case_src" "$dir/case" "$base${2:+,$2}" || { echo "resting_bed: $1 refused" >&2; return 1; }
  "$bin/brash-liggghts-run" "$dir/case" --np 1 --out "$dir/run" --no-post > "$dir/log.txt" 2>&1 ||
    { echo "resting_bed: $1 failed (see $dir/log.txt)" >&2; return 1; }
}
pids=()
for v in "${variants[@]}"; do
  run_variant "${v%%:*}" "${v#*:}" & pids+=($!)
  if [ ${#pids[@]} -ge "$jobs" ]; then wait "${pids[0]}"; pids=("${pids[@]:1}"); fi
done
for p in "${pids[@]}"; do wait "$p"; done
echo "== resting bed: $(basename "$case_src")'s ice, channel $length m, $duration s, no ship (bench/resting_bed.sh)"
/usr/bin/python3 - "$out" "$length" "$rho_ice" "${variants[@]%%:*}" <<'EOF'
import glob, os, sys
import numpy as np
out, length, rho_ice, names = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4:]
rows = []
for name in names:
    files = sorted(glob.glob(os.path.join(out, name, 'run', 'particles', 'particles_*.csv')))
    head = open(files[0]).readline().strip().split(',')
    cols = [head.index(c) for c in ('x', 'radius', 'vx', 'vy', 'vz')]
    x0, ke, kez, vz = None, [], [], []
    for f in files:
        d = np.loadtxt(f, skiprows=1, delimiter=',', usecols=cols)
        if x0 is None:
            x0 = d[:, 0].copy()  # rows are sorted by id: the same piece in every dump
        mid = (x0 > length / 4) & (x0 < 3 * length / 4)
        m = rho_ice * 4.0 / 3.0 * np.pi * d[mid, 1] ** 3  # ice mass [kg] (without the added mass)
        ke.append(0.5 * np.sum(m * (d[mid, 2] ** 2 + d[mid, 3] ** 2 + d[mid, 4] ** 2)) * 1e6)
        kez.append(0.5 * np.sum(m * d[mid, 4] ** 2) * 1e6)
        vz.append(np.median(np.abs(d[mid, 4])) * 1e3)
    rows.append((name, ke, kez, vz))
times = [0.25 * i for i in range(len(rows[0][1]))]
pick = [i for i, t in enumerate(times) if t in (0.5, 1.0, 1.5, 2.0, 2.5, 3.0) or i == len(times) - 1]
pick = sorted(set(pick))
print('kinetic energy of the middle half [uJ] (vertical part) | median |vz| [mm/s], at t [s]:')
print('| variant | ' + ' | '.join('t = %g' % times[i] for i in pick) + ' |')
print('|---|' + '---|' * len(pick))
for name, ke, kez, vz in rows:
    print('| %s | ' % name + ' | '.join('%.0f (%.0f) / %.1f' % (ke[i], kez[i], vz[i]) for i in pick) + ' |')
EOF
