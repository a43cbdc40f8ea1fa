// fix brash/farfield (speedups.farfield) on a tiny scene: a row of separated spheres along x, pushed along
// +y by a force on group `active` only, while a "hull" window [U t - behind, U t + bow + ahead] sweeps +x.
// Idle spheres do not move and have zero velocity, active ones move, membership follows the hull, and
// idle-idle pairs leave the neighbour list at the next build after their mask bits change (1 and 2 ranks).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <regex>
#include <sstream>

#include "liggghts_runner.h"

using brash::test::fresh_dir;
using brash::test::read_table;
using brash::test::read_text;
using brash::test::run_liggghts;

namespace {
constexpr double kD = 0.02, kU = 0.5, kDt = 1e-3;
constexpr int kSteps = 1000;
// window at time t: x in [U t + stern - behind, U t + bow + ahead] with stern 0, bow 0.1, ahead 0.2, behind 0.1
constexpr double kAhead = 0.2, kBehind = 0.1, kBow = 0.1;

std::string scene(bool farfield, int ranks) {
  std::string s = brash::test::box_along_x(1.1, ranks);
  // 20 separated spheres (ids 1..20) at x = 0.025 + 0.05 k, then three touching pairs (ids 21..26):
  // at x = 0.05 (active, then left behind), 0.6 (idle, then reached), 0.95 (idle throughout).
  for (int k = 0; k < 20; ++k) s += fmt::format("create_atoms 1 single {} 0 0 units box\n", 0.025 + 0.05 * k);
  for (double x : {0.05, 0.6, 0.95})
    s += fmt::format("create_atoms 1 single {0} 0.2 0 units box\ncreate_atoms 1 single {0} {1} 0 units box\n", x,
                     0.2 + kD);
  s += fmt::format(R"(set group all diameter {d} density 900
{groups}neighbor 0.002 bin
neigh_modify delay 0{exclude}
{contacts}
timestep {dt}
{ff}fix integr {grp} nve/sphere
fix push {grp} addforce 0 1e-3 0
dump d all custom {steps} dump.*.txt id x y z vx vy vz
dump_modify d sort id
thermo_style custom step atoms {thermo}
thermo 100
run {steps}
)",
                     fmt::arg("contacts", brash::test::ice_contact_model("0.5")),
                   fmt::arg("d", kD), fmt::arg("dt", kDt), fmt::arg("steps", kSteps),
                   fmt::arg("groups", farfield ? "group active type 1\ngroup idle subtract all all\n" : ""),
                   fmt::arg("exclude", farfield ? " exclude group idle idle" : ""),
                   fmt::arg("ff", farfield ? fmt::format("fix ff all brash/farfield every 10 ahead {} behind {} hull_x0 0 "
                                                         "speed {} bow_offset {} stern_offset 0\n",
                                                         kAhead, kBehind, kU, kBow)
                                           : ""),
                   fmt::arg("grp", farfield ? "active" : "all"), fmt::arg("thermo", farfield ? "f_ff[1] f_ff[2]" : "ke"));
  return s;
}

struct Atom {
  double x, y, vy, vx;
};
std::map<int, Atom> read_dump(const std::filesystem::path& file) {
  std::map<int, Atom> out;
  for (const auto& r : read_table(file))
    if (r.size() == 7) out[static_cast<int>(r[0])] = {r[1], r[2], r[5], r[4]};
  return out;
}

long total_neighbors(const std::string& screen) {
  const auto pos = screen.rfind("Total # of neighbors = ");
  if (pos == std::string::npos) return -1;
  return std::stol(screen.substr(pos + 23));
}

