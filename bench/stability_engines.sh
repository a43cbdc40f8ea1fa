#!/usr/bin/env bash
# Benchmark: stability map ON THE ENGINES (docs/stability.md, "Engine stability map").
# On cases/stability_small (JBC bow in ~875 spheres, 0.25 s), for LIGGGHTS (1 rank) and ODE, one run at a time:
#   grid      time step x Ca (uniform 0, 0.5, 2, 10: fluid.ca_table: uniform <Ca>) x treatment (implicit, explicit)
#             at the paper's speed, density ratio and E
#   paper     Table 1 at the paper's dt (5e-5, 1e-4) for both treatments
#   one-factor sweeps at the paper's settings (Table 1, dt 1e-4 / ODE 5e-4), both treatments:
#             speed 0.25 and 4 x 0.482 m/s, ice density 500 and 990 kg/m^3 (ratio 0.5, 0.99), E 1.25 and 20 MPa
#   boundary  explicit, uniform Ca 0.7 ... 1.5 at the paper's dt: the explicit boundary against m_a/m = 1
# Every run is judged by `brash-post stability` (verdict stable / guard <which> / crashed / silent); a silent
# failure (complete, but hull penetration > 0.5 d, overlap > 0.5 d, pieces beyond the walls or > 2 ice
# thicknesses above the water, NaN, or energy the hull did not supply) is a bug: the script exits 1 if it finds one.
#   bash bench/stability_engines.sh                 (env: BRASH_BIN, OUT (runs/stability-map-<stamp>),
#                                                    ENGINES="liggghts ode", TABLE_ONLY=1 re-prints OUT)
# Writes OUT/map.md (the tables) and OUT/cells.tsv; takes ~5-10 min on one core.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
bin="${BRASH_BIN:-$here/build/bin}"
case_dir="$here/cases/stability_small"
out="${OUT:-$here/runs/stability-map-$(date +%Y%m%dT%H%M%S)}"
engines="${ENGINES:-liggghts ode}"
mkdir -p "$out/cases"
source "$here/bench/case_variant.sh"

# the case with "section.key=value,..." edits (brash-case derive, checked by the case loader); the packing is the
# base case's, so every variant starts from the same ice (its density edits included)
variant() {  # $1 name, $2 edits
  case_variant_same_packing "$bin" "$case_dir" "$out/cases/$1" "$2" || return
  echo "$out/cases/$1"
}

# cell: engine name dt ca treatment speed_x rho_i E
cells=()
add() { cells+=("$*"); }
for eng in $engines; do
  if [ "$eng" = liggghts ]; then dts="5e-5 1e-4 2e-4 3e-4 4e-4"; dt0=1e-4; else dts="1e-4 5e-4 2e-3"; dt0=5e-4; fi
  for tr in implicit explicit; do
    for ca in 0 0.5 2 10; do for dt in $dts; do add "$eng grid $dt $ca $tr 1 900 5e6"; done; done
  done
  for tr in implicit explicit; do
    if [ "$eng" = liggghts ]; then for dt in 5e-5 1e-4; do add "$eng paper $dt table1 $tr 1 900 5e6"; done
    else add "$eng paper $dt0 table1 $tr 1 900 5e6"; fi
    for s in 0.25 4; do add "$eng speed $dt0 table1 $tr $s 900 5e6"; done
    for r in 500 990; do add "$eng density $dt0 table1 $tr 1 $r 5e6"; done
    for e in 1.25e6 2e7; do add "$eng stiffness $dt0 table1 $tr 1 900 $e"; done
  done
  # the explicit boundary: theory m_a/m = Ca rho_w s / rho_i = 1, i.e. Ca 0.9 for a piece pushed under, 1 afloat
  for ca in 0.7 0.8 0.9 1 1.1 1.25 1.5; do add "$eng boundary $dt0 $ca explicit 1 900 5e6"; done
done

cell_id() { echo "$1-$2-dt$3-ca$4-$5-u$6-rho$7-E$8"; }

