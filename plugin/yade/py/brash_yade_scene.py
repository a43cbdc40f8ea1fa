# brash YADE scene: a case run in YADE, launched by brash-yade-run as
#   yade -n -j<N> -x brash_yade_scene.py <run_dir>/scene.json [restart/<iteration>]
# in the run directory (with a restart point: the run resumes from it). scene.json is written by brash-yade-run from the case (every value resolved); the fluid
# parameters come from the run directory's case.yaml through brash_yade.Fluid.from_case.
# Writes hull_force_yade.csv (brash-yade-run makes hull_force.csv of it), particles/particles_<step>.csv +
# particles/index.csv, and yade_summary.json; brash-yade-run writes case.yaml and meta.json around it.
#
# Scene (same as the LIGGGHTS path, plugin/liggghts/runner/liggghts_input.cpp):
#   ice spheres from the packing CSV (FrictMat, Hertz-Mindlin with restitution via en/es),
#   the hull STL (already clipped to the case's band, STL frame: keel z = 0, aft perpendicular x = 0) as
#   facets shifted by (start_x, 0, -draft), moved at the case speed (Newton advances fixed bodies by vel),
#   two side walls y = +-W/2 (and end walls at x = 0 and x = L with channel.ends: walls), friction per
#   material pair, fluid forces by the brash core (PyRunner).
#
# Restart points: every restart_every_steps iterations the scene writes restart/<iteration, 10 digits>/ with
# scene.yade (O.save, binary: O.load continues bit for bit) and state.json (the body ids of ice, hull and walls
# and the fluid adapter's per-sphere previous velocities, which O.save does not hold), first into
# restart/.tmp-<iteration> and then renamed (a kill leaves a whole restart point or none); the last two are kept.
# A resumed scene loads one, keeps the hull_force.csv rows and snapshots before its iteration and goes on.
import json
import math
import os
import shutil
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


RESTART_KEEP = 2
# The scene's hull-force record; brash-yade-run reads it into hull_force.csv (the driver owns that file, and
# rewrites it while the run goes on).
FORCE_FILE = "hull_force_yade.csv"


def save_restart(run_dir, fluid, ids):
    """restart/<iteration>/{scene.yade, state.json}, written whole under a temporary name, then renamed; older
    restart points beyond the last RESTART_KEEP are removed."""
    root = os.path.join(run_dir, "restart")
    os.makedirs(root, exist_ok=True)
    name = "%010d" % O.iter
    tmp = os.path.join(root, ".tmp-" + name)
    shutil.rmtree(tmp, ignore_errors=True)
    os.makedirs(tmp)
    O.save(os.path.join(tmp, "scene.yade"))
    state = dict(ids, iteration=O.iter, fluid=fluid.state())
    write_atomic(os.path.join(tmp, "state.json"), json.dumps(state))
    final = os.path.join(root, name)
    shutil.rmtree(final, ignore_errors=True)
    os.rename(tmp, final)
    points = sorted(d for d in os.listdir(root) if d.isdigit() and len(d) == 10)
    for old in points[:-RESTART_KEEP]:
        shutil.rmtree(os.path.join(root, old), ignore_errors=True)
    for d in os.listdir(root):  # left by a kill during an earlier save
        if d.startswith(".tmp-") and d != ".tmp-" + name:
            shutil.rmtree(os.path.join(root, d), ignore_errors=True)


def read_rows(path):
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return f.read().splitlines()


def kept_force_rows(run_dir, t_restart, dt):
    """hull_force_yade.csv rows of the earlier attempts before the restart time (the resumed run writes the rest
    again)."""
    rows = read_rows(os.path.join(run_dir, FORCE_FILE))
    kept = []
    for line in rows[1:]:
        parts = line.split(",")
        try:
            t = float(parts[0])
        except ValueError:
            continue
        if len(parts) == 4 and t < t_restart - 0.5 * dt:
            kept.append(line)
    return kept


def main(scene_file, restart=None):
    s = json.load(open(scene_file))
    run_dir = os.path.dirname(os.path.abspath(scene_file))
    os.makedirs(os.path.join(run_dir, "particles"), exist_ok=True)
    dt, duration = s["dt_s"], s["duration_s"]
    steps = int(round(duration / dt))
    out_every = max(1, int(round(s["output_interval_s"] / dt)))
    dump_every = max(1, int(round(s["dump_interval_s"] / dt)))
    restart_every = int(s.get("restart_every_steps", 0))
    if restart:
        resume(s, run_dir, restart, steps, out_every, dump_every, restart_every)
    else:
        build(s, run_dir, steps, out_every, dump_every, restart_every)


