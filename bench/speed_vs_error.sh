#!/usr/bin/env bash
# Run time vs error of the speed-up switches (docs/performance.md): one reference run (every switch off)
# and one run per knob on the same scene, one run at a time, then a table
#   knob | wall time | speed-up | mean resistance +- 95 % CI | error vs reference (and its CI).
# DEM runs are chaotic: a difference is only meaningful if it exceeds the combined CI.
#   bash bench/speed_vs_error.sh [CASE_DIR] [KNOB ...]      (default cases/jbc_bench, every knob)
#   env: BRASH_BIN (default build-perf/bin or build/bin), NP (2), OUT (runs/bench-<stamp>), TABLE_ONLY=1
# A knob is NAME:section.key=value[,section.key=value...] applied to a copy of the case (brash-case derive); NAME
# only picks one from the list below. Re-print a finished study with TABLE_ONLY=1 OUT=<dir>.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
bin="${BRASH_BIN:-}"
[ -z "$bin" ] && { [ -x "$here/build-perf/bin/brash-liggghts-run" ] && bin="$here/build-perf/bin" || bin="$here/build/bin"; }
case_dir="$(cd "${1:-$here/cases/jbc_bench}" && pwd)"; shift || true
np="${NP:-2}"
out="${OUT:-$here/runs/bench-$(date +%Y%m%dT%H%M%S)}"
all_knobs=(
  "reference:"
  "farfield_0.3:speedups.farfield=true,speedups.farfield_ahead_m=0.3,speedups.farfield_behind_m=1.0"
  "symmetry_y:speedups.symmetry_y=true"
  "dt_x2:run.timestep_s=2.0e-4"
  "skin_0.4d:speedups.neighbor_skin_d=0.4"
  "stiff_E_x4:contact.youngs_modulus_pa=2.0e7"
  "soft_E_div4_dt_x2:contact.youngs_modulus_pa=1.25e6,run.timestep_s=2.0e-4"
  "restitution_0.1:contact.restitution=0.1"
  "restitution_0.6:contact.restitution=0.6"
  "output_0.05s:run.output_interval_s=0.05"
  "combined:speedups.farfield=true,speedups.farfield_ahead_m=0.3,speedups.farfield_behind_m=1.0,run.timestep_s=2.0e-4"
  "all_fast:speedups.farfield=true,speedups.farfield_ahead_m=0.3,speedups.farfield_behind_m=1.0,speedups.symmetry_y=true,run.timestep_s=2.0e-4"
)
knobs=()
if [ $# -gt 0 ]; then
  for k in "$@"; do
    if [[ "$k" == *:* ]]; then knobs+=("$k"); else
      for a in "${all_knobs[@]}"; do [ "${a%%:*}" = "$k" ] && knobs+=("$a"); done
    fi
  done
  [[ " ${knobs[*]} " == *" reference:"* ]] || knobs=("reference:" "${knobs[@]}")
else
  knobs=("${all_knobs[@]}")
fi
mkdir -p "$out"
source "$here/bench/case_variant.sh"

# the case with the knob's section.key=value edits, on the reference's packing
variant() {  # $1 name, $2 edits
  local dir="$out/cases/$1"
  case_variant_same_packing "$bin" "$case_dir" "$dir" "$2" || return
  echo "$dir"
}

if [ -z "${TABLE_ONLY:-}" ]; then
  # the packing once, outside the timed runs
  [ -f "$case_dir/generated/packing.csv" ] || "$bin/brash-pack" "$case_dir" >/dev/null
  for k in "${knobs[@]}"; do
    name="${k%%:*}"; edits="${k#*:}"
    [ -f "$out/$name/report.json" ] && { echo "== $name: done already ($out/$name)"; continue; }
    vdir="$(variant "$name" "$edits")" || { echo "   $name: refused by brash-case derive (message above)"; continue; }
    echo "== $name: ${edits:-all switches off} -> $out/$name"
    rm -rf "$out/$name"
    nice -n 5 "$bin/brash-liggghts-run" "$vdir" --np "$np" --out "$out/$name" > "$out/$name.runner.txt" 2>&1 ||
      { echo "   FAILED (see $out/$name.runner.txt)"; continue; }
  done
fi

# each knob against the reference: relative difference and combined 95 % CI (brash-post difference, stats/)
for k in "${knobs[@]}"; do
  name="${k%%:*}"
  [ -f "$out/reference/report.json" ] && [ -f "$out/$name/report.json" ] &&
    "$bin/brash-post" difference "$out/reference" "$out/$name" > "$out/$name/difference.json"
done

echo
echo "== speed vs error: $(basename "$case_dir"), $np rank(s), results in $out"
python3 - "$out" "${knobs[@]}" <<'PY'
import json, sys, os
out, knobs = sys.argv[1], sys.argv[2:]
def load(name):
    try:
        r = json.load(open(os.path.join(out, name, 'report.json')))
        m = json.load(open(os.path.join(out, name, 'meta.json')))
    except (OSError, ValueError):
        return None
    res = r['resistance_model_N']
    return dict(wall=m.get('wall_time_s') or r.get('wall_time_s'), loop=m.get('loop_time_s', 0),
                ps=m.get('particle_steps', 0), n=m.get('particles', 0), mean=res['mean'], ci=res['ci95'])
ref = load('reference')
print('| knob | edits | spheres | wall time [s] | speed-up | particle-steps/s | mean resistance [N] | error vs reference | combined 95 % CI |')
print('|---|---|---|---|---|---|---|---|---|')
for k in knobs:
    name, edits = k.split(':', 1)
    r = load(name)
    if r is None:
        print('| %s | %s | | failed or missing | | | | | |' % (name, edits or 'all off')); continue
    sp = ref['wall'] / r['wall'] if ref else float('nan')
    tput = r['ps'] / r['loop'] if r['loop'] else float('nan')
    try:
        d = json.load(open(os.path.join(out, name, 'difference.json')))
        err, cci, sig = 100 * d['diff_rel'], 100 * d['ci95_rel'], ' (outside CI)' if d['resolved'] else ''
    except (OSError, ValueError):
        err, cci, sig = float('nan'), float('nan'), ''
    print('| %s | %s | %d | %.0f | %.2fx | %.3g | %.2f ± %.2f | %+.1f %%%s | ± %.1f %% |' % (
        name, edits.replace(',', ', ') or 'all off', r['n'], r['wall'], sp, tput, r['mean'], r['ci'], err, sig, cci))
PY