if [ -z "${TABLE_ONLY:-}" ]; then
  [ -f "$case_dir/generated/packing.csv" ] || "$bin/brash-pack" "$case_dir" > /dev/null
  i=0
  for c in "${cells[@]}"; do
    i=$((i + 1))
    read -r eng sweep dt ca tr sx rho e <<< "$c"
    id="$(cell_id $eng $sweep $dt $ca $tr $sx $rho $e)"
    run="$out/$eng/$id"
    [ -f "$run/stability.json" ] && continue
    catab="$ca"; [ "$ca" != table1 ] && catab="uniform $ca"
    speed="$(awk -v s="$sx" 'BEGIN { printf "%.6g", 0.482 * s }')"
    edits="fluid.ca_table=$catab,ship.speed_m_s=$speed,ice.density_kg_m3=$rho,contact.youngs_modulus_pa=$e"
    [ "$eng" = liggghts ] && edits="$edits,run.timestep_s=$dt"
    rm -rf "$run"; mkdir -p "$(dirname "$run")"
    t0=$(date +%s.%N)
    if ! vdir="$(variant "$id" "$edits" 2> "$run.txt")"; then
      :  # refused by the case loader (its contact time-step check, bad input): its message is in $run.txt
    elif [ "$eng" = liggghts ]; then
      nice "$bin/brash-liggghts-run" "$vdir" --np 1 --out "$run" --treatment "$tr" --no-post > "$run.txt" 2>&1 || true
    else
      nice "$bin/brash-ode" "$vdir" --out "$run" --treatment "$tr" --dt "$dt" --no-progress --restart-every 0 \
        > "$run.txt" 2>&1 || true
    fi
    wall=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
    if [ -f "$run/meta.json" ]; then
      "$bin/brash-post" stability "$run" > /dev/null 2> "$run.post.txt" || echo "   brash-post stability failed: $run.post.txt"
    else  # refused before a run directory existed (the case loader's contact time-step check, bad input)
      mkdir -p "$run"
      python3 -c 'import json,sys; m=[l for l in open(sys.argv[1]) if "rror" in l]; r=(m[-1] if m else "no run directory").strip()
json.dump({"status": "guard" if "Rayleigh" in r else "crashed", "guard": "timestep" if "Rayleigh" in r else "",
 "verdict": "guard" if "Rayleigh" in r else "crashed", "message": r, "refused": True}, open(sys.argv[2], "w"))' \
        "$run.txt" "$run/stability.json"
    fi
    echo "$wall" > "$run.wall"
    printf '[%d/%d] %s: %s (%s s)\n' "$i" "${#cells[@]}" "$id" \
      "$(python3 -c 'import json,sys; j=json.load(open(sys.argv[1])); print(j["verdict"], j.get("guard",""))' "$run/stability.json")" "$wall"
  done
fi

python3 - "$out" "${cells[@]}" <<'PY'
import json, os, sys
out, cells = sys.argv[1], [c.split() for c in sys.argv[2:]]
rows, silent = [], []
for eng, sweep, dt, ca, tr, sx, rho, e in cells:
    cid = '-'.join([eng, sweep, 'dt' + dt, 'ca' + ca, tr, 'u' + sx, 'rho' + rho, 'E' + e])
    run = os.path.join(out, eng, cid)
    try:
        j = json.load(open(os.path.join(run, 'stability.json')))
    except (OSError, ValueError):
        j = {'verdict': 'missing'}
    try:
        wall = open(run + '.wall').read().strip()
    except OSError:
        wall = ''
    v = j['verdict']
    # m_a/m of a fully submerged piece: Ca rho_w / rho_i (Table 1: its largest Ca, 0.5)
    ca_num = 0.5 if ca == 'table1' else float(ca)
    mam = ca_num * 1000.0 / float(rho)
    mark = {'stable': 'stable', 'guard': 'guard: ' + j.get('guard', ''), 'crashed': 'CRASHED', 'silent': 'SILENT',
            'missing': 'missing'}[v]
    msg = j.get('message', '') or '; '.join(j.get('silent_reasons', []))
    if len(msg) > 90: msg = msg[:87] + '...'
    f = lambda k, fmt='%.3g': (fmt % j[k]) if j.get(k) is not None else '-'
    row = dict(eng=eng, sweep=sweep, dt=dt, ca=ca, tr=tr, sx=sx, rho=rho, e=e, v=v, mam=mam)
    rows.append(row)
    row['line'] = '| %s | %s | %s | %s | %s | %s | %.2f | %s | %.2f | %s | %s | %s | %s | %s | %s | %s | %s | %s |' % (
        eng, sweep, dt, ca, tr, sx, float(rho) / 1000, '%.3g' % (float(e) / 1e6), mam, mark, f('t_last_s', '%.3f'),
        f('max_hull_penetration_d'), f('max_overlap_d'), f('escaped_max', '%d'), f('above_water_max', '%d'),
        f('energy_excess', '%.2f'), wall, msg.replace('|', '/'))
    if v in ('silent', 'missing'): silent.append(row)
