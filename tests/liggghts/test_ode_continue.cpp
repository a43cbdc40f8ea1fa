// brash-ode going on from a LIGGGHTS run's particle snapshot (--scene-from, --scene-time): the narrowed quick case run
// on LIGGGHTS for 0.3 s (snapshots every 0.1 s), then on ODE from its snapshot at 0.2 s to 0.3 s. The ODE run is an
// ordinary run directory: its record's times start at 0.2 s, its first snapshot holds the LIGGGHTS snapshot's
// pieces where they were, its window is the part of the case's inside the run, meta.json names the snapshot, and
// an interrupted run resumes to the uninterrupted one. A moving window's removed pieces are left out; bad inputs
// are refused naming the option or the file.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "runner_case.h"

namespace fs = std::filesystem;

namespace {

const fs::path kRoot = brash::test::fresh_dir("ode_continue");
const fs::path kCase = kRoot / "case", kLiggghts = kRoot / "liggghts";

int run(const std::string& cmd) {
  const int st = std::system(cmd.c_str());
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

// A CSV with a header: its column names and rows.
struct Table {
  std::vector<std::string> names;
  std::vector<std::vector<double>> rows;
  std::size_t col(const std::string& name) const {
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == name) return i;
    ADD_FAILURE() << "no column " << name;
    return 0;
  }
};
Table read_csv(const fs::path& file) {
  Table t;
  std::ifstream in(file);
  std::string line, cell;
  std::getline(in, line);
  for (std::stringstream ss(line); std::getline(ss, cell, ',');) t.names.push_back(cell);
  while (std::getline(in, line)) {
    std::vector<double> row;
    for (std::stringstream ss(line); std::getline(ss, cell, ',');) row.push_back(std::strtod(cell.c_str(), nullptr));
    t.rows.push_back(row);
  }
  return t;
}

// The LIGGGHTS snapshot at 0.2 s (its particles/index.csv), and the ODE command going on from `snapshot`.
fs::path liggghts_snapshot() {
  std::ifstream in(kLiggghts / "particles" / "index.csv");
  std::string line, step, t, file;
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    if (std::getline(ss, step, ',') && std::getline(ss, t, ',') && std::getline(ss, file, ',') &&
        std::abs(std::strtod(t.c_str(), nullptr) - 0.2) < 1e-9)
      return kLiggghts / "particles" / file;
  }
  ADD_FAILURE() << "no LIGGGHTS snapshot at 0.2 s";
  return {};
}
std::string ode_cmd(const fs::path& out, const fs::path& snapshot, const std::string& extra = "",
                    const std::string& scene_time_s = "0.2", const std::string& duration_s = "0.3") {
  return fmt::format("env BRASH_HULL_DIR='{}' '{}/brash-ode' '{}' --scene-from '{}' --scene-time {} --duration {} "
                     "--restart-every 0.04 --no-progress --no-post --out '{}'{} > '{}.stdout' 2> '{}.stderr'",
                     BRASH_HULL_DIR, BRASH_BIN_DIR, kCase.string(), snapshot.string(), scene_time_s, duration_s,
                     out.string(), extra, out.string(), out.string());
}
std::string stderr_of(const fs::path& out) { return brash::test::read_text(out.string() + ".stderr"); }

class OdeContinue : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    brash::test::SmallCase k;
    k.duration_s = "0.3";
    k.window_s = "[0.0, 0.3]";
    brash::test::write_small_quick_case(kCase, k);
    ASSERT_EQ(run(brash::test::runner_command(kCase, kLiggghts) + " > '" + (kRoot / "liggghts.txt").string() + "' 2>&1"),
              0)
        << brash::test::read_text(kRoot / "liggghts.txt");
    ASSERT_EQ(run(ode_cmd(kRoot / "A", liggghts_snapshot())), 0) << stderr_of(kRoot / "A");
  }
  static void TearDownTestSuite() { fs::remove_all(kRoot); }
};

