# brash YADE scene: a case run in YADE, launched by brash-yade-run as
#   yade -n -j<N> -x brash_yade_scene.py <run_dir>/scene.json
# in the run directory. scene.json is written by brash-yade-run from the case (every value resolved); the fluid
# parameters come from the run directory's case.yaml through brash_yade.Fluid.from_case.
# Writes hull_force.csv, particles/particles_<step>.csv + particles/index.csv, and yade_summary.json;
# brash-yade-run writes case.yaml and meta.json around it.
#
# Scene (same as the LIGGGHTS path, plugin/liggghts/runner/liggghts_input.cpp):
#   ice spheres from the packing CSV (FrictMat, Hertz-Mindlin with restitution via en/es),
#   the hull STL (already clipped to the case's band, STL frame: keel z = 0, aft perpendicular x = 0) as
#   facets shifted by (start_x, 0, -draft), moved at the case speed (Newton advances fixed bodies by vel),
#   two side walls y = +-W/2, friction per material pair, fluid forces by the brash core (PyRunner).
import json
import math
import os
import sys
import time

import numpy as np

import yade
import yade.config

from yade import O, _utils, ymport
from yade.wrapper import (Bo1_Facet_Aabb, Bo1_Sphere_Aabb, Bo1_Wall_Aabb, ForceResetter, FrictMat,
                          Ig2_Facet_Sphere_ScGeom, Ig2_Sphere_Sphere_ScGeom, Ig2_Wall_Sphere_ScGeom,
                          InsertionSortCollider, InteractionLoop, Ip2_FrictMat_FrictMat_MindlinPhys,
                          Law2_ScGeom_MindlinPhys_Mindlin, MatchMaker, NewtonIntegrator, PyRunner)
from yade.utils import sphere, wall
Vector3 = yade.Vector3  # minieigen (HP) Vector3 of this YADE build

import brash_yade
from brash_yade_adapter import FluidAdapter, check_engine_order


def log(msg):
    print("[brash-yade] " + msg, flush=True)


