// brash-ode's cull with the far-field rule of brash/core/far_field.hpp, as tests/liggghts/test_farfield.cpp
// shows it for fix brash/farfield: a box hull at 0.05 m/s pushes a chain of 12 touching floating spheres
// along x, the window (0.035 m ahead of the bow) covering the first two. With the window alone the culled
// spheres are an immovable wall (the hull's mean force ~2000x that without the cull); with the wake rule
// (wake force 1e-4 N) each pushed culled sphere wakes and the whole chain is pushed along. ODE's contacts are
// hard: a culled sphere is a wall for the one step in which its force is measured, which stops the pushed
// chain once per woken sphere (observed: mean hull force 0.060 N with the wake, 0.0056 N without the cull,
// 12 N with the window alone; the spheres ahead are kicked up to 0.027 m further). Two lone spheres outside
// the window: one at rest (stays culled), one moving at 0.01 m/s (stays active).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "brash/core/reference.hpp"
#include "brash/ode/world.hpp"

using namespace brash::ode;
using brash::core::Vec3;

namespace {
constexpr int kChain = 12;
constexpr double kR = 0.01, kSpeed = 0.05, kSteps = 2000;  // 1 s at dt 5e-4 s
enum class Cull { None, WindowAlone, Wake, WakeNeighbour, PushFront };

struct End {
  std::vector<Vec3> x;       // chain, then the lone sphere at rest, then the moving one
  std::vector<bool> culled;
  double mean_fx_N = 0;      // hull force along x over the run
  long woken = 0;
};

// Box x in [-0.06, 0], |y|, |z| <= 0.03 (outward triangles), bow at x = 0.
void add_box_hull(World& w) {
  std::vector<double> v;
  for (int i = 0; i < 8; ++i)
    v.insert(v.end(), {i & 1 ? 0.0 : -0.06, i & 2 ? 0.03 : -0.03, i & 4 ? 0.03 : -0.03});
  std::vector<dTriIndex> t = {0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4,
                              2, 6, 7, 2, 7, 3, 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6};
  w.set_hull(std::move(v), std::move(t), Vec3::Zero(), Vec3(kSpeed, 0, 0));
}

// gap_m: the chain's spheres that far apart instead of touching
End run_chain(Cull mode, double gap_m = 0) {
  static OdeLibrary lib;
  Skips k;
  k.cull = mode != Cull::None;
  k.cull_ahead_m = 0.035;
  if (mode == Cull::Wake) k.wake_force_N = 1e-4, k.wake_speed_m_s = 0.001;
  if (mode == Cull::WakeNeighbour) k.wake_by = brash::WakeBy::NeighbourSpeed, k.wake_speed_m_s = 0.001;
  if (mode == Cull::PushFront)
    k.wake_by = brash::WakeBy::PushFront, k.wake_force_N = 1e-4, k.wake_speed_m_s = 0.001, k.front_speed_m_s = 0.001;
  // 20 quickstep iterations: the window alone's wall is a jam of hard contacts, whose reaction the default 8
  // iterations leave unconverged (2.6 N instead of 12 N, 490x the free push); the cull is the same either way
  StepperSettings st;
  st.iterations = 20;
  World w(brash::core::FluidParams{}, st, Frictions{}, k);
  const double z = kR - brash::core::analytic::height_for_fraction(kR, 0.9);  // floating
  for (int i = 0; i < kChain; ++i) w.add_sphere(Vec3(0.001 + kR + (2 * kR + gap_m) * i, 0, z), kR, 900);
  w.add_sphere(Vec3(0.4, 0.1, z), kR, 900);
  w.add_sphere(Vec3(0.4, -0.1, z), kR, 900, Vec3(0.01, 0, 0));
  add_box_hull(w);
  End e;
  for (int s = 0; s < kSteps; ++s) {
    w.step();
    e.mean_fx_N += w.hull_force().x() / kSteps;
  }
  for (std::size_t i = 0; i < w.size(); ++i) e.x.push_back(w.position(i)), e.culled.push_back(w.culled(i));
  e.woken = w.stats().woken;
  std::printf("[cull %d] mean hull fx %.6g N, woken %ld\n", static_cast<int>(mode), e.mean_fx_N, e.woken);
  return e;
}

double x0(int i, double gap_m = 0) { return 0.001 + kR + (2 * kR + gap_m) * i; }
}  // namespace

