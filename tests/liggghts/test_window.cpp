// fix brash/window (speedups.window) on a tiny scene: a chain of 12 touching spheres along x pushed on its
// first sphere, a row of separated spheres at rest ahead of it (y = 0.2), a lone piece moving along +x (y =
// -0.3) and one at rest behind the stern (y = -0.3), while the hull's window sweeps +x. The row beyond the
// front is held out at set-up and enters the scene, at rest where it was, as the front passes it (the front
// follows the moving piece, not only the bow); the piece behind the stern is removed. The pieces in the scene
// move exactly as without the fix (1 and 2 ranks), the counts and the held-out list survive a restart, and
// fix brash/exit is kept informed (it stops a run that loses atoms otherwise).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>

#include "liggghts_runner.h"

using brash::test::fresh_dir;
using brash::test::read_table;
using brash::test::read_text;
using brash::test::run_liggghts;

namespace {
constexpr double kD = 0.02, kU = 0.2, kDt = 1e-4, kAhead = 0.3, kBehind = 0.1, kMoverV = 0.3;
constexpr int kChain = 12, kRow = 13, kSteps = 6000, kHalf = 3000;
constexpr double kChainX0 = 0.05, kRowX0 = 0.35, kRowDx = 0.05, kMoverX0 = 0.2, kBackX = -0.08;
// ids: chain 1..12, row 13..25, the mover 26, the piece behind 27
constexpr int kMover = kChain + kRow + 1, kBack = kMover + 1;

enum class Mode { NoFix, Window };

std::string atoms_and_fixes() {
  std::string s =
      fmt::format(R"(set group all diameter {d} density 900
group pusher id 1
group mover id {mover}
velocity mover set {v} 0 0 units box
neighbor 0.002 bin
neigh_modify delay 0
{contacts}
timestep {dt}
fix integr all nve/sphere
fix push pusher addforce 2e-3 0 0
)",
                  fmt::arg("d", kD), fmt::arg("mover", kMover), fmt::arg("v", kMoverV), fmt::arg("dt", kDt),
                  fmt::arg("contacts", brash::test::ice_contact_model("0.5")));
  return s;
}

std::string window_fixes(Mode mode) {
  if (mode == Mode::NoFix) return "thermo_style custom step atoms\n";
  return fmt::format(
      "fix exit all brash/exit xlo -0.099 xhi 1.099\n"
      "fix w all brash/window every 100 ahead {} behind {} hull_x0 0 speed {} bow_offset 0 stern_offset 0\n"
      "thermo_style custom step atoms f_w[1] f_w[2] f_w[3]\n",
      kAhead, kBehind, kU);
}

std::string scene(Mode mode, int ranks) {
  std::string s = brash::test::box_along_x(1.1, ranks);
  for (int k = 0; k < kChain; ++k)
    s += fmt::format("create_atoms 1 single {} 0 0 units box\n", kChainX0 + kD * k);
  for (int k = 0; k < kRow; ++k)
    s += fmt::format("create_atoms 1 single {} 0.2 0 units box\n", kRowX0 + kRowDx * k);
  s += fmt::format("create_atoms 1 single {} -0.3 0 units box\n", kMoverX0);
  s += fmt::format("create_atoms 1 single {} -0.3 0 units box\n", kBackX);
  s += atoms_and_fixes() + window_fixes(mode);
  s += fmt::format(R"(dump d all custom {half} dump.*.txt id x y z vx vy vz
dump_modify d sort id
thermo 100
run {half}
write_restart half.restart
run {half}
)",
                   fmt::arg("half", kHalf));
  return s;
}

// The second half again, from the restart file written halfway.
std::string resumed_scene(int ranks) {
  std::string s = fmt::format("{}{}read_restart half.restart\n", brash::test::kGranularPreamble,
                              ranks > 1 ? "processors 2 1 1\n" : "");
  s.replace(s.find("atom_style granular\n"), 20, "");
  s += fmt::format(R"(neighbor 0.002 bin
neigh_modify delay 0
{contacts}
timestep {dt}
group pusher id 1
fix integr all nve/sphere
fix push pusher addforce 2e-3 0 0
{fixes}dump d all custom {half} resumed.*.txt id x y z vx vy vz
dump_modify d sort id
thermo 100
run {half} upto
)",
                   fmt::arg("contacts", brash::test::ice_contact_model("0.5")), fmt::arg("dt", kDt),
                   fmt::arg("fixes", window_fixes(Mode::Window)), fmt::arg("half", kSteps));
  return s;
}

