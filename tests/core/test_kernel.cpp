// The specialised array kernel against the reference evaluate() for every model x treatment, over
// spheres above, across and below the surface with random velocities; and replay exactness.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "brash/core/fluid.hpp"
#include "brash/core/kernel.hpp"
#include "brash/core/reference.hpp"

using namespace brash::core;

namespace {
struct Scene {
  std::vector<double> r, m, x, v, f, state, out;
  std::vector<FluidState> ref_state;
};

Scene make_scene(std::size_t n, unsigned seed) {
  std::mt19937_64 gen(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  Scene s;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = 0.008 + 0.002 * std::abs(u(gen));
    s.r.push_back(r);
    s.m.push_back(900 * analytic::sphere_volume(r));
    s.x.insert(s.x.end(), {u(gen), u(gen), 1.5 * r * u(gen)});  // above, across and below the surface
    s.v.insert(s.v.end(), {0.3 * u(gen), 0.3 * u(gen), 0.3 * u(gen)});
    s.f.insert(s.f.end(), {1e-3 * u(gen), 1e-3 * u(gen), -0.02 + 1e-3 * u(gen)});
  }
  s.state.assign(n * kStateStride, 0.0);
  s.out.assign(n * kOutputStride, 0.0);
  s.ref_state.assign(n, FluidState{});
  return s;
}

KernelArrays arrays(Scene& s) {
  KernelArrays a;
  a.n = s.r.size();
  a.radius_m = s.r.data(), a.mass_kg = s.m.data(), a.x_m = s.x.data(), a.v_m_s = s.v.data();
  a.f_N = s.f.data(), a.state = s.state.data(), a.output = s.out.data();
  return a;
}
}  // namespace

class KernelVsReference : public ::testing::TestWithParam<std::tuple<FluidModel, Treatment, int>> {};

TEST_P(KernelVsReference, SameForcesOverSeveralSteps) {
  FluidParams p;
  p.model = std::get<0>(GetParam());
  p.treatment = std::get<1>(GetParam());
  const int variant = std::get<2>(GetParam());
  if (variant == 1) p.drag_law = DragLaw::SchillerNaumann, p.ca = CaTable::text_variant();
  if (variant == 2) p.apply_gravity = true, p.flow_velocity_m_s = Vec3(0.1, -0.05, 0.02);
  // variant 5: a uniform flow that accelerates (flow_acceleration.hpp)
  if (variant == 5) p.flow_velocity_m_s = Vec3(0.1, -0.05, 0.02), p.flow_acceleration_m_s2 = Vec3(0.3, 0.2, -0.4);
  const double dt = 1e-3;
  Scene s = make_scene(400, 7 + variant);
  std::mt19937_64 gen(3);
  std::uniform_real_distribution<double> u(-1, 1);
  // variant 3: each sphere its own flow (a hull's flow field, hull_flow.hpp); the reference takes it as the
  // uniform flow of that sphere's evaluation
  // variant 4: and its own Du/Dt (the hull's flow with its acceleration)
  std::vector<double> flow, accel;
  if (variant == 3 || variant == 4)
    for (std::size_t j = 0; j < 3 * s.r.size(); ++j) flow.push_back(0.2 * u(gen));
  if (variant == 4)
    for (std::size_t j = 0; j < 3 * s.r.size(); ++j) accel.push_back(0.5 * u(gen));
  auto kernel_arrays = [&] {
    KernelArrays a = arrays(s);
    if (!flow.empty()) a.flow_m_s = flow.data();
    if (!accel.empty()) a.flow_acceleration_m_s2 = accel.data();
    return a;
  };
  for (int step = 0; step < 4; ++step) {
    std::vector<double> f_ref = s.f;
    for (std::size_t i = 0; i < s.r.size(); ++i) {
      const Vec3 x(s.x[3 * i], s.x[3 * i + 1], s.x[3 * i + 2]), v(s.v[3 * i], s.v[3 * i + 1], s.v[3 * i + 2]);
      FluidParams pi = p;
      if (!flow.empty()) pi.flow_velocity_m_s = Vec3(flow[3 * i], flow[3 * i + 1], flow[3 * i + 2]);
      if (!accel.empty()) pi.flow_acceleration_m_s2 = Vec3(accel[3 * i], accel[3 * i + 1], accel[3 * i + 2]);
      const FluidOutput o = evaluate(pi, Sphere{s.r[i], s.m[i], x, v}, s.ref_state[i], dt);
      for (int k = 0; k < 3; ++k) f_ref[3 * i + k] = (f_ref[3 * i + k] + o.force_N[k]) * o.scale[k];
      s.ref_state[i] = advance(s.ref_state[i], v);
    }
    std::vector<double> f_before = s.f;
    apply_kernel(p, kernel_arrays(), dt, false);
    for (std::size_t j = 0; j < s.f.size(); ++j)
      ASSERT_NEAR(s.f[j], f_ref[j], 1e-13 * (1 + std::abs(f_ref[j]))) << "step " << step << " index " << j;
    // replay: the same forces again from the stored state, state untouched
    std::vector<double> state_before = s.state, f_replay = f_before;
    KernelArrays a = kernel_arrays();
    a.f_N = f_replay.data();
    apply_kernel(p, a, dt, true);
    EXPECT_EQ(f_replay, s.f);
    EXPECT_EQ(state_before, s.state);
    // next step: new velocities (some vertical reversals) and positions
    for (std::size_t j = 0; j < s.v.size(); ++j) s.v[j] += 0.2 * u(gen);
    for (std::size_t j = 0; j < s.x.size(); ++j) s.x[j] += 0.002 * u(gen);
    s.f = f_before;
  }
}