TEST_F(OdeContinue, GoesOnFromTheSnapshotAsAnOrdinaryRun) {
  const fs::path a = kRoot / "A";
  const Table force = read_csv(a / "hull_force.csv");
  ASSERT_FALSE(force.rows.empty());
  EXPECT_NEAR(force.rows.front()[0], 0.21, 1e-9);  // one output interval after the start
  EXPECT_NEAR(force.rows.back()[0], 0.3, 1e-9);
  // the first ODE snapshot is at 0.2 s, the hull and every piece where the LIGGGHTS snapshot has them
  const Table index = read_csv(a / "particles" / "index.csv"), lig_index = read_csv(kLiggghts / "particles" / "index.csv");
  ASSERT_FALSE(index.rows.empty());
  EXPECT_NEAR(index.rows.front()[1], 0.2, 1e-12);
  for (const auto& row : lig_index.rows) {
    if (std::abs(row[1] - 0.2) < 1e-9) {
      EXPECT_NEAR(index.rows.front()[3], row[3], 1e-9);  // hull_x_m
    }
  }
  const Table lig = read_csv(liggghts_snapshot());
  const Table ode = read_csv(a / "particles" / fmt::format("particles_{}.csv", long(index.rows.front()[0])));
  ASSERT_EQ(ode.rows.size(), lig.rows.size());
  std::map<long, std::vector<double>> by_id;
  for (const auto& row : lig.rows) by_id[long(row[0])] = row;
  double dx = 0, dv = 0;
  for (const auto& row : ode.rows) {
    ASSERT_TRUE(by_id.count(long(row[0]))) << "piece " << row[0];
    const auto& l = by_id[long(row[0])];
    for (const char* c : {"x", "y", "z", "radius"}) dx = std::max(dx, std::abs(row[ode.col(c)] - l[lig.col(c)]));
    for (const char* c : {"vx", "vy", "vz"}) dv = std::max(dv, std::abs(row[ode.col(c)] - l[lig.col(c)]));
  }
  EXPECT_LE(dx, 1e-9);  // m: the snapshot's printed digits
  EXPECT_LE(dv, 1e-6);  // m/s
  const auto meta = nlohmann::json::parse(brash::test::read_text(a / "meta.json"));
  EXPECT_EQ(meta["status"], "complete");
  EXPECT_EQ(meta["scene_from"], liggghts_snapshot().string());
  EXPECT_DOUBLE_EQ(meta["scene_time_s"].get<double>(), 0.2);
  EXPECT_EQ(meta["particles"].get<std::size_t>(), lig.rows.size());
  // the case's window [0, 0.3] s begins before the run: its case.yaml averages over the part inside it
  EXPECT_EQ(meta["requested_window_s"], nlohmann::json::array({0.0, 0.3}));
  EXPECT_NE(brash::test::read_text(a / "case.yaml").find("window_s: [0.2, 0.3]"), std::string::npos);
  const std::string log = brash::test::read_text(a / "log.txt");
  EXPECT_NE(log.find("every piece (no state column)"), std::string::npos) << log;
  EXPECT_NE(log.find("no angular velocities in the snapshot: the pieces start without spin"), std::string::npos);
}

// Stopped like a kill -9 after step 540 (0.27 s; restart files at 0.24 and 0.28 s are every 0.04 s from t = 0), then
// resumed: the same record and last snapshot as the uninterrupted run.
TEST_F(OdeContinue, InterruptedRunResumesToTheUninterruptedOne) {
  const fs::path b = kRoot / "B";
  ASSERT_EQ(run(ode_cmd(b, liggghts_snapshot(), " --crash-after-step 540")), 137);
  ASSERT_EQ(run(fmt::format("env BRASH_HULL_DIR='{}' '{}/brash-ode' --resume '{}' --no-progress --no-post > /dev/null "
                            "2> '{}.stderr'",
                            BRASH_HULL_DIR, BRASH_BIN_DIR, b.string(), b.string())),
            0)
      << stderr_of(b);
  const auto meta = nlohmann::json::parse(brash::test::read_text(b / "meta.json"));
  EXPECT_EQ(meta["status"], "complete");
  ASSERT_EQ(meta["resumes"].size(), 1u);
  EXPECT_EQ(meta["resumes"][0]["step"], 480);
  const fs::path a = kRoot / "A";
  EXPECT_EQ(brash::test::read_text(b / "hull_force.csv"), brash::test::read_text(a / "hull_force.csv"));
  EXPECT_EQ(brash::test::read_text(b / "particles" / "particles_600.csv"),
            brash::test::read_text(a / "particles" / "particles_600.csv"));

  // the resume builds the scene from the snapshot again: one that is gone is named
  const fs::path copy = kRoot / "gone" / "particles_2000.csv", g = kRoot / "G";
  fs::create_directories(copy.parent_path());
  fs::copy_file(liggghts_snapshot(), copy);
  ASSERT_EQ(run(ode_cmd(g, copy, " --crash-after-step 500")), 137);
  fs::remove(copy);
  EXPECT_EQ(run(fmt::format("env BRASH_HULL_DIR='{}' '{}/brash-ode' --resume '{}' --no-progress --no-post > /dev/null "
                            "2> '{}.stderr'",
                            BRASH_HULL_DIR, BRASH_BIN_DIR, g.string(), g.string())),
            2);
  EXPECT_NE(stderr_of(g).find("the run started from the snapshot " + copy.string() + " (\"scene_from\"), which is gone"),
            std::string::npos)
      << stderr_of(g);
}

