// In still water the model with the water's acceleration (flow_acceleration.hpp) is bit for bit the model
// before it: the array kernel (LIGGGHTS) and evaluate() (ODE, YADE, the reference integrator) give the same
// bytes as the code before the term was added, recorded in golden/still_water.txt (hashes of every force and
// state on a bed of spheres above, across and under the water, with histories that reverse, for every model,
// treatment and gravity; and a heave run of the reference integrator). This file also builds against the
// older core: that build wrote the golden file (BRASH_GOLDEN_UPDATE=1 rewrites it, for an intended change).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "brash/core/fluid.hpp"
#include "brash/core/kernel.hpp"
#include "brash/core/reference.hpp"

#ifndef BRASH_STILL_WATER_GOLDEN
#error "BRASH_STILL_WATER_GOLDEN must be defined by the build"
#endif

namespace {

using namespace brash::core;

std::uint64_t hash_bytes(const void* p, std::size_t n, std::uint64_t h = 1469598103934665603ULL) {
  const unsigned char* b = static_cast<const unsigned char*>(p);
  for (std::size_t k = 0; k < n; ++k) h = (h ^ b[k]) * 1099511628211ULL;
  return h;
}

struct Bed {
  std::vector<double> r, m, x, v, f, state;
};

Bed make_bed(std::size_t n) {
  Bed b;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double r = 0.0088 * (1.0 + 0.1 * u(rng));
    b.r.push_back(r), b.m.push_back(900.0 * 4.18879 * r * r * r);
    b.x.insert(b.x.end(), {u(rng), u(rng), 1.5 * r * u(rng)});  // above, across and under the water
    b.v.insert(b.v.end(), {0.05 * u(rng), 0.05 * u(rng), 0.02 * u(rng)});
    b.f.insert(b.f.end(), {0.01 * u(rng), 0.01 * u(rng), -0.03 + 0.01 * u(rng)});
    // a history for most: previous velocity, flag (evaluated, or evaluated and reversed), lagged acceleration
    const double flag = i % 5 == 0 ? 0.0 : (i % 7 == 0 ? 2.0 : 1.0);
    b.state.insert(b.state.end(), {0.05 * u(rng), 0.05 * u(rng), 0.02 * u(rng), flag, 0.0, 0.1 * u(rng),
                                   0.1 * u(rng), 0.1 * u(rng)});
    if (flag == 0.0) std::fill(b.state.end() - kStateStride, b.state.end(), 0.0);
  }
  return b;
}

std::string fingerprints() {
  std::ostringstream out;
  const FluidModel models[] = {FluidModel::Both, FluidModel::Drag, FluidModel::AddedMass};
  const Treatment treatments[] = {Treatment::Implicit, Treatment::Explicit};
  for (FluidModel model : models)
    for (Treatment treatment : treatments)
      for (int gravity = 0; gravity < 2; ++gravity)
        for (int replay = 0; replay < 2; ++replay) {
          FluidParams p;
          p.model = model, p.treatment = treatment, p.apply_gravity = gravity;
          Bed b = make_bed(200);
          KernelArrays a;
          a.n = b.r.size(), a.radius_m = b.r.data(), a.mass_kg = b.m.data(), a.x_m = b.x.data();
          a.v_m_s = b.v.data(), a.f_N = b.f.data(), a.state = b.state.data();
          apply_kernel(p, a, 1e-4, replay);
          // evaluate() on the same spheres (the ODE engine's path)
          Bed e = make_bed(200);
          for (std::size_t i = 0; i < e.r.size(); ++i) {
            FluidState st;
            st.has_prev = e.state[kStateStride * i + 3] != 0.0;
            st.velocity_prev_m_s = Vec3(e.state[kStateStride * i], e.state[kStateStride * i + 1],
                                        e.state[kStateStride * i + 2]);
            const Sphere s{e.r[i], e.m[i], Vec3(e.x[3 * i], e.x[3 * i + 1], e.x[3 * i + 2]),
                           Vec3(e.v[3 * i], e.v[3 * i + 1], e.v[3 * i + 2])};
            const FluidOutput o = evaluate(p, s, st, 1e-4);
            const Vec3 total = total_force(Vec3(e.f[3 * i], e.f[3 * i + 1], e.f[3 * i + 2]), o);
            for (int k = 0; k < 3; ++k) e.f[3 * i + k] = total[k];
          }
          out << to_string(model) << ' ' << to_string(treatment) << " gravity " << gravity << " replay " << replay
              << " kernel " << std::hex << hash_bytes(b.f.data(), b.f.size() * sizeof(double)) << " state "
              << hash_bytes(b.state.data(), b.state.size() * sizeof(double)) << " evaluate "
              << hash_bytes(e.f.data(), e.f.size() * sizeof(double)) << std::dec << '\n';
        }
  // a piece dropped on the water, heaving until it floats: reversals, partial immersion, both treatments
  for (Treatment treatment : treatments) {
    ReferenceSphere s;
    s.params.treatment = treatment;
    s.x_m = Vec3(0, 0, 0.02), s.v_m_s = Vec3(0.03, -0.01, -0.2);
    s.setup();
    s.run(20000);
    const double end[6] = {s.x_m.x(), s.x_m.y(), s.x_m.z(), s.v_m_s.x(), s.v_m_s.y(), s.v_m_s.z()};
    out << "heave " << to_string(treatment) << ' ' << std::hex << hash_bytes(end, sizeof end) << std::dec << '\n';
  }
  return out.str();
}

TEST(StillWater, BitForBitTheModelBeforeTheFlowAcceleration) {
  const std::string now = fingerprints();
  const char* update = std::getenv("BRASH_GOLDEN_UPDATE");
  if (update && std::string(update) == "1") {
    std::ofstream(BRASH_STILL_WATER_GOLDEN) << now;
    GTEST_SKIP() << "rewrote " << BRASH_STILL_WATER_GOLDEN;
  }
  std::ifstream in(BRASH_STILL_WATER_GOLDEN);
  ASSERT_TRUE(in) << BRASH_STILL_WATER_GOLDEN;
  std::stringstream golden;
  golden << in.rdbuf();
  EXPECT_EQ(now, golden.str());
}

}  // namespace
