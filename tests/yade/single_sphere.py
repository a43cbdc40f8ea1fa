# Single-sphere checks of the YADE adapter, run inside YADE:
#   yade -n -j1 -x single_sphere.py <rise|heave|static|exact|gravity>
# (PYTHONPATH must hold brash_yade and brash_yade_adapter; HOME must be set.) Exit code 0 = pass.
# YADE integrates (leap-frog), the brash_yade PyRunner adds the fluid forces; the oracle is the core's
# velocity-Verlet ReferenceSphere and the closed forms (brash::core::analytic), as for LIGGGHTS.
import math
import sys

import numpy as np

import brash_yade
from brash_yade import analytic
from brash_yade_adapter import FluidAdapter, check_engine_order

D = 0.017578
R = D / 2
RHO_I, RHO_W, G = 900.0, 1000.0, 9.81
TOL = 5e-3  # 0.5 %
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def scene(z0, dt, newton_gravity=(0, 0, 0), g=G, **fluid):
    """One ice sphere at (0, 0, z0) at rest; returns (body id, adapter). newton_gravity: NewtonIntegrator's
    (zero: the fluid applies the weight)."""
    O.reset()
    mat = O.materials.append(FrictMat(young=5e6, poisson=0.3, frictionAngle=math.atan(0.3), density=RHO_I))
    sid = O.bodies.append(sphere((0, 0, z0), R, material=mat))
    fl = FluidAdapter([sid], water_level=0.0, water_density=RHO_W, g=g, **fluid)
    O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb()]),
        InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_MindlinPhys()],
                        [Law2_ScGeom_MindlinPhys_Mindlin()]),
        fl.engine(),
        NewtonIntegrator(damping=0, gravity=newton_gravity),
    ]
    O.dt = dt
    check_engine_order(O)
    # YADE's sphere() sets the mass from the material density: must equal the reference's.
    assert abs(O.bodies[sid].state.mass / (RHO_I * analytic.sphere_volume(R)) - 1) < 1e-14
    return sid, fl


def record(sid, steps, every):
    """Run `steps` steps; (t, z, vz) after every `every` steps. After n leap-frog steps pos = x(n) and
    vel = v(n - 1/2); with vel(0) = 0 standing for v(-1/2) the state is that of a start at t = -dt/2,
    so vel after n steps is compared with v at t = n dt."""
    b = O.bodies[sid]
    rows = []
    done = 0
    while done < steps:
        k = min(every, steps - done)
        O.run(k, True)
        done += k
        rows.append((done * O.dt, b.state.pos[2], b.state.vel[2]))
    return rows


def reference(z0, dt, **fluid):
    return brash_yade.ReferenceSphere(radius=R, density=RHO_I, dt=dt, z0=z0, vz0=0.0,
                                      fluid=brash_yade.Fluid(**fluid))


def test_rise():
    """Fully submerged rise from rest (model both: drag + added mass Ca_z 0.5), 1 s."""
    dt, steps, every = 1e-5, 100000, 10000
    sid, _ = scene(-1.0, dt, model="both")
    rows = record(sid, steps, every)
    ref = reference(-1.0, dt, model="both")
    vt, tau = analytic.rise(R, RHO_I, RHO_W, G, 0.44, 0.5)
    done, worst_ref, worst_an = 0, 0.0, 0.0
    for t, z, vz in rows:
        n = round(t / dt)
        ref.run(n - done)
        done = n
        worst_ref = max(worst_ref, abs(vz / ref.vz - 1))
        worst_an = max(worst_an, abs(vz / (vt * math.tanh(t / tau)) - 1))
    print("rise: v(1 s) = %.6f m/s, reference %.6f, analytic %.6f (v_t %.6f, tau %.5f s)"
          % (rows[-1][2], ref.vz, vt * math.tanh(rows[-1][0] / tau), vt, tau))
    check(worst_ref < TOL, "rise: velocity vs reference integrator, worst relative deviation %.2e" % worst_ref)
    check(worst_an < TOL, "rise: velocity vs v_t tanh(t/tau), worst relative deviation %.2e" % worst_an)


