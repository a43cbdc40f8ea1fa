// brash-ode restart / resume on a small scene: the YADE smoke case (720 spheres d 35 mm,
// the JBC bow entering the ice), 0.2 s at dt 5e-4 (400 steps), restart file every 0.04 s (80 steps).
//   - uninterrupted run A;
//   - run B stopped like a kill -9 after step 230 (hidden --crash-after-step: std::_Exit, no cleanup), then
//     `brash-ode --resume B` (from restart 160; the hull_force.csv rows at 0.09 and 0.10 s that were flushed
//     after it are dropped first) -> same hull force rows and final positions as A;
//   - run C killed with a real SIGKILL as soon as its first restart file exists, then resumed -> same as A;
//   - run D stopped after step 230 with its newest restart file truncated -> resume falls back to restart 80;
//   - all restart files broken -> exit 1 naming the files.
// The run binary is BRASH_ODE_EXE; the case folder BRASH_SMOKE_CASE; the hull comes from $BRASH_HULL_DIR.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "brash/stats/early_stop.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kRoot = fs::temp_directory_path() / ("brash_ode_restart_" + std::to_string(::getpid()));

int run(const std::string& cmd) {
  const int st = std::system(cmd.c_str());
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

std::string base_cmd(const fs::path& out) {
  return std::string("'") + BRASH_ODE_EXE + "' '" + BRASH_SMOKE_CASE + "' --out '" + out.string() +
         "' --duration 0.2 --restart-every 0.04 --no-progress --no-post";
}

std::string resume_cmd(const fs::path& dir) {
  return std::string("'") + BRASH_ODE_EXE + "' --resume '" + dir.string() + "' --no-progress --no-post > /dev/null";
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<std::vector<double>> read_csv(const fs::path& p) {
  std::istringstream in(slurp(p));
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> r;
    std::istringstream ls(line);
    std::string cell;
    while (std::getline(ls, cell, ',')) r.push_back(std::stod(cell));
    rows.push_back(r);
  }
  return rows;
}

// Max |a - b| over all cells of columns [c0, c1); expects the same shape.
double max_diff(const fs::path& a, const fs::path& b, std::size_t c0, std::size_t c1) {
  const auto ra = read_csv(a), rb = read_csv(b);
  EXPECT_EQ(ra.size(), rb.size()) << a << " vs " << b;
  double m = 0;
  for (std::size_t i = 0; i < std::min(ra.size(), rb.size()); ++i) {
    EXPECT_EQ(ra[i].size(), rb[i].size());
    EXPECT_EQ(ra[i][0], rb[i][0]) << "row " << i;  // time / id column
    for (std::size_t c = c0; c < std::min({c1, ra[i].size(), rb[i].size()}); ++c) m = std::max(m, std::abs(ra[i][c] - rb[i][c]));
  }
  return m;
}

// A resumed run against the uninterrupted one: the same hull force rows and final particle state, to the
// dumps' printed digits (%.9g, %.6g: 1e-12 m, 1e-7 m/s).
void expect_resumed_matches(const fs::path& uninterrupted, const fs::path& resumed) {
  const fs::path last = fs::path("particles") / "particles_400.csv";
  EXPECT_LE(max_diff(uninterrupted / "hull_force.csv", resumed / "hull_force.csv", 1, 4), 1e-6);
  EXPECT_LE(max_diff(uninterrupted / last, resumed / last, 1, 4), 1e-9);
  EXPECT_LE(max_diff(uninterrupted / last, resumed / last, 5, 8), 1e-6);
}

// The case's far field on the command line: idle beyond 0.08 m ahead of the bow, 0.02 m behind the stern and
// beside the hull's half beam
const std::string kFarFieldBeside =
    " --set speedups.farfield=true --set speedups.farfield_ahead_m=0.08 --set speedups.farfield_behind_m=0.02"
    " --set speedups.farfield_beside_m=0";

// The smoke case with the push front's far field, and the command that runs it with `extra` options
fs::path push_front_case() {
  const fs::path case_dir = kRoot / "push_front_case";
  if (fs::exists(case_dir / "case.yaml")) return case_dir;
  fs::create_directories(case_dir);
  for (const char* f : {"case.yaml", "packing.csv", "packing.json"})
    fs::copy_file(fs::path(BRASH_SMOKE_CASE) / f, case_dir / f, fs::copy_options::overwrite_existing);
  std::ofstream(case_dir / "case.yaml", std::ios::app)
      << "speedups:\n  farfield: true\n  farfield_ahead_m: 0.08\n  farfield_behind_m: 0.02\n"
         "  farfield_beside_m: 0.0\n  farfield_wake_by: push_front\n  farfield_front_speed_m_s: 0.05\n";
  return case_dir;
}

std::string push_front_cmd(const fs::path& out, const std::string& extra = "") {
  return std::string("'") + BRASH_ODE_EXE + "' '" + push_front_case().string() + "' --out '" + out.string() +
         "' --duration 0.2 --restart-every 0.04 --no-progress --no-post" + extra;
}

class Restart : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    fs::remove_all(kRoot);
    fs::create_directories(kRoot);
    ASSERT_EQ(run(base_cmd(kRoot / "A") + " > /dev/null"), 0);
  }
  static void TearDownTestSuite() { fs::remove_all(kRoot); }

  // Same hull force rows and final particle state as the uninterrupted run A.
  // bit_for_bit: resumed from a regular restart file (the orientations were reset there in run A too,
  // World::reset_orientations), the final snapshot is byte-identical to A's.
  static void expect_same_as_a(const fs::path& dir, const std::string& what, bool bit_for_bit = true) {
    const double df = max_diff(kRoot / "A" / "hull_force.csv", dir / "hull_force.csv", 1, 4);
    const double dx = max_diff(kRoot / "A" / "particles" / "particles_400.csv", dir / "particles" / "particles_400.csv", 1, 4);
    const double dv = max_diff(kRoot / "A" / "particles" / "particles_400.csv", dir / "particles" / "particles_400.csv", 5, 8);
    // dx, dv: from the dumps' printed digits (%.9g, %.6g), so 1e-12 m / 1e-7 m/s is the last printed digit.
    std::printf("[%s] max |dF| = %.3g N over 20 rows, max |dx| = %.3g m, max |dv| = %.3g m/s (720 spheres, t = 0.2 s); "
                "hull_force.csv byte-identical: %s\n",
                what.c_str(), df, dx, dv,
                slurp(kRoot / "A" / "hull_force.csv") == slurp(dir / "hull_force.csv") ? "yes" : "no");
    EXPECT_LE(df, 1e-6);   // N (forces are O(1-10) N)
    EXPECT_LE(dx, 1e-9);   // m
    EXPECT_LE(dv, 1e-6);   // m/s
    EXPECT_NE(slurp(dir / "meta.json").find("\"status\": \"complete\""), std::string::npos);
    if (bit_for_bit) {
      EXPECT_EQ(slurp(kRoot / "A" / "particles" / "particles_400.csv"), slurp(dir / "particles" / "particles_400.csv"));
    }
  }
};

