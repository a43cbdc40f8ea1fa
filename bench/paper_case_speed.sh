#!/usr/bin/env bash
# The paper case's cost on 2 cores from the archived runs' records (evidence/paper-liggghts-*/meta.json: wall time
# summed over a run's attempts, model time reached, particle-steps): wall seconds per model second of each, and the
# speed-up of the fast forms of the case (settled bed and idle far field: evidence/paper-liggghts-both-fast; and with
# the moving window too: evidence/paper-liggghts-both-window) over each run with every piece integrated, per model
# second and for the whole run to the same early stop. The runs themselves take
# hours (docs/performance.md "The paper case on 2 cores" has their commands); this prints what they recorded.
# Runs that record their stages (meta.json "stages": packing, settling, set-up, run, report) are then printed stage
# by stage by bench/run_stages.sh, the first of them the baseline of its ratios.
#   bash bench/paper_case_speed.sh [EVIDENCE_DIR (evidence)]
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
ev="${1:-$here/evidence}"
fast="$ev/paper-liggghts-both-fast"
if [ ! -f "$fast/meta.json" ]; then
  echo "paper_case_speed: skipped: no $fast/meta.json"
  exit 0
fi
/usr/bin/python3 - "$ev" "$fast" <<'EOF'
import glob, json, os, sys
ev, fast = sys.argv[1], sys.argv[2]

def record(d):
    m = json.load(open(os.path.join(d, 'meta.json')))
    r = json.load(open(os.path.join(d, 'report.json')))
    t = float(m['model_time_reached_s'])
    return dict(name=os.path.basename(d), t=t, wall=float(m['wall_time_s']), ps=float(m['particle_steps']),
                kn=r['resistance_full_kN'], ci=r['resistance_full_ci95_kN'], model=m['fluid_model'])

fasts = [record(d) for d in (fast, os.path.join(ev, 'paper-liggghts-both-window'))
         if os.path.exists(os.path.join(d, 'meta.json'))]
print(f"{'run':36s} {'model s':>7} {'wall s':>8} {'wall s / model s':>16} {'particle-steps/s':>16} {'kN':>14}")
full = [record(d) for d in sorted(glob.glob(os.path.join(ev, 'paper-liggghts-*-20s')))]
for r in fasts + full:
    print(f"{r['name']:36s} {r['t']:7.1f} {r['wall']:8.0f} {r['wall'] / r['t']:16.0f} {r['ps'] / r['wall']:16.3g} "
          f"{r['kn']:7.1f} ± {r['ci']:4.1f}")
for f in fasts:
    for r in full:
        rate_f, rate_r = f['wall'] / f['t'], r['wall'] / r['t']
        print(f"speed-up of {f['name']} on {r['name']} ({r['model']}, every piece integrated): "
              f"{rate_r / rate_f:.2f}x per model second; to the same stop at {f['t']:g} s: "
              f"{rate_r * f['t']:.0f} s against {f['wall']:.0f} s")
for f in fasts[1:]:
    print(f"speed-up of {f['name']} on {fasts[0]['name']}: {fasts[0]['wall'] / fasts[0]['t'] / (f['wall'] / f['t']):.2f}x "
          f"per model second; window means {f['kn']:.1f} and {fasts[0]['kn']:.1f} kN ({100 * (f['kn'] / fasts[0]['kn'] - 1):+.2f} %)")
EOF
staged=()
for d in "$ev"/paper-liggghts-*/; do
  if /usr/bin/python3 -c 'import json,sys; sys.exit(0 if "stages" in json.load(open(sys.argv[1])) else 1)' \
      "$d/meta.json" 2> /dev/null; then
    staged+=("$d")
  fi
done
if [ ${#staged[@]} -gt 0 ]; then
  echo
  echo "From a new packing, stage by stage (wall s; cached stages at what making them cost):"
  bash "$here/bench/run_stages.sh" "${staged[@]}"
fi
