"""brash.load_run on a real run: brash-ode on the 720-sphere smoke case for 0.05 s, then brash-post (~1 s).

ctest sets BRASH_ODE_EXE (and BRASH_HULL_DIR for the JBC hull); run by hand without them it skips.
"""

import os
import subprocess
import tempfile
import unittest
from pathlib import Path

import brash

ODE_EXE = os.environ.get("BRASH_ODE_EXE")
SMOKE_CASE = os.environ.get("BRASH_SMOKE_CASE",
                            str(Path(__file__).resolve().parents[2] / "tests" / "yade" / "smoke_case"))


@unittest.skipUnless(ODE_EXE, "BRASH_ODE_EXE not set (ctest sets it)")
class OdeRun(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.run_dir = Path(cls.tmp.name) / "run"
        done = subprocess.run([ODE_EXE, SMOKE_CASE, "--out", str(cls.run_dir), "--duration", "0.05",
                               "--no-progress"], capture_output=True, text=True, timeout=120)
        if done.returncode != 0:
            raise AssertionError(f"brash-ode exited {done.returncode}:\n{done.stderr}")
        cls.result = brash.load_run(cls.run_dir)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_meta_and_resolved_case(self):
        self.assertEqual(self.result.meta["engine"], "ode")
        self.assertEqual(self.result.status, "complete")
        self.assertEqual(self.result.case["name"], "yade_smoke")
        self.assertEqual(self.result.case["run"]["duration_s"], 0.05)

    def test_force_rows_match_meta(self):
        force = self.result.force
        self.assertEqual(len(force), self.result.meta["hull_force_rows"])
        self.assertAlmostEqual(force["t_s"].iloc[-1], 0.05, places=9)
        self.assertTrue((force["resistance_N"] == -force["fx_N"]).all())

    def test_resistance_is_the_window_mean_of_the_force(self):
        r = self.result.resistance()
        force = self.result.force
        t0, t1 = r.window_s
        in_window = force[(force["t_s"] >= t0 - 1e-9) & (force["t_s"] <= t1 + 1e-9)]
        self.assertGreater(len(in_window), 0)
        self.assertAlmostEqual(r.mean_N, in_window["resistance_N"].mean(), places=9)
        self.assertGreater(r.ci95_N, 0.0)
        self.assertIsNotNone(r.full_kN)
        lam = self.result.case["ship"]["scale_lambda"]
        # Froude scaling: F_full = F_model * lambda^3 (same density ratio of the case's water)
        self.assertAlmostEqual(r.full_kN, r.mean_N * lam ** 3 / 1000.0, delta=0.05 * abs(r.full_kN) + 1e-9)
        self.assertGreater(r.fsicr_R_CH_kN, 0.0)

    def test_snapshots_follow_the_hull(self):
        snaps = self.result.snapshots
        self.assertGreaterEqual(len(snaps), 2)
        last = self.result.snapshot(index=-1)
        self.assertEqual(len(last), self.result.meta["particles"])
        first = self.result.snapshot(int(snaps["step"].iloc[0]))
        self.assertEqual(first.attrs["t_s"], 0.0)
        hull, ship = self.result.case["hull"], self.result.case["ship"]
        self.assertAlmostEqual(last.attrs["hull_x_m"], hull["start_x_m"] + ship["speed_m_s"] * last.attrs["t_s"],
                               places=6)


if __name__ == "__main__":
    unittest.main()
