"""brash.load_run on a run directory this test writes itself (known values in every file)."""

import json
import tempfile
import unittest
from pathlib import Path

import brash

CASE_YAML = """\
name: synthetic
hull:
  file: box.stl
  draft_m: 0.4
  lpp_m: 7.0
ship:
  speed_m_s: 0.5
  scale_lambda: 25.0
run:
  window_s: [0.2, 0.4]
"""

META = {"engine": "ode", "fluid_model": "drag", "status": "complete", "particles": 3}

REPORT = {
    "status": "complete",
    "window_s": [0.2, 0.4],
    "resistance_model_N": {"mean": 2.5, "ci95": 0.25, "blocking": {"plateau_found": True}},
    "resistance_full_kN": 195.3,
    "resistance_full_ci95_kN": 19.5,
    "fsicr": {"R_CH_kN": 1000.0},
    "ratio_fsicr_to_sim": 5.12,
    "notes": ["a note"],
}


def write_run(root: Path) -> Path:
    run = root / "run"
    (run / "particles").mkdir(parents=True)
    (run / "case.yaml").write_text(CASE_YAML)
    (run / "meta.json").write_text(json.dumps(META))
    rows = ["t_s,fx_N,fy_N,fz_N"] + [f"{0.1 * i:.1f},{-1.0 * i},{0.5},{-0.25 * i}" for i in range(1, 5)]
    (run / "hull_force.csv").write_text("\n".join(rows) + "\n")
    (run / "particles" / "index.csv").write_text(
        "step,t_s,file,hull_x_m\n0,0,particles_0.csv,-7.5\n100,0.4,particles_100.csv,-7.3\n")
    header = "id,x,y,z,radius,vx,vy,vz,submerged_fraction,ca_x,ca_y,ca_z\n"
    (run / "particles" / "particles_0.csv").write_text(
        header + "".join(f"{i},{0.1 * i},0,-0.01,0.02,0,0,0,1,0,0,0\n" for i in range(1, 4)))
    # LIGGGHTS and ODE end with the active column (1 integrated, 0 idle far-field ice); YADE's files do not
    (run / "particles" / "particles_100.csv").write_text(
        header.replace("\n", ",active\n")
        + "".join(f"{i},{0.1 * i + 0.05},0,-0.01,0.02,0.1,0,0,1,0,0,0,{i % 2}\n" for i in range(1, 3)))
    return run