TEST_F(Restart, StopAfterStepThenResumeReproducesTheUninterruptedRun) {
  const fs::path b = kRoot / "B";
  ASSERT_EQ(run(base_cmd(b) + " --crash-after-step 230"), 137);
  EXPECT_NE(slurp(b / "meta.json").find("\"status\": \"running\""), std::string::npos);
  EXPECT_TRUE(fs::exists(b / "restart" / "restart_0000000080.bin"));
  EXPECT_TRUE(fs::exists(b / "restart" / "restart_0000000160.bin"));  // the last two are kept
  EXPECT_EQ(read_csv(b / "hull_force.csv").size(), 10u);             // flushed at t = 0.1 s (dump), after restart 160
  ASSERT_EQ(run(resume_cmd(b)), 0);
  const std::string meta = slurp(b / "meta.json");
  EXPECT_NE(meta.find("\"hull_force_rows_dropped\": 2"), std::string::npos) << meta;
  EXPECT_NE(meta.find("restart_0000000160.bin"), std::string::npos);
  expect_same_as_a(b, "stop after step 230, resume from 160");
  // Resuming a complete run does nothing.
  EXPECT_EQ(run(resume_cmd(b)), 0);
}

// SIGTERM (or Ctrl-C) is a handled stop: the step in progress ends, then the run is left resumable at that
// very step (hull_force.csv rows up to it, a restart file of it, meta status "interrupted" as on every engine),
// exit 143 (128 +
// SIGTERM). The resume goes on from there and reproduces the uninterrupted run.
TEST_F(Restart, SigtermStopsAtTheStepAndResumesFromIt) {
  const fs::path s = kRoot / "S";
  ASSERT_EQ(run(base_cmd(s) + " --stop-after-step 230 > /dev/null"), 143);
  const std::string meta = slurp(s / "meta.json");
  EXPECT_NE(meta.find("\"status\": \"interrupted\""), std::string::npos) << meta;
  EXPECT_NE(meta.find("continue with brash-ode --resume " + s.string()), std::string::npos) << meta;
  EXPECT_NE(meta.find("\"steps_done\": 230"), std::string::npos) << meta;
  EXPECT_TRUE(fs::exists(s / "restart" / "restart_0000000230.bin"));  // not only the periodic 160
  EXPECT_EQ(read_csv(s / "hull_force.csv").size(),
            11u);  // the 0.01 s rows to 0.11 s (the rest: in the restart)
  ASSERT_EQ(run(resume_cmd(s)), 0);
  const std::string resumed = slurp(s / "meta.json");
  EXPECT_NE(resumed.find("restart_0000000230.bin"), std::string::npos) << resumed;
  EXPECT_NE(resumed.find("\"hull_force_rows_dropped\": 0"), std::string::npos) << resumed;
  // the restart written at the signal is not one run A wrote: its orientations are ODE's, restored within ulps
  expect_same_as_a(s, "SIGTERM during step 230, resume from 230", false);
}