def build(s, run_dir, steps, out_every, dump_every, restart_every):
    dt = s["dt_s"]

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
    ends = s.get("channel_ends", "open")
    if ends == "walls":  # the channel's ends as an ice tank's end walls (the hull passes through them)
        wall_ids += [O.bodies.append(wall((0, 0, 0), axis=0, material=m_wall)),
                     O.bodies.append(wall((s["channel_length_m"], 0, 0), axis=0, material=m_wall))]
    for i in wall_ids:
        O.bodies[i].groupMask = 3
    log("%d spheres, %d hull facets (imported in %.1f s), 2 side walls at y = +-%.4g m, ends %s"
        % (len(ice_ids), len(hull_ids), time.time() - t0, half_w, ends))

    ids = {"ice_ids": list(ice_ids), "hull_ids": list(hull_ids), "wall_ids": wall_ids}
    fluid, outputs = setup(s, run_dir, ids, out_every, dump_every, iteration=0)
    guard, g = outputs["guard"], s.get("guards")

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
    log("dt = %.3g s (%.1f %% of the P-wave time step %.3g s), %d steps, output every %d, dump every %d, restart "
        "every %s" % (dt, 100 * dt / pwave, pwave, steps, out_every, dump_every, restart_every or "never"))
    if guard is not None:  # names the piece; YADE's P-wave limit below is a little stricter still
        msg = guard.check_timestep(dt, E, nu, g["max_dt_fraction"])
        if msg is not None:
            outputs["close"]()
            raise RuntimeError(msg)
    if dt > pwave:
        outputs["close"]()
        raise RuntimeError("dt %.3g s exceeds YADE's P-wave time step %.3g s" % (dt, pwave))

    bench_steps = int(os.environ.get("BRASH_YADE_BENCH_STEPS", "0"))
    if bench_steps > 0:
        bench(fluid, bench_steps, fluid.fluid.g)
        return
    run(s, run_dir, fluid, ids, outputs, steps, restart_every)


def resume(s, run_dir, restart, steps, out_every, dump_every, restart_every):
    """Continue from restart/<iteration>: the saved scene (bodies, interactions, engines with their schedules),
    the fluid adapter's state, the outputs before that iteration."""
    point = os.path.join(run_dir, restart)
    state_file = os.path.join(point, "state.json")
    if not os.path.isfile(state_file) or not os.path.isfile(os.path.join(point, "scene.yade")):
        raise RuntimeError("restart point %s is incomplete (needs scene.yade and state.json)" % point)
    with open(state_file) as f:
        saved = json.load(f)
    O.load(os.path.join(point, "scene.yade"))
    if O.iter != saved["iteration"]:
        raise RuntimeError("restart point %s: scene at iteration %d, state.json at %d" % (point, O.iter,
                                                                                          saved["iteration"]))
    ids = {k: saved[k] for k in ("ice_ids", "hull_ids", "wall_ids")}
    fluid, outputs = setup(s, run_dir, ids, out_every, dump_every, iteration=O.iter)
    fluid.restore(saved["fluid"])
    check_engine_order(O)
    log("resumed from %s: iteration %d, t = %.6g s (%d spheres, %d hull facets)"
        % (restart, O.iter, O.iter * s["dt_s"], len(ids["ice_ids"]), len(ids["hull_ids"])))
    run(s, run_dir, fluid, ids, outputs, steps, restart_every)


