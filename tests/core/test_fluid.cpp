// Table 1 selection, the reversal rule, drag, treatments and parameter validation.
#include <gtest/gtest.h>

#include <numbers>

#include "brash/core/fluid.hpp"
#include "brash/core/reference.hpp"
#include "brash/error.hpp"

using namespace brash::core;
constexpr double r = 0.008789;

namespace {
Immersion at_fraction(double s) {
  return immersion(r, -analytic::height_for_fraction(r, s) + r, 0.0);
}
FluidState moving(double vz) { return {Vec3(0, 0, vz), true}; }
}  // namespace

TEST(Table1, AboveWaterAllZero) {
  const CaTable t;
  EXPECT_EQ(select_ca(t, r, at_fraction(0.0), false), Vec3(0, 0, 0));
  EXPECT_EQ(select_ca(t, r, at_fraction(0.0), true), Vec3(0, 0, 0));
}

TEST(Table1, SubmergedRows) {
  const CaTable t;
  const auto im = immersion(r, -2 * r, 0);
  EXPECT_EQ(select_ca(t, r, im, false), Vec3(0.5, 0.5, 0.5));
  EXPECT_EQ(select_ca(t, r, im, true), Vec3(0.5, 0.5, 0.0));
}

TEST(Table1, PartialRowsLinearInHeight) {
  const CaTable t;
  for (double s : {0.1, 0.5, 0.9}) {
    const auto im = at_fraction(s);
    const Vec3 ca = select_ca(t, r, im, false);
    EXPECT_DOUBLE_EQ(ca.x(), 0.5);
    EXPECT_DOUBLE_EQ(ca.y(), 0.5);
    EXPECT_NEAR(ca.z(), 0.5 * im.height_m / (2 * r), 1e-15);
    EXPECT_EQ(select_ca(t, r, im, true), Vec3(0.5, 0.5, 0.0));
  }
  EXPECT_NEAR(select_ca(t, r, at_fraction(0.5), false).z(), 0.25, 1e-12);
}

TEST(Table1, TextVariantSetsTwoOnSubmergedReversal) {
  const CaTable t = CaTable::text_variant();
  EXPECT_EQ(select_ca(t, r, immersion(r, -2 * r, 0), true), Vec3(0.5, 0.5, 2.0));
  EXPECT_EQ(select_ca(t, r, at_fraction(0.5), true), Vec3(0.5, 0.5, 0.0));
}

TEST(Table1, ZeroTableHasNoAddedMassAnywhere) {  // ca_table: zero (the paper's Ca = 0 comparison)
  const CaTable t = parse_ca_table("zero");
  for (bool rev : {false, true}) {
    EXPECT_EQ(select_ca(t, r, immersion(r, -2 * r, 0), rev), Vec3(0, 0, 0));
    EXPECT_EQ(select_ca(t, r, at_fraction(0.5), rev), Vec3(0, 0, 0));
  }
  EXPECT_EQ(select_ca(parse_ca_table("table1"), r, immersion(r, -2 * r, 0), false), Vec3(0.5, 0.5, 0.5));
  EXPECT_THROW(parse_ca_table("none"), brash::InputError);
}

TEST(Reversal, SignChangeOfVerticalVelocityOnly) {
  EXPECT_TRUE(motion_reversed(moving(0.1), Vec3(0, 0, -0.1)));
  EXPECT_TRUE(motion_reversed(moving(-0.1), Vec3(0, 0, 0.2)));
  EXPECT_FALSE(motion_reversed(moving(0.1), Vec3(0, 0, 0.3)));
  EXPECT_FALSE(motion_reversed(moving(0.0), Vec3(0, 0, 0.3)));       // from rest: not a reversal
  EXPECT_FALSE(motion_reversed(FluidState{}, Vec3(0, 0, -0.3)));     // no history yet
  EXPECT_FALSE(motion_reversed(moving(0.1), Vec3(-0.5, 0.2, 0.3)));  // horizontal sign change does not count
}

TEST(Evaluate, ReversalSelectsReversedRowThroughEvaluate) {
  FluidParams p;
  const Sphere s{r, 900 * analytic::sphere_volume(r), Vec3(0, 0, -2 * r), Vec3(0, 0, -0.01)};
  EXPECT_EQ(evaluate(p, s, moving(0.01), 1e-4).ca, Vec3(0.5, 0.5, 0.0));
  EXPECT_EQ(evaluate(p, s, moving(-0.02), 1e-4).ca, Vec3(0.5, 0.5, 0.5));
}