// Restart files written before the two state flags were merged (state[3] = 1 once evaluated, state[4] = 1 if
// reversed) replay exactly like the current layout (state[3] = 2 if reversed), and come back in it.
TEST_P(KernelVsReference, OlderStateLayoutReplaysTheSame) {
  FluidParams p;
  p.model = std::get<0>(GetParam());
  p.treatment = std::get<1>(GetParam());
  Scene s = make_scene(400, 11);
  const double dt = 1e-3;
  apply_kernel(p, arrays(s), dt, false);  // history
  for (std::size_t j = 0; j < s.v.size(); j += 3) s.v[j + 2] = -s.v[j + 2];  // every vertical motion reversed
  const std::vector<double> f0 = s.f;
  apply_kernel(p, arrays(s), dt, false);
  std::size_t reversed = 0;
  for (std::size_t i = 0; i < s.r.size(); ++i) reversed += s.state[i * kStateStride + 3] == 2.0;
  ASSERT_GT(reversed, 300u);  // nearly every sphere (those with v_z = 0 exactly are not reversed)
  const std::vector<double> state_now = s.state;
  std::vector<double> old_layout = s.state;
  for (std::size_t i = 0; i < s.r.size(); ++i) {
    double* st = old_layout.data() + i * kStateStride;
    st[4] = st[3] == 2.0 ? 1.0 : 0.0;
    st[3] = 1.0;
  }
  std::vector<double> f_new = f0, f_old = f0;
  KernelArrays a = arrays(s);
  a.f_N = f_new.data();
  apply_kernel(p, a, dt, true);
  s.state = old_layout;
  a = arrays(s);
  a.f_N = f_old.data();
  apply_kernel(p, a, dt, true);
  EXPECT_EQ(f_old, f_new);
  EXPECT_EQ(s.state, state_now);
}

INSTANTIATE_TEST_SUITE_P(AllModels, KernelVsReference,
                         ::testing::Combine(::testing::Values(FluidModel::Drag, FluidModel::AddedMass,
                                                              FluidModel::Both),
                                            ::testing::Values(Treatment::Implicit, Treatment::Explicit),
                                            ::testing::Values(0, 1, 2, 3, 4, 5)));

// The output's rows are kOutputStride wide: fraction, Ca x, y, z, active. A sphere outside the group (idle far-field
// ice) floats all the same: its real submerged fraction, no Ca (no fluid force acts on it), active 0.
TEST(Kernel, MaskSelectsGroupAndOutputHoldsFractionAndCa) {
  FluidParams p;
  Scene s = make_scene(3, 1);
  s.x = {0, 0, -1.0, 0, 0, 1.0, 0, 0, 0.0};  // submerged, dry, half
  const int mask[3] = {1, 1, 2};
  KernelArrays a = arrays(s);
  a.mask = mask;
  a.groupbit = 1;
  const std::vector<double> f0 = s.f;
  apply_kernel(p, a, 1e-3, false);
  const auto out = [&](int sphere, int column) { return s.out[kOutputStride * sphere + column]; };
  EXPECT_EQ(out(0, 0), 1.0);
  EXPECT_EQ(out(0, 3), 0.5);  // Ca_z fully submerged, not reversed
  EXPECT_EQ(out(1, 0), 0.0);  // dry
  EXPECT_EQ(out(0, 4), 1.0);  // in the group: integrated
  EXPECT_EQ(out(1, 4), 1.0);
  EXPECT_EQ(out(2, 0), 0.5);  // not in the group: half submerged all the same
  for (int c = 1; c <= 4; ++c) EXPECT_EQ(out(2, c), 0.0) << c;  // no Ca, not active
  EXPECT_EQ(s.f[6], f0[6]);  // third sphere not in the group: untouched
  EXPECT_EQ(s.state[2 * kStateStride + 3], 0.0);
}
