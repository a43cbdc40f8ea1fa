// End to end: the default case exactly as `make run` runs it (scripts/brash-run cases/jbc_quick: packing,
// LIGGGHTS, brash-post), into a temporary runs root. Its report must pass its own checks (no "Read first"
// note: a blocking plateau, the window's halves within their CI, a complete record), use the default fluid
// model, give the reference run's numbers to the printed digit and compare with no published value (the quick case declares none); the run layout, the ParaView
// files and report.json carry everything a user reads.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

namespace fs = std::filesystem;

namespace {
std::string brash_read(const fs::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), {}};
}
nlohmann::json read_json(const fs::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}
}  // namespace

TEST(Pipeline, DefaultCaseAsMakeRunGivesAnUnflaggedReport) {
  const fs::path root = fs::temp_directory_path() / ("brash_pipeline_" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root);
  const fs::path log = root / "make_run.log";
  // what `make run` does after the build: ./scripts/brash-run cases/jbc_quick (default ranks)
  const std::string cmd = std::string("cd '") + BRASH_SOURCE_DIR + "' && BRASH_BIN='" + BRASH_BIN_DIR +
                          "' BRASH_RUNS_ROOT='" + root.string() + "' ./scripts/brash-run cases/jbc_quick > '" +
                          log.string() + "' 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << brash_read(log);
  std::smatch m;
  const std::string printed = brash_read(log);
  ASSERT_TRUE(std::regex_search(printed, m, std::regex("brash-run: run directory (.*)\n"))) << printed;
  const fs::path out = m[1].str();
  ASSERT_EQ(out.parent_path(), root);
  // brash-run prints the report; its first section would be "Read first" if any check had failed
  EXPECT_EQ(printed.find("Read first"), std::string::npos) << printed;

  for (const char* f : {"case.yaml", "meta.json", "hull_force.csv", "log.txt", "particles/index.csv", "report.json",
                        "report.md"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  for (const char* f : {".lock", "engine.pid"}) EXPECT_FALSE(fs::exists(out / f)) << f << ": left in a finished run";
  const auto meta = read_json(out / "meta.json");
  EXPECT_EQ(meta["status"], "complete");
  EXPECT_EQ(meta["engine"], "liggghts");
  EXPECT_GT(meta["particle_steps"].get<double>(), 15000.0 * 13750);  // > 15,000 pieces, 11 s at 8e-4 s

  const auto r = read_json(out / "report.json");
  EXPECT_EQ(r["fluid_model"], "both");
  EXPECT_TRUE(r["complete"].get<bool>());
  EXPECT_TRUE(r["notes"].empty()) << r["notes"].dump(2);
  EXPECT_TRUE(r["resistance_model_N"]["blocking"]["plateau_found"].get<bool>());
  EXPECT_FALSE(r["resistance_model_N"]["window_halves"]["drifts"].get<bool>())
      << r["resistance_model_N"]["window_halves"].dump();
  EXPECT_TRUE(r["reference"].is_null()) << r["reference"].dump();
  EXPECT_EQ(brash_read(out / "report.md").find("Published reference"), std::string::npos);

  for (const char* k : {"engine", "fluid_model", "window_s", "resistance_model_N", "lambda", "resistance_full_kN",
                        "fsicr", "ratio_fsicr_to_sim", "wall_time_s", "particle_steps"})
    EXPECT_TRUE(r.contains(k)) << k;
  for (const char* k : {"mean", "ci95", "x", "y", "z"}) EXPECT_TRUE(r["resistance_model_N"].contains(k)) << k;
  // The bow (stem at x = -0.2 m at t = 0, 0.482 m/s) is in the ice from 0.41 s: over the window [5.5, 11] s
  // the ice resists the ship (positive resistance, its CI within 5 % of it) and FSICR gives a finite R_CH.
  EXPECT_GT(r["resistance_model_N"]["mean"].get<double>(), 5.0);
  EXPECT_LT(r["resistance_model_N"]["ci95"].get<double>(), 0.05 * r["resistance_model_N"]["mean"].get<double>());
  EXPECT_DOUBLE_EQ(r["lambda"].get<double>(), 28.5);
  EXPECT_NEAR(r["resistance_full_kN"].get<double>(),
              r["resistance_model_N"]["mean"].get<double>() * 28.5 * 28.5 * 28.5 / 1000, 1e-6);
  EXPECT_GT(r["fsicr"]["R_CH_kN"].get<double>(), 100.0);
  // Behaviour kept: the report gives the resistance of make run's reference run (evidence/quick-liggghts-both,
  // same case, same ranks) to the printed digit, model and full scale, and the same FSICR R_CH.
  const auto ref = read_json(fs::path(BRASH_SOURCE_DIR) / "evidence/quick-liggghts-both/report.json");
  const auto printed4 = [](double v) { return std::to_string(std::lround(v * 1e4)); };  // "17.0433 ± 0.2867 N"
  EXPECT_EQ(printed4(r["resistance_model_N"]["mean"]), printed4(ref["resistance_model_N"]["mean"]));
  EXPECT_EQ(printed4(r["resistance_model_N"]["ci95"]), printed4(ref["resistance_model_N"]["ci95"]));
  EXPECT_EQ(std::lround(r["resistance_full_kN"].get<double>() * 10), std::lround(ref["resistance_full_kN"].get<double>() * 10));
  EXPECT_EQ(std::lround(r["fsicr"]["R_CH_kN"].get<double>() * 10), std::lround(ref["fsicr"]["R_CH_kN"].get<double>() * 10));
  // The ice stays within the contact band (hull.band_m) in the snapshots: nothing passes under it.
  ASSERT_TRUE(r.contains("contact_band"));
  EXPECT_TRUE(r["contact_band"]["ok"].get<bool>()) << r["contact_band"].dump();

  // ParaView files of the real run: the .pvd collection and its last particle file read back by meshio
  // (Debian's python3-meshio) with every field.
  ASSERT_TRUE(fs::exists(out / "particles.pvd"));
  ASSERT_TRUE(fs::exists(out / "hull.pvd"));
  fs::path last_vtu;
  for (const auto& e : fs::directory_iterator(out / "paraview"))
    if (e.path().filename().string().rfind("particles_", 0) == 0 && e.path().string() > last_vtu.string())
      last_vtu = e.path();
  ASSERT_FALSE(last_vtu.empty());
  const std::string py = "/usr/bin/python3 -c \"import meshio,sys; m=meshio.read(sys.argv[1]); "
                         "f=set(m.point_data); need={'radius','velocity','submerged_fraction','ca'}; "
                         "assert need<=f, f; assert len(m.points)>15000; "
                         "assert m.point_data['ca'].shape[1]==3\" '" + last_vtu.string() + "'";
  EXPECT_EQ(std::system(py.c_str()), 0) << py;
  // ... and by VTK's own XML reader (Debian's python3-vtk9), through the .pvd collection's last entry.
  const std::string vtk_py =
      "/usr/bin/python3 -c \"import vtk,sys; r=vtk.vtkXMLUnstructuredGridReader(); r.SetFileName(sys.argv[1]); "
      "r.Update(); o=r.GetOutput(); pd=o.GetPointData(); names={pd.GetArrayName(i) for i in "
      "range(pd.GetNumberOfArrays())}; assert {'radius','velocity','submerged_fraction','ca'}<=names, names; "
      "assert o.GetNumberOfPoints()>15000; assert pd.GetArray('ca').GetNumberOfComponents()==3\" '" +
      last_vtu.string() + "'";
  EXPECT_EQ(std::system(vtk_py.c_str()), 0) << vtk_py;
  EXPECT_NE(brash_read(out / "particles.pvd").find(last_vtu.filename().string()), std::string::npos);
  fs::remove_all(root);
}