TEST(OdeFarField, WindowAloneMakesAnImmovableWall) {
  const End e = run_chain(Cull::WindowAlone);
  // the window's front ends at 0.05 + 0.035 m: the spheres beyond it never moved
  for (int i = 0; i < kChain; ++i) {
    if (x0(i) <= 0.085 + kR) continue;
    EXPECT_EQ(e.x[i].x(), x0(i)) << "sphere " << i;
  }
  EXPECT_EQ(e.x[kChain + 1].x(), 0.4) << "a lone moving sphere outside the window is frozen";
  EXPECT_EQ(e.woken, 0);
}

namespace {
void check_push_travels(Cull mode) {
  const End e = run_chain(mode), ref = run_chain(Cull::None), wall = run_chain(Cull::WindowAlone);
  for (int i = 0; i < kChain; ++i) {
    const double moved_ref = ref.x[i].x() - x0(i), moved = e.x[i].x() - x0(i);
    EXPECT_GT(moved_ref, 0.045) << "sphere " << i;  // without the cull: pushed 0.049 m or more
    EXPECT_GT(moved, 0.95 * moved_ref) << "sphere " << i;
    EXPECT_FALSE(e.culled[i]) << "sphere " << i;
  }
  EXPECT_EQ(e.woken, kChain - 2);  // every chain sphere beyond the first window, once
  EXPECT_EQ(e.x[kChain].x(), 0.4) << "a lone sphere at rest outside the window stays culled";
  EXPECT_TRUE(e.culled[kChain]);
  EXPECT_FALSE(e.culled[kChain + 1]) << "a lone moving sphere stays active";
  EXPECT_NEAR(e.x[kChain + 1].x(), ref.x[kChain + 1].x(), 1e-12);
  EXPECT_GT(e.x[kChain + 1].x(), 0.4 + 1e-3);
  // the hull's mean force: the window alone's wall against the chain's drag, and the wake's one-step stops
  EXPECT_GT(wall.mean_fx_N / ref.mean_fx_N, 1000);
  EXPECT_LT(e.mean_fx_N / wall.mean_fx_N, 0.01);
}

}  // namespace

TEST(OdeFarField, WakeRuleLetsThePushTravel) { check_push_travels(Cull::Wake); }

// By a neighbour's speed: a culled sphere wakes when the active sphere of one of its contacts moves faster
// than 0.001 m/s after the step.
TEST(OdeFarField, WakeByNeighbourSpeedLetsThePushTravel) { check_push_travels(Cull::WakeNeighbour); }

// By the push front: the window's front lies 0.035 m ahead of the foremost active sphere faster than 0.001 m/s, so
// the chain the hull pushes is taken into the window as it starts to move; nothing wakes by the rule ahead of the
// bow. The chain's spheres lie 3 mm apart, as the pieces of a bed with voids.
TEST(OdeFarField, PushFrontTakesThePushedChainIntoTheWindow) {
  constexpr double kGap = 0.003;
  const End e = run_chain(Cull::PushFront, kGap), ref = run_chain(Cull::None, kGap),
            wall = run_chain(Cull::WindowAlone, kGap);
  for (int i = 0; i < kChain; ++i) {
    EXPECT_GT(ref.x[i].x() - x0(i, kGap), 0.01) << "sphere " << i;  // without the cull: pushed 0.016 m or more
    EXPECT_GT(e.x[i].x() - x0(i, kGap), 0.95 * (ref.x[i].x() - x0(i, kGap))) << "sphere " << i;
  EXPECT_FALSE(e.culled[i]) << "sphere " << i;
  }
  EXPECT_EQ(e.woken, 0);
  // the bed ahead is held out from the start, moving or not: the lone moving sphere too (it stays at
  // x = 0.4 m; the front, 0.035 m ahead of the pushed chain, does not reach it)
  EXPECT_TRUE(e.culled[kChain + 1]) << "a lone moving sphere far ahead is held out";
  EXPECT_EQ(e.x[kChain + 1].x(), 0.4);
  EXPECT_TRUE(e.culled[kChain]);
  EXPECT_EQ(e.x[kChain].x(), 0.4);
  EXPECT_LT(e.mean_fx_N / wall.mean_fx_N, 0.01);
}

