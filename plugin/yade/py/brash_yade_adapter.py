"""brash fluid forces (buoyancy, drag, added mass) for YADE spheres: the YADE adapter.

Debian's YADE ships no C++ headers, so the adapter is a PyRunner that calls the compiled core (brash_yade, a
pybind11 module linking brash_core) once per step. In an ordinary YADE script:

    fluid = FluidAdapter(mask=1, model="both")           # every sphere whose groupMask shares a bit with 1
    O.engines = [ForceResetter(), InsertionSortCollider([...]), InteractionLoop([...], [...], [...]),
                 fluid.engine(),                          # after the contacts, before Newton
                 NewtonIntegrator(gravity=(0, 0, -9.81), damping=0)]

Which spheres: `mask` (bodies whose groupMask & mask != 0 and whose shape is a Sphere, dynamic, not clump
members), re-scanned whenever bodies are appended (len(O.bodies) grows), or `ids` (that list; add()/remove()
change it). Erased spheres are dropped at the next step (YADE sets an erased body's id to -1). After changing
masks, O.bodies.insertAtId or a sphere's radius/mass, call rescan().

Gravity: where YADE users put it, NewtonIntegrator.gravity, or in the fluid (Newton's gravity zero). The
adapter reads Newton's gravity every step and adapts:
  - Newton gravity g_N = (0, 0, -g) (it must point along -z: buoyancy acts along +z): the fluid does not add the
    weight; g is the buoyancy's g too (keyword g=None takes it from Newton; a g that differs is an error);
    Newton adds m g_N as an acceleration, outside any force scaling, so the adapter counts m g_N among the
    "other" forces the implicit added mass scales and takes it back out of what it adds:
        addF = (f_contact + m g_N + f_fluid) * s - f_contact - m g_N,    s = m / (m + m_a) per axis,
    Newton then integrates (f_contact + m g_N + f_fluid) * s, the total of the core's reference integrator
    (gravity as an engine force) and of LIGGGHTS' fix. Explicit added mass / no added mass: s = 1, the
    adapter adds f_fluid.
  - Newton gravity zero: the fluid applies the weight -m g itself (apply_gravity) and addF =
    (f_contact + f_fluid) * s - f_contact.
Both set-ups give the same trajectories to round-off (tests/yade/single_sphere.py gravity).

The PyRunner sits between InteractionLoop and NewtonIntegrator so that O.forces.f(id, sync=True) holds the
contact forces of this step; the first step checks that order (check_engine_order).

Velocity: YADE's leap-frog keeps v(n - 1/2) in state.vel while forces at x(n) are computed, which is the
velocity the velocity-Verlet reference (brash::core::ReferenceSphere) and LIGGGHTS' fix see too.

State: the previous velocity of each sphere (explicit added mass, the 'motion reversed' rows of the Ca table).
O.save does not hold it: save_state()/load_state() (or state()/restore()) write and read it by body id next
to a saved scene; after O.load, build the adapter again and restore it.
"""
import json
import os

import __main__

import numpy as np

import brash_yade

_REGISTRY_NAME = "_brash_yade_adapters"


def _engines_of_type(O, name):
    return [e for e in O.engines if type(e).__name__ == name]


