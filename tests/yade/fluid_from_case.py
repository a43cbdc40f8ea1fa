"""brash_yade.Fluid.from_case: the YADE scene's fluid comes from a case.yaml through brash::fluid_params (the
mapping the LIGGGHTS and ODE runners use): every fluid key reaches the Fluid, and a bad case is refused by name.
   python3 fluid_from_case.py WORK_DIR  (brash_yade on PYTHONPATH) -> exit 0 = pass"""
import os
import sys

import brash_yade

work = sys.argv[1]
os.makedirs(work, exist_ok=True)
path = os.path.join(work, "case.yaml")
with open(path, "w") as f:
    f.write("name: fluid_keys\n"
            "water: {density_kg_m3: 1025.5, level_m: -0.05, gravity_m_s2: 9.8, kinematic_viscosity_m2_s: 1.3e-6}\n"
            "fluid: {model: drag, treatment: explicit, drag_coefficient: 0.3, drag_law: schiller_naumann, "
            "ca_table: uniform 0.25}\n")
bad = []


def need(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        bad.append(what)


fl = brash_yade.Fluid.from_case(path)
for name, want in (("model", "drag"), ("treatment", "explicit"), ("drag_law", "schiller_naumann"), ("cd", 0.3),
                   ("nu", 1.3e-6), ("ca_table", "uniform 0.25"), ("water_level", -0.05),
                   ("water_density", 1025.5), ("g", 9.8), ("apply_gravity", True)):
    need(getattr(fl, name) == want, "%s = %r (want %r)" % (name, getattr(fl, name), want))
need(not brash_yade.Fluid.from_case(path, apply_gravity=False).apply_gravity, "apply_gravity=False kept")
default = brash_yade.Fluid()
with open(path, "w") as f:
    f.write("name: defaults\n")
fd = brash_yade.Fluid.from_case(path)
for name in ("model", "treatment", "drag_law", "cd", "nu", "ca_table", "water_level", "water_density", "g"):
    need(getattr(fd, name) == getattr(default, name), "default %s = %r" % (name, getattr(fd, name)))
with open(path, "w") as f:
    f.write("name: bad\nfluid: {model: viscous}\n")
try:
    brash_yade.Fluid.from_case(path)
    need(False, "a bad fluid.model is refused")
except RuntimeError as e:
    need("fluid.model" in str(e) and "case.yaml" in str(e), "the error names the file and the key: %s" % e)
sys.exit(1 if bad else 0)