namespace {
// A loaded bed at rest: a floating row of 16 touching spheres in a narrow channel, held by an end wall against a
// current of 0.05 m/s along x, so that every contact carries the drag of the spheres upstream of it (up to 15
// times 1.6e-4 N, against a wake force of 3.7e-5 N). It is settled with every sphere integrated (damped, then
// undamped), then run again from rest with the cull: the box hull at rest beside it, its window over the first
// spheres upstream, the rest culled and pressed by the active ones through resting contacts.
constexpr int kBed = 16;
constexpr double kBedX0 = 0.02;   // first sphere's centre; the bow is at x = 0
constexpr double kAhead = 0.045;  // the window: x < 0.045, the first two spheres

struct Bed {
  std::vector<Vec3> x;
  double max_speed_m_s = 0;
};

brash::core::FluidParams current() {
  brash::core::FluidParams f;
  f.flow_velocity_m_s = Vec3(0.05, 0, 0);
  return f;
}

void add_bed_walls(World& w) {
  w.add_wall_box(Vec3(kBedX0 + 2 * kR * (kBed - 1) + kR + 0.005, 0, 0), Vec3(0.01, 0.2, 0.2));
  w.add_wall_box(Vec3(0.2, kR + 0.005, 0), Vec3(0.5, 0.01, 0.2));
  w.add_wall_box(Vec3(0.2, -kR - 0.005, 0), Vec3(0.5, 0.01, 0.2));
}

Bed settled_bed() {
  static OdeLibrary lib;
  World w(current(), StepperSettings{}, Frictions{});
  const double z = kR - brash::core::analytic::height_for_fraction(kR, 0.9);
  for (int i = 0; i < kBed; ++i) w.add_sphere(Vec3(kBedX0 + 2 * kR * i, 0, z), kR, 900);
  add_bed_walls(w);
  w.set_damping(0.02, 0.02);
  for (int s = 0; s < 4000; ++s) w.step();
  w.set_damping(0, 0);
  for (int s = 0; s < 2000; ++s) w.step();
  Bed b;
  for (std::size_t i = 0; i < w.size(); ++i) {
    b.x.push_back(w.position(i));
    b.max_speed_m_s = std::max(b.max_speed_m_s, w.velocity(i).norm());
  }
  return b;
}

struct BedRun {
  long woken = 0;
  std::size_t culled_end = 0;
  std::size_t culled_while_settling = 0;  // most spheres culled in a step before the cull began
  std::size_t ahead_at_cull_start = 0;    // spheres beyond the window's 0.045 m when the cull began
  double max_culled_shift_m = 0;  // largest move of a sphere culled at the end, since the cull began
  double max_settle_shift_m = 0;  // largest move of a sphere while settling
};

// settle_steps: the whole bed integrated that many steps before the cull begins (World::begin_cull_at_step)
BedRun run_bed(const Bed& bed, brash::WakeBy by, long settle_steps = 0) {
  static OdeLibrary lib;
  Skips k;
  k.cull = true;
  k.cull_ahead_m = kAhead;
  k.wake_by = by;
  k.wake_force_N = 1e-3 * 900 * (4.0 / 3.0 * M_PI * kR * kR * kR) * 9.81;  // the case's default, 1e-3 weight
  k.wake_speed_m_s = 0.005;
  k.front_speed_m_s = 0.005;
  World w(current(), StepperSettings{}, Frictions{}, k);
  for (const Vec3& x : bed.x) w.add_sphere(x, kR, 900);
  add_bed_walls(w);
  std::vector<double> v;
  for (int i = 0; i < 8; ++i)
    v.insert(v.end(), {i & 1 ? 0.0 : -0.06, i & 2 ? 0.03 : -0.03, i & 4 ? 0.03 : -0.03});
  std::vector<dTriIndex> t = {0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4,
                              2, 6, 7, 2, 7, 3, 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6};
  w.set_hull(std::move(v), std::move(t), Vec3(0, 0.2, 0), Vec3::Zero());  // beside the bed: it touches nothing
  w.begin_cull_at_step(settle_steps);
  BedRun r;
  std::vector<Vec3> at_cull_start = bed.x;
  for (long s = 0; s < settle_steps; ++s) {
    w.step();
    std::size_t culled = 0;
    for (std::size_t i = 0; i < w.size(); ++i) culled += w.culled(i);
    r.culled_while_settling = std::max(r.culled_while_settling, culled);
  }
  for (std::size_t i = 0; i < w.size(); ++i) {
    at_cull_start[i] = w.position(i);
    r.max_settle_shift_m = std::max(r.max_settle_shift_m, (at_cull_start[i] - bed.x[i]).norm());
    r.ahead_at_cull_start += at_cull_start[i].x() > kAhead + kR;  // wholly beyond the window
  }
  for (int s = 0; s < 2000; ++s) w.step();
  r.woken = w.stats().woken;
  for (std::size_t i = 0; i < w.size(); ++i)
    if (w.culled(i)) {
      ++r.culled_end;
      r.max_culled_shift_m = std::max(r.max_culled_shift_m, (w.position(i) - at_cull_start[i]).norm());
    }
  std::printf("[loaded bed, wake by %s, settled %ld steps first] woken %ld, culled at the end %zu of %zu, largest "
              "shift of a culled one %.3g m (while settling: %.3g m, culled %zu)\n",
              std::string(brash::to_string(by)).c_str(), settle_steps, r.woken, r.culled_end, w.size(),
              r.max_culled_shift_m, r.max_settle_shift_m, r.culled_while_settling);
  return r;
}

// The row as placed, floating 0.5 mm apart, its last sphere at the end wall: the current has yet to close the gaps
Bed unsettled_bed() {
  Bed b;
  const double z = kR - brash::core::analytic::height_for_fraction(kR, 0.9);
  for (int i = 0; i < kBed; ++i) b.x.emplace_back(kBedX0 + 2 * kR * (kBed - 1) - (2 * kR + 5e-4) * (kBed - 1 - i), 0, z);
  return b;
}
}  // namespace

