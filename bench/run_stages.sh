#!/usr/bin/env bash
# The wall time of each stage of runs made from their case (meta.json "stages": the packing, its settled bed, the
# scene's set-up, the run, the report), with each run's total from a new packing and its ratio to the first run's.
# A stage made before the run (a cached packing or settled bed) counts at what it cost when it was made; a stage the
# run did not have (no settling, no report: --no-post) counts 0, marked "(none)".
#   bash bench/run_stages.sh RUN_DIR [RUN_DIR ...]     (the first is the baseline of the ratios)
set -euo pipefail
if [ $# -lt 1 ]; then
  echo "usage: bash bench/run_stages.sh RUN_DIR [RUN_DIR ...]" >&2
  exit 2
fi
/usr/bin/python3 - "$@" <<'PY'
import json, os, sys

STAGES = [('packing', 'packing'), ('settling', 'settling'), ('setup_s', 'set-up'), ('run_s', 'run'),
          ('post_s', 'report')]

def stages(run_dir):
    meta_file = os.path.join(run_dir, 'meta.json')
    try:
        meta = json.load(open(meta_file))
    except (OSError, ValueError) as e:
        sys.exit(f"run_stages: {meta_file}: cannot read ({e})")
    if 'stages' not in meta:
        sys.exit(f"run_stages: {meta_file}: no \"stages\" (a run made before its stages were recorded)")
    s, out = meta['stages'], {}
    for key, name in STAGES:
        v = s.get(key)
        if isinstance(v, dict):  # a made input: its cost, made now or before
            out[name] = (v.get('wall_s'), '' if v.get('made_by_this_run') else ' (cached)')
        elif key in s:
            out[name] = (v, '')
        elif key in ('settling', 'post_s'):
            out[name] = (0.0, ' (none)')  # ice.settle off (the run starts from the packing), or --no-post
        else:
            out[name] = (None, '')
    return meta, out

rows = [(d,) + stages(d) for d in sys.argv[1:]]
names = [n for _, n in STAGES]
print(f"{'run':40s} " + ' '.join(f'{n + " s":>18s}' for n in names) + f" {'total s':>9s} {'model s':>7s} {'ratio':>6s}")
base = None
for d, meta, st in rows:
    missing = [n for n in names if st[n][0] is None]
    total = None if missing else sum(st[n][0] for n in names)
    base = base if base is not None else total
    cells = ' '.join(f"{'?' if st[n][0] is None else format(st[n][0], '.4g')}{st[n][1]:>9s}".rjust(18) for n in names)
    ratio = f"{base / total:.2f}x" if total and base else '-'
    tot = '?' if total is None else f"{total:.0f}"
    print(f"{os.path.basename(os.path.normpath(d)):40s} {cells} {tot:>9s} {meta.get('model_time_reached_s', 0):7.1f} {ratio:>6s}"
          + (f"  (not recorded: {', '.join(missing)})" if missing else ''))
print("ratio: the first run's total from a new packing over this run's (above 1: faster)")
PY