void check_farfield(int ranks) {
  const auto dir = fresh_dir(fmt::format("farfield{}", ranks));
  ASSERT_EQ(run_liggghts(dir, scene(true, ranks), ranks), 0) << read_text(dir / "screen_in.lmp.txt");
  const auto start = read_dump(dir / "dump.0.txt"), end = read_dump(dir / fmt::format("dump.{}.txt", kSteps));
  ASSERT_EQ(start.size(), 26u);
  ASSERT_EQ(end.size(), 26u);
  // last membership update at step 1000 (t = 1 s): window [0.4, 0.8]; the one before, at step 990, set who
  // was integrated during the last 10 steps.
  const double t_end = kSteps * kDt, lo = kU * t_end - kBehind, hi = kU * t_end + kBow + kAhead;
  int idle = 0;
  for (const auto& [id, a] : end) {
    const Atom& a0 = start.at(id);
    const bool idle_now = a.x < lo || a.x > hi;
    const bool idle_always = a0.x > kU * 0.99 + kBow + kAhead + 1e-9;  // ahead of the window all run long
    if (idle_now) {
      ++idle;
      EXPECT_EQ(a.vy, 0.0) << "idle atom " << id << " at x = " << a.x << " still moves";
    }
    if (idle_always) {
      EXPECT_EQ(a.y, a0.y) << "atom " << id << " at x = " << a0.x << " was idle but moved";
    }
    const bool active_before = a.x >= kU * 0.99 - kBehind && a.x <= kU * 0.99 + kBow + kAhead;  // at step 990
    if (!idle_now && active_before) {
      EXPECT_GT(a.vy, 0.0) << "active atom " << id << " at x = " << a.x << " does not move";
    }
    if (a0.x < kBow + kAhead && a0.x > 0) {  // active at the start: was pushed, then left behind and stopped
      EXPECT_GT(a.y, a0.y + 1e-3) << "atom " << id << " at x = " << a0.x << " was active at the start";
    }
  }
  const std::string screen = read_text(dir / "screen_in.lmp.txt");
  EXPECT_GT(idle, 10);
  // Only the pair at x = 0.6 is active at the end: the pair left behind (made idle by a mask change) and the
  // pair idle from the start are not in the neighbour list.
  EXPECT_EQ(total_neighbors(screen), 1) << screen;
}

}  // namespace

TEST(LiggghtsFarfield, IdleAtomsStillActiveAtomsMoveOneRank) { check_farfield(1); }
TEST(LiggghtsFarfield, IdleAtomsStillActiveAtomsMoveTwoRanks) { check_farfield(2); }

TEST(LiggghtsFarfield, WithoutTheFixAllPairsAreNeighbours) {
  const auto dir = fresh_dir("farfield_off");
  ASSERT_EQ(run_liggghts(dir, scene(false, 1)), 0) << read_text(dir / "screen_in.lmp.txt");
  EXPECT_EQ(total_neighbors(read_text(dir / "screen_in.lmp.txt")), 3);
}

TEST(LiggghtsFarfield, BadArgumentsAreNamed) {
  const auto dir = fresh_dir("farfield_bad");
  std::string in = scene(true, 1);
  const auto pos = in.find("fix ff all brash/farfield");
  const auto eol = in.find('\n', pos);
  in.replace(pos, eol - pos, "fix ff all brash/farfield every 10 ahead 0.2 behind 0.1 speed 0.5 bow_offset 0.1 stern_offset 0");
  EXPECT_NE(run_liggghts(dir, in), 0);
  EXPECT_NE(read_text(dir / "screen_in.lmp.txt").find("are required"), std::string::npos);
  in.replace(pos, in.find('\n', pos) - pos, "fix ff all brash/farfield every 10 ahead 0.2 behind 0.1 hull_x0 0 speed 0.5 "
                                           "bow_offset 0.1 stern_offset 0 idle nosuchgroup");
  EXPECT_NE(run_liggghts(dir, in), 0);
  EXPECT_NE(read_text(dir / "screen_in.lmp.txt").find("must exist"), std::string::npos);
}

