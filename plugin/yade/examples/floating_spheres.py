# Floating ice spheres in YADE with the brash fluid engine: an ordinary YADE script.
#
#   PYTHONPATH=<brash python dir> yade -n -j1 -x floating_spheres.py
#
# (<brash python dir>: <build>/python in a build tree, <prefix>/lib/brash/python installed.) Exit code 0 when every
# check holds; tests/yade runs it as ctest yade_example_floating_spheres.
#
# Three ice spheres of different sizes are let go at rest 0.1 r above their floating position and bob until drag
# settles them at their floating draft. Gravity is where YADE users put it, in NewtonIntegrator; the fluid engine
# (buoyancy, drag, added mass of the brash core) acts on every sphere whose groupMask shares a bit with 1. On the
# way: a sphere appended under water at t = 1 s gets the fluid force from its first step, one erased at t = 2 s
# drops out, and a sphere with groupMask 2 (not selected) falls as in air.
import math
import sys

from yade import O
from yade.utils import sphere
from yade.wrapper import (Bo1_Sphere_Aabb, ForceResetter, FrictMat, Ig2_Sphere_Sphere_ScGeom, InsertionSortCollider,
                          InteractionLoop, Ip2_FrictMat_FrictMat_MindlinPhys, Law2_ScGeom_MindlinPhys_Mindlin,
                          NewtonIntegrator)

import brash_yade
from brash_yade_adapter import FluidAdapter

RHO_ICE, RHO_WATER, G = 900.0, 1000.0, 9.81
DT = 1e-4

ice = O.materials.append(FrictMat(young=5e6, poisson=0.3, frictionAngle=math.atan(1.35), density=RHO_ICE))
radii = [0.010, 0.0175, 0.025]

def z_float(r):
    """Centre height of a floating sphere (bottom at the draft h: submerged fraction rho_i / rho_w)."""
    return r - brash_yade.analytic.height_for_fraction(r, RHO_ICE / RHO_WATER)


floating = [O.bodies.append(sphere((0.1 * k, 0, z_float(r) + 0.1 * r), r, material=ice)) for k, r in enumerate(radii)]
dry = O.bodies.append(sphere((0, 0.3, -0.2), 0.01, material=ice, mask=2))  # under water, but not selected

fluid = FluidAdapter(mask=1, model="both", treatment="implicit", water_level=0.0, water_density=RHO_WATER)
O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb()]),
    InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_MindlinPhys()],
                    [Law2_ScGeom_MindlinPhys_Mindlin()]),
    fluid.engine(),                                       # after the contact forces, before Newton
    NewtonIntegrator(gravity=(0, 0, -G), damping=0),
]
O.dt = DT

failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what, flush=True)
    if not ok:
        failures.append(what)


def volume(r):
    return 4.0 / 3.0 * math.pi * r ** 3


# 1 s of bobbing, then a sphere appended 0.1 m under water, at rest.
O.run(int(round(1.0 / DT)), True)
check(len(fluid.ids) == 3 and dry not in fluid.ids, "the mask selects the 3 floating spheres, not the dry one")
r_new = 0.015
late = O.bodies.append(sphere((0.4, 0, -0.1), r_new, material=ice))
O.run(1, True)
# Its first step: buoyancy - weight over the implicit mass m + m_a (Ca_z = 0.5 submerged, Table 1); no drag at rest.
a_expect = (RHO_WATER - RHO_ICE) * G / (RHO_ICE + 0.5 * RHO_WATER)
a_seen = O.bodies[late].state.vel[2] / DT
check(late in fluid.ids, "a sphere appended mid-run joins the fluid engine")
check(abs(a_seen / a_expect - 1) < 1e-9, "its first-step acceleration %.9f m/s^2 = (rho_w - rho_i) g / (rho_i + "
      "0.5 rho_w) = %.9f m/s^2" % (a_seen, a_expect))

# t = 2 s: erase the smallest floating sphere; the engine drops it and goes on.
O.run(int(round(1.0 / DT)) - 1, True)
O.bodies.erase(floating[0])
O.run(10, True)
check(floating[0] not in fluid.ids and len(fluid.ids) == 3, "an erased sphere leaves the fluid engine (%d spheres)"
      % len(fluid.ids))

# The dry sphere fell as in air all along (no buoyancy, no drag, no added mass): v = -g t.
v_dry = O.bodies[dry].state.vel[2]
check(abs(v_dry / (-G * O.iter * DT) - 1) < 1e-9, "the unselected sphere falls freely (v = %.6f m/s at t = %.4f s)"
      % (v_dry, O.iter * DT))

# On to 8 s; then the draft at the centre of the oscillation over the last second (two periods and more) against
# the closed form (submerged fraction rho_i / rho_w).
O.run(int(round(5.0 / DT)) - 10, True)
samples = {i: [] for i in floating[1:]}
for _ in range(500):
    O.run(int(round(0.002 / DT)), True)
    for i in samples:
        samples[i].append(O.bodies[i].state.pos[2])
for i, zs in samples.items():
    r = O.bodies[i].shape.radius
    draft = r - 0.5 * (max(zs) + min(zs))               # depth of the sphere's bottom under the surface
    expect = brash_yade.analytic.height_for_fraction(r, RHO_ICE / RHO_WATER)
    swing = max(zs) - min(zs)
    print("sphere %d (r = %.4f m): draft %.6f m, closed form %.6f m, swing over the last second %.2e m"
          % (i, r, draft, expect, swing))
    check(abs(draft / expect - 1) < 0.01, "sphere %d floats at its draft within 1 %% (%.3f %%)"
          % (i, 100 * (draft / expect - 1)))
    check(abs(O.bodies[i].state.pos[0] - 0.1 * floating.index(i)) < 1e-12,
          "sphere %d stayed in its place (no horizontal force in still water)" % i)
# The late sphere rose to the surface and floats there too (its swing is still large: it came up from 0.1 m).
z_late = O.bodies[late].state.pos[2]
check(-r_new < z_late < r_new, "the appended sphere surfaced (centre at z = %.4f m)" % z_late)

print("%d check(s) failed" % len(failures) if failures else "all checks passed", flush=True)
sys.exit(1 if failures else 0)