TEST_F(Restart, RealKill9ThenResume) {
  const fs::path c = kRoot / "C";
  const std::string cmd = base_cmd(c) + " > /dev/null 2>&1 & pid=$!; i=0; while [ $i -lt 2000 ] && ! ls '" +
                          (c / "restart").string() + "'/restart_*.bin > /dev/null 2>&1; do sleep 0.01; i=$((i+1)); done; "
                          "kill -9 $pid; wait $pid; echo $? > '" + (kRoot / "C.rc").string() + "'";
  run(cmd);  // std::system runs it with sh
  const std::string rc = slurp(kRoot / "C.rc");
  std::printf("[kill -9] exit status of the killed run: %s", rc.c_str());
  if (rc.rfind("137", 0) != 0) GTEST_SKIP() << "the run ended before the kill (status " << rc << ")";
  ASSERT_EQ(run(resume_cmd(c)), 0);
  expect_same_as_a(c, "kill -9 at the first restart file, resume");
}

// A second brash-ode in the directory of a run still going (a --resume) is refused: it would write the same files.
TEST_F(Restart, ResumeOfARunStillGoingIsRefused) {
  const fs::path g = kRoot / "busy";
  const std::string cmd = std::string("'") + BRASH_ODE_EXE + "' '" + BRASH_SMOKE_CASE + "' --out '" + g.string() +
                          "' --duration 5 --restart-every 0.04 --no-progress --no-post > /dev/null 2>&1 & echo $! > '" +
                          (kRoot / "busy.pid").string() + "'; i=0; while [ $i -lt 2000 ] && ! ls '" +
                          (g / "restart").string() + "'/restart_*.bin > /dev/null 2>&1; do sleep 0.01; i=$((i+1)); done";
  run(cmd);
  const fs::path err = kRoot / "busy.err";
  const int rc = run(std::string("'") + BRASH_ODE_EXE + "' --resume '" + g.string() + "' --no-progress --no-post 2> '" +
                     err.string() + "'");
  const std::string meta = slurp(g / "meta.json");
  run("kill -9 $(cat '" + (kRoot / "busy.pid").string() + "') 2>/dev/null; sleep 0.3");
  EXPECT_EQ(rc, 2);
  EXPECT_NE(meta.find("\"status\": \"running\""), std::string::npos) << meta;  // the refusal left the run alone
  EXPECT_NE(slurp(err).find("another process is running in this run directory"), std::string::npos) << slurp(err);
}

TEST_F(Restart, TruncatedNewestRestartFallsBackToThePreviousOne) {
  const fs::path d = kRoot / "D";
  ASSERT_EQ(run(base_cmd(d) + " --crash-after-step 230"), 137);
  const fs::path newest = d / "restart" / "restart_0000000160.bin";
  fs::resize_file(newest, fs::file_size(newest) / 2);
  ASSERT_EQ(run(resume_cmd(d)), 0);
  const std::string log = slurp(d / "log.txt");
  EXPECT_NE(log.find("skipped " + newest.string() + ": truncated"), std::string::npos) << log;
  EXPECT_NE(log.find("restart_0000000080.bin at step 80"), std::string::npos) << log;
  EXPECT_NE(slurp(d / "meta.json").find("\"hull_force_rows_dropped\": 6"), std::string::npos);
  expect_same_as_a(d, "newest restart truncated, resume from 80");
}

// The far field with frozen spheres left out of collision detection (the default) vs kept in it
// (ode.idle_geoms_out: false):
// the same contacts, so the same run to the last bit; and a resume restores the left-out set.
TEST_F(Restart, CullGeomsGiveTheSameRunAndResume) {
  const std::string cull = kFarFieldBeside;
  const fs::path f = kRoot / "F", g = kRoot / "G", h = kRoot / "H";
  ASSERT_EQ(run(base_cmd(f) + cull + " > /dev/null"), 0);
  ASSERT_EQ(run(base_cmd(g) + cull + " --set ode.idle_geoms_out=false > /dev/null"), 0);
  const std::string meta_f = slurp(f / "meta.json"), meta_g = slurp(g / "meta.json");
  const auto out_max = [](const std::string& meta) {
    const auto p = meta.find("\"cull_geoms_out_max\": ");
    return p == std::string::npos ? -1L : std::stol(meta.substr(p + 22));
  };
  std::printf("[cull geoms] at most %ld of 720 frozen spheres out of collision detection\n", out_max(meta_f));
  EXPECT_GT(out_max(meta_f), 20);  // the scene really had spheres deep in the frozen zone beside the hull
  EXPECT_EQ(out_max(meta_g), 0);
  // the wake rule is on (the case's wake force), so brash-post does not flag the run as "window alone"
  const auto skips = nlohmann::json::parse(meta_f)["skips"];
  EXPECT_GT(skips.value("cull_wake_force_N", 0.0), 0.0) << skips.dump();
  EXPECT_EQ(slurp(f / "hull_force.csv"), slurp(g / "hull_force.csv"));
  EXPECT_EQ(slurp(f / "particles" / "particles_400.csv"), slurp(g / "particles" / "particles_400.csv"));
  EXPECT_NE(slurp(f / "hull_force.csv"), slurp(kRoot / "A" / "hull_force.csv"));  // culling did act
  ASSERT_EQ(run(base_cmd(h) + cull + " --crash-after-step 230"), 137);
  ASSERT_EQ(run(resume_cmd(h)), 0);
  // As for the plain resume (expect_same_as_a): a resumed run matches to the dumps' printed digits.
  expect_resumed_matches(f, h);
}