def setup(s, run_dir, ids, out_every, dump_every, iteration):
    """The fluid adapter, the outputs and the guard (PyRunner callables in __main__) of a scene whose bodies exist:
    built now (iteration 0) or loaded from a restart point (its outputs before `iteration` kept)."""
    dt = s["dt_s"]
    U = s["speed_m_s"]
    ice_ids, hull_ids = ids["ice_ids"], ids["hull_ids"]
    # The fluid (water.*, fluid.*) of the run's resolved case.yaml, through brash::fluid_params: the mapping the
    # LIGGGHTS and ODE runners use.
    fluid = FluidAdapter(ice_ids, fluid=brash_yade.Fluid.from_case(os.path.join(run_dir, "case.yaml")))
    fp = fluid.fluid
    log("fluid (case.yaml): model %s, treatment %s, C_D %g (%s), nu %g m^2/s, Ca %s, water level %g m, density %g "
        "kg/m^3, g %g m/s^2" % (fp.model, fp.treatment, fp.cd, fp.drag_law, fp.nu, fp.ca_table, fp.water_level,
                                fp.water_density, fp.g))

    # Outputs. hull_force_yade.csv: instantaneous force of the ice on the hull every out_every steps (like the
    # LIGGGHTS path's fix ave/time N 1 N), read after InteractionLoop (contacts only: the fluid engine
    # touches spheres only). Time = iteration * dt (positions x(n) of that step).
    hf_path = os.path.join(run_dir, FORCE_FILE)
    kept = kept_force_rows(run_dir, iteration * dt, dt) if iteration > 0 else []
    hf = open(hf_path + ".tmp", "w")
    hf.write("t_s,fx_N,fy_N,fz_N\n")
    hf.write("".join(line + "\n" for line in kept))
    hf.flush()
    os.replace(hf_path + ".tmp", hf_path)  # the earlier attempt's record stays whole until the new one has its rows
    index_rows = ["step,t_s,file,hull_x_m"]
    if iteration > 0:  # snapshots before the restart point stay; later ones are written again
        for line in read_rows(os.path.join(run_dir, "particles", "index.csv"))[1:]:
            if line.split(",")[0].isdigit() and int(line.split(",")[0]) < iteration:
                index_rows.append(line)
    write_atomic(os.path.join(run_dir, "particles", "index.csv"), "\n".join(index_rows) + "\n")

    def close_outputs():
        """A stopped run leaves its record with the rows written so far (the snapshots and index.csv are always
        complete files); brash-yade-run marks meta.json failed."""
        if not hf.closed:
            hf.close()
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
    outputs = {"hull_force": hull_force, "dump": dump, "guard": guard, "guard_check": guard_check,
               "close": close_outputs, "hf": hf, "hf_path": hf_path, "stop": stop}
    return fluid, outputs


def run(s, run_dir, fluid, ids, outputs, steps, restart_every):
    """Iterations O.iter .. steps (outputs at t = 0 .. duration, like LIGGGHTS' `run steps`), a restart point every
    restart_every iterations (none at the end), progress lines for brash-yade-run."""
    dt, duration = s["dt_s"], s["duration_s"]
    hf, stop = outputs["hf"], outputs["stop"]
    O.timingEnabled = True
    exec_before = [(e.execTime, e.execCount) for e in O.engines]  # a loaded scene carries its counters
    chunk = max(1, min(steps // 200, int(round(0.01 / dt))))
    t_start = time.time()
    last_print = -1e9
    total = steps + 1
    first = done = O.iter
    while done < total:
        k = min(chunk, total - done)
        if restart_every > 0:  # end chunks on restart iterations
            k = min(k, restart_every - done % restart_every)
        O.run(k, True)
        done += k
        hf.flush()
        if stop["message"] is not None:
            # Outputs consistent at the stop: hull_force.csv with the rows written so far, the snapshots and
            # particles/index.csv as they are; brash-yade-run marks meta.json failed with this message.
            outputs["close"]()
            raise RuntimeError(stop["message"])
        if restart_every > 0 and done % restart_every == 0 and done < total:
            save_restart(run_dir, fluid, ids)
        el = time.time() - t_start
        if el - last_print >= 5.0 or done == total:
            last_print = el
            log("t = %.3f / %.3f s  step %d  elapsed %.0f s  ETA %.0f s  interactions %d"
                % (done * dt, duration, done, el, el * (total - done) / (done - first), len(O.interactions)))
    wall_s = time.time() - t_start
    outputs["close"]()

    n_ice = len(ids["ice_ids"])
    timing = {}
    for eng, (t0, c0) in zip(O.engines, exec_before):
        name = eng.label or type(eng).__name__
        timing[name] = {"exec_time_s": (eng.execTime - t0) * 1e-9, "exec_count": eng.execCount - c0}
    attempt_steps = total - first
    fluid_calls = max(1, timing["brashFluid"]["exec_count"])
    summary = {"steps": attempt_steps, "particles": n_ice, "hull_facets": len(ids["hull_ids"]),
               "loop_time_s": wall_s, "particle_steps": float(n_ice) * attempt_steps, "engines": timing,
               "fluid_us_per_particle_step": 1e6 * timing["brashFluid"]["exec_time_s"] / max(1.0, n_ice * fluid_calls),
               "resumed_at_iteration": first, "yade_version": getattr(yade.config, "version", "")}
    write_atomic(os.path.join(run_dir, "yade_summary.json"), json.dumps(summary, indent=1))
    log("done: %d steps in %.1f s, %.3g particle-steps/s; fluid adapter %.3g us per particle-step"
        % (attempt_steps, wall_s, n_ice * attempt_steps / wall_s, summary["fluid_us_per_particle_step"]))


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
    main(sys.argv[1], sys.argv[2] if len(sys.argv) > 2 else None)
except Exception as exc:  # an exit code for brash-yade-run (yade -x would otherwise exit 0 on some errors)
    import traceback
    traceback.print_exc()
    print("[brash-yade] ERROR: %s" % exc, flush=True)
    sys.exit(1)
sys.exit(0)
