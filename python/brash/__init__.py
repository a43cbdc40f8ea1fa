"""brash: read a brash run directory from Python.

    import brash
    run = brash.load_run("runs/jbc_quick-liggghts-both-20240101-120000")
    run.force.plot(x="t_s", y="resistance_N")
    print(run.resistance())

The run layout is docs/case_format.md ("Run layout"); numpy, pandas and yaml come from Debian
(python3-numpy, python3-pandas, python3-yaml).
"""

from .run import REQUIRED_FILES, NotARunError, Resistance, Run, RunError, load_run

__all__ = ["REQUIRED_FILES", "NotARunError", "Resistance", "Run", "RunError", "load_run"]
__version__ = "0.1.0"