// The far field woken by the push front keeps its front in the restart file: a run killed after step 230 and
// resumed ends as the uninterrupted one (to the dumps' printed digits, as above).
TEST_F(Restart, PushFrontResumesWithItsFront) {
  const fs::path p = kRoot / "P", q = kRoot / "Q";
  ASSERT_EQ(run(push_front_cmd(p) + " > /dev/null"), 0);
  const auto skips = nlohmann::json::parse(slurp(p / "meta.json"))["skips"];
  EXPECT_EQ(skips.value("cull_wake_by", std::string()), "push_front") << skips.dump();
  EXPECT_NE(slurp(p / "hull_force.csv"), slurp(kRoot / "A" / "hull_force.csv"));  // the far field did act
  ASSERT_EQ(run(push_front_cmd(q, " --crash-after-step 230")), 137);
  ASSERT_EQ(run(resume_cmd(q)), 0);
  // the wake counts carry over the resume (restart format 5)
  const auto woken = nlohmann::json::parse(slurp(p / "meta.json"))["cull_woken"];
  EXPECT_GT(woken.value("all", 0L), 0) << woken.dump();
  EXPECT_EQ(nlohmann::json::parse(slurp(q / "meta.json"))["cull_woken"], woken);
  expect_resumed_matches(p, q);
}

// With --settle the whole bed is integrated first and the far field's membership updates count from its end
// (World::begin_cull_at_step): a resumed run skips the settling (the restart file holds the state after it)
// and keeps that schedule, so it ends as the uninterrupted run does.
TEST_F(Restart, SettlingThenPushFrontResumesOnItsSchedule) {
  const std::string settle = " --settle 0.025 --settle-damping 0.02";
  const std::string settled_line = "settling 0.025 of 0.025 s (50 steps)";
  const fs::path r = kRoot / "R", s = kRoot / "S", p = kRoot / "P2";
  ASSERT_EQ(run(push_front_cmd(r, settle) + " > /dev/null"), 0);
  const std::string log = slurp(r / "log.txt");
  EXPECT_NE(log.find(settled_line), std::string::npos) << log;
  ASSERT_EQ(run(push_front_cmd(p) + " > /dev/null"), 0);
  EXPECT_NE(slurp(r / "hull_force.csv"), slurp(p / "hull_force.csv"));  // the settling did act
  ASSERT_EQ(run(push_front_cmd(s, settle + " --crash-after-step 230")), 137);
  ASSERT_EQ(run(resume_cmd(s)), 0);
  const std::string resumed_log = slurp(s / "log.txt");
  EXPECT_NE(resumed_log.find(settled_line), std::string::npos) << resumed_log;
  EXPECT_EQ(resumed_log.find(settled_line), resumed_log.rfind(settled_line))
      << "the resumed run settled again";
  expect_resumed_matches(r, s);
}

// The grid broad phase (default) and ODE's sweep and prune hand the same pairs to the narrow phase and the joints
// are made in a fixed order: the runs are the same to the last bit, plain, with culling (frozen spheres as static
// obstacles, deep ones out of collision detection) and with end walls; a run resumes with the broad phase it had.
TEST_F(Restart, GridAndSapBroadPhasesGiveTheSameRun) {
  const std::string cull = kFarFieldBeside;
  const fs::path s = kRoot / "S", gc = kRoot / "GC", sc = kRoot / "SC", gw = kRoot / "GW", sw = kRoot / "SW";
  ASSERT_EQ(run(base_cmd(s) + " --broad-phase sap > /dev/null"), 0);
  ASSERT_EQ(run(base_cmd(gc) + cull + " > /dev/null"), 0);
  ASSERT_EQ(run(base_cmd(sc) + cull + " --broad-phase sap > /dev/null"), 0);
  ASSERT_EQ(run(base_cmd(gw) + " --set channel.ends=walls > /dev/null"), 0);
  ASSERT_EQ(run(base_cmd(sw) + " --set channel.ends=walls --broad-phase sap > /dev/null"), 0);
  EXPECT_NE(slurp(kRoot / "A" / "case.yaml").find("\n  broad_phase: grid\n"), std::string::npos);
  EXPECT_NE(slurp(s / "case.yaml").find("\n  broad_phase: sap\n"), std::string::npos);
  EXPECT_NE(slurp(gw / "case.yaml").find("\n  ends: walls\n"), std::string::npos);
  for (const auto& [grid, sap] : {std::pair{kRoot / "A", s}, std::pair{gc, sc}, std::pair{gw, sw}}) {
    SCOPED_TRACE(grid.filename().string());
    const std::string f = slurp(grid / "hull_force.csv");
    EXPECT_GT(f.size(), 200u);
    EXPECT_EQ(f, slurp(sap / "hull_force.csv"));
    EXPECT_FALSE(slurp(grid / "particles" / "particles_400.csv").empty());
    EXPECT_EQ(slurp(grid / "particles" / "particles_400.csv"), slurp(sap / "particles" / "particles_400.csv"));
  }
  EXPECT_NE(slurp(gc / "hull_force.csv"), slurp(kRoot / "A" / "hull_force.csv"));  // culling did act
  EXPECT_NE(slurp(gw / "particles" / "particles_400.csv"),
            slurp(kRoot / "A" / "particles" / "particles_400.csv"));  // the end walls did act
  // A sap run resumed goes on with sap, to the same end.
  const fs::path r = kRoot / "SR";
  ASSERT_EQ(run(base_cmd(r) + " --broad-phase sap --crash-after-step 230"), 137);
  ASSERT_EQ(run(resume_cmd(r)), 0);
  EXPECT_NE(slurp(r / "case.yaml").find("\n  broad_phase: sap\n"), std::string::npos);
  EXPECT_LE(max_diff(s / "hull_force.csv", r / "hull_force.csv", 1, 4), 1e-6);
}