// The force rule wakes a resting bed through its resting contacts (the load a culled sphere gets from its active
// neighbours is unbalanced: its culled neighbours' side is not computed); the push front wakes nothing ahead of the
// bow and, with nothing moving, stays where it is, so the bed stays culled.
TEST(OdeFarField, PushFrontLeavesALoadedBedAtRestCulled) {
  const Bed bed = settled_bed();
  std::printf("[loaded bed] settled: largest speed %.3g m/s\n", bed.max_speed_m_s);
  ASSERT_LT(bed.max_speed_m_s, 1e-4);
  const BedRun by_force = run_bed(bed, brash::WakeBy::Force);
  const BedRun by_front = run_bed(bed, brash::WakeBy::PushFront);
  EXPECT_GT(by_force.woken, 10) << "the resting contacts wake the bed by force";
  const auto outside = std::count_if(bed.x.begin(), bed.x.end(), [](const Vec3& x) { return x.x() > kAhead; });
  EXPECT_EQ(outside, kBed - 2);
  // the push front: nothing moves, so the front stays 0.045 m ahead of the bow; nothing wakes ahead of it
  EXPECT_EQ(by_front.woken, 0);
  EXPECT_EQ(by_front.culled_end, static_cast<std::size_t>(outside));
  EXPECT_EQ(by_front.max_culled_shift_m, 0.0);
}

