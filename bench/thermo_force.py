#!/usr/bin/env python3
"""The hull's x force from a LIGGGHTS run's thermo lines (log.txt: step t atoms ke hull[1] ...), an
instantaneous sample every `thermo` steps, against the run's hull_force.csv (means over 0.01 s) on stretches
of model time: a check of a record with a gap, and an estimate of the resistance there.
    python3 bench/thermo_force.py RUN_DIR T0-T1 [T0-T1 ...]
Per stretch: thermo samples (n, mean resistance -fx, its standard error assuming independent samples, from
`brash-post sample-stats`: BRASH_BIN, default build/bin) and the record's rows (n, mean). A thermo sample repeated
by a resumed attempt (same t) is counted once."""
import json
import os
import re
import subprocess
import sys


def sample_stats(values):
    """n, mean and standard error of independent samples, by the project's statistics (brash-post sample-stats)."""
    if len(values) < 2:
        return len(values), float("nan"), float("nan")
    exe = os.path.join(os.environ.get("BRASH_BIN", "build/bin"), "brash-post")
    out = subprocess.run([exe, "sample-stats", "-"], input="\n".join(repr(v) for v in values), text=True,
                         capture_output=True, check=True).stdout
    s = json.loads(out)
    return s["n"], s["mean"], s["se"]


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    run = sys.argv[1]
    thermo = {}
    row = re.compile(r"^\s+\d+\s+([0-9.eE+-]+)\s+\d+\s+[-0-9.eE+]+\s+([-0-9.eE+]+)\s")
    with open(f"{run}/log.txt") as f:
        for line in f:
            if m := row.match(line):
                thermo[float(m.group(1))] = float(m.group(2))
    record = []
    with open(f"{run}/hull_force.csv") as f:
        next(f)
        for line in f:
            t, fx = line.split(",")[:2]
            record.append((float(t), float(fx)))
    print("| model time [s] | thermo samples | thermo mean R [N] | ± se | record rows | record mean R [N] |")
    print("|---|---|---|---|---|---|")
    for span in sys.argv[2:]:
        a, b = map(float, span.split("-"))
        ts = [-fx for t, fx in thermo.items() if a < t <= b]
        rs = [-fx for t, fx in record if a < t <= b]
        n, mean, se = sample_stats(ts)
        rmean = f"{sum(rs) / len(rs):.3f}" if rs else "—"
        print(f"| {a:g}-{b:g} | {n} | {mean:.3f} | {se:.3f} | {len(rs)} | {rmean} |")


if __name__ == "__main__":
    main()