struct Piece {
  double x, y, z, vx;
};
std::map<int, Piece> read_dump(const std::filesystem::path& file) {
  std::map<int, Piece> out;
  for (const auto& r : read_table(file))
    if (r.size() == 7) out[static_cast<int>(r[0])] = {r[1], r[2], r[3], r[4]};
  return out;
}

// The last thermo row of a step: step atoms held removed front.
std::vector<double> thermo_at(const std::string& screen, int step) {
  std::istringstream lines(screen);
  std::vector<double> found;
  for (std::string line; std::getline(lines, line);) {
    std::istringstream row(line);
    std::vector<double> v(5);
    if (row >> v[0] >> v[1] >> v[2] >> v[3] >> v[4] && v[0] == step) found = v;
  }
  return found;
}

double row_x(int id) {
  return kRowX0 + kRowDx * (id - kChain - 1);
}

std::map<int, Piece> run_scene(Mode mode, int ranks, const std::filesystem::path& dir) {
  EXPECT_EQ(run_liggghts(dir, scene(mode, ranks), ranks), 0) << read_text(dir / "screen_in.lmp.txt");
  return read_dump(dir / fmt::format("dump.{}.txt", kSteps));
}

}  // namespace

TEST(LiggghtsWindow, HoldsOutTheBedAheadInsertsItAtRestAndRemovesThePiecesBehind) {
  const auto ref = run_scene(Mode::NoFix, 1, fresh_dir("window_nofix"));
  ASSERT_EQ(ref.size(), static_cast<std::size_t>(kBack));
  std::map<int, Piece> ends[2];
  for (int ranks : {1, 2}) {
    const auto dir = fresh_dir(fmt::format("window{}", ranks));
    const auto& end = ends[ranks - 1] = run_scene(Mode::Window, ranks, dir);
    const std::string screen = read_text(dir / "screen_in.lmp.txt");
    // at set-up: the front 0.3 m ahead of the bow (x = 0) and of nothing moving faster than 5 mm/s but the
    // mover (x = 0.2 at 0.3 m/s): x = 0.5; the row's 3 pieces before it stay, its other 10 are held out
    const auto start = read_dump(dir / "dump.0.txt");
    EXPECT_EQ(start.size(), static_cast<std::size_t>(kBack - 10)) << "ranks " << ranks;
    const auto first = thermo_at(screen, 0);
    ASSERT_EQ(first.size(), 5u) << screen;
    EXPECT_EQ(first[2], 10);
    EXPECT_DOUBLE_EQ(first[4], kMoverX0 + kAhead);
    // at the end (t = 0.6 s): the mover at 0.38, so the front at 0.68 (to within the 100-step period); the
    // stern at 0.12, so the piece behind (x = -0.08 < 0.02) is gone
    const auto last = thermo_at(screen, kSteps);
    ASSERT_EQ(last.size(), 5u) << screen;
    const double front = last[4];
    EXPECT_NEAR(front, kMoverX0 + kMoverV * kSteps * kDt + kAhead, kMoverV * 100 * kDt + 1e-9);
    EXPECT_EQ(last[3], 1) << "the piece behind the stern";
    EXPECT_FALSE(end.contains(kBack));
    int held = 0;
    for (int id = kChain + 1; id <= kChain + kRow; ++id) {
      if (row_x(id) >= front) {
        ++held;
        EXPECT_FALSE(end.contains(id)) << "row piece " << id << " beyond the front";
      } else {
        ASSERT_TRUE(end.contains(id)) << "row piece " << id << " before the front";
        EXPECT_DOUBLE_EQ(end.at(id).x, row_x(id)) << "entered where it was held, at rest";
        EXPECT_DOUBLE_EQ(end.at(id).y, 0.2);
        EXPECT_EQ(end.at(id).vx, 0.0);
      }
    }
    EXPECT_EQ(last[2], held);
    EXPECT_GT(held, 3);
    EXPECT_LT(held, 10);
    EXPECT_EQ(last[1], kBack - 1 - held);
    // the pieces in the scene move as without the fix
    for (const auto& [id, p] : end) {
      EXPECT_NEAR(p.x, ref.at(id).x, 1e-9) << "piece " << id << " on " << ranks << " rank(s)";
      EXPECT_NEAR(p.vx, ref.at(id).vx, 1e-9) << "piece " << id << " on " << ranks << " rank(s)";
    }
    EXPECT_GT(end.at(kChain).x, kChainX0 + kD * (kChain - 1) + 1e-3) << "the push reached the chain's end";
  }
  EXPECT_EQ(ends[0].size(), ends[1].size());
}

