#!/usr/bin/env bash
# Run time vs error of the speed-up knobs as a Pareto plot: one point per paired-seed ensemble of
# bench/rank_ensemble.sh (OUT/ensemble-<reference>-vs-<knob>.json): x = speed-up of the knob over the reference
# (summed wall times), y = the knob's effect on the window-mean resistance, (B - A) / A, with its 95 % CI, the tolerance
# band shaded. Prints the table (markdown) and writes the PNG, its data and the gnuplot script.
#   bash bench/pareto_plot.sh [ENSEMBLE_DIR (runs/rank-ensemble)] [PNG (docs/performance_pareto.png)]
# env: TOL_PCT (2), REFERENCE (np1: only ensembles whose side A is this run name).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
dir="${1:-$here/runs/rank-ensemble}"
png="${2:-$here/docs/performance_pareto.png}"
ref="${REFERENCE:-np1}"
shopt -s nullglob
files=("$dir"/ensemble-"$ref"-vs-*.json)
[ ${#files[@]} -gt 0 ] || { echo "pareto_plot: no $dir/ensemble-$ref-vs-*.json (run bench/rank_ensemble.sh first)" >&2; exit 2; }
stem="${png%.png}"
/usr/bin/python3 - "$stem" "${TOL_PCT:-2}" "$ref" "${files[@]}" <<'PY'
import json, os, sys
stem, tol, ref, files = sys.argv[1], float(sys.argv[2]), sys.argv[3], sys.argv[4:]
rows = []
for f in files:
    e = json.load(open(f))
    if e['side_a'].split(':')[0] != e['side_b'].split(':')[0]:
        continue  # a rank comparison, not a knob: its wall times are not a like-for-like speed-up
    knob = e['side_b'].partition(':')[2] or '(none)'
    if 'effect_rel' not in e:
        sys.exit('pareto_plot: %s holds no effect on side A (written before effects were (B - A) / A): run '
                 'brash-post paired-ensemble on its runs again' % f)
    rows.append((e['speedup'], 100 * e['effect_rel'], 100 * e['effect_ci95_rel'], e['pairs'], knob, e['case'],
                 e['mean_a_N'], e['mean_b_N']))
if not rows:
    sys.exit('pareto_plot: no knob ensembles (side A and B on the same ranks) in the files given')
rows.sort()
print('| knob (side B; side A: the case as it is) | pairs | speed-up | mean A [N] | mean B [N] | (B − A) / A, 95 %% CI | within %g %% |' % tol)
print('|---|---|---|---|---|---|---|')
within = []
for sp, d, ci, n, knob, case, ma, mb in rows:
    ok = abs(d) + ci < tol
    if ok:
        within.append((sp, knob))
    print('| %s | %d | %.2fx | %.3f | %.3f | %+.2f %% ± %.2f %% | %s |' % (knob, n, sp, ma, mb, d, ci, 'yes' if ok else 'not shown'))
if within:
    sp, knob = max(within)
    print('fastest knob shown within %g %%: %s (%.2fx)' % (tol, knob, sp))
else:
    print('no knob is shown within %g %%' % tol)
with open(stem + '.dat', 'w') as f:
    f.write('# speed-up  paired-difference-%%  ci95-%%  label (case %s, reference %s)\n' % (rows[0][5], ref))
    for i, (sp, d, ci, n, knob, case, ma, mb) in enumerate(rows):
        f.write('%.4f %.4f %.4f "K%d"\n' % (sp, d, ci, i + 1))
    f.write('\n\n1 0 0 "reference"\n')  # index 1: the reference itself
base = os.path.basename(stem)
with open(stem + '.gp', 'w') as f:
    f.write("set terminal pngcairo size 900,600\nset output '%s.png'\nset termoption noenhanced\n" % base)
    f.write("set xlabel 'speed-up over the reference (summed wall time of the ensemble)'\n")
    f.write("set ylabel 'mean resistance: effect on the reference, (B - A) / A [%]'\nset grid\nset key right center\n")
    f.write("set title 'Run time vs error (%s, paired-seed ensembles; bars: 95 %% CI)'\n" % rows[0][5])
    f.write("set offsets graph 0.1, graph 0.1, graph 0.1, graph 0.1\n")
    f.write("plot %g with lines dt 2 lc 'grey' title '+-%g %%', %g with lines dt 2 lc 'grey' notitle, " % (tol, tol, -tol))
    f.write("'%s.dat' index 0 using 1:2:3 with yerrorbars pt 7 ps 1.5 lc 1 title 'knob', " % base)
    f.write("'' index 0 using 1:2:4 with labels offset 2,1 notitle, ")
    f.write("'' index 1 using 1:2 with points pt 5 ps 1.5 lc 2 title 'reference'\n")
for i, r in enumerate(rows):
    print('K%d = %s' % (i + 1, r[4]))
PY
(cd "$(dirname "$png")" && gnuplot "$(basename "$stem").gp")
echo "wrote $png (data ${stem}.dat, script ${stem}.gp)"