hdr = ('| engine | sweep | dt [s] | Ca | treatment | U / 0.482 | rho_i/rho_w | E [MPa] | m_a/m sub. | verdict | t end [s] | '
       'hull pen. / d | overlap / d | escaped | above water | energy excess | wall [s] | message |\n' + '|---' * 18 + '|')
md = ['# Engine stability map (bench/stability_engines.sh, cases/stability_small)', '', hdr] + [r['line'] for r in rows]
md += ['', '## Summary', '']
for eng in sorted(set(r['eng'] for r in rows)):
    er = [r for r in rows if r['eng'] == eng]
    cnt = {}
    for r in er: cnt[r['v']] = cnt.get(r['v'], 0) + 1
    md.append('- %s: %d cells: %s' % (eng, len(er), ', '.join('%s %d' % kv for kv in sorted(cnt.items()))))
    for tr in ('implicit', 'explicit'):
        g = [r for r in er if r['sweep'] == 'grid' and r['tr'] == tr]
        for ca in ('0', '0.5', '2', '10'):
            cg = [r for r in g if r['ca'] == ca]
            md.append('  - %s Ca %s (m_a/m %.2f submerged): %s' % (tr, ca, cg[0]['mam'] if cg else 0,
                      ', '.join('dt %s %s' % (r['dt'], r['v']) for r in cg)))
    b = sorted((float(r['ca']), r['v']) for r in er if r['sweep'] == 'boundary')
    if b:
        ok = [c for c, v in b if v == 'stable']
        bad = [c for c, v in b if v != 'stable']
        md.append('  - explicit boundary (uniform Ca at dt %s): largest stable Ca %s, smallest unstable Ca %s; theory '
                  'Ca rho_w s / rho_i = 1: Ca 0.9 (piece pushed under), 1.0 (floating, s = 0.9)' % (
                      [r['dt'] for r in er if r['sweep'] == 'boundary'][0], max(ok) if ok else '-', min(bad) if bad else '-'))
    p = [r for r in er if r['sweep'] not in ('grid', 'boundary') and r['tr'] == 'implicit']
    md.append('  - implicit, Table 1 (paper settings and one-factor sweeps): %d of %d stable' % (
        sum(r['v'] == 'stable' for r in p), len(p)))
md.append('- silent failures: %d%s' % (len(silent), ''.join('\n  - ' + r['line'] for r in silent)))
text = '\n'.join(md) + '\n'
open(os.path.join(out, 'map.md'), 'w').write(text)
with open(os.path.join(out, 'cells.tsv'), 'w') as t:
    t.write('engine\tsweep\tdt\tca\ttreatment\tspeed_x\trho_i\tE\tverdict\n')
    for r in rows: t.write('\t'.join([r[k] for k in ('eng', 'sweep', 'dt', 'ca', 'tr', 'sx', 'rho', 'e', 'v')]) + '\n')
print(text)
print('(written to %s)' % os.path.join(out, 'map.md'))
sys.exit(1 if silent else 0)
PY
