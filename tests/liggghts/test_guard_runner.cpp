// brash-liggghts-run with the run-time guards (docs/stability.md, "Run-time guards") on a small case: the
// quick case narrowed and shortened (the JBC bow enters a 0.8 m channel of 35 mm ice; the contact hull is the
// case's waterline band, the guard's the full closed hull written as hull_full.stl).
//   - a normal run does not trip any guard, the hull guard included;
//   - with guards.max_hull_penetration_d tiny, the first real hull contact stops the run: the message names
//   the
//     step, the atom and the cause, meta.json says failed with it, hull_force.csv and particles/ stay
//     readable.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <sys/wait.h>
#include <string>
#include <vector>

#include "../run/idle_pieces.hpp"
#include "runner_case.h"

namespace fs = std::filesystem;

namespace {

void write_small_case(const fs::path& case_dir, const std::string& duration, const std::string& extra) {
  brash::test::write_small_quick_case(case_dir, {.duration_s = duration,
                                                 .window_s = "[0.0, " + duration + "]",
                                                 .output_interval_s = "0.01",
                                                 .dump_interval_s = "0.05",
                                                 .fluid_model = "",
                                                 .extra = extra});
}

// Rewrites case_dir/case.yaml with `pattern` replaced (ECMAScript regex, $1 for a group); the pattern must match.
void edit_case(const fs::path& case_dir, const std::string& pattern, const std::string& replacement) {
  const std::string yaml = brash::test::read_text(case_dir / "case.yaml");
  ASSERT_TRUE(std::regex_search(yaml, std::regex(pattern))) << pattern << " not in\n" << yaml;
  std::ofstream(case_dir / "case.yaml") << std::regex_replace(yaml, std::regex(pattern), replacement);
}

int run_case(const fs::path& dir) {
  return brash::test::run_runner(dir / "case", dir / "run", dir / "run.log");
}

}  // namespace

TEST(LiggghtsGuardRunner, NormalRunDoesNotTripTheHullGuard) {
  const fs::path dir = brash::test::fresh_dir("guard_normal");
  write_small_case(dir / "case", "0.3", "");
  EXPECT_EQ(run_case(dir), 0) << brash::test::read_text(dir / "run.log");
  const std::string in = brash::test::read_text(dir / "run/in.lmp");
  EXPECT_NE(in.find(" hull hull_full.stl -7.05 0 -0.4125 0.482 0 0 max_penetration 0.5\n"), std::string::npos)
      << in;
  EXPECT_TRUE(fs::exists(dir / "run/hull_full.stl"));
  EXPECT_NE(brash::test::read_text(dir / "run/meta.json").find("\"complete\""), std::string::npos);
  // The bow did push ice: there was hull contact for the guard to look at.
  const auto log = brash::test::read_text(dir / "run/log.txt");
  EXPECT_EQ(log.find("ERROR"), std::string::npos);
  fs::remove_all(dir);
}

TEST(LiggghtsGuardRunner, HullPenetrationStopsTheRunWithAClearMessage) {
  const fs::path dir = brash::test::fresh_dir("guard_stop");
  // 1e-4 d = 3.5 micrometres: any Hertz contact with the hull is deeper than that.
  write_small_case(dir / "case", "0.3", "guards:\n  max_hull_penetration_d: 1.0e-4\n  every_steps: 5\n");
  EXPECT_NE(run_case(dir), 0);
  const std::string meta = brash::test::read_text(dir / "run/meta.json");
  EXPECT_NE(meta.find("\"status\": \"failed\""), std::string::npos) << meta;
  const std::regex re(
      R"("reason": "ERROR: fix brash/guard: step ([0-9]+): atom [0-9]+: hull penetration: [0-9.e-]+ m = [0-9]+ % of its )"
      R"(diameter [0-9.]+ m > max_hull_penetration_d 0.0001 \(centre outside the hull; hull frame x = )");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(meta, m, re)) << meta;
  const long step = std::stol(m[1]);
  EXPECT_GT(step, 0);
  EXPECT_EQ(step % 5, 0);
  // Outputs up to the stop: hull force rows until its time, the snapshot index readable.
  const std::string csv = brash::test::read_text(dir / "run/hull_force.csv");
  ASSERT_EQ(csv.rfind("t_s,fx_N,fy_N,fz_N", 0), 0u);
  EXPECT_GT(std::count(csv.begin(), csv.end(), '\n'), 1);
  EXPECT_TRUE(fs::exists(dir / "run/particles/index.csv"));
  EXPECT_NE(brash::test::read_text(dir / "run.log").find("hull penetration"), std::string::npos);
  fs::remove_all(dir);
}

