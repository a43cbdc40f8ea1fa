// brash-ode's run-time guards (docs/stability.md, "Run-time guards") on the YADE smoke case (720 spheres of
// 35 mm ice at the JBC bow, the contact hull a waterline band): each guard stops the run with
// "guard: step N (t = T s): piece ID: cause" on stderr and as meta.json's reason, status "failed", and the
// outputs up to the stop readable; a normal run trips none of them. Also what a run starts from or refuses: the case
// keys only LIGGGHTS carries out, the settled bed, another run's particle dump (bench-ode --scene-from).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <fmt/format.h>

#include <iomanip>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "brash/case.hpp"
#include "../run/idle_pieces.hpp"
#include "brash/core/params.hpp"
#include "brash/packing.hpp"
#include "brash/run/settle.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kRoot = fs::temp_directory_path() / ("brash_ode_guard_" + std::to_string(::getpid()));

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A copy of the smoke case in kRoot/name with `edit` applied to case.yaml and extra packing rows appended.
fs::path make_case(const std::string& name, const std::string& yaml_from, const std::string& yaml_to,
                   const std::string& extra_rows) {
  const fs::path dir = kRoot / name / "case";
  fs::create_directories(dir);
  for (const char* f : {"case.yaml", "packing.csv", "packing.json"})
    fs::copy_file(fs::path(BRASH_SMOKE_CASE) / f, dir / f, fs::copy_options::overwrite_existing);
  std::string yaml = slurp(dir / "case.yaml");
  if (!yaml_from.empty()) {
    const auto at = yaml.find(yaml_from);
    EXPECT_NE(at, std::string::npos) << yaml_from;
    if (at != std::string::npos) yaml.replace(at, yaml_from.size(), yaml_to);
  }
  std::ofstream(dir / "case.yaml") << yaml;
  std::ofstream(dir / "packing.csv", std::ios::app) << extra_rows;
  return dir;
}

struct Result {
  int exit_code;
  std::string err, meta;
  fs::path run;
};

// brash-ode on case_dir with the extra options, into the run folder `name` beside the case.
Result run(const fs::path& case_dir, const std::string& duration, const std::string& extra = "",
           const std::string& name = "run") {
  const fs::path out = case_dir.parent_path() / name;
  const fs::path err = case_dir.parent_path() / (name == "run" ? "stderr.txt" : name + "_stderr.txt");
  const std::string cmd = std::string("'") + BRASH_ODE_EXE + "' '" + case_dir.string() + "' --out '" +
                          out.string() + "' --duration " + duration + " --no-progress --no-post " + extra +
                          " > /dev/null 2> '" + err.string() + "'";
  const int st = std::system(cmd.c_str());
  return {WIFEXITED(st) ? WEXITSTATUS(st) : -1, slurp(err), slurp(out / "meta.json"), out};
}

// The stop names the step (returned; -1 if missing), the piece and the cause, on stderr and in meta.json;
// the outputs stay readable.
long expect_stop(const Result& r, const std::string& piece, const std::string& cause) {
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.meta.find("\"status\": \"failed\""), std::string::npos) << r.meta;
  const std::regex re("guard: step ([0-9]+) \\(t = ([0-9.e-]+) s\\): piece " + piece + ": " + cause);
  std::smatch m;
  EXPECT_TRUE(std::regex_search(r.err, re)) << r.err;
  EXPECT_TRUE(std::regex_search(r.meta, m, re)) << r.meta;
  EXPECT_EQ(slurp(r.run / "hull_force.csv").rfind("t_s,fx_N,fy_N,fz_N", 0), 0u);
  EXPECT_NE(slurp(r.run / "log.txt").find("error: guard: step"), std::string::npos);
  return m.size() > 1 ? std::stol(m[1]) : -1;  // the step
}

class OdeGuard : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { fs::remove_all(kRoot); }
  static void TearDownTestSuite() { fs::remove_all(kRoot); }
};

}  // namespace

TEST_F(OdeGuard, NormalRunTripsNoGuard) {
  const auto r = run(make_case("normal", "", "", ""), "0.2");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.meta.find("\"status\": \"complete\""), std::string::npos);
  EXPECT_NE(slurp(r.run / "log.txt").find("hull penetration > 0.5 d (full closed hull"), std::string::npos);
}

