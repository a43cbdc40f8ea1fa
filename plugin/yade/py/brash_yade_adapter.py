"""brash fluid forces for YADE spheres (the YADE adapter of issue 8).

Debian's YADE ships no C++ headers, so the adapter is a PyRunner that calls the compiled core
(brash_yade, a pybind11 module linking brash_core) once per step:

    O.engines = [ForceResetter(), collider, InteractionLoop(...),
                 adapter.engine(),                    # reads contacts, adds fluid + implicit correction
                 NewtonIntegrator(damping=0, gravity=(0, 0, 0))]

Gravity is part of the fluid step (apply_gravity), not NewtonIntegrator.gravity: with implicit added
mass the sum of every force, gravity included, is scaled per axis by m / (m + m_a) (physics.md), which
YADE's gravity (added as an unscaled acceleration) would bypass. The PyRunner sits between
InteractionLoop and NewtonIntegrator so that O.forces.f(id, sync=True) holds the contact forces of this
step; it adds `(f_contact + f_fluid) * scale - f_contact`, so Newton sees the corrected total.

Velocity: YADE's leap-frog keeps v(n - 1/2) in state.vel while forces at x(n) are computed, which is the
velocity the velocity-Verlet reference (brash::core::ReferenceSphere) and LIGGGHTS' fix see too.
"""
import __main__

import numpy as np

import brash_yade

_REGISTRY_NAME = "_brash_yade_adapters"


class FluidAdapter:
    """Fluid forces of the brash core on the given YADE sphere ids (same set for the whole run)."""

    def __init__(self, ids, model="both", treatment="implicit", cd=0.44, drag_law="constant",
                 nu=1.79e-6, ca_table="table1", water_level=0.0, water_density=1000.0, g=9.81, fluid=None):
        """fluid: a brash_yade.Fluid (e.g. Fluid.from_case(case.yaml), gravity applied by the fluid) used instead
        of the keyword parameters."""
        from yade import O  # imported here so the module can be imported (for docs) outside yade
        self.O = O
        self.ids = [int(i) for i in ids]
        bodies = [O.bodies[i] for i in self.ids]
        # State objects stay the live state of their bodies: cache them (saves a lookup per sphere).
        self.states = [b.state for b in bodies]
        self.radius = np.array([b.shape.radius for b in bodies], dtype=float)
        self.mass = np.array([b.state.mass for b in bodies], dtype=float)
        if fluid is None:
            fluid = brash_yade.Fluid(model=model, treatment=treatment, cd=cd, drag_law=drag_law, nu=nu,
                                     ca_table=ca_table, water_level=water_level, water_density=water_density,
                                     g=g, apply_gravity=True)
        elif not fluid.apply_gravity:
            raise ValueError("FluidAdapter: the fluid must apply gravity (NewtonIntegrator.gravity is 0)")
        self.fluid = fluid
        self.steps = 0
        registry = getattr(__main__, _REGISTRY_NAME, None)
        if registry is None:
            registry = []
            setattr(__main__, _REGISTRY_NAME, registry)
        self.index = len(registry)
        registry.append(self)

    def step(self):
        self.fluid.apply(self.radius, self.mass, self.states, self.ids, self.O.forces, self.O.dt)
        self.steps += 1

    def engine(self, label="brashFluid"):
        """The PyRunner to place right before NewtonIntegrator (runs every step, also at iteration 0)."""
        from yade.wrapper import PyRunner
        return PyRunner(command="%s[%d].step()" % (_REGISTRY_NAME, self.index), iterPeriod=1, initRun=True,
                        label=label)

    @property
    def fraction(self):
        """Submerged fraction per sphere at the last step."""
        return self.fluid.fraction

    @property
    def ca(self):
        """Added-mass coefficients (n, 3) used at the last step."""
        return self.fluid.ca


def check_engine_order(O, label="brashFluid"):
    """Raise if the fluid PyRunner is not between InteractionLoop and NewtonIntegrator, or if
    NewtonIntegrator applies gravity or numerical damping itself."""
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
    if newton.gravity.norm() != 0:
        raise RuntimeError("brash: NewtonIntegrator.gravity must be 0 (the fluid step applies gravity)")
    if newton.damping != 0:
        raise RuntimeError("brash: NewtonIntegrator.damping must be 0 for physical runs")