// ode.sphere_order packing (--sphere-order) adds the bodies in the packing file's order instead of the spatial one: the same
// pieces under the same ids at the same places (the dumps list them in the bodies' order), a run that differs
// from the spatial one only as far as the order of ODE's constraint rows changes its sums, and one that a resume
// goes on with.
TEST_F(Restart, PackingSphereOrderKeepsTheIdsAndResumesInItsOrder) {
  const fs::path p = kRoot / "P", pr = kRoot / "PR";
  ASSERT_EQ(run(base_cmd(p) + " --sphere-order packing > /dev/null"), 0);
  EXPECT_NE(slurp(p / "case.yaml").find("\n  sphere_order: packing\n"), std::string::npos);
  EXPECT_NE(slurp(kRoot / "A" / "case.yaml").find("\n  sphere_order: spatial\n"), std::string::npos);
  auto a0 = read_csv(kRoot / "A" / "particles" / "particles_0.csv");
  auto p0 = read_csv(p / "particles" / "particles_0.csv");
  ASSERT_EQ(a0.size(), 720u);
  ASSERT_EQ(p0.size(), a0.size());
  EXPECT_NE(a0, p0);  // the bodies in another order
  std::sort(a0.begin(), a0.end());  // by id
  std::sort(p0.begin(), p0.end());
  for (std::size_t i = 0; i < a0.size(); ++i) {
    EXPECT_EQ(a0[i][0], double(i + 1)) << "row " << i;  // ids 1..720, each once
    for (std::size_t c = 0; c < 5; ++c) EXPECT_EQ(a0[i][c], p0[i][c]) << "row " << i;  // the packing's piece
  }
  // the same physics: the bow's mean force over the run within 2 % of the spatial order's
  double fa = 0, fp = 0;
  for (const auto& r : read_csv(kRoot / "A" / "hull_force.csv")) fa += r[1];
  for (const auto& r : read_csv(p / "hull_force.csv")) fp += r[1];
  EXPECT_LT(fa, 0);
  EXPECT_NEAR(fp / fa, 1.0, 0.02) << "mean Fx, packing order / spatial order";
  ASSERT_EQ(run(base_cmd(pr) + " --sphere-order packing --crash-after-step 230"), 137);
  ASSERT_EQ(run(resume_cmd(pr)), 0);
  EXPECT_NE(slurp(pr / "case.yaml").find("\n  sphere_order: packing\n"), std::string::npos);
  EXPECT_LE(max_diff(p / "hull_force.csv", pr / "hull_force.csv", 1, 4), 1e-6);
  EXPECT_LE(max_diff(p / "particles" / "particles_400.csv", pr / "particles" / "particles_400.csv", 1, 4), 1e-9);
}