// A start off the output grid (rows every 0.03 s: 0.21, 0.24, ...): the first row averages the steps since the start,
// the same steps as the uninterrupted run's row at 0.21 s (every 0.01 s), not a third of them.
TEST_F(OdeContinue, FirstRowAveragesTheStepsSinceTheStart) {
  const fs::path c = kRoot / "C";
  ASSERT_EQ(run(ode_cmd(c, liggghts_snapshot(), " --set run.output_interval_s=0.03", "0.2", "0.24")), 0) << stderr_of(c);
  const Table coarse = read_csv(c / "hull_force.csv"), fine = read_csv(kRoot / "A" / "hull_force.csv");
  ASSERT_GE(coarse.rows.size(), 2u);
  EXPECT_NEAR(coarse.rows[0][0], 0.21, 1e-9);
  EXPECT_NEAR(fine.rows[0][0], 0.21, 1e-9);
  for (std::size_t col = 1; col < 4; ++col) EXPECT_NEAR(coarse.rows[0][col], fine.rows[0][col], 1e-6 * (1 + std::abs(fine.rows[0][col])));
  // the next row: a whole interval, 0.21 to 0.24 s, the mean of the fine rows at 0.22, 0.23 and 0.24 s
  EXPECT_NEAR(coarse.rows[1][1], (fine.rows[1][1] + fine.rows[2][1] + fine.rows[3][1]) / 3, 1e-6 * (1 + std::abs(coarse.rows[1][1])));
}

// A moving window's snapshot: the piece removed (state 2) is left out, the one held out (state 1) kept; the log
// counts them.
TEST_F(OdeContinue, RemovedPiecesAreLeftOut) {
  const Table lig = read_csv(liggghts_snapshot());
  const fs::path copy = kRoot / "window" / "particles_2000.csv";
  fs::create_directories(copy.parent_path());
  {
    std::ifstream in(liggghts_snapshot());
    std::ofstream out(copy);
    std::string line;
    std::getline(in, line);
    out << line << ",state\n";
    for (int i = 0; std::getline(in, line); ++i) out << line << "," << (i == 0 ? 2 : i == 1 ? 1 : 0) << "\n";
  }
  const fs::path w = kRoot / "W";
  ASSERT_EQ(run(ode_cmd(w, copy, "", "0.2", "0.21")), 0) << stderr_of(w);
  const std::string log = brash::test::read_text(w / "log.txt");
  EXPECT_NE(log.find(fmt::format("{} pieces, hull at", lig.rows.size() - 1)), std::string::npos) << log;
  EXPECT_NE(log.find(fmt::format("{} in its scene (state 0), 1 held out at their packing position at rest (state 1), "
                                 "1 removed (state 2) left out",
                                 lig.rows.size() - 2)),
            std::string::npos)
      << log;
  const Table first = read_csv(w / "particles" / "particles_400.csv");
  ASSERT_EQ(first.rows.size(), lig.rows.size() - 1);
  for (const auto& row : first.rows) EXPECT_NE(long(row[0]), long(lig.rows[0][0]));
}

