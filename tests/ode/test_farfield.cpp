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

#include <cstdio>
#include <vector>

#include "brash/core/reference.hpp"
#include "brash/ode/world.hpp"

using namespace brash::ode;
using brash::core::Vec3;

namespace {
constexpr int kChain = 12;
constexpr double kR = 0.01, kSpeed = 0.05, kSteps = 2000;  // 1 s at dt 5e-4 s
enum class Cull { None, WindowAlone, Wake, WakeNeighbour };

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

End run_chain(Cull mode) {
  static OdeLibrary lib;
  Skips k;
  k.cull = mode != Cull::None;
  k.cull_ahead_m = 0.035;
  if (mode == Cull::Wake) k.wake_force_N = 1e-4, k.wake_speed_m_s = 0.001;
  if (mode == Cull::WakeNeighbour) k.wake_by = brash::WakeBy::NeighbourSpeed, k.wake_speed_m_s = 0.001;
  // 20 quickstep iterations: the window alone's wall is a jam of hard contacts, whose reaction the default 8
  // iterations leave unconverged (2.6 N instead of 12 N, 490x the free push); the cull is the same either way
  StepperSettings st;
  st.iterations = 20;
  World w(brash::core::FluidParams{}, st, Frictions{}, k);
  const double z = kR - brash::core::analytic::height_for_fraction(kR, 0.9);  // floating
  for (int i = 0; i < kChain; ++i) w.add_sphere(Vec3(0.001 + kR + 2 * kR * i, 0, z), kR, 900);
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

double x0(int i) { return 0.001 + kR + 2 * kR * i; }
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
