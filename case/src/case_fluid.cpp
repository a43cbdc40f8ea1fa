#include "brash/case_fluid.hpp"

namespace brash {
namespace {

core::CaTable ca_table(const CaTableSpec& spec) {
  switch (spec.table) {
    case CaTable::Table1: return core::CaTable::table1();
    case CaTable::Text: return core::CaTable::text_variant();
    case CaTable::Zero: return core::CaTable::uniform(0.0);  // the paper's "Ca = 0" comparison
    case CaTable::Uniform: return core::CaTable::uniform(spec.uniform_ca);
  }
  return core::CaTable::table1();
}

}  // namespace

core::FluidParams fluid_params(const Case& c) {
  core::FluidParams p;
  p.water_density_kg_m3 = c.water.density_kg_m3;
  p.water_level_m = c.water.level_m;
  p.gravity_m_s2 = c.water.gravity_m_s2;
  p.kinematic_viscosity_m2_s = c.water.kinematic_viscosity_m2_s;
  p.model = c.fluid.model;
  p.treatment = c.fluid.treatment;
  p.drag_law = c.fluid.drag_law;
  p.drag_coefficient = c.fluid.drag_coefficient;
  p.ca = ca_table(c.fluid.ca_table);
  return p;
}

}  // namespace brash
