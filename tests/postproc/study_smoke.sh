#!/usr/bin/env bash
# brash-study on study/smoke.yaml end to end into a temp dir (docs/study.md and docs/paper_runs are not touched),
# then the archives: the study's runs copied beside the document, a complete run in the paper dir archived, each
# listed from its copy (also once its run directory is gone).
#   bash study_smoke.sh REPO BIN_DIR TMP_DIR
set -euo pipefail
repo="$1" bin="$2" tmp="$3"
rm -rf "$tmp" && mkdir -p "$tmp/paper" "$tmp/elsewhere/deeper/work"
# the work dir is a symlink to a folder at another depth (as runs/ is on our machines): the manifest's paths
# relative to it must still name the copies beside the document
ln -s "$tmp/elsewhere/deeper/work" "$tmp/work"
study() {
  "$bin/brash-study" --study "$repo/study/smoke.yaml" --repo "$repo" --bin "$bin" --work "$tmp/work" \
    --out "$tmp/study.md" --paper-dir "$tmp/paper" --archive "$tmp/archive"
}
expect() {  # expect TEXT...: every TEXT is in the document
  local t
  for t in "$@"; do grep -qF -- "$t" "$tmp/study.md" || { echo "missing in study.md: $t"; cat "$tmp/study.md"; exit 1; }; done
}
study
expect '## (a) Paper comparison' '## (b) Speed sweep' '## (c) Sensitivities' '## (d) Engines' \
  '## (e) Runs and the commands' 'reduced case' '| liggghts | added_mass | 2 |' 'brash-liggghts-run' \
  '![full-scale resistance vs the paper](study_figs/paper_bars.png)' '![R1 force history](' \
  'Fig. 4 analog' 'None: every run listed in the manifest has a complete report.json.'
