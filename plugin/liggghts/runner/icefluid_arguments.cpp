#include "icefluid_arguments.h"

#include <fmt/format.h>

namespace brash::liggghts {

std::string icefluid_arguments(const core::FluidParams& p) {
  std::string s = fmt::format(
      "model {} treatment {} cd {:.9g} drag_law {} nu {:.9g} ca {} water_level {:.9g} water_density {:.9g} g {:.9g}",
      to_string(p.model), to_string(p.treatment), p.drag_coefficient, to_string(p.drag_law),
      p.kinematic_viscosity_m2_s, core::ca_table_spelling(p.ca), p.water_level_m, p.water_density_kg_m3,
      p.gravity_m_s2);
  if (!p.flow_velocity_m_s.isZero())
    s += fmt::format(" flow {:.9g} {:.9g} {:.9g}", p.flow_velocity_m_s.x(), p.flow_velocity_m_s.y(),
                     p.flow_velocity_m_s.z());
  if (p.apply_gravity) s += " gravity yes";
  return s;
}

}  // namespace brash::liggghts
