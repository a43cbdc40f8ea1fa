// The fluid model's options, one definition for the core (brash::core), the case file (brash::Case) and every
// engine adapter, each with its one spelling (case.yaml, `fix icefluid`, the runners' --model / --treatment).
// Parsing with errors lives with the callers (brash::core::parse_*, the case loader), which know the context.
#pragma once
#include <string_view>

namespace brash {

enum class FluidModel { Drag, AddedMass, Both };   // Eq. 1, Eq. 2, Eq. 1 + Eq. 2
enum class Treatment { Explicit, Implicit };       // lagged acceleration vs mass augmentation
enum class DragLaw { Constant, SchillerNaumann };  // C_D constant or C_D(Re)
enum class HullFlow { None, ThinShip, Panel };     // still water, or the flow around the hull (drag's U_flow)
// How the hull's flow acts on a piece: Full = the table valid up to the hull and the forces of the water's
// acceleration with the drag; Drag = that table, the drag alone; DragRegularTable = the drag alone from a regular
// table that samples nodes inside the hull (the coupling of earlier versions, kept to measure the corrections)
enum class HullFlowCoupling { Full, Drag, DragRegularTable };

// Defaults of the fluid parameters, one value for the core (brash::core::FluidParams), the case file (brash::Case)
// and the engines' own keywords (the YADE module passes them on to Python as brash_yade.DEFAULT_*).
inline constexpr double kDefaultDragCoefficient = 0.44;
inline constexpr double kDefaultKinematicViscosity_m2_s = 1.79e-6;  // water near 0 C
inline constexpr double kDefaultWaterDensity_kg_m3 = 1000.0;
inline constexpr double kDefaultGravity_m_s2 = 9.81;

constexpr std::string_view to_string(FluidModel m) {
  switch (m) {
    case FluidModel::Drag: return "drag";
    case FluidModel::AddedMass: return "added_mass";
    case FluidModel::Both: return "both";
  }
  return "?";
}
constexpr std::string_view to_string(Treatment t) { return t == Treatment::Explicit ? "explicit" : "implicit"; }
constexpr std::string_view to_string(DragLaw d) {
  return d == DragLaw::Constant ? "constant" : "schiller_naumann";
}

constexpr std::string_view to_string(HullFlow h) {
  return h == HullFlow::None ? "none" : h == HullFlow::ThinShip ? "thin_ship" : "panel";
}

constexpr std::string_view to_string(HullFlowCoupling h) {
  return h == HullFlowCoupling::Full ? "full" : h == HullFlowCoupling::Drag ? "drag" : "drag_regular_table";
}

}  // namespace brash