TEST_F(OdeGuard, PieceSlippingUnderTheBandIsCaughtInsideTheFullHull) {
  // A piece 30 cm down, 13.5 cm into the channel (as in tests/yade/guard_stop.py): below the contact band (down to
  // 15 cm), so the band never touches it; the bulb sweeps over it and its centre ends up inside the full hull.
  const auto r = run(make_case("under_band", "", "", "721,0.135,0,-0.3,0.035\n"), "0.4");
  const long step = expect_stop(r, "721",
                                R"(hull penetration: 0\.0[0-9]+ m = [0-9]+ % of its diameter 0\.035 m > )"
                                R"(max_hull_penetration_d 0\.5 \(centre inside the hull)");
  EXPECT_GT(step, 0);
  EXPECT_EQ(step % 10, 0);  // guards.every_steps
}

TEST_F(OdeGuard, HullOverlapAboveTheCaseThreshold) {
  // guards.max_hull_penetration_d = 1e-4: the first real contact of the bow with the ice is too deep. The
  // hull starts 12 cm further back than in the smoke case, clear of the ice (there the stem already touches a
  // piece at t = 0, by 17 % of its diameter).
  const auto dir =
      make_case("threshold", "run:", "guards:\n  max_hull_penetration_d: 1.0e-4\n  every_steps: 2\nrun:", "");
  std::string yaml = slurp(dir / "case.yaml");
  yaml.replace(yaml.find("start_x_m: -7.03"), 16, "start_x_m: -7.15");
  std::ofstream(dir / "case.yaml") << yaml;
  const long step = expect_stop(run(dir, "0.3"), "[0-9]+",
                                R"(hull penetration: [0-9.e-]+ m = [0-9]+ % of its diameter 0\.0[0-9]+ m > )"
                                R"(max_hull_penetration_d 0\.0001 \(centre outside the hull)");
  EXPECT_EQ(step % 2, 0);
  EXPECT_GT(step, 0);
}

#ifdef BRASH_POST_EXE
// A run that ends before the bow reaches the ice (the hull 12 cm further back than in the smoke case, 0.05 s): the
// record holds only zero forces, and brash-post says the hull met no ice instead of a resistance of 0 +- 0 N.
TEST_F(OdeGuard, RunEndingBeforeTheBowReachesTheIceMetNoIce) {
  const auto dir = make_case("met_no_ice", "start_x_m: -7.03", "start_x_m: -7.15", "");
  const Result r = run(dir, "0.05");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path log = dir.parent_path() / "post.log";
  const std::string post = std::string("'") + BRASH_POST_EXE + "' '" + r.run.string() +
                           "' --no-plots --no-paraview > '" + log.string() + "' 2>&1";
  ASSERT_EQ(std::system(post.c_str()), 0) << slurp(log);
  const auto report = nlohmann::json::parse(slurp(r.run / "report.json"), nullptr, false);
  ASSERT_TRUE(report.is_object()) << slurp(log);
  EXPECT_EQ(report.value("met_no_ice", false), true) << report.dump(2);
  EXPECT_TRUE(report["resistance_model_N"].is_null()) << report.dump(2);
  EXPECT_NE(slurp(log).find("the hull met no ice in the window"), std::string::npos) << slurp(log);
}
#endif

TEST_F(OdeGuard, RunawayKineticEnergy) {
  // Explicit added mass with the text's Ca_z = 2 on reversal: m_a / m = 2.2 > 1 diverges (docs/stability.md);
  // ke_max is the largest piece (40.25 mm) at 5 m/s.
  const auto e = make_case("ke", "treatment: implicit", "treatment: explicit", "");
  std::string yaml = slurp(e / "case.yaml");
  yaml.replace(yaml.find("ca_table: table1"), 16, "ca_table: text");
  std::ofstream(e / "case.yaml") << yaml;
  const long step =
      expect_stop(run(e, "0.2"), "[0-9]+", R"(runaway kinetic energy: [0-9.e+]+ J > ke_max = 1\.428 J)");
  EXPECT_GT(step, 0);
}

