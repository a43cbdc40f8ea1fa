// Fluid-model parameters shared by every engine adapter, with self-validation.
// Defaults are the paper's added-mass model as its results show it (physics.md): drag (Eq. 1, the constant C_D of
// brash/fluid_options.hpp) plus added mass (Eq. 2, Table 1), implicit treatment. FluidModel::AddedMass (Eq. 2
// alone, the literal reading of the paper's Methods sentence) and FluidModel::Drag stay selectable.
#pragma once
#include <Eigen/Core>

#include "brash/fluid_options.hpp"
#include <string>
#include <string_view>
#include <vector>

namespace brash::core {

using Vec3 = Eigen::Vector3d;

// The option enums and their spelling are shared with the case file (brash/fluid_options.hpp).
using brash::DragLaw;
using brash::FluidModel;
using brash::to_string;
using brash::Treatment;

// Added-mass coefficients per axis (x, y, z) for each state of Table 1. "partial.z" is the value at
// full immersion of the linear law Ca_z = partial.z * h / (2r).
struct CaTable {
  Vec3 above{0.0, 0.0, 0.0};
  Vec3 submerged{0.5, 0.5, 0.5};
  Vec3 submerged_reversed{0.5, 0.5, 0.0};
  Vec3 partial{0.5, 0.5, 0.5};
  Vec3 partial_reversed{0.5, 0.5, 0.0};

  static CaTable table1() { return {}; }
  // The paper's text: on reversal of a submerged piece "the added mass coefficient is set to 2".
  static CaTable text_variant() {
    CaTable t;
    t.submerged_reversed = Vec3(0.5, 0.5, 2.0);
    return t;
  }
  static CaTable uniform(double ca) {
    CaTable t;
    t.submerged = t.submerged_reversed = t.partial = t.partial_reversed = Vec3::Constant(ca);
    return t;
  }
};

struct FluidParams {
  double water_density_kg_m3 = kDefaultWaterDensity_kg_m3;
  double water_level_m = 0.0;
  double gravity_m_s2 = kDefaultGravity_m_s2;
  bool apply_gravity = false;                 // add -m g here (else the engine's own gravity does)
  Vec3 flow_velocity_m_s = Vec3::Zero();
  // Du/Dt of that flow, earth frame (flow_acceleration.hpp): the pressure-gradient force and the added mass's
  // reaction to the relative acceleration; zero in still water (and then no term is computed at all)
  Vec3 flow_acceleration_m_s2 = Vec3::Zero();
  FluidModel model = FluidModel::Both;
  Treatment treatment = Treatment::Implicit;
  DragLaw drag_law = DragLaw::Constant;
  double drag_coefficient = kDefaultDragCoefficient;
  double kinematic_viscosity_m2_s = kDefaultKinematicViscosity_m2_s;
  CaTable ca;

  bool has_drag() const { return model != FluidModel::AddedMass; }
  bool has_added_mass() const { return model != FluidModel::Drag; }

  // Every problem found, each naming its parameter; empty when valid.
  std::vector<std::string> problems() const;
  // Throws brash::InputError listing problems(), prefixed by `context` (file, command ...).
  void validate(std::string_view context = "fluid parameters") const;
};

// String <-> enum for case files and engine commands; throw brash::InputError on unknown names.
FluidModel parse_fluid_model(std::string_view s);
Treatment parse_treatment(std::string_view s);
DragLaw parse_drag_law(std::string_view s);
CaTable parse_ca_table(std::string_view s);  // "table1" | "text" | "zero" | "uniform <Ca>" (Ca >= 0)
// The inverse: the text parse_ca_table() reads back as exactly `t` ("zero" for a uniform 0, "uniform <Ca>" with
// the shortest round-trip number). Throws brash::InputError for a table with no such name (engine commands
// such as fix icefluid's `ca` keyword only take named tables).
std::string ca_table_spelling(const CaTable& t);

}  // namespace brash::core