// speedups.early_stop_rel_ci in brash-ode: the smoke case with a row every 0.001 s (window [0.1, 0.2] s), run
// to the end, then with early_stop_rel_ci 0.5: it stops exactly where the rule replayed on the full run's
// record says (ODE runs are deterministic, so the stopped run is the full run's prefix), its record and case
// end there; and so does the run killed one step before the stop and resumed.
TEST_F(Restart, EarlyStopEndsWhereTheRuleSays) {
  const fs::path cdir = kRoot / "es_case";
  fs::create_directories(cdir);
  for (const auto& e : fs::directory_iterator(BRASH_SMOKE_CASE)) fs::copy(e.path(), cdir / e.path().filename());
  std::string yaml = slurp(cdir / "case.yaml");
  const auto p = yaml.find("  output_interval_s:");
  ASSERT_NE(p, std::string::npos);
  yaml.replace(p, yaml.find('\n', p) - p, "  output_interval_s: 0.001");
  std::ofstream(cdir / "case.yaml") << yaml;
  const std::string exe = std::string("'") + BRASH_ODE_EXE + "' '" + cdir.string() + "' --no-progress --no-post --out '";
  ASSERT_EQ(run(exe + (kRoot / "es_full").string() + "' > /dev/null 2>&1"), 0);
  const auto full = read_csv(kRoot / "es_full" / "hull_force.csv");
  std::vector<double> t, r;
  for (const auto& row : full) t.push_back(row[0]), r.push_back(-row[1]);
  const auto replay = brash::stats::replay_early_stop(t, r, 0.1, 0.2, 0.5, 0.2 / 200, true);
  ASSERT_TRUE(replay.stopped) << "the smoke record no longer meets the rule at 50 %: pick another threshold";
  std::ofstream(cdir / "case.yaml", std::ios::app) << "speedups:\n  early_stop_rel_ci: 0.5\n";
  ASSERT_EQ(run(exe + (kRoot / "es_run").string() + "' > /dev/null 2>&1"), 0);
  const std::string meta = slurp(kRoot / "es_run" / "meta.json");
  EXPECT_NE(meta.find("\"status\": \"complete\""), std::string::npos) << meta;
  EXPECT_NE(meta.find("\"early_stop\""), std::string::npos) << meta;
  // why it stopped, in the rule's words, and its estimate of the full window's mean (early_stop.hpp)
  EXPECT_NE(meta.find("\"reason\": \"" + replay.last.explain() + "\""), std::string::npos) << meta;
  EXPECT_NE(meta.find("\"estimate_ci95_N\""), std::string::npos) << meta;
  EXPECT_EQ(meta.find("\"early_stop_last_check\""), std::string::npos) << meta;  // the stop is the last check
  const auto stopped = read_csv(kRoot / "es_run" / "hull_force.csv");
  ASSERT_FALSE(stopped.empty());
  std::printf("[early stop] replay: stop at %.4f s; the run's record ends at %.4f s\n", replay.t_stop_s,
              stopped.back()[0]);
  EXPECT_NEAR(stopped.back()[0], replay.t_stop_s, 1e-9);
  ASSERT_LE(stopped.size(), full.size());
  for (std::size_t i = 0; i < stopped.size(); ++i) EXPECT_EQ(stopped[i], full[i]) << "row " << i;
  EXPECT_NE(slurp(kRoot / "es_run" / "case.yaml").find(fmt::format("duration_s: {}", stopped.back()[0])),
            std::string::npos);

  // The same run stopped like a kill -9 one step before the stop, then resumed: the resumed run takes the
  // rows written before its restart point (inside the window) from hull_force.csv and stops at the same row.
  ASSERT_NE(meta.find("\"dt_s\": 0.0005"), std::string::npos) << meta;
  const long stop_step = std::lround(replay.t_stop_s / 5e-4), restart_steps = 80;  // --restart-every 0.04 s
  const long crash_step = stop_step - 1;
  ASSERT_GT((crash_step / restart_steps) * restart_steps * 5e-4, 0.1 + 1e-9)
      << "no restart file inside the window before the stop: the resume would not read window rows back";
  const fs::path k = kRoot / "es_killed";
  EXPECT_EQ(run(exe + k.string() + "' --restart-every 0.04 --crash-after-step " + std::to_string(crash_step) +
                " > /dev/null 2>&1"),
            137);
  ASSERT_EQ(run(resume_cmd(k) + " 2>&1"), 0);
  EXPECT_NE(slurp(k / "meta.json").find("\"early_stop\""), std::string::npos);
  const auto resumed = read_csv(k / "hull_force.csv");
  ASSERT_EQ(resumed.size(), stopped.size());
  EXPECT_NEAR(resumed.back()[0], replay.t_stop_s, 1e-9);
  for (std::size_t i = 0; i < resumed.size(); ++i)
    EXPECT_NEAR(resumed[i][1], stopped[i][1], 1e-6) << "row " << i;

  // A threshold the record never meets: the run goes to its end and meta.json says why, with the verdict of its
  // last check (0.199 s: the runner does not check at the run's last point) as the rule gives it on the record.
  ASSERT_FALSE(brash::stats::replay_early_stop(t, r, 0.1, 0.2, 0.001, 0.2 / 200, true).stopped);
  std::vector<double> since;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= 0.1 - 1e-12 && t[i] <= 0.199 + 1e-9) since.push_back(r[i]);
  const auto last = brash::stats::early_stop_verdict(since, 0.199, 0.1, 0.2, 0.001);
  ASSERT_TRUE(last.checked);
  yaml = slurp(cdir / "case.yaml");
  yaml.replace(yaml.find("early_stop_rel_ci: 0.5"), 22, "early_stop_rel_ci: 0.001");
  std::ofstream(cdir / "case.yaml") << yaml;
  ASSERT_EQ(run(exe + (kRoot / "es_never").string() + "' > /dev/null 2>&1"), 0);
  const std::string meta_never = slurp(kRoot / "es_never" / "meta.json");
  EXPECT_EQ(meta_never.find("\"early_stop\""), std::string::npos) << meta_never;
  EXPECT_NE(meta_never.find("\"early_stop_last_check\""), std::string::npos) << meta_never;
  EXPECT_NE(meta_never.find("\"t_s\": 0.199"), std::string::npos) << meta_never;
  EXPECT_NE(meta_never.find("\"reason\": \"" + last.explain() + "\""), std::string::npos) << meta_never;
}