// A piece the domain or zmax guard would stop at step 0, or one beyond the channel's end that would leave the
// scene at once, cannot be the case's ice: brash-ode refuses the packing naming its file and line (row 721 is
// line 723) before it makes the run directory (brash::read_case_packing, shared by every runner).
TEST_F(OdeGuard, PieceOutsideTheChannelOrTheWaterIsRefusedBeforeTheRun) {
  const struct {
    const char *name, *row, *problem;
  } bad[] = {
      {"box", "721,0.1,0,-0.6,0.035", "is far below the water: its centre is 0.6 m below water.level_m = 0 m"},
      {"zmax", "721,0.1,0,0.4,0.035", "is far above the water: its bottom is 0.3825 m above water.level_m = 0 m"},
      {"exit", "721,1.2,0,0,0.035", "lies outside the channel [0, 0.2] x [-0.8, 0.8] m: x + d/2 = 1.2175 m"},
  };
  for (const auto& b : bad) {
    const auto r = run(make_case(b.name, "", "", std::string(b.row) + "\n"), "0.1");
    EXPECT_EQ(r.exit_code, 2) << b.name << ": " << r.err;
    EXPECT_NE(r.err.find("packing.csv:723: piece id 721 "), std::string::npos) << b.name << ": " << r.err;
    EXPECT_NE(r.err.find(b.problem), std::string::npos) << b.name << ": " << r.err;
    EXPECT_FALSE(fs::exists(r.run)) << b.name << ": a run directory was written";
  }
}

// fluid.hull_flow on brash-ode (the same thin-ship flow as on LIGGGHTS): a drag run with it completes and
// says so in its log; with model added_mass (no drag for the flow to act through) the case is refused by
// name.
TEST_F(OdeGuard, HullFlowRunsWithDragAndIsRefusedWithAddedMass) {
  const auto r =
      run(make_case("hull_flow", "model: added_mass", "model: drag\n  hull_flow: thin_ship", ""), "0.1");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.meta.find("\"status\": \"complete\""), std::string::npos) << r.meta;
  const std::string log = slurp(r.run / "log.txt");
  EXPECT_NE(log.find("hull flow thin_ship: "), std::string::npos) << log;
  EXPECT_NE(slurp(r.run / "case.yaml").find("hull_flow: thin_ship"), std::string::npos);

  const auto am =
      run(make_case("hull_flow_am", "treatment: implicit", "treatment: implicit\n  hull_flow: thin_ship", ""),
          "0.1");
  EXPECT_NE(am.exit_code, 0);
  EXPECT_NE(am.err.find("fluid.hull_flow"), std::string::npos) << am.err;
  EXPECT_NE(am.err.find("added_mass"), std::string::npos) << am.err;
}

