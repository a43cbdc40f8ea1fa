// The arguments of fix icefluid that brash-liggghts-run writes (plugin/liggghts/runner/icefluid_arguments.h):
// every FluidParams field the fix reads, in the fix's keywords.
#include <gtest/gtest.h>

#include "brash/error.hpp"
#include "icefluid_arguments.h"

using brash::core::CaTable;
using brash::core::FluidParams;
using brash::liggghts::icefluid_arguments;

TEST(IcefluidArguments, DefaultParameters) {
  EXPECT_EQ(icefluid_arguments(FluidParams{}),
            "model both treatment implicit cd 0.44 drag_law constant nu 1.79e-06 ca table1 water_level 0 "
            "water_density 1000 g 9.81");
}

TEST(IcefluidArguments, EveryFieldInItsKeyword) {
  FluidParams p;
  p.model = brash::FluidModel::Drag;
  p.treatment = brash::Treatment::Explicit;
  p.drag_coefficient = 0.3;
  p.drag_law = brash::DragLaw::SchillerNaumann;
  p.kinematic_viscosity_m2_s = 1.3e-6;
  p.ca = CaTable::uniform(0.25);
  p.water_level_m = -0.05;
  p.water_density_kg_m3 = 1025.5;
  p.gravity_m_s2 = 9.8;
  p.flow_velocity_m_s = brash::core::Vec3(0.5, 0, -0.1);
  p.apply_gravity = true;
  EXPECT_EQ(icefluid_arguments(p),
            "model drag treatment explicit cd 0.3 drag_law schiller_naumann nu 1.3e-06 ca uniform 0.25 "
            "water_level -0.05 water_density 1025.5 g 9.8 flow 0.5 0 -0.1 gravity yes");
  p.ca = CaTable::text_variant();
  p.model = brash::FluidModel::AddedMass;
  EXPECT_NE(icefluid_arguments(p).find("model added_mass "), std::string::npos);
  EXPECT_NE(icefluid_arguments(p).find(" ca text "), std::string::npos);
}

TEST(IcefluidArguments, TableWithoutNameIsRefused) {
  FluidParams p;
  p.ca.submerged.x() = 0.7;
  EXPECT_THROW((void)icefluid_arguments(p), brash::InputError);
}