// LIGGGHTS refuses E < 5 MPa in SI units unless the script says `soft_particles yes`: the runner writes it
// for soft cases, so a case the loader accepts also runs (found by bench/stability_engines.sh: E 1.25 MPa
// crashed).
TEST(LiggghtsGuardRunner, SoftIceBelowFiveMegapascalRuns) {
  const fs::path dir = brash::test::fresh_dir("soft_ice");
  write_small_case(dir / "case", "0.02", "");
  edit_case(dir / "case", "\n  youngs_modulus_pa:[^\n]*", "\n  youngs_modulus_pa: 1.25e6");
  EXPECT_EQ(run_case(dir), 0) << brash::test::read_text(dir / "run.log");
  EXPECT_NE(brash::test::read_text(dir / "run/in.lmp").find("\nsoft_particles yes\n"), std::string::npos);
  EXPECT_NE(brash::test::read_text(dir / "run/meta.json").find("\"complete\""), std::string::npos);
  fs::remove_all(dir);
}

// A run whose window ends before the bow reaches the ice (the hull 0.25 m further back than in the small case, its
// bulb 0.1 m outside the ice, 0.2 s away): the record holds only zero forces, and brash-post says the hull met no
// ice instead of a resistance of 0 +- 0 N.
TEST(LiggghtsGuardRunner, WindowBeforeTheBowReachesTheIceMetNoIce) {
  const fs::path dir = brash::test::fresh_dir("met_no_ice");
  write_small_case(dir / "case", "0.04", "");
  edit_case(dir / "case", "\n  start_x_m:[^\n]*", "\n  start_x_m: -7.3");
  ASSERT_EQ(run_case(dir), 0) << brash::test::read_text(dir / "run.log");
  const std::string post = std::string("'") + BRASH_BIN_DIR + "/brash-post' '" + (dir / "run").string() +
                           "' --no-plots --no-paraview > '" + (dir / "post.log").string() + "' 2>&1";
  ASSERT_EQ(std::system(post.c_str()), 0) << brash::test::read_text(dir / "post.log");
  const std::string report = brash::test::read_text(dir / "run/report.json");
  EXPECT_NE(report.find("\"met_no_ice\": true"), std::string::npos) << report;
  EXPECT_NE(report.find("\"resistance_model_N\": null"), std::string::npos) << report;
  EXPECT_NE(brash::test::read_text(dir / "post.log").find("the hull met no ice in the window"), std::string::npos)
      << brash::test::read_text(dir / "post.log");
  fs::remove_all(dir);
}

// The far field's idle pieces float at rest: the particle files give their real submerged fraction (the core's
// immersion of their position), no Ca and active = 0; the integrated ones active = 1.
TEST(LiggghtsGuardRunner, IdleFarFieldPiecesAreExportedFloatingAndInactive) {
  const fs::path dir = brash::test::fresh_dir("farfield_export");
  write_small_case(dir / "case", "0.05",
                   "speedups:\n  farfield: true\n  farfield_ahead_m: 0.1\n  farfield_every_steps: 100\n");
  ASSERT_EQ(run_case(dir), 0) << brash::test::read_text(dir / "run.log");
  brash::test::expect_idle_pieces_afloat(brash::test::read_text(dir / "run/particles/particles_0000000500.csv"));
  fs::remove_all(dir);
}

// channel.ends: walls puts the channel's end walls into the scene (primitive planes at x = 0 and x = length, of
// the walls' material); the bow enters through the one at x = 0 (a mesh is not a particle) and the run completes.
TEST(LiggghtsGuardRunner, WalledChannelEndsAreInTheSceneAndTheHullPassesThem) {
  const fs::path dir = brash::test::fresh_dir("walled_ends");
  write_small_case(dir / "case", "0.3", "");
  const std::string yaml = brash::test::read_text(dir / "case/case.yaml");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(yaml, m, std::regex("\n  length_m: ([^ \n]*)"))) << yaml;
  const std::string length_m = m[1].str();
  edit_case(dir / "case", "\n  width_m:([^\n]*)", "\n  width_m:$1\n  ends: walls");
  EXPECT_EQ(run_case(dir), 0) << brash::test::read_text(dir / "run.log");
  const std::string in = brash::test::read_text(dir / "run/in.lmp");
  EXPECT_NE(in.find("primitive type 3 xplane 0\n"), std::string::npos) << in;
  EXPECT_NE(in.find("primitive type 3 xplane " + length_m + "\n"), std::string::npos) << in;
  EXPECT_NE(brash::test::read_text(dir / "run/meta.json").find("\"complete\""), std::string::npos);
  EXPECT_NE(brash::test::read_text(dir / "run/case.yaml").find("ends: walls"), std::string::npos);
  // an open channel has none
  write_small_case(dir / "open", "0.02", "");
  EXPECT_EQ(brash::test::run_runner(dir / "open", dir / "open_run", dir / "open.log"), 0);
  EXPECT_EQ(brash::test::read_text(dir / "open_run/in.lmp").find("xplane"), std::string::npos);
  fs::remove_all(dir);
}