// Keys only LIGGGHTS carries out are refused by name before any output, not run as the whole channel with
// every piece awake: the half channel and the moving window.
TEST_F(OdeGuard, KeysOnlyLiggghtsCarriesOutAreRefusedByName) {
  const struct {
    const char* name;
    const char* from;
    const char* to;
    const char* key;
  } cases[] = {{"symmetry", "\nrun:\n", "\nspeedups:\n  symmetry_y: true\nrun:\n", "speedups.symmetry_y: true"},
               // (the moving window needs the settled bed, which brash-ode runs: only the window is named)
               {"window", "\nice:\n", "\nspeedups:\n  moving_window: true\nice:\n  settle: true\n",
                "speedups.moving_window: true"}};
  for (const auto& c : cases) {
    const auto r = run(make_case(std::string("refused_") + c.name, c.from, c.to, ""), "0.1");
    EXPECT_EQ(r.exit_code, 2) << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(c.key), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("brash-liggghts-run"), std::string::npos) << r.err;
    // and says how to run the case here
    EXPECT_NE(r.err.find("brash-case derive"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(std::string("--set ") + std::string(c.key).substr(0, std::string(c.key).find(':')) + "=false"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(r.run / "meta.json")) << c.name;  // refused before any output
  }
  // switches together: one message names both refused keys and the one copy to run; the settled bed and the far
  // field are kept
  const auto r = run(make_case("refused_both", "\nice:\n",
                               "\nspeedups:\n  symmetry_y: true\n  farfield: true\n  moving_window: true\nice:\n"
                               "  settle: true\n",
                               ""),
                     "0.1");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--set speedups.symmetry_y=false --set speedups.moving_window=false --out DIR"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("ice.settle"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("speedups.farfield"), std::string::npos) << r.err;
  // the paper case's form (moving window, far field woken by neighbour speed): one message, one copy to run
  const auto paper = run(make_case("refused_paper", "\nice:\n",
                                   "\nspeedups:\n  farfield: true\n  farfield_ahead_m: 0.3\n"
                                   "  farfield_wake_by: neighbour_speed\n  moving_window: true\nice:\n  settle: true\n",
                                   ""),
                         "0.1");
  EXPECT_EQ(paper.exit_code, 2) << paper.err;
  EXPECT_NE(paper.err.find("--set speedups.moving_window=false --set speedups.farfield_wake_by=force --out DIR"),
            std::string::npos)
      << paper.err;
  EXPECT_FALSE(fs::exists(paper.run / "meta.json"));
}

// The settled bed (ice.settle) runs on ODE with a contact surface layer as deep as its largest overlap (deeper
// with a larger ode.surface_layer_m), named in the log and meta.json; the packing runs with none. The bed here is the
// smoke packing drawn 0.5 % closer to its centroid, written where the run looks for the cached settled bed.
TEST_F(OdeGuard, SettledBedRunsWithASurfaceLayerAsDeepAsItsLargestOverlap) {
  const fs::path dir = make_case("settled", "\nice:\n", "\nice:\n  settle: true\n", "");
  const brash::Case c = brash::load_case(dir / "case.yaml");
  const auto rows = brash::read_packing_csv(c.ice.packing_file);
  brash::core::Vec3 centroid = brash::core::Vec3::Zero();
  for (const auto& p : rows) centroid += brash::core::Vec3(p.x_m, p.y_m, p.z_m) / double(rows.size());
  std::vector<brash::core::Vec3> x;
  for (const auto& p : rows) x.push_back(centroid + 0.995 * (brash::core::Vec3(p.x_m, p.y_m, p.z_m) - centroid));
  double largest = 0;
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t j = i + 1; j < rows.size(); ++j)
      largest = std::max(largest, 0.5 * (rows[i].diameter_m + rows[j].diameter_m) - (x[i] - x[j]).norm());
  ASSERT_GT(largest, 1e-3 * c.ice.diameter_mean_m);
  {
    std::ofstream bed(brash::settled_packing_file(c));
    bed << "# a settled bed for the test\nid,x,y,z,diameter\n" << std::setprecision(17);
    for (std::size_t i = 0; i < rows.size(); ++i)
      bed << i + 1 << "," << x[i].x() << "," << x[i].y() << "," << x[i].z() << "," << rows[i].diameter_m << "\n";
  }
  const auto layer_in = [](const std::string& meta) {
    const auto j = nlohmann::json::parse(meta, nullptr, false);
    return j.is_object() ? j["stepper"].value("contact_surface_layer_m", -1.0) : -1.0;
  };
  const auto settled = run(dir, "0.02");
  ASSERT_EQ(settled.exit_code, 0) << settled.err;
  EXPECT_NEAR(layer_in(settled.meta), largest, 1e-12);
  EXPECT_NE(slurp(settled.run / "log.txt").find("settled bed: contact surface layer"), std::string::npos);
  const auto packing = run(make_case("packing", "", "", ""), "0.02");
  ASSERT_EQ(packing.exit_code, 0) << packing.err;
  EXPECT_EQ(layer_in(packing.meta), 0.0);
}

