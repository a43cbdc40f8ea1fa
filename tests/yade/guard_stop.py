"""brash-yade-run's run-time guards (docs/stability.md, "Run-time guards") on the smoke case (720 spheres at the
JBC bow, contact hull = waterline band): one scenario per guard; each must stop the run naming the step, the
piece and the cause, with meta.json failed and the outputs up to the stop readable.
   python3 guard_stop.py BRASH_YADE_RUN SMOKE_CASE_DIR WORK_DIR SCENARIO  -> exit 0 = pass
Scenarios: under_band (a piece below the band, swept into the full hull), kinetic_energy (explicit added mass
with Ca_z = 2 diverges), timestep (a 5 mm piece in the packing: dt too large for its contact stiffness); box (a
piece below the domain floor) and zmax (a piece above zmax) cannot be the case's ice: the runner refuses their
packing naming its file and line before it makes the run directory (brash::read_case_packing)."""
import json
import os
import re
import shutil
import subprocess
import sys

runner, smoke, work, scenario = sys.argv[1:5]

# packing rows to append, case.yaml replacements, duration, expected piece, cause regex, step check
SCENARIOS = {
    # 12 cm down the bulb's path, 30 cm down: under the band (down to 15 cm), outside the hull at t = 0
    # (the bulb nose is 1.5 cm behind it); the hull sweeps over it at 0.48 m/s.
    "under_band": (["721,0.135,0,-0.3,0.035"], [], "0.12", "721",
                   r"hull penetration: 0\.0[0-9]+ m = [0-9]+ % of its diameter 0\.035 m > max_hull_penetration_d "
                   r"0\.5 \(centre inside the hull", "positive"),
    "kinetic_energy": ([], [("treatment: implicit", "treatment: explicit"), ("ca_table: table1", "ca_table: text")],
                       "0.05", "[0-9]+", r"(runaway kinetic energy: [0-9.e+]+ J > ke_max = 1\.428 J|non-finite)",
                       "positive"),
    "box": (["721,0.1,0,-0.6,0.035"], [], "0.02", "721",
            r"is far below the water: its centre is 0\.6 m below water\.level_m = 0 m", "refused"),
    "zmax": (["721,0.1,0,0.4,0.035"], [], "0.02", "721",
             r"is far above the water: its bottom is 0\.3825 m above water\.level_m = 0 m", "refused"),
    # resting on the bed (clear of its pieces by 0.2 mm)
    "timestep": (["721,0.1,0.3,-0.0045,0.005"], [], "0.02", "721",
                 r"timestep 0\.0001 s is too large for the contact stiffness: [0-9]+ % of the Rayleigh time", "zero"),
}
rows, edits, duration, piece, cause, step_check = SCENARIOS[scenario]

case = os.path.join(work, "case")
run = os.path.join(work, "run")
shutil.rmtree(work, ignore_errors=True)
shutil.copytree(smoke, case)
with open(os.path.join(case, "packing.csv"), "a") as f:
    f.write("".join(r + "\n" for r in rows))
text = open(os.path.join(case, "case.yaml")).read()
for a, b in edits:
    assert a in text, a
    text = text.replace(a, b)
open(os.path.join(case, "case.yaml"), "w").write(text)

p = subprocess.run([runner, case, "--out", run, "--no-post", "--duration", duration], stdout=subprocess.PIPE,
                   stderr=subprocess.STDOUT, text=True)
print(p.stdout)
bad = []


def need(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        bad.append(what)


if step_check == "refused":  # row 721 is line 723 of the packing
    need(p.returncode == 2, "exit code 2, bad input (got %d)" % p.returncode)
    need(re.search(r"packing\.csv:723: piece id %s \(.*\) %s" % (piece, cause), p.stdout) is not None,
         "the error names the packing's line, the piece and the problem")
    need(not os.path.exists(run), "no run directory")
    if bad:
        sys.exit(1)
    shutil.rmtree(work, ignore_errors=True)
    sys.exit(0)
need(p.returncode == 1, "exit code 1 (got %d)" % p.returncode)
meta = json.load(open(os.path.join(run, "meta.json")))
need(meta.get("status") == "failed", "meta.json status failed")
reason = meta.get("reason", "")
m = re.match(r"guard: step ([0-9]+) \(t = [0-9.e-]+ s\): piece %s: %s" % (piece, cause), reason)
need(m is not None, "reason names step, piece %s and cause: %r" % (piece, reason))
if m:
    step = int(m.group(1))
    need(step > 0 if step_check == "positive" else step == 0, "stop step %d (%s)" % (step, step_check))
need(reason in open(os.path.join(run, "log.txt")).read(), "log.txt has the message")
hf = open(os.path.join(run, "hull_force.csv")).read().splitlines() if os.path.isfile(
    os.path.join(run, "hull_force.csv")) else []
need(hf[:1] == ["t_s,fx_N,fy_N,fz_N"], "hull_force.csv written up to the stop (%d rows)" % (len(hf) - 1))
need(os.path.isfile(os.path.join(run, "particles", "index.csv")), "particles/index.csv")
if bad:
    sys.exit(1)
shutil.rmtree(work, ignore_errors=True)
