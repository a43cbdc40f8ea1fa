// brash::fluid_params: every fluid key of a case file (water.*, fluid.*) reaches the core's FluidParams, and
// nothing else changes with it.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <map>
#include <string>

#include "brash/case.hpp"
#include "brash/case_fluid.hpp"

namespace {

using brash::core::FluidParams;

std::string vec(const brash::core::Vec3& v) { return fmt::format("({}, {}, {})", v.x(), v.y(), v.z()); }

// Every field of FluidParams by name, as text (a field missing here is a field the test cannot see).
std::map<std::string, std::string> fields(const FluidParams& p) {
  return {{"water_density_kg_m3", fmt::format("{}", p.water_density_kg_m3)},
          {"water_level_m", fmt::format("{}", p.water_level_m)},
          {"gravity_m_s2", fmt::format("{}", p.gravity_m_s2)},
          {"apply_gravity", fmt::format("{}", p.apply_gravity)},
          {"flow_velocity_m_s", vec(p.flow_velocity_m_s)},
          {"model", std::string(to_string(p.model))},
          {"treatment", std::string(to_string(p.treatment))},
          {"drag_law", std::string(to_string(p.drag_law))},
          {"drag_coefficient", fmt::format("{}", p.drag_coefficient)},
          {"kinematic_viscosity_m2_s", fmt::format("{}", p.kinematic_viscosity_m2_s)},
          {"ca", fmt::format("above {} submerged {} submerged_reversed {} partial {} partial_reversed {}",
                             vec(p.ca.above), vec(p.ca.submerged), vec(p.ca.submerged_reversed), vec(p.ca.partial),
                             vec(p.ca.partial_reversed))}};
}

FluidParams params_of(const std::string& yaml) {
  return brash::fluid_params(brash::parse_case("name: m\n" + yaml, BRASH_SOURCE_DIR, "mem"));
}

struct KeyCase {
  std::string yaml;   // the case file's key, changed from its default
  std::string field;  // the FluidParams field it sets
  std::string value;  // that field's expected text (fields())
};

}  // namespace

TEST(CaseFluid, DefaultCaseGivesTheCoreDefaults) {
  EXPECT_EQ(fields(params_of("")), fields(FluidParams{}));
}

TEST(CaseFluid, EveryFluidKeyReachesItsFieldAndNoOther) {
  const FluidParams def = params_of("");
  const auto ca = [](const brash::core::CaTable& t) {
    FluidParams p;
    p.ca = t;
    return fields(p).at("ca");
  };
  const KeyCase keys[] = {
      {"water: {density_kg_m3: 1025.5}", "water_density_kg_m3", "1025.5"},
      {"water: {level_m: 0.125}", "water_level_m", "0.125"},
      {"water: {gravity_m_s2: 9.8}", "gravity_m_s2", "9.8"},
      {"water: {kinematic_viscosity_m2_s: 1.3e-6}", "kinematic_viscosity_m2_s", "1.3e-06"},
      {"fluid: {model: drag}", "model", "drag"},
      {"fluid: {model: added_mass}", "model", "added_mass"},
      {"fluid: {treatment: explicit}", "treatment", "explicit"},
      {"fluid: {drag_coefficient: 0.3}", "drag_coefficient", "0.3"},
      {"fluid: {drag_law: schiller_naumann}", "drag_law", "schiller_naumann"},
      {"fluid: {ca_table: text}", "ca", ca(brash::core::CaTable::text_variant())},
      {"fluid: {ca_table: zero}", "ca", ca(brash::core::CaTable::uniform(0.0))},
      {"fluid: {ca_table: uniform 0.25}", "ca", ca(brash::core::CaTable::uniform(0.25))},
  };
  for (const auto& k : keys) {
    SCOPED_TRACE(k.yaml);
    auto expected = fields(def);
    ASSERT_TRUE(expected.count(k.field)) << k.field;
    ASSERT_NE(expected.at(k.field), k.value) << "the test's value is the default: it shows nothing";
    expected[k.field] = k.value;
    EXPECT_EQ(fields(params_of(k.yaml + "\n")), expected);
  }
}

TEST(CaseFluid, AllKeysAtOnce) {
  const FluidParams p = params_of(
      "water: {density_kg_m3: 1010, level_m: -0.05, gravity_m_s2: 9.7, kinematic_viscosity_m2_s: 1.1e-6}\n"
      "fluid: {model: drag, treatment: explicit, drag_coefficient: 0.5, drag_law: schiller_naumann, "
      "ca_table: uniform 0.75}\n");
  EXPECT_EQ(p.water_density_kg_m3, 1010);
  EXPECT_EQ(p.water_level_m, -0.05);
  EXPECT_EQ(p.gravity_m_s2, 9.7);
  EXPECT_EQ(p.kinematic_viscosity_m2_s, 1.1e-6);
  EXPECT_EQ(p.model, brash::FluidModel::Drag);
  EXPECT_EQ(p.treatment, brash::Treatment::Explicit);
  EXPECT_EQ(p.drag_coefficient, 0.5);
  EXPECT_EQ(p.drag_law, brash::DragLaw::SchillerNaumann);
  EXPECT_EQ(brash::core::ca_table_spelling(p.ca), "uniform 0.75");
  EXPECT_FALSE(p.apply_gravity);  // the engines add gravity themselves
  EXPECT_TRUE(p.flow_velocity_m_s.isZero());
  EXPECT_TRUE(p.problems().empty());
}