class LoadRun(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.root = Path(self.tmp.name)
        self.run_dir = write_run(self.root)

    def tearDown(self):
        self.tmp.cleanup()

    def test_meta_and_case(self):
        run = brash.load_run(self.run_dir)
        self.assertEqual(run.meta["engine"], "ode")
        self.assertEqual(run.status, "complete")
        self.assertEqual(run.case["hull"]["lpp_m"], 7.0)
        self.assertEqual(run.case["run"]["window_s"], [0.2, 0.4])
        self.assertIn("status='complete'", repr(run))

    def test_force_has_resistance_column(self):
        force = brash.load_run(str(self.run_dir)).force
        self.assertEqual(list(force.columns), ["t_s", "fx_N", "fy_N", "fz_N", "resistance_N"])
        self.assertEqual(len(force), 4)
        self.assertEqual(force["resistance_N"].tolist(), [1.0, 2.0, 3.0, 4.0])
        self.assertAlmostEqual(force["t_s"].iloc[-1], 0.4)

    def test_snapshots_by_step_and_index(self):
        run = brash.load_run(self.run_dir)
        self.assertEqual(run.snapshots["step"].tolist(), [0, 100])
        first = run.snapshot(0)
        self.assertEqual(len(first), 3)
        self.assertAlmostEqual(first["x"].iloc[2], 0.3)
        self.assertEqual(first.attrs["step"], 0)
        last = run.snapshot(index=-1)
        self.assertEqual(len(last), 2)
        self.assertEqual(last.attrs["step"], 100)
        self.assertAlmostEqual(last.attrs["t_s"], 0.4)
        self.assertAlmostEqual(last.attrs["hull_x_m"], -7.3)
        self.assertAlmostEqual(last["vx"].iloc[0], 0.1)
        self.assertEqual(last["active"].tolist(), [1, 0])
        self.assertNotIn("active", first.columns)

    def test_moving_window_state_column(self):
        # a run with the moving window writes every piece with its state: 0 in the scene, 1 held out, 2 removed
        index = self.run_dir / "particles" / "index.csv"
        index.write_text(index.read_text() + "200,0.8,particles_200.csv,-7.1\n")
        header = "id,x,y,z,radius,vx,vy,vz,submerged_fraction,ca_x,ca_y,ca_z,active,state\n"
        (self.run_dir / "particles" / "particles_200.csv").write_text(
            header + "1,0.1,0,-0.01,0.02,0,0,0,1,0,0,0,0,2\n2,0.25,0,-0.01,0.02,0.1,0,0,1,0.4,0.4,0.8,1,0\n"
            "3,0.3,0,-0.01,0.02,0,0,0,1,0,0,0,0,1\n")
        run = brash.load_run(self.run_dir)
        scene = run.snapshot(200)  # what a statistic reads: the pieces in the scene
        self.assertEqual(scene["id"].tolist(), [2])
        self.assertEqual(scene["state"].tolist(), [0])
        whole = run.snapshot(200, all_pieces=True)  # a picture of the whole channel
        self.assertEqual(whole["id"].tolist(), [1, 2, 3])
        self.assertEqual(whole["state"].tolist(), [2, 0, 1])
        self.assertAlmostEqual(whole["x"].iloc[2], 0.3)
        # files without the column are read as they are, every piece
        self.assertEqual(len(run.snapshot(0, all_pieces=False)), 3)
        (self.run_dir / "particles" / "particles_200.csv").write_text(header + "1,0.1,0,-0.01,0.02,0,0,0,1,0,0,0,0,5\n")
        with self.assertRaisesRegex(brash.RunError, r"particles_200.csv: column state: \[5\] not among 0 \(in the scene"):
            brash.load_run(self.run_dir).snapshot(200)

    def test_snapshot_errors(self):
        run = brash.load_run(self.run_dir)
        with self.assertRaisesRegex(brash.RunError, r"no snapshot at step 7 \(steps: 0, 100\)"):
            run.snapshot(7)
        with self.assertRaisesRegex(brash.RunError, "index 2 out of range"):
            run.snapshot(index=2)
        with self.assertRaises(TypeError):
            run.snapshot()
        (self.run_dir / "particles" / "particles_100.csv").unlink()
        with self.assertRaisesRegex(brash.RunError, r"particles_100\.csv is missing"):
            run.snapshot(100)

    def test_report_before_and_after_post(self):
        run = brash.load_run(self.run_dir)
        self.assertIsNone(run.report)
        with self.assertRaisesRegex(brash.RunError, r"report\.json is missing: run `brash-post"):
            run.resistance()
        (self.run_dir / "report.json").write_text(json.dumps(REPORT))
        run = brash.load_run(self.run_dir)
        self.assertEqual(run.report["status"], "complete")
        r = run.resistance()
        self.assertEqual((r.mean_N, r.ci95_N), (2.5, 0.25))
        self.assertEqual((r.full_kN, r.full_ci95_kN), (195.3, 19.5))
        self.assertEqual(r.window_s, (0.2, 0.4))
        self.assertTrue(r.plateau_found)
        self.assertEqual(r.fsicr_R_CH_kN, 1000.0)
        self.assertAlmostEqual(r.rel_ci95, 0.1)
        self.assertEqual(r.notes, ("a note",))
        self.assertIn("2.5 ± 0.25 N model, 195.3 ± 19.5 kN full scale", str(r))

    def test_report_without_resistance(self):
        (self.run_dir / "report.json").write_text(json.dumps({"status": "failed", "notes": ["guard stop"]}))
        with self.assertRaisesRegex(brash.RunError, r"no resistance_model_N.*'failed'.*guard stop"):
            brash.load_run(self.run_dir).resistance()

    def test_report_of_a_hull_that_met_no_ice(self):
        (self.run_dir / "report.json").write_text(json.dumps(
            dict(REPORT, met_no_ice=True, resistance_model_N=None, resistance_full_kN=None,
                 resistance_full_ci95_kN=None, ratio_fsicr_to_sim=None)))
        run = brash.load_run(self.run_dir)
        self.assertTrue(run.report["met_no_ice"])
        with self.assertRaisesRegex(brash.RunError, r"met no ice in the averaging window \[0\.2, 0\.4\] s"):
            run.resistance()

    def test_not_a_run_directory_names_the_missing_file(self):
        empty = self.root / "empty"
        empty.mkdir()
        with self.assertRaisesRegex(brash.NotARunError, r"empty is not a run directory: .*empty/case\.yaml is missing"):
            brash.load_run(empty)
        (empty / "case.yaml").write_text(CASE_YAML)
        with self.assertRaisesRegex(brash.NotARunError, r"meta\.json is missing \(a case folder\?"):
            brash.load_run(empty)
        with self.assertRaisesRegex(brash.NotARunError, "no such run directory"):
            brash.load_run(self.root / "nowhere")
        with self.assertRaisesRegex(brash.NotARunError, "not a folder"):
            brash.load_run(self.run_dir / "meta.json")

    def test_own_deck_folder_without_meta(self):
        """An own LIGGGHTS deck's folder: case.yaml, fix ave/time's hull_force.raw and dump custom files."""
        deck = self.root / "deck"
        deck.mkdir()
        (deck / "case.yaml").write_text("name: deck\nhull:\n  start_x_m: -1.0\nship:\n  speed_m_s: 0.5\n"
                                        "run:\n  timestep_s: 1.0e-4\n")
        (deck / "hull_force.raw").write_text("# Time-averaged data for fix hf\n# TimeStep v_t f_hull[1] f_hull[2] "
                                             "f_hull[3]\n0 0 0 0 0\n100 0.01 -1.5 0.25 2\n")

        def dump(step: int, atoms: str, rows: str) -> str:
            return (f"ITEM: TIMESTEP\n{step}\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp ff\n-1 1\n-1 1\n"
                    f"-1 1\nITEM: ATOMS {atoms}\n{rows}")

        (deck / "ice_2000.liggghts").write_text(dump(2000, "id x y z diameter", "1 0 0 0 0.02\n2 0 0 -0.02 0.02\n"))
        (deck / "ice_1000.liggghts").write_text(dump(1000, "id x y z radius vx", "1 0 0 0.01 0.01 0.1\n2 0 0 0 0.01 0\n"))
        run = brash.load_run(deck)
        self.assertEqual(run.status, "unknown")
        self.assertEqual(run.force["resistance_N"].tolist(), [0.0, 1.5])
        self.assertEqual(run.force["t_s"].tolist(), [0.0, 0.01])
        snaps = run.snapshots
        self.assertEqual(snaps["step"].tolist(), [1000, 2000])
        self.assertAlmostEqual(snaps["t_s"].iloc[1], 0.2)
        self.assertAlmostEqual(snaps["hull_x_m"].iloc[1], -0.9)
        first = run.snapshot(1000)
        self.assertEqual(first["vx"].tolist(), [0.1, 0.0])
        self.assertEqual(first["submerged_fraction"].iloc[0], 0.0)  # resting on the water line
        self.assertAlmostEqual(first["submerged_fraction"].iloc[1], 0.5)  # centred on it
        last = run.snapshot(index=-1)
        self.assertEqual(last["radius"].tolist(), [0.01, 0.01])  # diameter / 2
        self.assertAlmostEqual(last["submerged_fraction"].iloc[1], 1.0)
        self.assertAlmostEqual(last.attrs["t_s"], 0.2)

    def test_missing_or_bad_force_file(self):
        (self.run_dir / "hull_force.csv").unlink()
        run = brash.load_run(self.run_dir)  # a running run: meta and case still load
        with self.assertRaisesRegex(brash.RunError, r"hull_force\.csv is missing .*status 'complete'"):
            run.force
        (self.run_dir / "hull_force.csv").write_text("t_s,fx_N,fz_N\n0.1,1,2\n")
        with self.assertRaisesRegex(brash.RunError, r"column\(s\) fy_N missing"):
            brash.load_run(self.run_dir).force

    def test_bad_meta_and_case(self):
        (self.run_dir / "meta.json").write_text("{\"engine\": ")
        with self.assertRaisesRegex(brash.RunError, r"meta\.json: not valid JSON"):
            brash.load_run(self.run_dir)
        (self.run_dir / "meta.json").write_text(json.dumps(META))
        (self.run_dir / "case.yaml").write_text("- a list\n")
        with self.assertRaisesRegex(brash.RunError, r"case\.yaml: expected a mapping"):
            brash.load_run(self.run_dir)


if __name__ == "__main__":
    unittest.main()


class ResistanceSplitTest(unittest.TestCase):
    """Run.resistance_split() from report.json; Run.has_split from hull_force.csv's header."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.run_dir = write_run(Path(self.tmp.name))

    def tearDown(self):
        self.tmp.cleanup()

    def test_split_parts_and_full_scale(self):
        rows = ["t_s,fx_N,fy_N,fz_N," + ",".join(brash.SPLIT_COLUMNS)] + [
            f"{0.1 * i:.1f},{-1.0 * i},0.5,0,{-0.5 * i},{-0.25 * i},{-0.25 * i},{-0.75 * i},{-0.25 * i}"
            for i in range(1, 5)]
        (self.run_dir / "hull_force.csv").write_text("\n".join(rows) + "\n")
        split = {"bow": {"mean": 1.5, "ci95": 0.2}, "mid": {"mean": 0.5, "ci95": 0.1},
                 "stern": {"mean": 0.5, "ci95": 0.1}, "normal": {"mean": 2.0, "ci95": 0.2},
                 "tangential": {"mean": 0.5, "ci95": 0.05}, "x_par_m": [1.25, 4.5]}
        (self.run_dir / "report.json").write_text(
            json.dumps(dict(REPORT, resistance_split_model_N=split, **{"lambda": 25.0})))
        run = brash.load_run(self.run_dir)
        self.assertTrue(run.has_split)
        self.assertIn("fx_bow_N", run.force.columns)
        s = run.resistance_split()
        self.assertEqual(s["bow"].mean_N, 1.5)
        self.assertAlmostEqual(s["bow"].full_kN, 1.5 * 25.0 ** 3 / 1000)
        self.assertEqual(s.x_par_m, (1.25, 4.5))
        self.assertAlmostEqual(sum(s[p].mean_N for p in ("bow", "mid", "stern")), 2.5)
        self.assertIn("tangential 0.5", str(s))
        self.assertTrue(s["stern"].contact)  # a report from before "contact" was recorded

    def test_part_that_touched_no_ice_says_no_contact(self):
        split = {p: {"mean": 1.0, "ci95": 0.1, "contact": True} for p in brash.SPLIT_PARTS}
        split["stern"] = {"mean": 0.0, "ci95": 0.0, "contact": False}
        (self.run_dir / "report.json").write_text(json.dumps(dict(REPORT, resistance_split_model_N=split)))
        s = brash.load_run(self.run_dir).resistance_split()
        self.assertFalse(s["stern"].contact)
        self.assertTrue(s["bow"].contact)
        self.assertIn("stern no contact", str(s))
        self.assertNotIn("stern 0", str(s))

    def test_no_split_says_why(self):
        report = dict(REPORT, resistance_split_model_N=None,
                      resistance_split_not_recorded="not recorded: the YADE scene records the total hull force only")
        (self.run_dir / "report.json").write_text(json.dumps(report))
        run = brash.load_run(self.run_dir)
        self.assertFalse(run.has_split)
        with self.assertRaisesRegex(brash.RunError, "no hull force split: not recorded: the YADE scene"):
            run.resistance_split()