// ice.settle: the runner starts from the settled bed, made once by brash-settle beside the packing (its rms speed
// below ice.settle_speed_m_s, the same bytes when made again), reused by the next run; ODE starts from it too, with
// a contact surface layer as deep as its largest overlap.
TEST(LiggghtsGuardRunner, SettledBedIsMadeOnceCachedAndStartedFrom) {
  const fs::path dir = brash::test::fresh_dir("settled_bed");
  write_small_case(dir / "case", "0.05", "");
  edit_case(dir / "case", "\nice:", "\nice:\n  settle: true");
  EXPECT_EQ(run_case(dir), 0) << brash::test::read_text(dir / "run.log");
  std::vector<fs::path> settled;
  for (const auto& e : fs::directory_iterator(dir / "case/generated"))
    if (e.path().extension() == ".csv" && e.path().filename().string().rfind("settled-", 0) == 0)
      settled.push_back(e.path());
  ASSERT_EQ(settled.size(), 1u);
  const std::string bed = brash::test::read_text(settled[0]);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(bed, m, std::regex("vrms_m_s=([0-9.eE+-]+)"))) << bed.substr(0, 300);
  EXPECT_LT(std::stod(m[1].str()), 1e-3);
  EXPECT_NE(brash::test::read_text(dir / "run.log").find("settling the packing"), std::string::npos);
  // the settling reports each chunk's model time and rms speed while it goes
  EXPECT_NE(brash::test::read_text(dir / "run.log").find("[brash-settle] t = 0.05 s, rms speed"), std::string::npos)
      << brash::test::read_text(dir / "run.log");
  // the run starts from it: its scene's pieces are the settled ones, not the packing's
  const std::string data = brash::test::read_text(dir / "run/packing.data");
  std::smatch first;
  ASSERT_TRUE(std::regex_search(bed, first, std::regex("\n1,([^,]+),")));
  EXPECT_NE(data.find(" " + first[1].str() + " "), std::string::npos);
  // meta.json's stages: the packing and the bed made by this run, with what each cost (the bed's as its header
  // says), the scene's set-up and the run itself (wall_time_s); no report (--no-post)
  const auto meta = nlohmann::json::parse(brash::test::read_text(dir / "run/meta.json"));
  const auto& stages = meta.at("stages");
  EXPECT_TRUE(stages.at("packing").at("made_by_this_run").get<bool>());
  EXPECT_GT(stages.at("packing").at("wall_s").get<double>(), 0);
  EXPECT_TRUE(stages.at("settling").at("made_by_this_run").get<bool>());
  ASSERT_TRUE(std::regex_search(bed, m, std::regex(" wall_s=([0-9.]+) ")));
  EXPECT_GT(std::stod(m[1].str()), 0);
  EXPECT_EQ(stages.at("settling").at("wall_s").get<double>(), std::stod(m[1].str()));
  EXPECT_GE(stages.at("setup_s").get<double>(), 0);
  EXPECT_EQ(stages.at("run_s").get<double>(), meta.at("wall_time_s").get<double>());
  EXPECT_FALSE(stages.contains("post_s"));
  // cached: a second run does not settle again and records what the bed and the packing cost when they were made;
  // with its report, what the report cost
  std::string with_post = brash::test::runner_command(dir / "case", dir / "run2");
  with_post.replace(with_post.find(" --no-post"), 10, "");
  ASSERT_EQ(WEXITSTATUS(std::system((with_post + " > '" + (dir / "run2.log").string() + "' 2>&1").c_str())), 0)
      << brash::test::read_text(dir / "run2.log");
  EXPECT_EQ(brash::test::read_text(dir / "run2.log").find("settling the packing"), std::string::npos);
  const auto stages2 = nlohmann::json::parse(brash::test::read_text(dir / "run2/meta.json")).at("stages");
  EXPECT_FALSE(stages2.at("packing").at("made_by_this_run").get<bool>());
  EXPECT_EQ(stages2.at("packing").at("wall_s"), stages.at("packing").at("wall_s"));
  EXPECT_FALSE(stages2.at("settling").at("made_by_this_run").get<bool>());
  EXPECT_EQ(stages2.at("settling").at("wall_s"), stages.at("settling").at("wall_s"));
  EXPECT_GT(stages2.at("post_s").get<double>(), 0);
  // bench/run_stages.sh prints them stage by stage with each run's total from a new packing and its ratio to the
  // first run's; a run directory without stages is refused by name
  const auto stage_table = [&](const std::string& runs) {
    const std::string cmd = "bash '" + std::string(BRASH_SOURCE_DIR) + "/bench/run_stages.sh' " + runs + " > '" +
                            (dir / "stages.txt").string() + "' 2>&1";
    return WEXITSTATUS(std::system(cmd.c_str()));
  };
  ASSERT_EQ(stage_table("'" + (dir / "run").string() + "' '" + (dir / "run2").string() + "'"), 0);
  const std::string table = brash::test::read_text(dir / "stages.txt");
  EXPECT_TRUE(std::regex_search(table, std::regex(R"(\nrun .* 1\.00x\n)"))) << table;
  EXPECT_TRUE(std::regex_search(table, std::regex(R"(\nrun2 .*\(cached\).*\(cached\).* [0-9.]+x\n)"))) << table;
  fs::create_directories(dir / "old");
  std::ofstream(dir / "old/meta.json") << "{\"status\": \"complete\"}";
  EXPECT_NE(stage_table("'" + (dir / "old").string() + "'"), 0);
  EXPECT_NE(brash::test::read_text(dir / "stages.txt").find("old/meta.json: no \"stages\""), std::string::npos)
      << brash::test::read_text(dir / "stages.txt");
  // made again, the bed is the same to the byte but for the wall time its header records
  fs::remove(settled[0]);
  ASSERT_EQ(brash::test::run_runner(dir / "case", dir / "run3", dir / "run3.log"), 0);
  const auto untimed = [](const std::string& b) { return std::regex_replace(b, std::regex(" wall_s=[0-9.]+ "), " "); };
  EXPECT_EQ(untimed(brash::test::read_text(settled[0])), untimed(bed));
  // ODE starts from the same bed (its first snapshot holds piece 1 where the bed has it), the bed's overlaps within
  // the surface layer
  const std::string ode = std::string(BRASH_BIN_DIR) + "/brash-ode '" + (dir / "case").string() + "' --out '" +
                          (dir / "ode").string() + "' --no-post > '" + (dir / "ode.log").string() + "' 2>&1";
  EXPECT_EQ(WEXITSTATUS(std::system(ode.c_str())), 0) << brash::test::read_text(dir / "ode.log");
  EXPECT_NE(brash::test::read_text(dir / "ode/log.txt").find("settled bed: contact surface layer"), std::string::npos);
  const std::string snapshot = brash::test::read_text(dir / "ode/particles/particles_0.csv");
  std::smatch ode_first;
  ASSERT_TRUE(std::regex_search(snapshot, ode_first, std::regex("\n1,([^,]+),"))) << snapshot.substr(0, 300);
  EXPECT_NEAR(std::stod(ode_first[1].str()), std::stod(first[1].str()), 1e-8);  // (written to 9 digits)
  fs::remove_all(dir);
}