// A far field that begins after a settling (brash-ode --settle) integrates the whole bed until then: the row as
// placed drifts with the current against the end wall and comes to rest there, every sphere stepped; then the cull
// takes the resting ice out where it lies, and the push front wakes none of it.
TEST(OdeFarField, SettlingBeforeTheCullIntegratesTheWholeBed) {
  const Bed placed = unsettled_bed();
  constexpr long kSettle = 4000;  // 2 s at dt 5e-4 s
  const BedRun settled_first = run_bed(placed, brash::WakeBy::PushFront, kSettle);
  EXPECT_EQ(settled_first.culled_while_settling, 0u);
  EXPECT_GT(settled_first.max_settle_shift_m, 0.007) << "the row closes its 15 gaps of 0.5 mm while settling";
  EXPECT_GE(settled_first.culled_end, settled_first.ahead_at_cull_start);
  EXPECT_GE(settled_first.ahead_at_cull_start, static_cast<std::size_t>(kBed - 3));
  EXPECT_EQ(settled_first.woken, 0);
  EXPECT_EQ(settled_first.max_culled_shift_m, 0.0);
}

namespace {
// Floating spheres ahead of the box hull at rest (its window: 0.035 m): one at rest at x = 0.06 m, beyond the
// window; one at (mover_x_m, 0.1 m) moving at mover_m_s along x; one heaving at 0.02 m/s at (0.03 m, -0.1 m),
// in the window. Returns whether the resting one is culled after 0.1 s (membership every 20 steps).
bool resting_sphere_culled(double mover_x_m, double mover_m_s) {
  static OdeLibrary lib;
  Skips k;
  k.cull = true;
  k.cull_ahead_m = 0.035;
  k.wake_by = brash::WakeBy::PushFront, k.wake_force_N = 1e-4, k.wake_speed_m_s = 0.001, k.front_speed_m_s = 0.005;
  World w(brash::core::FluidParams{}, StepperSettings{}, Frictions{}, k);
  const double z = kR - brash::core::analytic::height_for_fraction(kR, 0.9);
  w.add_sphere(Vec3(0.06, 0, z), kR, 900);
  w.add_sphere(Vec3(mover_x_m, 0.1, z), kR, 900, Vec3(mover_m_s, 0, 0));
  w.add_sphere(Vec3(0.03, -0.1, z), kR, 900, Vec3(0, 0, 0.02));
  add_box_hull(w);
  w.set_hull_velocity(Vec3::Zero());
  for (int s = 0; s < 200; ++s) w.step();
  return w.culled(0);
}
}  // namespace

// The push front follows the ice pushed ahead, along the ship's course: a piece in the window moving forward
// faster than the front speed takes the front past the resting one (which then is active); one moving back
// out of the channel (as the bed spreads from an open end) or heaving does not, nor does one moving ahead far
// beyond the window at the start (held out, as the moving window holds the bed ahead: ice spreading out of
// the far open end).
TEST(OdeFarField, PushFrontFollowsOnlyIceMovingAhead) {
  EXPECT_FALSE(resting_sphere_culled(0.03, 0.02)) << "ice in the window moving ahead takes the front with it";
  EXPECT_TRUE(resting_sphere_culled(0.03, -0.02))
      << "ice moving back or heaving leaves the front where it is";
  EXPECT_TRUE(resting_sphere_culled(0.5, 0.02))
      << "ice moving ahead far beyond the window at the start is held out";
}
