"""brash: read a brash run directory from Python.

    import brash
    run = brash.load_run("runs/jbc_quick-liggghts-both-20240101-120000")
    run.force.plot(x="t_s", y="resistance_N")
    print(run.resistance())
    print(run.resistance_split())  # bow / mid / stern, normal / tangential (LIGGGHTS, brash-ode)

The run layout is docs/case_format.md ("Run layout"); numpy, pandas and yaml come from Debian
(python3-numpy, python3-pandas, python3-yaml).
"""

from .run import (REQUIRED_FILES, SPLIT_COLUMNS, SPLIT_PARTS, NotARunError, Resistance, ResistanceSplit, Run,
                  RunError, SplitPart, load_run)

__all__ = ["REQUIRED_FILES", "SPLIT_COLUMNS", "SPLIT_PARTS", "NotARunError", "Resistance", "ResistanceSplit", "Run",
           "RunError", "SplitPart", "load_run"]
__version__ = "0.1.0"