TEST(Evaluate, ImplicitScaleIsMassRatio) {
  FluidParams p;
  const double v = analytic::sphere_volume(r), m = 900 * v;
  const auto out = evaluate(p, Sphere{r, m, Vec3(0, 0, -2 * r), Vec3::Zero()}, FluidState{}, 1e-4);
  EXPECT_NEAR(out.scale.z(), m / (m + 500 * v), 1e-15);
  EXPECT_NEAR(out.force_N.z(), 1000 * 9.81 * v, 1e-15);  // buoyancy only (at rest: no drag)
}

TEST(Evaluate, ExplicitAddsLaggedAccelerationForce) {
  FluidParams p;
  p.model = FluidModel::AddedMass;  // Eq. 2 alone: no drag on the moving piece
  p.treatment = Treatment::Explicit;
  const double v = analytic::sphere_volume(r), m = 900 * v, dt = 1e-3;
  const auto out = evaluate(p, Sphere{r, m, Vec3(0, 0, -2 * r), Vec3(0.02, 0, 0.01)}, moving(0.0), dt);
  EXPECT_EQ(out.scale, Vec3::Ones());
  EXPECT_NEAR(out.force_N.x(), -1000 * 0.5 * v * 0.02 / dt, 1e-15);
  EXPECT_NEAR(out.force_N.z(), 1000 * 9.81 * v - 1000 * 0.5 * v * 0.01 / dt, 1e-15);
}

TEST(Drag, QuadraticSubmergedAndZeroInAir) {
  FluidParams p;
  p.model = FluidModel::Drag;
  const Vec3 u(0.3, -0.4, 0.0);
  const Vec3 f = drag_force(p, r, immersion(r, -2 * r, 0), u);
  const Vec3 expect = -0.5 * 1000 * 0.44 * std::numbers::pi * r * r * 0.5 * u;
  EXPECT_NEAR((f - expect).norm(), 0.0, 1e-15);
  EXPECT_EQ(drag_force(p, r, immersion(r, 2 * r, 0), u), Vec3::Zero());
  p.flow_velocity_m_s = u;  // moving with the flow: no drag
  EXPECT_EQ(drag_force(p, r, immersion(r, -2 * r, 0), u), Vec3::Zero());
}

TEST(Drag, SchillerNaumannMatchesStokesAtLowRe) {
  FluidParams p;
  p.drag_law = DragLaw::SchillerNaumann;
  const Vec3 u(0, 0, 1e-9);  // Re ~ 1e-5
  const Vec3 f = drag_force(p, r, immersion(r, -2 * r, 0), u);
  const double mu = 1000 * p.kinematic_viscosity_m2_s;
  EXPECT_NEAR(f.z(), -3 * std::numbers::pi * mu * 2 * r * 1e-9, 1e-3 * std::abs(f.z()));
  EXPECT_NEAR(drag_coefficient(p, 1.0, 2 * r), 0.44, 1e-15);  // Re ~ 1e4
}

TEST(Params, DefaultsAreValid) { EXPECT_NO_THROW(FluidParams{}.validate()); }

TEST(Params, DefaultModelIsDragPlusAddedMass) {
  const FluidParams p;
  EXPECT_EQ(p.model, FluidModel::Both);
  EXPECT_TRUE(p.has_drag());
  EXPECT_TRUE(p.has_added_mass());
}

TEST(Params, ProblemsNameTheParameter) {
  FluidParams p;
  p.water_density_kg_m3 = -1;
  p.ca.submerged.z() = -0.5;
  p.drag_coefficient = std::nan("");
  try {
    p.validate("case.yaml");
    FAIL() << "expected InputError";
  } catch (const brash::InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("case.yaml"), std::string::npos);
    EXPECT_NE(msg.find("water_density = -1"), std::string::npos);
    EXPECT_NE(msg.find("ca.submerged"), std::string::npos);
    EXPECT_NE(msg.find("drag_coefficient"), std::string::npos);
  }
}

