#!/usr/bin/python3
"""The README's headline table, read against the report files it links.

Usage: check_readme_headline.py README.md

In the section "## The paper case": every table row that links a report (report.md) must show that run's
full-scale resistance and its 95 % interval (report.json: resistance_full_kN, resistance_full_ci95_kN, to 0.1 kN),
its ratio R_CH / resistance (ratio_fsicr_to_sim, to 0.01) and its window halves (resistance_model_N.window_halves:
the second half's mean on the first's, to 0.1 %, and "**drifts**" where the report flags drift, else "steady");
the paper's rows their levels (paper_full_kN) and ratios (the paper's R_CH over them) and no halves; the R_CH line ours and the paper's (fsicr.R_CH_kN, fsicr.paper_R_CH_kN, to
1 kN). Prints each mismatch; exit 1 if there is one or if no report is linked.
"""
import json
import os
import re
import sys


def halves_cell(rep):
    """The window halves' cell of a run: "+2.1 %: **drifts**" or "+0.3 %: steady"."""
    h = rep["resistance_model_N"]["window_halves"]
    return "%+.1f %%: %s" % (100 * h["difference"] / h["first_mean"], "**drifts**" if h["drifts"] else "steady")


def main(readme):
    text = open(readme, encoding="utf-8").read()
    section = text.split("## The paper case", 1)[1].split("\n## ", 1)[0]
    here = os.path.dirname(os.path.abspath(readme))
    problems, reports = [], []
    rows = [line for line in section.splitlines() if line.startswith("| ") and not line.startswith("| run ")]
    for line in rows:
        cells = [c.strip() for c in line.strip("|").split("|")]
        link = re.search(r"\]\(([^)]+report\.md)\)", line)
        if link:
            rep = json.load(open(os.path.join(here, os.path.dirname(link.group(1)), "report.json"), encoding="utf-8"))
            reports.append(rep)
            want = "%.1f ± %.1f" % (rep["resistance_full_kN"], rep["resistance_full_ci95_kN"])
            if cells[1] != want:
                problems.append("%s: resistance %s, its report says %s" % (cells[0], cells[1], want))
            if cells[2] != "%.2f" % rep["ratio_fsicr_to_sim"]:
                problems.append("%s: ratio %s, its report says %.2f" % (cells[0], cells[2], rep["ratio_fsicr_to_sim"]))
            if cells[3] != halves_cell(rep):
                problems.append("%s: window halves %s, its report says %s" % (cells[0], cells[3], halves_cell(rep)))
    if not reports:
        return ["no report linked in the section"]
    rep = reports[0]
    paper_rch = rep["fsicr"]["paper_R_CH_kN"]
    for key, name in (("added_mass", "paper, added-mass model"), ("drag", "paper, drag model")):
        row = [line for line in rows if line.startswith("| " + name + " |")]
        level = rep["paper_full_kN"][key]
        want = ["%g" % level, "%.2f" % (paper_rch / level), "—"]
        got = [c.strip() for c in row[0].strip("|").split("|")][1:4] if row else None
        if got != want:
            problems.append("%s: %s, the reports say %s" % (name, got, want))
    m = re.search(r"R_CH \(ice class \w+\): (\d+) kN from our hull, (\d+) kN in the paper", section)
    want = ("%.0f" % rep["fsicr"]["R_CH_kN"], "%.0f" % paper_rch)
    if not m or m.groups() != want:
        problems.append("R_CH line: %s, the reports say %s" % (m.groups() if m else None, want))
    return problems


if __name__ == "__main__":
    found = main(sys.argv[1])
    for p in found:
        print(p)
    print("%d mismatch(es)" % len(found))
    sys.exit(1 if found else 0)