// wake_speed / wake_force: a chain of 12 touching spheres along x, the first one pushed along +x (2e-3 N), the
// window (fixed ship) covering only the first two. With the window alone the third sphere is an immovable wall;
// with wake_force 1e-4 N the push travels down the chain (each pushed idle piece wakes), as without the fix.
// Two lone spheres outside the window: one at rest (stays idle), one moving at 0.01 m/s (stays active).
namespace {
constexpr int kChain = 12;
constexpr double kWakeSteps = 6000, kChainDt = 1e-4;  // dt well below the contacts' Rayleigh time (~7e-4 s)

// NoFix: every piece active (the reference); WindowAlone: the fix without a wake; Wake: wake_force 1e-4 N, wake_speed
// 0.001 m/s; WakeNeighbour: wake_neighbour_speed 1e-4 m/s. An idle piece is a wall until the piece pushing it is
// faster than V: the chain, started from rest, lags 0.16 mm (2 % of its travel) behind the reference at V = 1e-3
// m/s, and moves with it within 1 % at 1e-4 (what the rule's speed does to the resistance: docs/performance.md).
enum class Chain { NoFix, WindowAlone, Wake, WakeNeighbour };

std::string wake_keywords(Chain mode) {
  if (mode == Chain::Wake) return " wake_speed 0.001 wake_force 1e-4";
  if (mode == Chain::WakeNeighbour) return " wake_neighbour_speed 1e-4";
  return "";
}

std::string chain_scene(Chain mode, int ranks) {
  std::string s = brash::test::box_along_x(0.5, ranks);
  for (int k = 0; k < kChain; ++k) s += fmt::format("create_atoms 1 single {} 0 0 units box\n", 0.01 + kD * k);
  s += "create_atoms 1 single 0.4 0.3 0 units box\ncreate_atoms 1 single 0.4 -0.3 0 units box\n";
  s += fmt::format(R"(set group all diameter {d} density 900
group active type 1
group idle subtract all all
group pusher id 1
group mover id {mover}
velocity mover set 0.01 0 0 units box
neighbor 0.002 bin
neigh_modify delay 0 exclude group idle idle
{contacts}
timestep {dt}
{ff}fix integr active nve/sphere
fix push pusher addforce 2e-3 0 0
dump d all custom {steps} dump.*.txt id x y z vx vy vz
dump_modify d sort id
thermo_style custom step atoms{ff_thermo}
thermo 100
run {steps}
)",
                   fmt::arg("d", kD), fmt::arg("mover", kChain + 2), fmt::arg("dt", kChainDt),
                   fmt::arg("steps", static_cast<int>(kWakeSteps)),
                   fmt::arg("contacts", brash::test::ice_contact_model("0.5")),
                   fmt::arg("ff", mode == Chain::NoFix ? ""
                                  : "fix ff all brash/farfield every 100 ahead 0.035 behind 1 hull_x0 0 speed 0 "
                                    "bow_offset 0 stern_offset 0" +
                                        wake_keywords(mode) + "\n"),
                   fmt::arg("ff_thermo", mode == Chain::NoFix ? "" : " f_ff[1] f_ff[2]"));
  return s;
}

std::map<int, Atom> run_chain(Chain mode, int ranks, const std::string& name) {
  const auto dir = fresh_dir(name);
  EXPECT_EQ(run_liggghts(dir, chain_scene(mode, ranks), ranks), 0) << read_text(dir / "screen_in.lmp.txt");
  return read_dump(dir / fmt::format("dump.{}.txt", static_cast<int>(kWakeSteps)));
}
}  // namespace

TEST(LiggghtsFarfield, WindowAloneMakesAnIdleWall) {
  const auto end = run_chain(Chain::WindowAlone, 1, "farfield_chain_window");
  ASSERT_EQ(end.size(), static_cast<std::size_t>(kChain + 2));
  for (int id = 3; id <= kChain; ++id)  // idle from the start: never moved
    EXPECT_DOUBLE_EQ(end.at(id).x, 0.01 + kD * (id - 1)) << "atom " << id;
  EXPECT_DOUBLE_EQ(end.at(kChain + 2).x, 0.4) << "a lone moving piece outside the window is frozen";
}