// The case's far field (speedups.farfield: true) is brash-ode's cull with the case's window (ahead, behind, beside),
// membership period (farfield_every_steps DEM steps in ODE steps) and wake; --set on the command line changes the
// case, and the run folder's case.yaml records it. The neighbour-speed wake is refused (biased on rigid contacts),
// naming the key and the copy to run.
TEST_F(OdeGuard, CaseFarFieldIsTheCullWithTheCasesWindow) {
  const fs::path dir = make_case("farfield", "\nrun:\n",
                                 "\nspeedups:\n  farfield: true\n  farfield_ahead_m: 0.3\n  farfield_behind_m: 0.7\n"
                                 "  farfield_beside_m: 0.1\n  farfield_every_steps: 100\n"
                                 "  farfield_wake_by: force\nrun:\n",
                                 "");
  const auto skips = [&](const std::string& name, const std::string& extra) {
    const Result r = run(dir, "0.02", "--dt 5e-4 " + extra, name);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const auto meta = nlohmann::json::parse(r.meta, nullptr, false);
    return meta.is_object() ? meta["skips"] : nlohmann::json();
  };
  const auto k = skips("case", "");
  EXPECT_EQ(k.value("cull", false), true) << k;
  EXPECT_DOUBLE_EQ(k.value("cull_ahead_m", -1.0), 0.3);
  EXPECT_DOUBLE_EQ(k.value("cull_behind_m", -1.0), 0.7);
  EXPECT_DOUBLE_EQ(k.value("cull_side_m", -1.0), 0.1);
  EXPECT_EQ(k.value("cull_every_steps", -1), 20);  // 100 steps of 1e-4 s = 0.01 s = 20 steps of 5e-4 s
  EXPECT_EQ(k.value("cull_wake_by", std::string()), "force");
  const auto given = skips("given", "--set speedups.farfield_ahead_m=0.5 --set speedups.farfield_beside_m=0.2");
  EXPECT_DOUBLE_EQ(given.value("cull_ahead_m", -1.0), 0.5);
  EXPECT_DOUBLE_EQ(given.value("cull_behind_m", -1.0), 0.7);
  EXPECT_DOUBLE_EQ(given.value("cull_side_m", -1.0), 0.2);
  const std::string given_yaml = slurp(dir.parent_path() / "given" / "case.yaml");
  EXPECT_NE(given_yaml.find("\n  farfield_ahead_m: 0.5\n"), std::string::npos) << given_yaml;
  EXPECT_NE(given_yaml.find("\n  farfield_beside_m: 0.2\n"), std::string::npos) << given_yaml;
  std::string yaml = slurp(dir / "case.yaml");
  yaml.replace(yaml.find("farfield_wake_by: force"), 23, "farfield_wake_by: neighbour_speed");
  std::ofstream(dir / "case.yaml") << yaml;
  const Result neighbour = run(dir, "0.02", "", "neighbour");
  EXPECT_EQ(neighbour.exit_code, 2);
  EXPECT_NE(neighbour.err.find("speedups.farfield_wake_by: neighbour_speed"), std::string::npos) << neighbour.err;
  EXPECT_NE(neighbour.err.find("--set speedups.farfield_wake_by=force"), std::string::npos) << neighbour.err;
  EXPECT_FALSE(fs::exists(neighbour.run / "meta.json"));
  // the push front runs with the case's front speed, and the log names it
  yaml.replace(yaml.find("farfield_wake_by: neighbour_speed"), 33, "farfield_wake_by: push_front");
  std::ofstream(dir / "case.yaml") << yaml;
  const Result front = run(dir, "0.02", "--dt 5e-4", "push_front");
  EXPECT_EQ(front.exit_code, 0) << front.err;
  const auto meta = nlohmann::json::parse(front.meta, nullptr, false);
  ASSERT_TRUE(meta.is_object()) << front.meta;
  EXPECT_EQ(meta["skips"].value("cull_wake_by", std::string()), "push_front") << front.meta;
  EXPECT_DOUBLE_EQ(meta["skips"].value("cull_front_speed_m_s", -1.0), 0.005) << front.meta;
  const std::string log = slurp(front.run / "log.txt");
  EXPECT_NE(log.find("the front 0.3 m ahead of the foremost piece moving ahead faster than 0.005 m/s"),
            std::string::npos)
      << log;
}

// The far field's idle pieces float at rest: the particle files give their real submerged fraction (the core's
// immersion of their position), no Ca and active = 0; the integrated ones active = 1. The hull 12 cm further back
// than in the smoke case, the push front 0.07 m ahead of its bow: the bed beyond is idle from the start.
TEST_F(OdeGuard, IdleFarFieldPiecesAreExportedFloatingAndInactive) {
  const fs::path dir = make_case("farfield_export", "\nrun:\n",
                                 "\nspeedups:\n  farfield: true\n  farfield_ahead_m: 0.07\n"
                                 "  farfield_wake_by: push_front\nrun:\n",
                                 "");
  std::string yaml = slurp(dir / "case.yaml");
  yaml.replace(yaml.find("start_x_m: -7.03"), 16, "start_x_m: -7.15");
  std::ofstream(dir / "case.yaml") << yaml;
  const Result r = run(dir, "0.02", "--dt 5e-4", "export");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  brash::test::expect_idle_pieces_afloat(slurp(r.run / "particles" / "particles_40.csv"));
}

