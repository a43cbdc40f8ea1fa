#!/usr/bin/python3
"""How far the ice has moved at the channel's free far end, and how far ahead of the bow the push reaches, in the
particle dumps of a run (LIGGGHTS while it goes; any engine when it is done).
    /usr/bin/python3 bench/channel_end_spread.py RUN_DIR [EVERY (3: every third dump)]
A floating two-layer bed with no end wall relaxes at its free end (the top layer's weight pushes the bottom layer
out into open water); this prints, per dump, where that relaxation front is (the first 0.25 m strip, counted from
the far end, whose pieces moved less than 1 cm on average from their packing positions), how many pieces have left
the channel (x > length), the bow's push ahead (the last strip ahead of the bow that moved more than 1 cm), and how
still the bed between them is: the median |vz| of the pieces more than 3 m ahead of the bow and short of the front,
and the share of them faster than 5 mm/s (the far field's wake speed; docs/performance.md "The wake rule on the
paper scene").
Needs Debian's python3-numpy (hence /usr/bin/python3). Reads RUN_DIR/case.yaml for the channel length, the hull's
start and the speed, and the case's packing file for the packing positions (piece id = packing row)."""
import sys

import numpy as np
from run_dumps import case_value, every_nth, load, meta, snapshots

run = sys.argv[1]
every = int(sys.argv[2]) if len(sys.argv) > 2 else 3
length = float(case_value(run, 'channel.length_m'))
start_x = float(case_value(run, 'hull.start_x_m'))
lpp = float(case_value(run, 'hull.lpp_m'))
speed = float(case_value(run, 'ship.speed_m_s'))
packing_file = case_value(run, 'ice.packing_file')
with open(packing_file) as f:  # '#' comment lines, then the header id,x,y,z,diameter
    rows = [line for line in f if not line.startswith('#')]
columns = rows[0].strip().split(',')
packing = np.loadtxt(rows[1:], delimiter=',')
packing_x = packing[:, columns.index('x')]
if not (packing[:, columns.index('id')] == np.arange(1, len(packing) + 1)).all():  # dump ids index the rows
    sys.exit('%s: ids are not 1..N in file order' % packing_file)
dt = float(meta(run)['dt_s'])
dumps = snapshots(run, dt)
print('| t [s] | bow x [m] | far-end front at x0 [m] | pieces beyond x = %g m | push reaches (ahead of bow) [m] '
      '| bed between: median abs(vz) [mm/s] | faster than 5 mm/s |' % length)
print('|---|---|---|---|---|---|---|')
for t, f in every_nth(dumps, every):
    d = load(f, (0, 1, 5, 6, 7))  # id x vx vy vz
    x0 = packing_x[d[:, 0].astype(int) - 1]
    moved = np.abs(d[:, 1] - x0)
    front = length
    for a in np.arange(length - 0.25, 0, -0.25):
        m = (x0 >= a) & (x0 < a + 0.25)
        if m.any() and moved[m].mean() < 0.01:
            front = a + 0.25
            break
    bow = start_x + lpp + speed * t  # the hull's x range is [start_x, start_x + Lpp] at t = 0
    reach = 0.0
    for a in np.arange(0, max(0.0, front - bow), 0.25):
        m = (x0 >= bow + a) & (x0 < bow + a + 0.25)
        if m.any() and moved[m].mean() >= 0.01:
            reach = a + 0.25
        else:
            break
    between = (x0 > bow + 3.0) & (x0 < front)
    piece_speed = np.linalg.norm(d[between, 2:5], axis=1)
    still = ('%.1f | %.0f %%' % (np.median(np.abs(d[between, 4])) * 1e3, 100 * np.mean(piece_speed > 5e-3))
             if between.any() else '- | -')
    print('| %.1f | %.2f | %.2f | %d | %.2f | %s |' % (t, bow, front, (d[:, 1] > length).sum(), reach, still))
