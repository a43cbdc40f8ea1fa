// Validation and string conversion of FluidParams.
#include "brash/core/params.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <cstdlib>

#include "brash/error.hpp"

namespace brash::core {
namespace {

bool finite(const Vec3& v) { return v.allFinite(); }

bool same_table(const CaTable& a, const CaTable& b) {
  return a.above == b.above && a.submerged == b.submerged && a.submerged_reversed == b.submerged_reversed &&
         a.partial == b.partial && a.partial_reversed == b.partial_reversed;
}

void check_ca(std::vector<std::string>& out, const char* name, const Vec3& ca) {
  if (!finite(ca) || (ca.array() < 0).any())
    out.push_back(fmt::format("ca.{} = ({}, {}, {}): added-mass coefficients must be finite and >= 0", name,
                              ca.x(), ca.y(), ca.z()));
}

}  // namespace

std::vector<std::string> FluidParams::problems() const {
  std::vector<std::string> out;
  if (!(water_density_kg_m3 > 0) || !std::isfinite(water_density_kg_m3))
    out.push_back(fmt::format("water_density = {}: must be a positive number (kg/m^3)", water_density_kg_m3));
  if (!std::isfinite(water_level_m)) out.push_back("water_level: must be finite (m)");
  if (!(gravity_m_s2 >= 0) || !std::isfinite(gravity_m_s2))
    out.push_back(fmt::format("gravity = {}: must be >= 0 (m/s^2)", gravity_m_s2));
  if (!finite(flow_velocity_m_s)) out.push_back("flow_velocity: must be finite (m/s)");
  if (!finite(flow_acceleration_m_s2)) out.push_back("flow_acceleration: must be finite (m/s^2)");
  if (!(drag_coefficient >= 0) || !std::isfinite(drag_coefficient))
    out.push_back(fmt::format("drag_coefficient = {}: must be >= 0", drag_coefficient));
  if (!(kinematic_viscosity_m2_s > 0) || !std::isfinite(kinematic_viscosity_m2_s))
    out.push_back(fmt::format("kinematic_viscosity = {}: must be > 0 (m^2/s)", kinematic_viscosity_m2_s));
  check_ca(out, "above", ca.above);
  check_ca(out, "submerged", ca.submerged);
  check_ca(out, "submerged_reversed", ca.submerged_reversed);
  check_ca(out, "partial", ca.partial);
  check_ca(out, "partial_reversed", ca.partial_reversed);
  return out;
}

void FluidParams::validate(std::string_view context) const {
  const auto p = problems();
  if (p.empty()) return;
  std::string msg = fmt::format("{}: invalid fluid parameters:", context);
  for (const auto& s : p) msg += "\n  - " + s;
  throw InputError(msg);
}

FluidModel parse_fluid_model(std::string_view s) {
  if (s == "drag") return FluidModel::Drag;
  if (s == "added_mass") return FluidModel::AddedMass;
  if (s == "both") return FluidModel::Both;
  throw InputError(fmt::format("unknown fluid model '{}' (expected drag | added_mass | both)", s));
}

Treatment parse_treatment(std::string_view s) {
  if (s == "explicit") return Treatment::Explicit;
  if (s == "implicit") return Treatment::Implicit;
  throw InputError(fmt::format("unknown acceleration treatment '{}' (expected explicit | implicit)", s));
}

DragLaw parse_drag_law(std::string_view s) {
  if (s == "constant") return DragLaw::Constant;
  if (s == "schiller_naumann") return DragLaw::SchillerNaumann;
  throw InputError(fmt::format("unknown drag law '{}' (expected constant | schiller_naumann)", s));
}

CaTable parse_ca_table(std::string_view s) {
  if (s == "table1") return CaTable::table1();
  if (s == "text") return CaTable::text_variant();
  if (s == "zero") return CaTable::uniform(0.0);  // the paper's "Ca = 0" comparison
  if (s.starts_with("uniform") && s.size() > 7 && std::isspace(static_cast<unsigned char>(s[7]))) {
    const std::string rest(s.substr(7));  // "uniform <Ca>": the case file's form (stability studies)
    char* end = nullptr;
    const double ca = std::strtod(rest.c_str(), &end);
    const bool number =
        end != rest.c_str() && std::string_view(end).find_first_not_of(" \t") == std::string_view::npos;
    if (number && std::isfinite(ca) && ca >= 0) return CaTable::uniform(ca);
  }
  throw InputError(
      fmt::format("unknown added-mass table '{}' (expected table1 | text | zero | uniform <Ca >= 0>)", s));
}

std::string ca_table_spelling(const CaTable& t) {
  if (same_table(t, CaTable::table1())) return "table1";
  if (same_table(t, CaTable::text_variant())) return "text";
  const double ca = t.submerged.x();
  if (same_table(t, CaTable::uniform(ca))) return ca == 0.0 ? "zero" : fmt::format("uniform {}", ca);
  throw InputError(fmt::format(
      "added-mass table (submerged {} {} {}, submerged_reversed {} {} {}, partial {} {} {}, partial_reversed {} {} "
      "{}) has no name (table1 | text | zero | uniform <Ca>)",
      t.submerged.x(), t.submerged.y(), t.submerged.z(), t.submerged_reversed.x(), t.submerged_reversed.y(),
      t.submerged_reversed.z(), t.partial.x(), t.partial.y(), t.partial.z(), t.partial_reversed.x(),
      t.partial_reversed.y(), t.partial_reversed.z()));
}

}  // namespace brash::core