// fluid.hull_flow through the runner: the paper case's template keeps model added_mass, so a hull-flow case
// is run with --model drag (the case's model checks wait for the override); without it the runner refuses,
// naming the key. The fix gets the full hull and the hull's start and speed, and builds its table.
TEST(LiggghtsGuardRunner, HullFlowCaseRunsWithModelDragAndIsRefusedWithAddedMass) {
  const fs::path dir = brash::test::fresh_dir("hull_flow_runner");
  write_small_case(dir / "case", "0.1", "");
  edit_case(dir / "case", "\n  ca_table: table1", "\n  ca_table: table1\n  hull_flow: thin_ship");
  const std::string cmd = brash::test::runner_command(dir / "case", dir / "run");
  // the case's model (both) takes the flow; --model added_mass has no drag for it and is refused
  ASSERT_NE(std::system((cmd + " --model added_mass > '" + (dir / "refused.log").string() + "' 2>&1").c_str()), 0);
  const std::string refused = brash::test::read_text(dir / "refused.log");
  EXPECT_NE(refused.find("fluid.hull_flow"), std::string::npos) << refused;
  EXPECT_NE(refused.find("added_mass has none"), std::string::npos) << refused;
  fs::remove_all(dir / "run");
  ASSERT_EQ(std::system((cmd + " --model drag > '" + (dir / "run.log").string() + "' 2>&1").c_str()), 0)
      << brash::test::read_text(dir / "run.log");
  const std::string in = brash::test::read_text(dir / "run/in.lmp");
  EXPECT_NE(in.find("model drag "), std::string::npos) << in;
  // the runner computes the table once (brash::hull_flow_table) and hands it to fix icefluid
  EXPECT_NE(in.find(" hull_flow hull_flow.bin -7.05 0 -0.4125 0.482\n"), std::string::npos) << in;
  EXPECT_NE(brash::test::read_text(dir / "run/log.txt").find("fix icefluid: hull flow from hull_flow.bin"),
            std::string::npos);
  EXPECT_NE(brash::test::read_text(dir / "run/case.yaml").find("  hull_flow: thin_ship\n"), std::string::npos);
  EXPECT_NE(brash::test::read_text(dir / "run/meta.json").find("\"complete\""), std::string::npos);
  fs::remove_all(dir);
}