TEST_F(Restart, NoUsableRestartFileIsAClearError) {
  const fs::path e = kRoot / "E";
  ASSERT_EQ(run(base_cmd(e) + " --crash-after-step 100"), 137);
  for (const auto& p : fs::directory_iterator(e / "restart")) std::ofstream(p.path(), std::ios::trunc) << "junk";
  const fs::path err = kRoot / "E.err";
  EXPECT_EQ(run(resume_cmd(e) + " 2> '" + err.string() + "'"), 1);
  const std::string msg = slurp(err);
  EXPECT_NE(msg.find("no usable restart file"), std::string::npos) << msg;
  EXPECT_NE(msg.find("restart_0000000080.bin: not a brash-ode restart file or truncated"), std::string::npos) << msg;
}

// brash-ode's settings are case keys: a short form (--dt, --iterations) is the same change of the case as --set,
// the run folder's case.yaml records it and meta.json holds no second copy; a resume runs as that case.yaml says
// and takes no change of it; a bad value is refused naming the key.
TEST_F(Restart, SettingsAreCaseKeysThatTheRunFolderRecords) {
  const fs::path s = kRoot / "short", k = kRoot / "keys", r = kRoot / "short_resumed", err = kRoot / "keys.err";
  ASSERT_EQ(run(base_cmd(s) + " --dt 1e-3 --iterations 12 > /dev/null"), 0);
  ASSERT_EQ(run(base_cmd(k) + " --set ode.timestep_s=1e-3 --set ode.iterations=12 > /dev/null"), 0);
  const std::string yaml = slurp(s / "case.yaml");
  EXPECT_NE(yaml.find("\node:\n  timestep_s: 0.001\n  iterations: 12\n"), std::string::npos) << yaml;
  EXPECT_EQ(yaml, slurp(k / "case.yaml"));
  EXPECT_GT(slurp(s / "hull_force.csv").size(), 200u);
  EXPECT_EQ(slurp(s / "hull_force.csv"), slurp(k / "hull_force.csv"));
  EXPECT_NE(slurp(s / "hull_force.csv"), slurp(kRoot / "A" / "hull_force.csv"));  // the settings did act
  const auto meta = nlohmann::json::parse(slurp(s / "meta.json"));
  EXPECT_FALSE(meta.contains("ode_options")) << meta.dump();
  EXPECT_EQ(meta.value("dt_s", 0.0), 1e-3);
  EXPECT_EQ(meta["stepper"].value("quickstep_iterations", 0), 12);
  ASSERT_EQ(run(base_cmd(r) + " --dt 1e-3 --iterations 12 --crash-after-step 130"), 137);
  EXPECT_EQ(run(std::string("'") + BRASH_ODE_EXE + "' --resume '" + r.string() + "' --dt 5e-4 --no-post 2> '" +
                err.string() + "'"),
            2);
  EXPECT_NE(slurp(err).find("--resume continues a run as it was set up (its case.yaml)"), std::string::npos)
      << slurp(err);
  ASSERT_EQ(run(resume_cmd(r)), 0);
  EXPECT_LE(max_diff(s / "hull_force.csv", r / "hull_force.csv", 1, 4), 1e-6);
  EXPECT_EQ(run(base_cmd(kRoot / "bad_dt") + " --dt 0 2> '" + err.string() + "'"), 2);
  EXPECT_NE(slurp(err).find("key 'ode.timestep_s': must be > 0"), std::string::npos) << slurp(err);
  EXPECT_FALSE(fs::exists(kRoot / "bad_dt" / "meta.json"));
}

// What brash-ode wrote into meta.json as "ode_options" before its settings were case keys (a run's case.yaml then
// had no ode: section): here a time step of 1e-3 s, the packing's order and --cull's window (0.08 m ahead, 0.02 m
// behind and beside, membership every 20 ODE steps), the rest brash-ode's defaults.
nlohmann::json ode_options_before_the_keys() {
  return {{"case_dir", BRASH_SMOKE_CASE}, {"duration_s", 0.2}, {"model", ""}, {"treatment", ""}, {"dt_s", 1e-3},
          {"iterations", 8}, {"erp", 0.2}, {"cfm", 1e-5}, {"contact_surface_layer_m", 0.0},
          {"max_contacts_per_pair", 8}, {"angular_damping", 0.0}, {"broad_phase", "grid"},
          {"sphere_order", "packing"}, {"auto_disable", false}, {"disable_linear_m_s", 0.005},
          {"disable_angular_rad_s", 0.5}, {"disable_steps", 20}, {"auto_disable_far_only", true}, {"cull", true},
          {"cull_ahead_m", 0.08}, {"cull_behind_m", 0.02}, {"cull_side_m", 0.0}, {"cull_every", 20},
          {"cull_geoms", true}, {"cull_wake_force_weight", -1.0}, {"cull_wake_speed_m_s", -1.0},
          {"implicit", "effective_mass"}, {"end_walls", false}, {"settle_s", 0.0}, {"settle_damping", 0.0},
          {"overlap_tolerance_over_d", 1e-4}, {"restart_every_s", 0.04}, {"scene_from", ""}, {"scene_time_s", 0.0}};
}