def test_heave():
    """Floating sphere released 1e-3 r above equilibrium (added_mass model, undamped), 3 s: period
    with Ca_z = 0.5 h/2r and oscillation centre at the floating draft s = 0.9."""
    dt, steps = 2e-5, 150000
    h = analytic.height_for_fraction(R, RHO_I / RHO_W)
    z_eq = R - h
    sid, fl = scene(z_eq + 1e-3 * R, dt, model="added_mass")
    b = O.bodies[sid]
    zs = np.empty(steps + 1)
    zs[0] = b.state.pos[2]
    # sample z every step through a second PyRunner after Newton
    sampler = {"i": 0}

    def sample():
        sampler["i"] += 1
        zs[sampler["i"]] = b.state.pos[2]

    import __main__
    __main__._brash_sample = sample
    O.engines = O.engines + [PyRunner(command="_brash_sample()", iterPeriod=1)]
    O.run(steps, True)
    assert sampler["i"] == steps - 1  # PyRunner skips iteration 0 (no initRun): z(1)..z(steps-1)
    zs = zs[: steps]
    t = dt * np.arange(steps)
    # z recorded at the end of iteration k is x(k+1): shift the time by one step
    t = t + dt
    t[0] = 0.0
    a, c = zs[:-1] - z_eq, zs[1:] - z_eq
    up = np.nonzero((a < 0) & (c >= 0))[0]
    crossings = t[up] + (t[up + 1] - t[up]) * (-a[up]) / (c[up] - a[up])
    check(len(crossings) >= 5, "heave: %d upward crossings" % len(crossings))
    period = (crossings[-1] - crossings[0]) / (len(crossings) - 1)
    expect = analytic.heave_period(R, RHO_I, RHO_W, G, 0.5 * h / (2 * R))
    centre = 0.5 * (zs[1:].min() + zs[1:].max())
    print("heave: period %.6f s, linearised analytic %.6f s; centre %.9f m, z_eq %.9f m, amplitude %.3e m"
          % (period, expect, centre, z_eq, 0.5 * (zs.max() - zs.min())))
    check(abs(period / expect - 1) < TOL, "heave: period vs analytic, deviation %.2e" % (period / expect - 1))
    check(abs(centre - z_eq) < 1e-4 * D, "heave: oscillation centre at the floating draft s = 0.9 (|dz| = %.2e d)"
          % (abs(centre - z_eq) / D))
    # same run through the reference integrator: the whole trajectory
    ref = reference(z_eq + 1e-3 * R, dt, model="added_mass")
    worst = 0.0
    for n in range(10000, steps, 10000):
        ref.run(10000)
        worst = max(worst, abs(zs[n] - ref.z) / (1e-3 * R))
    check(worst < TOL, "heave: z vs reference integrator, worst deviation %.2e of the amplitude" % worst)


def test_static():
    """A sphere placed at its floating draft s = 0.9 stays there (buoyancy = weight through YADE)."""
    dt = 1e-4
    h = analytic.height_for_fraction(R, RHO_I / RHO_W)
    z_eq = R - h
    sid, fl = scene(z_eq, dt, model="both")
    O.run(10000, True)
    z = O.bodies[sid].state.pos[2]
    print("static: z after 1 s %.12f m, z_eq %.12f m, fraction %.9f" % (z, z_eq, fl.fraction[0]))
    check(abs(z - z_eq) < 1e-6 * D, "static: stays at the floating draft (|dz| = %.2e d)" % (abs(z - z_eq) / D))
    check(abs(fl.fraction[0] - 0.9) < 1e-9, "static: submerged fraction 0.9")


def test_exact():
    """The force YADE integrates equals the core's (f_contact + f_fluid) * scale to the last digit, for
    both treatments, spheres above, across and below the surface, moving in all directions."""
    for treatment in ("implicit", "explicit"):
        O.reset()
        mat = O.materials.append(FrictMat(young=5e6, poisson=0.3, frictionAngle=0.5, density=RHO_I))
        zs = [0.02, 0.5 * R, 0.0, -0.5 * R, -0.1]
        ids = [O.bodies.append(sphere((0.1 * k, 0, z), R, material=mat)) for k, z in enumerate(zs)]
        for k, i in enumerate(ids):
            O.bodies[i].state.vel = (0.1 * (k - 2), 0.05, 0.2 - 0.1 * k)
        # a contact force on one sphere: a second sphere pressed into it
        ids2 = O.bodies.append(sphere((0.4, 0, -0.1 + 1.9 * R), R, material=mat))
        fl = FluidAdapter(ids + [ids2], model="both", treatment=treatment)
        probe = {}

        def before():
            probe["f0"] = np.array([tuple(O.forces.f(i, True)) for i in fl.ids])
            probe["pos"] = np.array([tuple(O.bodies[i].state.pos) for i in fl.ids])
            probe["vel"] = np.array([tuple(O.bodies[i].state.vel) for i in fl.ids])

        def after():
            probe["f1"] = np.array([tuple(O.forces.f(i, True)) for i in fl.ids])

        import __main__
        __main__._brash_before, __main__._brash_after = before, after
        O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                     InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_MindlinPhys()],
                                     [Law2_ScGeom_MindlinPhys_Mindlin()]),
                     PyRunner(command="_brash_before()", iterPeriod=1, initRun=True), fl.engine(),
                     PyRunner(command="_brash_after()", iterPeriod=1, initRun=True),
                     NewtonIntegrator(damping=0, gravity=(0, 0, 0))]
        O.dt = 1e-5
        oracle = brash_yade.Fluid(model="both", treatment=treatment)
        worst = 0.0
        for step in range(3):
            O.run(1, True)
            c = oracle.correction(fl.radius, fl.mass, probe["pos"], probe["vel"], probe["f0"], O.dt)
            worst = max(worst, np.abs(probe["f1"] - (probe["f0"] + c)).max())
        contact = np.abs(probe["f0"][-1]).max()
        check(contact > 0, "exact (%s): a contact force is present (%.3e N)" % (treatment, contact))
        check(worst == 0.0, "exact (%s): YADE total force == core total, worst |diff| %.1e N" % (treatment, worst))


