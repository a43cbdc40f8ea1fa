#!/usr/bin/env python3
"""Wall time of a LIGGGHTS run made of several attempts, from the runner's own stderr log.

usage: wall_from_runner_log.py RUNNER_LOG [--write-meta RUN_DIR]

brash-liggghts-run keeps wall time and particle-steps over a run's attempts in meta.json ("attempts") since
this script's commit; a run resumed with an older runner only has its last attempt's wall time there. The
runner's stderr (e.g. the file `nohup brash-liggghts-run ... >> RUN.log` wrote) has a progress line every 30 s:
an attempt starts at "[brash-liggghts] N spheres ..." and its wall time is the last "elapsed" before the
next start or its "done in" line (an attempt killed outright loses at most the 30 s after its last line).
--write-meta stores the attempts, the total, the model's particle-steps (pieces x steps to the record's end) and a note of where they come from in RUN_DIR/meta.json.
"""
import json
import os
import re
import sys


def attempts(log_text):
    """One entry per engine started: a runner start, and each restart file a runner tried."""
    out = []
    for line in log_text.splitlines():
        if re.match(r"\[brash-liggghts\] \d+ spheres(, | -> )", line):
            out.append({"from": "start", "t_from_s": None, "t_to_s": None, "wall_s": 0.0})
        elif not out:
            continue
        elif m := re.match(r"\[brash-liggghts\] resuming .* from (restart/\S+)", line):
            if out[-1]["from"] == "start" and out[-1]["t_from_s"] is None:
                out[-1]["from"] = m.group(1)  # the runner's first engine resumes
            else:  # the runner's next engine (the newest restart file failed): its elapsed starts again
                out.append({"from": m.group(1), "t_from_s": None, "t_to_s": None, "wall_s": 0.0})
        elif m := re.match(r"\[brash-liggghts\] t = ([0-9.]+) / [0-9.]+ s .*elapsed ([0-9.]+) s", line):
            a = out[-1]
            a["t_to_s"] = float(m.group(1))
            if a["t_from_s"] is None:
                a["t_from_s"] = a["t_to_s"]
            a["wall_s"] = float(m.group(2))
        elif m := re.match(r"\[brash-liggghts\] done in ([0-9.]+) s", line):
            out[-1]["wall_s"] = float(m.group(1))
    return out


def main():
    if len(sys.argv) not in (2, 4) or (len(sys.argv) == 4 and sys.argv[2] != "--write-meta"):
        sys.exit(__doc__)
    with open(sys.argv[1]) as f:
        att = attempts(f.read())
    if not att:
        sys.exit(f"{sys.argv[1]}: no brash-liggghts-run attempt found")
    total = sum(a["wall_s"] for a in att)
    print("| attempt | from | model time [s] | wall [s] |\n|---|---|---|---|")
    for i, a in enumerate(att, 1):
        span = f"{a['t_from_s']} -> {a['t_to_s']}" if a["t_from_s"] is not None else "(no progress line)"
        print(f"| {i} | {a['from']} | {span} | {a['wall_s']:.0f} |")
    print(f"\ntotal wall time {total:.0f} s = {total / 3600:.2f} h over {len(att)} attempt(s)")
    if len(sys.argv) == 4:
        path = os.path.join(sys.argv[3], "meta.json")
        with open(path) as f:
            meta = json.load(f)
        meta["attempts"] = att
        meta["wall_time_s"] = total
        # the model's particle-steps (pieces x steps to the record's end; steps redone after a resume not counted)
        t_end = max(a["t_to_s"] or 0.0 for a in att)
        meta["particle_steps"] = float(meta["particles"]) * round(t_end / float(meta["dt_s"]))
        meta["wall_time_note"] = (f"sum over the attempts reconstructed from the runner's log {sys.argv[1]} "
                                  "(bench/wall_from_runner_log.py): progress lines every 30 s, pauses included; t_from_s is the first "
                                  "progress line's model time")
        tmp = path + ".tmp"
        with open(tmp, "w") as f:
            json.dump(meta, f, indent=2)
        os.replace(tmp, path)
        print(f"wrote {path}")


if __name__ == "__main__":
    main()