TEST(LiggghtsWindow, ARestartKeepsTheHeldOutBedAndTheCounts) {
  const auto dir = fresh_dir("window_resume");
  const auto straight = run_scene(Mode::Window, 1, dir);
  ASSERT_EQ(run_liggghts(dir, resumed_scene(1), 1, "in_resumed.lmp"), 0)
      << read_text(dir / "screen_in_resumed.lmp.txt");
  const auto resumed = read_dump(dir / fmt::format("resumed.{}.txt", kSteps));
  ASSERT_EQ(resumed.size(), straight.size());
  for (const auto& [id, p] : straight) {
    ASSERT_TRUE(resumed.contains(id)) << "piece " << id;
    EXPECT_NEAR(resumed.at(id).x, p.x, 1e-9) << "piece " << id;
  }
  const auto a = thermo_at(read_text(dir / "screen_in.lmp.txt"), kSteps);
  const auto b = thermo_at(read_text(dir / "screen_in_resumed.lmp.txt"), kSteps);
  ASSERT_EQ(b.size(), 5u);
  EXPECT_EQ(a, b);
}

TEST(LiggghtsWindow, OrderAndArgumentsAreChecked) {
  const auto dir = fresh_dir("window_bad");
  std::string in = scene(Mode::Window, 1);
  const std::string exit_line = "fix exit all brash/exit xlo -0.099 xhi 1.099\n";
  std::string swapped = in;
  swapped.erase(swapped.find(exit_line), exit_line.size());
  swapped.insert(swapped.find("thermo_style"), exit_line);
  EXPECT_NE(run_liggghts(dir, swapped), 0);
  EXPECT_NE(read_text(dir / "screen_in.lmp.txt").find("define it after fix brash/exit"), std::string::npos);
  std::string bad = in;
  bad.replace(bad.find("ahead 0.3"), 9, "ahead -1");
  EXPECT_NE(run_liggghts(dir, bad), 0);
  EXPECT_NE(read_text(dir / "screen_in.lmp.txt").find("'ahead' and 'behind' must be > 0"), std::string::npos);
}

// With the far field: the held-out pieces are idle ones and enter the scene idle (their group bits are kept), so
// they stay where they were while a force pulls every active piece down; the moving piece stays active.
TEST(LiggghtsWindow, HeldOutIdlePiecesEnterIdle) {
  const auto dir = fresh_dir("window_farfield");
  std::string s = brash::test::box_along_x(1.1, 1);
  for (int k = 0; k < kRow; ++k) s += fmt::format("create_atoms 1 single {} 0.2 0 units box\n", kRowX0 + kRowDx * k);
  s += fmt::format("create_atoms 1 single {} -0.3 0 units box\n", kMoverX0);
  s += fmt::format(R"(set group all diameter {d} density 900
group mover id {mover}
velocity mover set {v} 0 0 units box
group active type 1
group idle subtract all all
neighbor 0.002 bin
neigh_modify delay 0 exclude group idle idle
{contacts}
timestep {dt}
fix ff all brash/farfield every 100 ahead 0.1 behind 1 hull_x0 0 speed {u} bow_offset 0 stern_offset 0 wake_neighbour_speed 0.005
fix exit all brash/exit xlo -0.099 xhi 1.099
fix w all brash/window every 100 ahead {ahead} behind {behind} hull_x0 0 speed {u} bow_offset 0 stern_offset 0
fix integr active nve/sphere
fix pull active addforce 0 0 -1e-4
dump d all custom {steps} dump.*.txt id x y z vx vy vz
dump_modify d sort id
thermo_style custom step atoms f_w[1] f_ff[1]
thermo 100
run {steps}
)",
                   fmt::arg("d", kD), fmt::arg("mover", kRow + 1), fmt::arg("v", kMoverV), fmt::arg("dt", kDt),
                   fmt::arg("contacts", brash::test::ice_contact_model("0.5")), fmt::arg("u", kU),
                   fmt::arg("ahead", kAhead), fmt::arg("behind", kBehind), fmt::arg("steps", kSteps));
  ASSERT_EQ(run_liggghts(dir, s), 0) << read_text(dir / "screen_in.lmp.txt");
  const auto start = read_dump(dir / "dump.0.txt"), end = read_dump(dir / fmt::format("dump.{}.txt", kSteps));
  EXPECT_EQ(start.size(), 4u);  // the mover and the row's 3 pieces before x = 0.5
  ASSERT_GT(end.size(), 7u);    // the front passed more of the row
  for (const auto& [id, p] : end) {
    if (id == kRow + 1) {
      EXPECT_LT(p.z, -1e-3) << "the moving piece is active";
    } else {
      EXPECT_EQ(p.z, 0.0) << "row piece " << id << " entered active";
      EXPECT_DOUBLE_EQ(p.x, kRowX0 + kRowDx * (id - 1));
    }
  }
}