def test_gravity():
    """Gravity in NewtonIntegrator (as YADE users write it) or in the fluid: the same trajectory to round-off, for
    every model and treatment. A sphere released 3 d under the surface rises, overshoots and bobs (submerged,
    partial and reversed Ca rows, drag both ways): 0.4 s at dt 2e-5."""
    dt, steps, every = 2e-5, 20000, 200
    z0 = -R - 0.5 * D
    for model, treatment in (("both", "implicit"), ("both", "explicit"), ("added_mass", "implicit"),
                             ("added_mass", "explicit"), ("drag", "implicit")):
        runs = {}
        for where in ("fluid", "newton"):
            newton = (0, 0, -G) if where == "newton" else (0, 0, 0)
            sid, fl = scene(z0, dt, newton_gravity=newton, g=None if where == "newton" else G, model=model,
                            treatment=treatment)
            runs[where] = np.array(record(sid, steps, every))
            if where == "newton":
                check(not fl.fluid.apply_gravity and fl.fluid.g == G,
                      "gravity (%s, %s): with Newton's gravity the fluid adds no weight, g %g taken from Newton"
                      % (model, treatment, fl.fluid.g))
        a, b = runs["fluid"], runs["newton"]
        dz = np.abs(a[:, 1] - b[:, 1]).max() / D
        dv = np.abs(a[:, 2] - b[:, 2]).max() / np.abs(a[:, 2]).max()
        crossed = a[:, 1].max() > -R and np.any(np.diff(np.sign(a[:, 2])) != 0)
        print("gravity (%s, %s): z range %.4f..%.4f m, max |dz| %.1e d, max |dv| %.1e of max |v|"
              % (model, treatment, a[:, 1].min(), a[:, 1].max(), dz, dv))
        check(crossed, "gravity (%s, %s): the sphere reached the surface and reversed" % (model, treatment))
        check(dz < 1e-9 and dv < 1e-9, "gravity (%s, %s): Newton gravity == fluid gravity to round-off "
              "(|dz| %.1e d, |dv| %.1e)" % (model, treatment, dz, dv))
    # a g that disagrees with NewtonIntegrator's, or a gravity off the -z axis, is refused (buoyancy would not
    # balance the weight): at set-up (check_engine_order) or, at the latest, at the first step
    def refused(newton, g):
        try:
            scene(z0, dt, newton_gravity=newton, g=g)
            O.run(1, True)
        except RuntimeError as e:
            print("refused: %s" % str(e).splitlines()[0])
            return True
        return False

    check(refused((0, 0, -9.80665), G), "gravity: a fluid g that differs from NewtonIntegrator's stops the run")
    check(refused((1.0, 0, -G), None), "gravity: a NewtonIntegrator gravity off the -z axis is refused")


tests = {"rise": test_rise, "heave": test_heave, "static": test_static, "exact": test_exact, "gravity": test_gravity}
which = sys.argv[1:] or list(tests)
for name in which:
    if name not in tests:
        print("unknown test %s (choose from %s)" % (name, ", ".join(tests)))
        sys.exit(2)
    tests[name]()
if failures:
    print("%d check(s) failed" % len(failures))
    sys.exit(1)
print("all checks passed")
sys.exit(0)