void check_push_travels(Chain mode, const std::string& name) {
  const double t_end = kWakeSteps * kChainDt;
  std::map<int, Atom> ends[2];
  for (int ranks : {1, 2}) {
    const auto& end = ends[ranks - 1] = run_chain(mode, ranks, fmt::format("{}{}", name, ranks));
    ASSERT_EQ(end.size(), static_cast<std::size_t>(kChain + 2));
    for (int id = 2; id <= kChain; ++id)
      EXPECT_GT(end.at(id).x, 0.01 + kD * (id - 1) + 1e-3) << "atom " << id << " on " << ranks << " rank(s)";
    EXPECT_DOUBLE_EQ(end.at(kChain + 1).x, 0.4) << "a lone piece at rest outside the window stays idle";
    EXPECT_NEAR(end.at(kChain + 2).x, 0.4 + 0.01 * t_end, 1e-9) << "a lone moving piece stays active";
  }
  // the same membership on 1 and 2 ranks (the chain crosses the rank boundary at x = 0.2): same trajectory
  for (const auto& [id, a] : ends[0]) EXPECT_NEAR(a.x, ends[1].at(id).x, 1e-9) << "atom " << id;
  // and the chain's push as without the fix (observed within 0.13 %; the window alone: not at all)
  const auto ref = run_chain(Chain::NoFix, 1, "farfield_chain_nofix");
  for (int id = 1; id <= kChain; ++id) {
    const double x0 = 0.01 + kD * (id - 1), moved_ref = ref.at(id).x - x0, moved = ends[0].at(id).x - x0;
    EXPECT_GT(moved_ref, 1e-3);
    EXPECT_NEAR(moved, moved_ref, 0.01 * moved_ref) << "atom " << id;
  }
}

TEST(LiggghtsFarfield, WakeForceLetsThePushTravelOneAndTwoRanks) {
  check_push_travels(Chain::Wake, "farfield_chain_wake");
}

TEST(LiggghtsFarfield, WakeNeighbourSpeedLetsThePushTravelOneAndTwoRanks) {
  check_push_travels(Chain::WakeNeighbour, "farfield_chain_neighbour");
}

// A loaded bed at rest: the chain pressed against a wall at its far end by the push on its first sphere, settled
// with every piece active (viscous damping), then the fix with the window over the first two spheres. The idle
// third sphere feels the second one's contact force but not its idle neighbour's (idle-idle pairs are excluded):
// the force rule wakes it, and so on down the resting chain; the neighbour-speed rule leaves the chain idle.
namespace {
constexpr int kSettleSteps = 20000, kLoadedSteps = 2000;

std::string loaded_chain_scene(Chain mode) {
  std::string s = brash::test::box_along_x(0.5, 1);
  for (int k = 0; k < kChain; ++k) s += fmt::format("create_atoms 1 single {} 0 0 units box\n", 0.01 + kD * k);
  s += fmt::format(R"(set group all diameter {d} density 900
group pusher id 1
neighbor 0.002 bin
neigh_modify delay 0
{contacts}
fix end all wall/gran model hertz tangential history primitive type 1 xplane {wall_x}
timestep {dt}
fix push pusher addforce 2e-3 0 0
fix settle all nve/sphere
fix calm all viscous 0.05
dump d all custom {every} dump.*.txt id x y z vx vy vz
dump_modify d sort id
run {settle}
unfix settle
unfix calm
group active type 1
group idle subtract all all
neigh_modify exclude group idle idle
fix ff all brash/farfield every 100 ahead 0.035 behind 1 hull_x0 0 speed 0 bow_offset 0 stern_offset 0{wake}
fix integr active nve/sphere
thermo_style custom step atoms f_ff[1] f_ff[2]
thermo 100
run {loaded}
)",
                   fmt::arg("d", kD), fmt::arg("wall_x", 0.01 + kD * (kChain - 1) + kD / 2), fmt::arg("dt", kChainDt),
                   fmt::arg("contacts", brash::test::ice_contact_model("0.5")), fmt::arg("every", kLoadedSteps),
                   fmt::arg("settle", kSettleSteps), fmt::arg("loaded", kLoadedSteps),
                   fmt::arg("wake", wake_keywords(mode)));
  return s;
}

// The idle count (f_ff[1]) on the thermo line of the run's last step (step atoms f_ff[1] f_ff[2]); -1 if none.
double last_idle_count(const std::string& screen) {
  std::istringstream lines(screen);
  double idle = -1;
  for (std::string line; std::getline(lines, line);) {
    std::istringstream row(line);
    double step = 0, atoms = 0, count = 0, changed = 0;
    if (row >> step >> atoms >> count >> changed && step == kSettleSteps + kLoadedSteps) idle = count;
  }
  return idle;
}
}  // namespace

