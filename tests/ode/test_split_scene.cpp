// brash-ode's hull force split (World::hull_split, brash/core/hull_split.hpp) on a scene with a known split, as
// tests/liggghts/test_hullsplit.cpp checks it for fix brash/hullsplit.
//
// Known split: a sphere (gravity only: above the water, no fluid force) lies on a plate inclined by theta, the
// hull, which moves up its own slope at U. With mu < tan(theta) / 3.5 the contact never sticks: the sphere's
// contact point accelerates down the slope at g (3.5 mu cos(theta) - sin(theta)) < 0 (its centre at
// g (mu cos(theta) - sin(theta)), its spin adding 5/2 mu g cos(theta)) while the plate goes up. So the push is
// Fn = m g cos(theta) along the plate's normal n = (-sin, 0, cos) and the friction on the sphere mu Fn up the slope
// t = (cos, 0, sin) (ODE's friction pyramid has an edge along t for this normal: dPlaneSpace gives (0, -1, 0) and
// t). On the hull: normal part -Fn n, x = m g cos(theta) sin(theta); tangential part -mu Fn t,
// x = -mu m g cos^2(theta). The contact lies at hull-frame x within +-0.15 m: all in one region.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "brash/ode/world.hpp"

using namespace brash::ode;
using brash::core::Vec3;

namespace {

constexpr double kTheta = 20.0 * M_PI / 180.0, kMu = 0.05, kSpeed = 0.1;
constexpr double kR = 0.02, kDensity = 900, kG = 9.81, kDt = 5e-4;
constexpr long kSteps = 500, kSettleSteps = 100;  // 0.25 s; the first 0.05 s: the soft contact settles

// The split and the total of each step after the settling, and the sphere's mass.
struct Record {
  std::vector<brash::core::HullSplit> split;
  std::vector<Vec3> force_N;
  std::vector<std::size_t> contacts;
  double mass_kg = 0;
};

// The plate: the 0.6 m square through the origin spanned by t and y, wound so that its normal is n.
void add_plate_hull(World& w) {
  const double c = std::cos(kTheta), s = std::sin(kTheta);
  std::vector<double> v;
  const double corner[4][2] = {{-0.3, -0.3}, {0.3, -0.3}, {0.3, 0.3}, {-0.3, 0.3}};  // (along t, along y)
  for (const auto& ab : corner) v.insert(v.end(), {ab[0] * c, ab[1], ab[0] * s});
  std::vector<dTriIndex> tri = {0, 1, 2, 0, 2, 3};
  w.set_hull(std::move(v), std::move(tri), Vec3::Zero(), Vec3(kSpeed * c, 0, kSpeed * s));
}

Record run_scene(const brash::core::HullRegions& regions) {
  static OdeLibrary lib;
  brash::core::FluidParams fluid;
  fluid.model = brash::core::FluidModel::Drag;  // no added mass; above the water no drag and no buoyancy either
  fluid.water_level_m = -1.0;
  fluid.gravity_m_s2 = kG;
  StepperSettings st;
  st.dt_s = kDt;
  World w(fluid, st, Frictions{1.35, kMu, 1.35});
  add_plate_hull(w);
  w.set_hull_regions(regions);
  const Vec3 n(-std::sin(kTheta), 0, std::cos(kTheta));
  w.add_sphere((kR - 1e-5) * n, kR, kDensity);  // touching the plate at the origin, 10 um deep
  Record r;
  r.mass_kg = w.mass(0);
  for (long k = 0; k < kSteps; ++k) {
    w.step();
    if (k < kSettleSteps) continue;
    r.split.push_back(w.hull_split());
    r.force_N.push_back(w.hull_force());
    r.contacts.push_back(w.hull_contacts());
  }
  return r;
}

}  // namespace

TEST(OdeHullSplitScene, SlidingSphereOnAnInclinedHullHasTheKnownSplit) {
  const Record r = run_scene({-1.0, 1.0});  // the whole plate is mid-body
  const double c = std::cos(kTheta), s = std::sin(kTheta);
  const double fn = r.mass_kg * kG * c;
  ASSERT_GT(fn, 0.2);
  const double normal_x = fn * s, tangential_x = -kMu * fn * c;  // 0.0951 N and -0.0131 N on the hull
  const double tol = 1e-6 * fn;  // observed: 3e-8 of Fn (the contact's CFM), tangential to round-off
  ASSERT_EQ(r.split.size(), static_cast<std::size_t>(kSteps - kSettleSteps));
  for (std::size_t i = 0; i < r.split.size(); ++i) {
    const auto& p = r.split[i];
    ASSERT_EQ(r.contacts[i], 1u) << "step " << i + kSettleSteps;
    EXPECT_NEAR(p[brash::core::kSplitNormal], normal_x, tol) << "step " << i + kSettleSteps;
    EXPECT_NEAR(p[brash::core::kSplitTangential], tangential_x, tol) << "step " << i + kSettleSteps;
    // the parts add up to the total, which is the push and the friction together
    EXPECT_NEAR(p[brash::core::kSplitNormal] + p[brash::core::kSplitTangential], r.force_N[i].x(), 1e-12);
    EXPECT_NEAR(r.force_N[i].x(), normal_x + tangential_x, tol);
    EXPECT_EQ(p[brash::core::kSplitBow], 0.0);
    EXPECT_EQ(p[brash::core::kSplitStern], 0.0);
    EXPECT_EQ(p[brash::core::kSplitMid], r.force_N[i].x());
  }
}

// The same contact booked to the bow when the mid-body lies behind it, to the stern when it lies ahead.
TEST(OdeHullSplitScene, RegionFollowsTheContactsHullFrameX) {
  const Record bow = run_scene({-1.0, -0.5}), stern = run_scene({0.5, 1.0});
  ASSERT_EQ(bow.split.size(), stern.split.size());
  for (std::size_t i = 0; i < bow.split.size(); ++i) {
    EXPECT_EQ(bow.split[i][brash::core::kSplitBow], bow.force_N[i].x());
    EXPECT_EQ(bow.split[i][brash::core::kSplitMid], 0.0);
    EXPECT_EQ(bow.split[i][brash::core::kSplitStern], 0.0);
    EXPECT_EQ(stern.split[i][brash::core::kSplitStern], stern.force_N[i].x());
    EXPECT_EQ(stern.split[i][brash::core::kSplitMid], 0.0);
    EXPECT_EQ(stern.split[i][brash::core::kSplitBow], 0.0);
    // the regions change the booking, not the run
    EXPECT_EQ(bow.force_N[i].x(), stern.force_N[i].x());
  }
}