def write_atomic(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def read_packing(path):
    rows = []
    with open(path) as f:
        for line in f:
            line = line.strip()
            if not line or line.startswith("#") or line.startswith("id"):
                continue
            _, x, y, z, d = line.split(",")[:5]
            rows.append((float(x), float(y), float(z), float(d)))
    if not rows:
        raise RuntimeError("packing %s holds no spheres" % path)
    return np.array(rows)


def main(scene_file):
    s = json.load(open(scene_file))
    run_dir = os.path.dirname(os.path.abspath(scene_file))
    os.makedirs(os.path.join(run_dir, "particles"), exist_ok=True)
    dt, duration = s["dt_s"], s["duration_s"]
    steps = int(round(duration / dt))
    out_every = max(1, int(round(s["output_interval_s"] / dt)))
    dump_every = max(1, int(round(s["dump_interval_s"] / dt)))

    # Materials: ice, hull, walls. Friction per pair set explicitly (MatchMaker on material ids), so a
    # case with ice_wall > ice_ice gets its value (YADE's default would be the smaller angle).
    E, nu, e = s["youngs_modulus_pa"], s["poisson_ratio"], s["restitution"]
    f = s["friction"]
    m_ice = O.materials.append(FrictMat(young=E, poisson=nu, frictionAngle=math.atan(f["ice_ice"]),
                                        density=s["ice_density_kg_m3"], label="ice"))
    m_hull = O.materials.append(FrictMat(young=E, poisson=nu, frictionAngle=math.atan(f["ice_hull"]),
                                         density=1000.0, label="hull"))
    m_wall = O.materials.append(FrictMat(young=E, poisson=nu, frictionAngle=math.atan(f["ice_wall"]),
                                         density=1000.0, label="wall"))
    friction = MatchMaker(matches=((m_ice, m_ice, math.atan(f["ice_ice"])), (m_ice, m_hull, math.atan(f["ice_hull"])),
                                   (m_ice, m_wall, math.atan(f["ice_wall"]))), algo="min")

    # Ice: group mask 1. Hull facets and walls: mask 3 with avoidSelfInteractionMask = 2, so the collider
    # drops facet-facet, facet-wall and wall-wall pairs (yade.md: 325k -> 22k potential pairs).
    pk = read_packing(s["packing_file"])
    ice = [sphere((x, y, z), 0.5 * d, material=m_ice) for x, y, z, d in pk]
    ice_ids = O.bodies.append(ice)
    t0 = time.time()
    hull = ymport.stl(s["hull_stl"], material=m_hull, shift=Vector3(s["hull_start_x_m"], 0, -s["draft_m"]),
                      wire=True)
    hull_ids = O.bodies.append(hull)
    U = s["speed_m_s"]
    for i in hull_ids:
        b = O.bodies[i]
        b.groupMask = 3
        b.state.vel = Vector3(U, 0, 0)  # fixed (non-dynamic) bodies: Newton advances pos += vel dt
    half_w = 0.5 * s["channel_width_m"]
    wall_ids = [O.bodies.append(wall((0, -half_w, 0), axis=1, material=m_wall)),
                O.bodies.append(wall((0, half_w, 0), axis=1, material=m_wall))]
    for i in wall_ids:
        O.bodies[i].groupMask = 3
    log("%d spheres, %d hull facets (imported in %.1f s), 2 side walls at y = +-%.4g m"
        % (len(ice_ids), len(hull_ids), time.time() - t0, half_w))

    # The fluid (water.*, fluid.*) of the run's resolved case.yaml, through brash::fluid_params: the mapping the
    # LIGGGHTS and ODE runners use.
    fluid = FluidAdapter(ice_ids, fluid=brash_yade.Fluid.from_case(os.path.join(run_dir, "case.yaml")))
    fp = fluid.fluid
    log("fluid (case.yaml): model %s, treatment %s, C_D %g (%s), nu %g m^2/s, Ca %s, water level %g m, density %g "
        "kg/m^3, g %g m/s^2" % (fp.model, fp.treatment, fp.cd, fp.drag_law, fp.nu, fp.ca_table, fp.water_level,
                                fp.water_density, fp.g))

    # Outputs. hull_force.csv: instantaneous force of the ice on the hull every out_every steps (like the
    # LIGGGHTS path's fix ave/time N 1 N), read after InteractionLoop (contacts only: the fluid engine
    # touches spheres only). Time = iteration * dt (positions x(n) of that step).
    hf_path = os.path.join(run_dir, "hull_force.csv")
    hf = open(hf_path + ".part", "w")
    hf.write("t_s,fx_N,fy_N,fz_N\n")
    index_rows = ["step,t_s,file,hull_x_m"]
    write_atomic(os.path.join(run_dir, "particles", "index.csv"), index_rows[0] + "\n")

    def close_outputs():
        """A stopped run leaves hull_force.csv with the rows written so far (the snapshots and index.csv are
        always complete files); brash-yade-run marks meta.json failed."""
        if not hf.closed:
            hf.close()
            os.replace(hf_path + ".part", hf_path)
    hull_probe = hull_ids[0]

    def hull_force():
        O.forces.f(hull_probe, True)  # sync the force container
        fx = _utils.sumForces(hull_ids, Vector3(1, 0, 0))
        fy = _utils.sumForces(hull_ids, Vector3(0, 1, 0))
        fz = _utils.sumForces(hull_ids, Vector3(0, 0, 1))
        hf.write("%.9g,%.9g,%.9g,%.9g\n" % (O.iter * dt, fx, fy, fz))

    states = fluid.states

    def dump():
        step = O.iter
        name = "particles_%010d.csv" % step
        frac, ca = fluid.fraction, fluid.ca
        lines = ["id,x,y,z,radius,vx,vy,vz,submerged_fraction,ca_x,ca_y,ca_z"]
        for k, st in enumerate(states):
            p, v = st.pos, st.vel
            lines.append("%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.6g,%.6g,%.6g,%.6g"
                         % (k + 1, p[0], p[1], p[2], fluid.radius[k], v[0], v[1], v[2], frac[k], ca[k][0], ca[k][1],
                            ca[k][2]))
        write_atomic(os.path.join(run_dir, "particles", name), "\n".join(lines) + "\n")
        t = step * dt
        index_rows.append("%d,%.9g,%s,%.9g" % (step, t, name, s["hull_start_x_m"] + U * t))
        write_atomic(os.path.join(run_dir, "particles", "index.csv"), "\n".join(index_rows) + "\n")

    # Run-time guards (brash::guard through brash_yade.Guard, the checks of the LIGGGHTS and ODE paths): every
    # guards.every_steps iterations, on the state of that iteration (before NewtonIntegrator, like dump()). A stop
    # pauses YADE; the loop below then closes the outputs and raises with the guard's message.
    g = s.get("guards")
    guard = None
    stop = {"message": None}
    if g:
        guard = brash_yade.Guard(fluid.radius, fluid.mass, box=g["box"], z_max=g["z_max_m"], ke_max=g["ke_max_J"],
                                 max_hull_penetration_d=g["max_hull_penetration_d"], hull_stl=g["hull_stl"],
                                 hull_origin=g["hull_origin_m"], hull_velocity=g["hull_velocity_m_s"])
        log("guards every %d steps: NaN/Inf, box, zmax %.4g m, ke_max %.4g J, hull penetration %s, dt vs contact "
            "stiffness" % (g["every_steps"], g["z_max_m"], g["ke_max_J"],
                           ("> %g d" % g["max_hull_penetration_d"]) if guard.has_hull else "off"))

    def guard_check():
        if stop["message"] is None:
            stop["message"] = guard.check(states, O.iter, O.iter * dt)
            if stop["message"] is not None:
                O.pause()

    import __main__
    __main__._brash_hull_force, __main__._brash_dump, __main__._brash_guard = hull_force, dump, guard_check

    collider = InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb(), Bo1_Wall_Aabb()],
                                     avoidSelfInteractionMask=2, label="collider")
    O.engines = [
        ForceResetter(),
        collider,
        InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
                        [Ip2_FrictMat_FrictMat_MindlinPhys(en=MatchMaker(algo="val", val=e),
                                                           es=MatchMaker(algo="val", val=e), frictAngle=friction)],
                        [Law2_ScGeom_MindlinPhys_Mindlin()], label="contacts"),
        fluid.engine(),
        PyRunner(command="_brash_hull_force()", iterPeriod=out_every, initRun=True, label="hullForce"),
        PyRunner(command="_brash_dump()", iterPeriod=dump_every, initRun=True, label="dump"),
        NewtonIntegrator(damping=0, gravity=(0, 0, 0), label="newton"),
    ]
    if guard is not None:
        O.engines = O.engines[:-2] + [PyRunner(command="_brash_guard()", iterPeriod=g["every_steps"], initRun=True,
                                               label="guard")] + O.engines[-2:]
    check_engine_order(O)
    O.dt = dt
    pwave = _utils.PWaveTimeStep()
    log("dt = %.3g s (%.1f %% of the P-wave time step %.3g s), %d steps, output every %d, dump every %d"
        % (dt, 100 * dt / pwave, pwave, steps, out_every, dump_every))
    if guard is not None:  # names the piece; YADE's P-wave limit below is a little stricter still
        msg = guard.check_timestep(dt, E, nu, g["max_dt_fraction"])
        if msg is not None:
            close_outputs()
            raise RuntimeError(msg)
    if dt > pwave:
        close_outputs()
        raise RuntimeError("dt %.3g s exceeds YADE's P-wave time step %.3g s" % (dt, pwave))

    bench_steps = int(os.environ.get("BRASH_YADE_BENCH_STEPS", "0"))
    if bench_steps > 0:
        bench(fluid, bench_steps, fluid.fluid.g)
        return

    O.timingEnabled = True
    chunk = max(1, min(steps // 200, int(round(0.01 / dt))))
    t_start = time.time()
    last_print = -1e9
    done = 0
    total = steps + 1  # iterations 0..steps: outputs at t = 0 .. duration, like LIGGGHTS' `run steps`
    while done < total:
        k = min(chunk, total - done)
        O.run(k, True)
        done += k
        hf.flush()
        if stop["message"] is not None:
            # Outputs consistent at the stop: hull_force.csv with the rows written so far, the snapshots and
            # particles/index.csv as they are; brash-yade-run marks meta.json failed with this message.
            close_outputs()
            raise RuntimeError(stop["message"])
        el = time.time() - t_start
        if el - last_print >= 5.0 or done == total:
            last_print = el
            log("t = %.3f / %.3f s  step %d  elapsed %.0f s  ETA %.0f s  interactions %d"
                % (done * dt, duration, done, el, el * (total - done) / done, len(O.interactions)))
    wall_s = time.time() - t_start
    hf.close()
    os.replace(hf_path + ".part", hf_path)

    timing = {}
    for eng in O.engines:
        name = eng.label or type(eng).__name__
        timing[name] = {"exec_time_s": eng.execTime * 1e-9, "exec_count": eng.execCount}
    summary = {"steps": total, "particles": len(ice_ids), "hull_facets": len(hull_ids), "loop_time_s": wall_s,
               "particle_steps": float(len(ice_ids)) * total, "engines": timing,
               "fluid_us_per_particle_step": 1e6 * timing["brashFluid"]["exec_time_s"] / max(1.0, len(ice_ids) * total),
               "yade_version": getattr(yade.config, "version", "")}
    write_atomic(os.path.join(run_dir, "yade_summary.json"), json.dumps(summary, indent=1))
    log("done: %d steps in %.1f s, %.3g particle-steps/s; fluid adapter %.3g us per particle-step"
        % (total, wall_s, len(ice_ids) * total / wall_s, summary["fluid_us_per_particle_step"]))


def bench(fluid, n, g):
    """Particle-steps/s of this scene with and without the fluid adapter (paired windows of n steps,
    3 repetitions, same process). 'without': the fluid PyRunner is dead and NewtonIntegrator applies
    gravity (bare YADE DEM step: collider, Hertz-Mindlin contacts, hull facets, walls, Newton)."""
    newton = [e for e in O.engines if e.label == "newton"][0]
    runner = [e for e in O.engines if e.label == "brashFluid"][0]
    others = [e for e in O.engines if e.label in ("hullForce", "dump")]
    for e in others:
        e.dead = True
    O.run(20, True)  # warm-up: first collider run, allocations
    O.timingEnabled = True
    npart = len(fluid.ids)
    rates = {"with": [], "without": []}
    fluid_ns = 0
    fluid_calls = 0
    for rep in range(3):
        for mode in ("with", "without"):
            runner.dead = mode == "without"
            newton.gravity = (0, 0, 0) if mode == "with" else (0, 0, -g)
            t0_exec, c0 = runner.execTime, runner.execCount
            t0 = time.time()
            O.run(n, True)
            rates[mode].append(npart * n / (time.time() - t0))
            fluid_ns += runner.execTime - t0_exec
            fluid_calls += runner.execCount - c0
    best = {k: max(v) for k, v in rates.items()}
    us = 1e-3 * fluid_ns / max(1, fluid_calls * npart)
    print("BENCH spheres %d steps_per_window %d" % (npart, n))
    for mode in ("without", "with"):
        print("BENCH %-7s adapter: particle-steps/s best %.4g, all %s"
              % (mode, best[mode], " ".join("%.4g" % r for r in rates[mode])))
    print("BENCH adapter cost (YADE engine timer): %.3f us per particle-step; bare step %.3f us per particle-step;"
          " slowdown x%.2f" % (us, 1e6 / best["without"], best["without"] / best["with"]), flush=True)


try:
    main(sys.argv[1])
except Exception as exc:  # an exit code for brash-yade-run (yade -x would otherwise exit 0 on some errors)
    import traceback
    traceback.print_exc()
    print("[brash-yade] ERROR: %s" % exc, flush=True)
    sys.exit(1)
sys.exit(0)