TEST(LiggghtsFarfield, WakeNeighbourSpeedLeavesALoadedBedAtRestIdle) {
  for (Chain mode : {Chain::WakeNeighbour, Chain::Wake}) {
    const bool by_neighbour = mode == Chain::WakeNeighbour;
    const auto dir = fresh_dir(by_neighbour ? "farfield_loaded_neighbour" : "farfield_loaded_force");
    ASSERT_EQ(run_liggghts(dir, loaded_chain_scene(mode)), 0) << read_text(dir / "screen_in.lmp.txt");
    const auto settled = read_dump(dir / fmt::format("dump.{}.txt", kSettleSteps));
    const auto end = read_dump(dir / fmt::format("dump.{}.txt", kSettleSteps + kLoadedSteps));
    ASSERT_EQ(end.size(), static_cast<std::size_t>(kChain));
    // settled: pressed together (each contact overlaps) and at rest
    EXPECT_LT(settled.at(kChain).x - settled.at(1).x, kD * (kChain - 1) - 1e-6);
    for (const auto& [id, a] : settled) EXPECT_LT(std::abs(a.vx), 1e-4) << "atom " << id;
    const double idle = last_idle_count(read_text(dir / "screen_in.lmp.txt"));
    if (by_neighbour) {
      EXPECT_EQ(idle, kChain - 2);
      for (int id = 3; id <= kChain; ++id)
        EXPECT_DOUBLE_EQ(end.at(id).x, settled.at(id).x) << "idle atom " << id << " moved";
    } else {
      EXPECT_EQ(idle, 0) << "the force rule wakes the resting chain through its contacts";
    }
  }
}

TEST(LiggghtsFarfield, WakeSpeedMustNotBeNegative) {
  const auto dir = fresh_dir("farfield_wake_bad");
  std::string in = chain_scene(Chain::Wake, 1);
  const auto pos = in.find("wake_speed 0.001");
  in.replace(pos, 16, "wake_speed -1");
  EXPECT_NE(run_liggghts(dir, in), 0);
  EXPECT_NE(read_text(dir / "screen_in.lmp.txt").find("'wake_speed' must be >= 0"), std::string::npos);
}

// beside H: a resting piece with |y| > H goes idle at the first update (no faster than the wake speed), one inside
// |y| <= H stays active; both lie within the window along x. The push on group `active` then moves only the one
// inside, and the thermo's idle count is 1.
TEST(LiggghtsFarfield, BesideTheHullIdlesThePieceBeyondTheHalfWidth) {
  const auto dir = fresh_dir("farfield_beside");
  std::string s = brash::test::box_along_x(1.1, 1);
  s += "create_atoms 1 single 0.1 0 0 units box\ncreate_atoms 1 single 0.1 0.3 0 units box\n";
  s += fmt::format(R"(set group all diameter {d} density 900
group active type 1
group idle subtract all all
neighbor 0.002 bin
neigh_modify delay 0 exclude group idle idle
{contacts}
timestep {dt}
fix ff all brash/farfield every 10 ahead 0.5 behind 0.5 beside 0.2 hull_x0 0 speed 0 bow_offset 0.1 stern_offset 0 wake_neighbour_speed 0.005
fix integr active nve/sphere
fix push active addforce 1e-3 0 0
dump d all custom 100 dump.*.txt id x y z vx vy vz
dump_modify d sort id
thermo_style custom step atoms f_ff[1]
thermo 100
run 100
)",
                   fmt::arg("contacts", brash::test::ice_contact_model("0.5")), fmt::arg("d", kD), fmt::arg("dt", kDt));
  ASSERT_EQ(run_liggghts(dir, s), 0) << read_text(dir / "screen_in.lmp.txt");
  const auto start = read_dump(dir / "dump.0.txt"), end = read_dump(dir / "dump.100.txt");
  ASSERT_EQ(end.size(), 2u);
  EXPECT_GT(end.at(1).x, start.at(1).x + 1e-4);  // inside: pushed
  EXPECT_EQ(end.at(2).x, start.at(2).x);         // beside: idle
  EXPECT_EQ(end.at(2).vx, 0.0);
  const std::string screen = read_text(dir / "screen_in.lmp.txt");
  EXPECT_TRUE(std::regex_search(screen, std::regex(R"(\n\s*100\s+2\s+1\s*\n)"))) << screen;  // step, atoms, idle
}
