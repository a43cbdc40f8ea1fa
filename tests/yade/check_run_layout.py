"""Checks a run directory written by brash-yade-run against docs/case_format.md's run layout.
   python3 check_run_layout.py RUN_DIR DURATION_S OUTPUT_INTERVAL_S  -> exit 0 = pass"""
import csv
import json
import os
import sys

run, duration, out_dt = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
bad = []


def need(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        bad.append(what)


for f in ("case.yaml", "meta.json", "hull_force.csv", "log.txt", "particles/index.csv"):
    need(os.path.isfile(os.path.join(run, f)), "file " + f)
need(os.path.isdir(os.path.join(run, "restart")), "folder restart/")
meta = json.load(open(os.path.join(run, "meta.json")))
for k in ("engine", "engine_version", "fluid_model", "treatment", "dt_s", "ranks", "particles", "wall_time_s",
          "particle_steps", "git_commit", "status", "reason"):
    need(k in meta, "meta.json key " + k)
need(meta.get("engine") == "yade", "engine yade")
need(meta.get("status") == "complete", "status complete (%s %s)" % (meta.get("status"), meta.get("reason")))
rows = list(csv.reader(open(os.path.join(run, "hull_force.csv"))))
need(rows[0] == ["t_s", "fx_N", "fy_N", "fz_N"], "hull_force.csv header")
data = [[float(x) for x in r] for r in rows[1:]]
need(len(data) == round(duration / out_dt) + 1, "hull_force.csv rows %d (t = 0 .. duration)" % len(data))
need(abs(data[-1][0] - duration) < 1e-9, "last row at t = duration")
fx = [r[1] for r in data]
need(min(fx) < 0, "the ice resists the hull at some time (min fx = %.4g N)" % min(fx))
idx = list(csv.DictReader(open(os.path.join(run, "particles", "index.csv"))))
need(len(idx) >= 2, "particle snapshots: %d" % len(idx))
for r in idx:
    p = os.path.join(run, "particles", r["file"])
    with open(p) as f:
        head = f.readline().strip()
        n = sum(1 for _ in f)
    need(head == "id,x,y,z,radius,vx,vy,vz,submerged_fraction,ca_x,ca_y,ca_z" and n == meta["particles"],
         "%s: header and %d rows" % (r["file"], n))
sys.exit(1 if bad else 0)
