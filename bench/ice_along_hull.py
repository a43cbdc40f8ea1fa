#!/usr/bin/python3
"""Where the ice is along the hull, per particle dump of a LIGGGHTS run (finished or still going): what the
resistance history does not say by itself (where we differ from the paper, and why).
    /usr/bin/python3 bench/ice_along_hull.py RUN_DIR [EVERY (2: every second dump)]
Per dump (LIGGGHTS raw dumps while the run goes, the particles_*.csv of any engine when it is done), with the hull's x range from the case (bow at start_x + Lpp + speed t, Lpp long) and its beam B:
  - ahead: the ice within 1 m ahead of the bow, in pieces per m2 over the undisturbed bed's (the bed's mean
    areal density, pieces / channel area): above 1 = ice piled up ahead;
  - alongside: the ice beside the hull (|y| > B/2, between stern and bow), same ratio;
  - under: the pieces pushed down inside the hull's Lpp x B outline seen from above (|y| < B/2, between stern
    and bow, top of the piece deeper than DEPTH = 5 cm below the water level), in the bow, middle and stern thirds
    of the length; they press on the hull with their buoyancy and rub on it as it moves. Near the bow that
    outline is wider than the hull, so most of them ride down the bow's sides rather than lie beneath the flat
    bottom (LIGGGHTS drag paper run at 40 s: 90 % within 0.9 m of the bow, 6-17 cm deep, the model's draft being
    0.41 m);
  - behind: pieces still deeper than DEPTH behind the stern (within 2 m).
Needs Debian's python3-numpy (hence /usr/bin/python3). Reads RUN_DIR/case.yaml (channel, hull, ship) through brash-case get."""
import sys

import numpy as np
from run_dumps import case_value, every_nth, load, meta, snapshots

DEPTH = 0.05  # [m] below the water level: well below the undisturbed two-layer bed (0.035 m thick)

run = sys.argv[1]
every = int(sys.argv[2]) if len(sys.argv) > 2 else 2
length = float(case_value(run, 'channel.length_m'))
width = float(case_value(run, 'channel.width_m'))
water = float(case_value(run, 'water.level_m'))
start_x = float(case_value(run, 'hull.start_x_m'))
lpp = float(case_value(run, 'hull.lpp_m'))
beam = float(case_value(run, 'hull.beam_m'))
speed = float(case_value(run, 'ship.speed_m_s'))
dt = float(meta(run)['dt_s'])
dumps = snapshots(run, dt)

print('| t [s] | bow x [m] | ahead (1 m) / bed | alongside / bed | under: bow third | middle third | stern third '
      '| behind (2 m), deep |')
print('|---|---|---|---|---|---|---|---|')
density = None
for t, f in every_nth(dumps, every):
    d = load(f, (1, 2, 3, 4))  # x y z radius
    x, y, top = d[:, 0], d[:, 1], d[:, 2] + d[:, 3]
    if density is None:  # pieces per m2 of the undisturbed bed
        density = len(d) / (length * width)
    bow = start_x + lpp + speed * t
    stern = bow - lpp
    inside = (x > stern) & (x < bow)
    ahead = ((x >= bow) & (x < bow + 1.0)).sum() / (1.0 * width) / density
    side_area = max(1e-9, (min(bow, length) - max(stern, 0.0))) * (width - beam)
    alongside = (inside & (np.abs(y) > 0.5 * beam)).sum() / side_area / density if bow > 0 else float('nan')
    deep = top < water - DEPTH
    under = inside & (np.abs(y) < 0.5 * beam) & deep
    thirds = [(under & (x > bow - (k + 1) * lpp / 3) & (x <= bow - k * lpp / 3)).sum() for k in range(3)]
    behind = (deep & (x <= stern) & (x > stern - 2.0)).sum()
    print('| %.1f | %.2f | %.2f | %.2f | %d | %d | %d | %d |' % (t, bow, ahead, alongside, *thirds, behind))
