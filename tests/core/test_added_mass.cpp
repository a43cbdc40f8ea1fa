// The one composition of added mass and its implicit treatment (added_mass.hpp), against values by hand.
#include <gtest/gtest.h>

#include "brash/core/added_mass.hpp"
#include "brash/core/fluid.hpp"
#include "brash/core/reference.hpp"

using namespace brash::core;

namespace {
// m = 2 kg displacing 3 kg of water with Ca = (0.5, 0.5, 0.25): m_a = (1.5, 1.5, 0.75) kg,
// s = (2/3.5, 2/3.5, 2/2.75) = (4/7, 4/7, 8/11).
constexpr double m = 2.0, displaced = 3.0;
const Vec3 ca(0.5, 0.5, 0.25);
}  // namespace

TEST(AddedMass, IsCaTimesDisplacedWater) {
  EXPECT_EQ(added_mass_kg(displaced, ca), Vec3(1.5, 1.5, 0.75));
  EXPECT_EQ(added_mass_kg(displaced, 0.25), 0.75);
}

TEST(AddedMass, ImplicitScaleIsMassOverMassPlusAddedMass) {
  const Vec3 s = implicit_scale(m, added_mass_kg(displaced, ca));
  EXPECT_DOUBLE_EQ(s.x(), 4.0 / 7.0);
  EXPECT_DOUBLE_EQ(s.y(), 4.0 / 7.0);
  EXPECT_DOUBLE_EQ(s.z(), 8.0 / 11.0);
  EXPECT_EQ(implicit_scale(m, 0.0), 1.0);  // a dry sphere keeps its forces
}

TEST(AddedMass, ScaledTotalForceGivesTheAccelerationOfMassPlusAddedMass) {
  // other forces (1, 0, -19) N, fluid (2.5, -7, 30) N: F = (3.5, -7, 11) N, a = F / (m + m_a) = (1, -2, 4)
  const Vec3 s = implicit_scale(m, added_mass_kg(displaced, ca));
  const Vec3 f = scaled_total_force(Vec3(1, 0, -19), Vec3(2.5, -7, 30), s);
  const Vec3 a = f / m;
  EXPECT_DOUBLE_EQ(a.x(), 1.0);
  EXPECT_DOUBLE_EQ(a.y(), -2.0);
  EXPECT_DOUBLE_EQ(a.z(), 4.0);
}

TEST(AddedMass, IsotropicBodyMassGivesTheSameAccelerationAsScaling) {
  const Vec3 ma = added_mass_kg(displaced, ca);
  const double M = isotropic_body_mass_kg(m, ma);
  EXPECT_DOUBLE_EQ(M, 3.5);  // m + (1.5 + 1.5) / 2
  const Vec3 total = scaled_total_force(Vec3(1, 0, -19), Vec3(2.5, -7, 30), implicit_scale(m, ma));
  const Vec3 a = force_for_body_mass(total, m, M) / M;
  EXPECT_DOUBLE_EQ(a.x(), 1.0);
  EXPECT_DOUBLE_EQ(a.y(), -2.0);
  EXPECT_DOUBLE_EQ(a.z(), 4.0);
  EXPECT_EQ(force_for_body_mass(total, m, m), total);  // the bare mass leaves the force as it is
}

TEST(AddedMass, ImplicitOnlyWithAnAddedMassModelTreatedImplicitly) {
  FluidParams p;
  EXPECT_TRUE(implicit_added_mass(p));
  p.treatment = Treatment::Explicit;
  EXPECT_FALSE(implicit_added_mass(p));
  p.treatment = Treatment::Implicit;
  p.model = FluidModel::Drag;
  EXPECT_FALSE(implicit_added_mass(p));
  p.model = FluidModel::AddedMass;
  EXPECT_TRUE(implicit_added_mass(p));
}

TEST(AddedMass, EvaluateReportsRhoVCaAndItsScale) {
  // fully submerged, at rest: Ca = (0.5, 0.5, 0.5), m_a = 1000 kg/m^3 * V * 0.5 = 500 V
  const double rad = 0.01, v = analytic::sphere_volume(rad), mass = 900 * v;
  const Sphere sphere{rad, mass, Vec3(0, 0, -2 * rad), Vec3::Zero()};
  const auto out = evaluate(FluidParams{}, sphere, FluidState{}, 1e-4);
  EXPECT_DOUBLE_EQ(out.added_mass_kg.x(), 500 * v);
  EXPECT_DOUBLE_EQ(out.added_mass_kg.z(), 500 * v);
  EXPECT_DOUBLE_EQ(out.scale.x(), 900.0 / 1400.0);
  EXPECT_DOUBLE_EQ(out.scale.z(), 900.0 / 1400.0);
  EXPECT_EQ(total_force(Vec3(1, 2, 3), out), scaled_total_force(Vec3(1, 2, 3), out.force_N, out.scale));
}