class FluidAdapter:
    """Fluid forces of the brash core on YADE spheres chosen by `mask` or `ids`."""

    # The fluid defaults are the core's (brash/fluid_options.hpp), as the module passes them on.
    def __init__(self, ids=None, model="both", treatment="implicit", cd=brash_yade.DEFAULT_CD, drag_law="constant",
                 nu=brash_yade.DEFAULT_NU, ca_table="table1", water_level=0.0,
                 water_density=brash_yade.DEFAULT_WATER_DENSITY, g=None, fluid=None, mask=None, label="brashFluid"):
        """ids: body ids (a fixed list, see add()/remove()), or mask: a groupMask (re-scanned), one of the two.
        fluid: a brash_yade.Fluid (e.g. Fluid.from_case(case.yaml)) used instead of the keyword parameters; its g
        must then agree with NewtonIntegrator's gravity when that is not zero. g=None: brash_yade.DEFAULT_G, or
        NewtonIntegrator's |gravity| when it has one."""
        from yade import O  # imported here so the module can be imported (for docs) outside yade
        self.O = O
        if (ids is None) == (mask is None):
            raise ValueError("FluidAdapter: give the spheres either by ids=[...] or by mask=<groupMask>")
        self.mask = None if mask is None else int(mask)
        if self.mask is not None and self.mask == 0:
            raise ValueError("FluidAdapter: mask 0 selects no body")
        if fluid is None:
            self._g_given = g is not None
            fluid = brash_yade.Fluid(model=model, treatment=treatment, cd=cd, drag_law=drag_law, nu=nu,
                                     ca_table=ca_table, water_level=water_level, water_density=water_density,
                                     g=brash_yade.DEFAULT_G if g is None else g, apply_gravity=True)
        else:
            if g is not None:
                raise ValueError("FluidAdapter: give g through the fluid (Fluid(g=...)) when passing fluid=")
            self._g_given = True
        self.fluid = fluid
        self.label = label
        self.steps = 0
        self._gravity = None  # NewtonIntegrator.gravity the fluid is configured for
        self._order_checked = False
        self.ids, self.bodies, self.states = [], [], []
        self.radius = np.zeros(0)
        self.mass = np.zeros(0)
        self._seen = 0
        if self.mask is None:
            self._set([int(i) for i in ids], check=True)
        else:
            self.rescan()
        registry = getattr(__main__, _REGISTRY_NAME, None)
        if registry is None:
            registry = []
            setattr(__main__, _REGISTRY_NAME, registry)
        self.index = len(registry)
        registry.append(self)

    # --- which spheres ---------------------------------------------------------------------------------------
    def _is_fluid_sphere(self, b):
        return (b is not None and b.id >= 0 and type(b.shape).__name__ == "Sphere" and b.dynamic
                and not b.isClumpMember and (self.mask is None or (b.groupMask & self.mask) != 0))

    def _set(self, new_ids, check=False):
        """Make new_ids the sphere list, keeping the fluid state of the spheres that stay."""
        O = self.O
        bodies = []
        for i in new_ids:
            b = O.bodies[i] if 0 <= i < len(O.bodies) else None
            if b is None or b.id < 0:
                raise ValueError("FluidAdapter: body %d does not exist" % i)
            if check and not self._is_fluid_sphere(b):
                raise ValueError("FluidAdapter: body %d is not a dynamic sphere (shape %s, dynamic %s)"
                                 % (i, type(b.shape).__name__, b.dynamic))
            bodies.append(b)
        old = {i: k for k, i in enumerate(self.ids)}
        self.fluid.remap([old.get(i, -1) for i in new_ids])
        self.ids = list(new_ids)
        self.bodies = bodies
        # State objects stay the live state of their bodies: cache them (saves a lookup per sphere).
        self.states = [b.state for b in bodies]
        self.radius = np.array([b.shape.radius for b in bodies], dtype=float)
        self.mass = np.array([b.state.mass for b in bodies], dtype=float)
        self._seen = len(O.bodies)

    def rescan(self):
        """Mask mode: every matching sphere now in O.bodies (in id order). List mode: drops erased ids and
        re-reads radius and mass."""
        O = self.O
        if self.mask is None:
            self._set([i for i, b in zip(self.ids, self.bodies) if b.id == i])
        else:
            self._set([b.id for b in O.bodies if self._is_fluid_sphere(b)])

    def add(self, ids):
        """Add spheres by id (list mode; in mask mode set their groupMask instead)."""
        if self.mask is not None:
            raise RuntimeError("FluidAdapter.add: this adapter selects by mask: give the new bodies a groupMask "
                               "that shares a bit with %d" % self.mask)
        new = [int(i) for i in ids if int(i) not in set(self.ids)]
        for i in new:
            b = self.O.bodies[i] if 0 <= i < len(self.O.bodies) else None
            if not self._is_fluid_sphere(b):
                raise ValueError("FluidAdapter.add: body %d is not a dynamic sphere" % i)
        self._set(self.ids + new)

    def remove(self, ids):
        """Stop applying fluid forces to these ids (list mode)."""
        if self.mask is not None:
            raise RuntimeError("FluidAdapter.remove: this adapter selects by mask: change the bodies' groupMask "
                               "and call rescan()")
        drop = set(int(i) for i in ids)
        self._set([i for i in self.ids if i not in drop])

    def _follow_bodies(self):
        """Appended bodies (mask mode) and erased ones (both modes; erased ones are also caught by apply)."""
        n = len(self.O.bodies)
        if n == self._seen:
            return
        if n < self._seen or self.mask is None:  # O.bodies cleared or replaced, or list mode
            self.rescan()
            return
        O = self.O
        added = [i for i in range(self._seen, n) if self._is_fluid_sphere(O.bodies[i])]
        if added:
            self._set(self.ids + added)
        self._seen = n

    # --- gravity ---------------------------------------------------------------------------------------------
    def _newton(self):
        newtons = _engines_of_type(self.O, "NewtonIntegrator")
        if len(newtons) != 1:
            raise RuntimeError("brash: O.engines needs exactly one NewtonIntegrator (found %d)" % len(newtons))
        return newtons[0]

    def _follow_gravity(self, gravity):
        """Configure the fluid for NewtonIntegrator.gravity (see the module's doc)."""
        if gravity == self._gravity:
            return
        gx, gy, gz = gravity
        fl = self.fluid
        if gravity == (0.0, 0.0, 0.0):
            fl.configure_gravity(fl.g, True)
        else:
            if gx != 0 or gy != 0 or not gz < 0:
                raise RuntimeError("brash: NewtonIntegrator.gravity = (%g, %g, %g): it must point along -z "
                                   "(buoyancy acts along +z)" % gravity)
            if self._g_given and abs(-gz - fl.g) > 1e-12 * fl.g:
                raise RuntimeError("brash: NewtonIntegrator.gravity %g m/s^2 differs from the fluid's g = %g m/s^2 "
                                   "(buoyancy would not balance the weight): give the fluid the same g" % (-gz, fl.g))
            fl.configure_gravity(-gz, False)
        self._gravity = gravity

    # --- the step --------------------------------------------------------------------------------------------
    def step(self):
        O = self.O
        if not self._order_checked:
            check_engine_order(O, self.label, require_no_damping=False)
            self._order_checked = True
        self._follow_bodies()
        gravity = tuple(float(c) for c in self._newton().gravity)
        self._follow_gravity(gravity)
        gone = self.fluid.apply(self.radius, self.mass, self.states, self.ids, O.forces, O.dt, gravity, self.bodies)
        if gone is not None:  # erased since the last step
            gone = set(gone)
            self._set([i for k, i in enumerate(self.ids) if k not in gone])
            self.fluid.apply(self.radius, self.mass, self.states, self.ids, O.forces, O.dt, gravity, self.bodies)
        self.steps += 1

    def engine(self):
        """The PyRunner to place right before NewtonIntegrator (runs every step, also at iteration 0)."""
        from yade.wrapper import PyRunner
        return PyRunner(command="%s[%d].step()" % (_REGISTRY_NAME, self.index), iterPeriod=1, initRun=True,
                        label=self.label)

    # --- restart ---------------------------------------------------------------------------------------------
    def state(self):
        """The adapter's state (per-sphere previous velocities, by body id) as plain Python data."""
        v, has = self.fluid.get_state()
        if len(has) != len(self.ids):  # not stepped since the last change of spheres
            v, has = np.zeros((len(self.ids), 3)), np.zeros(len(self.ids), dtype=bool)
        return {"ids": list(self.ids), "velocity_prev": [[float(c) for c in row] for row in v],
                "has_prev": [bool(h) for h in has], "steps": self.steps}

    def restore(self, saved):
        """Restore state() output (after O.load): spheres are matched by body id; the adapter's sphere list
        becomes the saved one (list mode) or stays the scan (mask mode; spheres not in `saved` start fresh)."""
        if self.mask is None:
            self._set([int(i) for i in saved["ids"]], check=True)
        pos = {int(i): k for k, i in enumerate(saved["ids"])}
        v = np.zeros((len(self.ids), 3))
        has = np.zeros(len(self.ids), dtype=bool)
        for k, i in enumerate(self.ids):
            j = pos.get(i)
            if j is not None:
                v[k] = saved["velocity_prev"][j]
                has[k] = saved["has_prev"][j]
        self.fluid.set_state(v, has)
        self.steps = int(saved.get("steps", 0))

    def save_state(self, path):
        """state() as JSON (floats written exactly), with an atomic rename."""
        tmp = path + ".tmp"
        with open(tmp, "w") as f:
            json.dump(self.state(), f)
        os.replace(tmp, path)

    def load_state(self, path):
        with open(path) as f:
            self.restore(json.load(f))

    # --- outputs ---------------------------------------------------------------------------------------------
    @property
    def fraction(self):
        """Submerged fraction per sphere at the last step."""
        return self.fluid.fraction

    @property
    def ca(self):
        """Added-mass coefficients (n, 3) used at the last step."""
        return self.fluid.ca


def check_engine_order(O, label="brashFluid", require_no_damping=True):
    """Raise if the fluid PyRunner is not between InteractionLoop and NewtonIntegrator, if NewtonIntegrator's
    gravity does not point along -z, or (require_no_damping) if NewtonIntegrator applies numerical damping."""
    names = [type(e).__name__ for e in O.engines]
    labels = [getattr(e, "label", "") for e in O.engines]
    if label not in labels:
        raise RuntimeError("brash: fluid engine '%s' missing from O.engines" % label)
    k = labels.index(label)
    if "InteractionLoop" in names and names.index("InteractionLoop") > k:
        raise RuntimeError("brash: the fluid engine must come after InteractionLoop")
    if "NewtonIntegrator" not in names[k + 1:]:
        raise RuntimeError("brash: the fluid engine must come before NewtonIntegrator")
    newton = O.engines[names.index("NewtonIntegrator")]
    g = newton.gravity
    if g[0] != 0 or g[1] != 0 or g[2] > 0:
        raise RuntimeError("brash: NewtonIntegrator.gravity must be zero or point along -z (buoyancy acts along +z)")
    if require_no_damping and newton.damping != 0:
        raise RuntimeError("brash: NewtonIntegrator.damping must be 0 for physical runs")