test -s "$tmp/study_manifest.tsv" && test -s "$tmp/study_figs/paper_bars.png"
# a run's own plot is linked where it is, relative to the document
fh="$(sed -n 's/^!\[R1 force history\](\(.*\))$/\1/p' "$tmp/study.md")"
test -n "$fh" && test -s "$tmp/$fh" || { echo "R1's force history link does not name its plot: '$fh'"; exit 1; }
test ! -e "$tmp/study_figs/R1_force_history.png"
if grep -q 'paper-liggghts' "$tmp/study.md"; then echo "a paper run listed with none made"; exit 1; fi
test ! -e "$tmp/archive"
test ! -e "$tmp/paper/cases"  # smoke mode makes no paper case folder (it never starts a paper run)
# the study's own runs: their outputs copied beside the document (study_runs/<id>) and listed from there
for id in smoke_am smoke_drag smoke_u0.8_am; do
  for f in meta.json case.yaml report.json report.md hull_force.csv; do
    test -s "$tmp/study_runs/$id/$f" || { echo "not copied: $id/$f"; exit 1; }
  done
  cmp "$tmp/work/runs/$id/report.json" "$tmp/study_runs/$id/report.json"
  # the plots stay in the run directory; the document's figures are taken from there
  if ls "$tmp/study_runs/$id"/*.png > /dev/null 2>&1; then echo "plots copied to study_runs/$id"; exit 1; fi
done
test ! -e "$tmp/study_runs/smoke_am/restart" && test ! -e "$tmp/study_runs/smoke_am/particles"
expect '/study_runs/smoke_am` | smoke_base | liggghts | added_mass |' '| report files |'
# the ParaView files are named in the full run directory the copy came from
expect '/work/runs/smoke_am/particles.pvd` and `' '/work/runs/smoke_am/force_history.png`)'
if grep -qF '/work/runs/smoke_am`' "$tmp/study.md"; then echo "a run listed from the work dir"; exit 1; fi
grep -qF 'study_runs/smoke_drag' "$tmp/study_manifest.tsv"

# a complete run standing in for the drag paper run: archived and listed from the archive; a copy of a run the
# study no longer lists is dropped from study_runs
mkdir -p "$tmp/study_runs/stale"
cp -r "$tmp/work/runs/smoke_drag" "$tmp/paper/paper-liggghts-drag-20s"
study
test ! -e "$tmp/study_runs/stale"
expect '/archive/paper-liggghts-drag-20s` | smoke_base | liggghts | drag |'
for f in meta.json case.yaml report.json report.md hull_force.csv force_history.png; do
  test -s "$tmp/archive/paper-liggghts-drag-20s/$f" || { echo "not archived: $f"; exit 1; }
done
ls "$tmp/archive/paper-liggghts-drag-20s"/ice_views_*.png > /dev/null
cmp "$tmp/paper/paper-liggghts-drag-20s/report.json" "$tmp/archive/paper-liggghts-drag-20s/report.json"

# its run directory gone (a new machine): listed from the archive, not run again
rm -rf "$tmp/paper/paper-liggghts-drag-20s"
study
expect '/archive/paper-liggghts-drag-20s` | smoke_base | liggghts | drag |' \
  '/paper/paper-liggghts-drag-20s`, where the run was made.'
test ! -e "$tmp/paper/paper-liggghts-drag-20s"
# a paired ensemble's summary: listed, archived, and listed from the archive once its folder is gone
qs="1:contact.youngs_modulus_pa=3.125e5,run.timestep_s=8.0e-4"
mkdir -p "$tmp/paper/fluid-reading"
cat > "$tmp/paper/fluid-reading/ensemble-smoke.json" <<JSON
{ "side_a": "$qs,fluid.model=added_mass", "side_b": "$qs,fluid.model=drag", "case": "jbc_narrow", "pairs": 3,
  "mean_a_N": 10.0, "mean_b_N": 12.5, "diff_rel": 0.2222, "ci95_rel": 0.0123 }
JSON
study
expect '| P1 |' 'drag on added_mass' '+25.0 % (CI on A not recomputable; recorded on the pair mean: ± 1.2 %)' 'archive/ensembles/fluid-reading/ensemble-smoke.json'
cmp "$tmp/paper/fluid-reading/ensemble-smoke.json" "$tmp/archive/ensembles/fluid-reading/ensemble-smoke.json"
rm -rf "$tmp/paper/fluid-reading"
study
expect '| P1 |' '+25.0 % (CI on A not recomputable; recorded on the pair mean: ± 1.2 %)' 'archive/ensembles/fluid-reading/ensemble-smoke.json'

# a run still in progress (no complete report) is not archived
# (listed as in progress, with the model time its record has reached; the stand-in's meta.json is smoke_am's)
mkdir -p "$tmp/paper/paper-liggghts-both-20s" && cp "$tmp/work/runs/smoke_am/meta.json" "$tmp/paper/paper-liggghts-both-20s/"
study
test ! -e "$tmp/archive/paper-liggghts-both-20s"
expect '/paper/paper-liggghts-both-20s` | ? | liggghts | added_mass | **IN PROGRESS**'
test ! -e "$tmp/paper/cases"

# an ODE paper run (it takes tens of hours and is archived while it goes on) with a partial record: the record
# so far is archived (complete rows only), the run is listed with its bins beside the LIGGGHTS run of the same
# fluid model (here a stand-in at 1.1x the drag stand-in's force, its totals only: a record without the hull
# force split's columns, as an ODE run started before them has), and once its directory is gone it is listed
# from the archive as stopped part-way
o="$tmp/paper/paper-ode-drag-20s"
mkdir -p "$o"
sed 's/"engine": "liggghts"/"engine": "ode"/' "$tmp/work/runs/smoke_drag/meta.json" > "$o/meta.json"
cp "$tmp/work/runs/smoke_drag/case.yaml" "$o/"
awk -F, 'NR == 1 { print "t_s,fx_N,fy_N,fz_N"; next } { printf "%s,%.9g,%s,%s\n", $1, 1.1 * $2, $3, $4 }' \
  "$tmp/archive/paper-liggghts-drag-20s/hull_force.csv" > "$o/hull_force.csv"
printf '9.99,-1.0,0.0,0.' >> "$o/hull_force.csv"  # a row still being written
study
test -s "$tmp/archive/paper-ode-drag-20s/hull_force.csv" && test -s "$tmp/archive/paper-ode-drag-20s/meta.json"
if grep -q '^9.99' "$tmp/archive/paper-ode-drag-20s/hull_force.csv"; then echo "unterminated row archived"; exit 1; fi
expect '/paper/paper-ode-drag-20s` | ? | ode | drag | **IN PROGRESS** (in progress: model time 0.30 s of' \
  'ode [N] |' '| 0.2-0.3 |' '+10.0 %'
rm -rf "$o"
study
expect '/archive/paper-ode-drag-20s` | ? | ode | drag | **IN PROGRESS** (in progress, stopped: model time 0.30 s of' \
  'ode [N] |' '+10.0 %'
test ! -e "$o"
# a shorter record of the same run (started again elsewhere) does not replace the longer archived one
mkdir -p "$o" && cp "$tmp/archive/paper-ode-drag-20s/meta.json" "$tmp/archive/paper-ode-drag-20s/case.yaml" "$o/"
head -n 5 "$tmp/archive/paper-ode-drag-20s/hull_force.csv" > "$o/hull_force.csv"
study
test "$(wc -l < "$tmp/archive/paper-ode-drag-20s/hull_force.csv")" -gt 5
cat "$tmp/study.md"