// bench-ode --scene-from starts from another run's particle dump (its pieces, with their velocities) with the hull
// where it was at --scene-time, and goes on from there to --duration; of a moving window's snapshot the removed
// pieces are left out, the held-out ones kept; a dump without a needed column is refused naming the file and the
// column.
TEST_F(OdeGuard, SceneFromADumpStartsWithItsPiecesAndTheHullWhereItWas) {
  const fs::path dir = make_case("scene", "", "", "");
  const brash::Case c = brash::load_case(dir / "case.yaml");
  const auto rows = brash::read_packing_csv(c.ice.packing_file);
  const fs::path dump = dir.parent_path() / "particles_0000001000.csv";
  {
    std::ofstream out(dump);
    out << "id,x,y,z,radius,vx,vy,vz,submerged_fraction\n" << std::setprecision(17);
    // 20 fewer pieces than the packing, where the hull finds them after 0.5 s
    for (std::size_t i = 0; i + 20 < rows.size(); ++i)
      out << i + 1 << "," << rows[i].x_m + 0.5 * c.ship.speed_m_s << "," << rows[i].y_m << "," << rows[i].z_m << "," << 0.5 * rows[i].diameter_m
          << ",0.01,0,0,1\n";
  }
  const fs::path out = dir.parent_path() / "run", err = dir.parent_path() / "stderr.txt";
  const auto bench = [&](const fs::path& file) {
    const std::string cmd = std::string("'") + BRASH_BENCH_ODE_EXE + "' '" + dir.string() + "' --scene-from '" +
                            file.string() + "' --scene-time 0.5 --duration 0.52 --set 'run.window_s=[0.5, 0.52]' --out '" + out.string() +
                            "' > /dev/null 2> '" + err.string() + "'";
    const int st = std::system(cmd.c_str());
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  };
  ASSERT_EQ(bench(dump), 0) << slurp(err);
  const std::string log = slurp(out / "log.txt");
  EXPECT_NE(log.find(fmt::format("at t = 0.5 s of its run: {} pieces, hull at x = {:.4g} m", rows.size() - 20,
                                 c.hull.start_x_m + 0.5 * c.ship.speed_m_s)),
            std::string::npos)
      << log;
  // the pieces start with the dump's velocity (0.01 m/s along x): the first dump, at 0.5 s, holds it
  EXPECT_NE(slurp(out / "particles" / "particles_1000.csv").find(",0.01,0,0,"), std::string::npos);
  // a moving window's snapshot holds every piece with its state: the scene is those of state 0 and 1 (held out)
  {
    std::ofstream win(dump);
    win << "id,x,y,z,radius,vx,vy,vz,submerged_fraction,ca_x,ca_y,ca_z,active,state\n" << std::setprecision(17);
    for (std::size_t i = 0; i < rows.size(); ++i)
      win << i + 1 << "," << rows[i].x_m + 0.5 * c.ship.speed_m_s << "," << rows[i].y_m << "," << rows[i].z_m << ","
          << 0.5 * rows[i].diameter_m << ",0.01,0,0,1,0,0,0,1," << (i + 20 < rows.size() ? 0 : 1 + i % 2) << "\n";
  }
  fs::remove_all(out);
  ASSERT_EQ(bench(dump), 0) << slurp(err);
  EXPECT_NE(slurp(out / "log.txt").find(fmt::format("at t = 0.5 s of its run: {} pieces,", rows.size() - 10)),
            std::string::npos)
      << slurp(out / "log.txt");
  std::ofstream(dump) << "id,x,y,z,diameter\n1,0,0,0,0.035\n";
  EXPECT_EQ(bench(dump), 2);  // an input error, before any output
  EXPECT_NE(slurp(err).find(dump.string() + ":1: no column \"radius\""), std::string::npos) << slurp(err);
}

// The progress line names the model time to the case's step (here 4 decimals), the wall time and the contacts:
// bench/ode_paper_scene.sh reads seconds per step off these lines.
TEST_F(OdeGuard, ProgressLineGivesTheModelTimeToTheStep) {
  const fs::path dir = make_case("progress", "", "", "");
  const fs::path out = dir.parent_path() / "run", err = dir.parent_path() / "stderr.txt";
  const std::string cmd = std::string("'") + BRASH_ODE_EXE + "' '" + dir.string() + "' --out '" + out.string() +
                          "' --duration 0.05 --no-post > /dev/null 2> '" + err.string() + "'";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const std::string text = slurp(err);
  const std::regex line(R"(t = 0\.[0-9]{4} / 0\.05 s \( *[0-9]+%\)  elapsed [0-9]+ s  ETA [0-9]+ s  Fx [-+0-9.]+ N  awake [0-9]+  contacts [0-9]+)");
  EXPECT_TRUE(std::regex_search(text, line)) << text;
}