// The run folder `dir` as brash-ode left it before the ode: keys: the plain smoke case's case.yaml (run A's, no
// far field) without its ode: section, and `options` in meta.json.
void make_run_from_before_the_keys(const fs::path& dir, const nlohmann::json& options) {
  std::string yaml = slurp(kRoot / "A" / "case.yaml");
  const auto at = yaml.find("\node:\n");
  ASSERT_NE(at, std::string::npos) << yaml;
  auto end = at + 1;
  while ((end = yaml.find('\n', end)) != std::string::npos && end + 1 < yaml.size() && yaml[end + 1] == ' ') ++end;
  yaml.erase(at + 1, end == std::string::npos ? std::string::npos : end - at);
  ASSERT_EQ(yaml.find("\node:"), std::string::npos) << yaml;
  std::ofstream(dir / "case.yaml") << yaml;
  auto meta = nlohmann::json::parse(slurp(dir / "meta.json"));
  meta["ode_options"] = options;
  std::ofstream(dir / "meta.json") << meta.dump(2);
}

// A run folder from before the ode: keys resumes: its "ode_options" move into its case.yaml as the keys that give
// the same run (the ode: section; --cull as speedups.farfield_*), meta.json keeps no copy, and the run ends as the
// uninterrupted run with those keys does. Options the keys cannot give are refused naming meta.json, the folder
// left as it was.
TEST_F(Restart, RunFolderFromBeforeTheOdeKeysResumesWithItsSettingsInItsCase) {
  const fs::path full = kRoot / "keys_full", old = kRoot / "old", bad = kRoot / "old_bad";
  const std::string keys = " --dt 1e-3 --sphere-order packing" + kFarFieldBeside +
                           " --set speedups.farfield_every_steps=200";  // 20 ODE steps of 1e-3 s in steps of 1e-4 s
  ASSERT_EQ(run(base_cmd(full) + keys + " > /dev/null"), 0);
  ASSERT_EQ(run(base_cmd(old) + keys + " --crash-after-step 130"), 137);
  make_run_from_before_the_keys(old, ode_options_before_the_keys());
  fs::copy(old, bad, fs::copy_options::recursive);
  auto options = ode_options_before_the_keys();
  options["max_contacts_per_pair"] = 4;
  make_run_from_before_the_keys(bad, options);
  const std::string bad_yaml = slurp(bad / "case.yaml");
  const fs::path err = kRoot / "old_bad.err";
  EXPECT_EQ(run(resume_cmd(bad) + " 2> '" + err.string() + "'"), 2);
  EXPECT_NE(slurp(err).find((bad / "meta.json").string() + ": \"ode_options\": max_contacts_per_pair is not 8"),
            std::string::npos)
      << slurp(err);
  EXPECT_EQ(slurp(bad / "case.yaml"), bad_yaml);
  EXPECT_TRUE(nlohmann::json::parse(slurp(bad / "meta.json")).contains("ode_options"));

  ASSERT_EQ(run(resume_cmd(old)), 0);
  const std::string yaml = slurp(old / "case.yaml");
  for (const char* line : {"\n  farfield: true\n", "\n  farfield_ahead_m: 0.08\n", "\n  farfield_beside_m: 0.0\n",
                           "\n  farfield_every_steps: 200\n", "\node:\n  timestep_s: 0.001\n",
                           "\n  sphere_order: packing\n"})
    EXPECT_NE(yaml.find(line), std::string::npos) << line << " in\n" << yaml;
  const auto meta = nlohmann::json::parse(slurp(old / "meta.json"));
  EXPECT_FALSE(meta.contains("ode_options"));
  EXPECT_EQ(meta.value("status", std::string()), "complete");
  EXPECT_EQ(meta["skips"].value("cull_every_steps", 0), 20);
  EXPECT_EQ(yaml, slurp(full / "case.yaml"));
  EXPECT_LE(max_diff(full / "hull_force.csv", old / "hull_force.csv", 1, 4), 1e-6);
  EXPECT_LE(max_diff(full / "particles" / "particles_200.csv", old / "particles" / "particles_200.csv", 1, 4), 1e-9);
}

// A run from before the keys with its far field off (no --cull, no auto-disable: the ODE paper run's set-up) skips
// nothing, so whatever its options say of the window (-1: unset, 20 steps) it migrates and resumes.
TEST_F(Restart, RunFolderFromBeforeTheOdeKeysWithoutAFarFieldResumes) {
  const fs::path old = kRoot / "old_no_far_field";
  ASSERT_EQ(run(base_cmd(old) + " --dt 1e-3 --sphere-order packing --crash-after-step 130"), 137);
  auto options = ode_options_before_the_keys();
  options["cull"] = false;
  for (const char* key : {"cull_ahead_m", "cull_behind_m", "cull_side_m"}) options[key] = -1.0;
  make_run_from_before_the_keys(old, options);
  ASSERT_EQ(run(resume_cmd(old)), 0);
  const auto meta = nlohmann::json::parse(slurp(old / "meta.json"));
  EXPECT_FALSE(meta.contains("ode_options"));
  EXPECT_EQ(meta.value("status", std::string()), "complete");
  EXPECT_NE(slurp(old / "case.yaml").find("\n  farfield: false\n"), std::string::npos);
}

}  // namespace
