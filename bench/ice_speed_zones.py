#!/usr/bin/python3
"""Where the moving ice is, in one particle dump of a run: the pieces ahead of the bow, alongside the hull and
behind the stern, and alongside the hull by distance behind the bow and by |y| across the channel, with each
zone's piece count, median speed and share faster than 5 mm/s (the far field's wake speed). Idle pieces of the
far field (speed exactly 0) are counted as such. It shows what the far field can still skip: a piece alongside
the hull is inside the window and always integrated, however slow (docs/performance.md "The idle far field").
    /usr/bin/python3 bench/ice_speed_zones.py RUN_DIR [T_S (the last dump)]
Needs Debian's python3-numpy (hence /usr/bin/python3). The bow's and stern's offsets from the hull's reference
point come from the run's in.lmp (fix brash/farfield) when it has them, else stern = bow - hull.lpp_m."""
import os
import re
import sys

import numpy as np
from run_dumps import case_value, load, meta, snapshots

run = sys.argv[1]
start_x = float(case_value(run, 'hull.start_x_m'))
speed = float(case_value(run, 'ship.speed_m_s'))
snaps = snapshots(run, float(meta(run)['dt_s']))
t, path = snaps[-1]
if len(sys.argv) > 2:
    t, path = min(snaps, key=lambda s: abs(s[0] - float(sys.argv[2])))
bow_offset, stern_offset = None, None
in_lmp = os.path.join(run, 'in.lmp')
if os.path.exists(in_lmp):
    m = re.search(r'bow_offset (\S+) stern_offset (\S+)', open(in_lmp).read())
    if m:
        bow_offset, stern_offset = float(m[1]), float(m[2])
hull_x = start_x + speed * t
if bow_offset is None:
    bow = hull_x + float(case_value(run, 'hull.lpp_m'))
    stern = hull_x
else:
    bow, stern = hull_x + bow_offset, hull_x + stern_offset
a = load(path, [0, 1, 2, 3, 5, 6, 7])
x, y = a[:, 1], a[:, 2]
v = np.linalg.norm(a[:, 4:7], axis=1)


def zone(mask):
    n = int(mask.sum())
    if n == 0:
        return f'{0:7d} {"-":>9} {"-":>6} {"-":>6}'
    return f'{n:7d} {1000 * np.median(v[mask]):9.1f} {np.mean(v[mask] > 0.005):6.2f} {np.mean(v[mask] == 0):6.2f}'


print(f'{run}: t = {t:.2f} s, bow at x = {bow:.3f} m, stern at {stern:.3f} m, {len(x)} pieces')
print(f'{"zone":34s} {"pieces":>7} {"median":>9} {">5mm/s":>6} {"idle":>6}')
print(f'{"":34s} {"":>7} {"[mm/s]":>9}')
print(f'{"ahead of the bow":34s} {zone(x >= bow)}')
print(f'{"alongside the hull":34s} {zone((x >= stern) & (x < bow))}')
print(f'{"behind the stern":34s} {zone(x < stern)}')
half_width = float(case_value(run, 'channel.width_m')) / 2
y_edges = np.linspace(0, half_width, 6)
for lo, hi in [(0, 0.5), (0.5, 1.5), (1.5, 3), (3, 5), (5, 1e9)]:
    along = (x >= stern) & (x < bow - lo) & (x >= bow - hi)
    label = f'alongside, {lo:g}-{hi:g} m behind the bow' if hi < 1e9 else f'alongside, over {lo:g} m behind the bow'
    print(f'{label:34s} {zone(along)}')
    for y0, y1 in zip(y_edges[:-1], y_edges[1:]):
        print(f'{"":4s}{f"|y| {y0:.2f}-{y1:.2f} m":30s} {zone(along & (np.abs(y) >= y0) & (np.abs(y) < y1))}')