// A snapshot with angular velocities (omegax,omegay,omegaz) starts the pieces spinning: the log says so, and 0.01 s
// later the pieces are elsewhere than in the same run from the snapshot without them.
TEST_F(OdeContinue, AngularVelocitiesOfTheSnapshotAreTaken) {
  const fs::path plain = kRoot / "spin" / "plain" / "particles_2000.csv", spin = kRoot / "spin" / "particles_2000.csv";
  fs::create_directories(plain.parent_path());
  fs::copy_file(liggghts_snapshot(), plain);
  {
    std::ifstream in(liggghts_snapshot());
    std::ofstream out(spin);
    std::string line;
    std::getline(in, line);
    out << line << ",omegax,omegay,omegaz\n";
    while (std::getline(in, line)) out << line << ",0,30,0\n";  // rolling along x at 30 rad/s
  }
  const fs::path p = kRoot / "P", s = kRoot / "S";
  ASSERT_EQ(run(ode_cmd(p, plain, "", "0.2", "0.21")), 0) << stderr_of(p);
  ASSERT_EQ(run(ode_cmd(s, spin, "", "0.2", "0.21")), 0) << stderr_of(s);
  EXPECT_NE(brash::test::read_text(s / "log.txt").find("the snapshot's velocities, the snapshot's angular velocities"),
            std::string::npos)
      << brash::test::read_text(s / "log.txt");
  const Table a = read_csv(p / "particles" / "particles_420.csv"), b = read_csv(s / "particles" / "particles_420.csv");
  ASSERT_EQ(a.rows.size(), b.rows.size());
  double dx = 0;
  for (std::size_t i = 0; i < a.rows.size(); ++i) dx = std::max(dx, std::abs(a.rows[i][1] - b.rows[i][1]));
  EXPECT_GT(dx, 1e-4);  // m: friction on the spinning pieces moves them
}

TEST_F(OdeContinue, BadInputsAreRefusedByName) {
  const fs::path snapshot = liggghts_snapshot(), e = kRoot / "E";
  // the run must reach past the snapshot's time
  EXPECT_EQ(run(ode_cmd(e, snapshot, "", "0.2", "0.2")), 2);
  EXPECT_NE(stderr_of(e).find("--duration 0.2 s is not after --scene-time 0.2 s"), std::string::npos) << stderr_of(e);
  EXPECT_FALSE(fs::exists(e / "meta.json"));
  // the snapshot's own time (its index.csv) is not --scene-time
  EXPECT_EQ(run(ode_cmd(e, snapshot, "", "0.1")), 2);
  EXPECT_NE(stderr_of(e).find("--scene-time 0.1 s: " + snapshot.string() + " is the snapshot at t = 0.2 s"),
            std::string::npos)
      << stderr_of(e);
  // a snapshot needs its time
  EXPECT_NE(run(fmt::format("'{}/brash-ode' '{}' --scene-from '{}' --no-post > /dev/null 2> '{}.stderr'", BRASH_BIN_DIR,
                            kCase.string(), snapshot.string(), e.string())),
            0);
  EXPECT_NE(stderr_of(e).find("--scene-from requires --scene-time"), std::string::npos) << stderr_of(e);
  // no such file
  EXPECT_NE(run(ode_cmd(e, kRoot / "nothing.csv")), 0);
  EXPECT_NE(stderr_of(e).find((kRoot / "nothing.csv").string()), std::string::npos) << stderr_of(e);
  // a snapshot of another case: an id beyond the case's pieces
  const fs::path other = kRoot / "other" / "particles_1.csv";
  fs::create_directories(other.parent_path());
  {
    const Table lig = read_csv(snapshot);
    std::ofstream out(other);
    out << "id,x,y,z,radius\n";
    out << lig.rows.size() + 5 << ",0.5,0,0,0.0175\n";
  }
  EXPECT_EQ(run(ode_cmd(e, other)), 2);
  EXPECT_NE(stderr_of(e).find(fmt::format("piece id {} is not one of the case's", read_csv(snapshot).rows.size() + 5)),
            std::string::npos)
      << stderr_of(e);
}

}  // namespace