TEST(Params, ParseEnumsAndRejectUnknown) {
  EXPECT_EQ(parse_fluid_model("both"), FluidModel::Both);
  EXPECT_EQ(parse_treatment("explicit"), Treatment::Explicit);
  EXPECT_EQ(parse_drag_law("schiller_naumann"), DragLaw::SchillerNaumann);
  EXPECT_EQ(parse_ca_table("text").submerged_reversed.z(), 2.0);
  EXPECT_THROW(parse_fluid_model("dragg"), brash::InputError);
  EXPECT_THROW(parse_treatment("semi"), brash::InputError);
  EXPECT_THROW(parse_ca_table("table2"), brash::InputError);
  EXPECT_EQ(to_string(parse_fluid_model("added_mass")), "added_mass");
}

TEST(Params, CaTableSpellingReadsBackAsTheSameTable) {  // fix icefluid's `ca` text, written by the runner
  const auto same = [](const CaTable& a, const CaTable& b) {
    return a.above == b.above && a.submerged == b.submerged && a.submerged_reversed == b.submerged_reversed &&
           a.partial == b.partial && a.partial_reversed == b.partial_reversed;
  };
  EXPECT_EQ(ca_table_spelling(CaTable::table1()), "table1");
  EXPECT_EQ(ca_table_spelling(CaTable::text_variant()), "text");
  EXPECT_EQ(ca_table_spelling(CaTable::uniform(0.0)), "zero");
  EXPECT_EQ(ca_table_spelling(CaTable::uniform(0.25)), "uniform 0.25");
  for (const char* text : {"table1", "text", "zero", "uniform 0.25", "uniform 2", "uniform 0.1"}) {
    const CaTable t = parse_ca_table(text);
    EXPECT_EQ(ca_table_spelling(t), text);
    EXPECT_TRUE(same(parse_ca_table(ca_table_spelling(t)), t)) << text;
  }
  const CaTable third = CaTable::uniform(1.0 / 3.0);  // shortest round-trip digits, not rounded ones
  EXPECT_TRUE(same(parse_ca_table(ca_table_spelling(third)), third));
  CaTable custom = CaTable::table1();
  custom.partial.z() = 0.7;  // no name: an engine command cannot carry it
  EXPECT_THROW((void)ca_table_spelling(custom), brash::InputError);
}

TEST(Params, UniformCaTableFromText) {  // the case file's "ca_table: uniform <Ca>" (stability map)
  const CaTable t = parse_ca_table("uniform 2");
  for (const Vec3& v : {t.submerged, t.submerged_reversed, t.partial, t.partial_reversed})
    EXPECT_EQ(v, Vec3(2, 2, 2));
  EXPECT_EQ(t.above, Vec3::Zero());
  EXPECT_EQ(parse_ca_table("uniform 0.5").partial_reversed.z(), 0.5);
  EXPECT_EQ(parse_ca_table("uniform  1e1 ").submerged.x(), 10.0);
  for (const char* bad :
       {"uniform", "uniform2", "uniform -1", "uniform x", "uniform 2 3", "uniform nan", "uniform inf"})
    EXPECT_THROW(parse_ca_table(bad), brash::InputError) << bad;
}

TEST(Arrays, MatchesPerSphereEvaluation) {
  FluidParams p;
  p.model = FluidModel::Both;
  const double rad[2] = {r, 1.1 * r};
  const double mass[2] = {900 * analytic::sphere_volume(rad[0]), 900 * analytic::sphere_volume(rad[1])};
  const double x[2][3] = {{0, 0, -0.2 * r}, {1, 0, 3 * r}};
  const double v[2][3] = {{0.1, 0.0, -0.05}, {0, 0.2, 0.1}};
  double f[2][3] = {{1, 2, 3}, {4, 5, 6}};
  FluidState st[2];
  apply_to_arrays(p, 2, rad, mass, x, v, f, st, 1e-4);
  const auto out = evaluate(p, Sphere{r, mass[0], Vec3(0, 0, -0.2 * r), Vec3(0.1, 0, -0.05)}, FluidState{}, 1e-4);
  EXPECT_NEAR(f[0][2], (3 + out.force_N.z()) * out.scale.z(), 1e-15);
  EXPECT_EQ(f[1][0], 4.0);  // dry sphere: nothing changes
  EXPECT_TRUE(st[0].has_prev);
  EXPECT_EQ(st[1].velocity_prev_m_s, Vec3(0, 0.2, 0.1));
}
