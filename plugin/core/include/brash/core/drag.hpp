// The drag law of Eq. 1, coded once for every engine: evaluate() (fluid.hpp, the reference for ODE, YADE and the
// reference integrator) and the array kernel (LIGGGHTS) both take C_D |u| from drag_cd_speed().
//
// Eq. 1 on the submerged projected area A: F = -1/2 rho_w C_D A |u| u, u = v - U_flow. The law gives C_D |u|
// rather than C_D so that Schiller-Naumann stays finite as |u| -> 0 (Stokes: C_D |u| -> 24 nu / d, written
// without dividing by Re):
//   constant          C_D = fluid.drag_coefficient
//   schiller_naumann  C_D = 24 / Re (1 + 0.15 Re^0.687) for Re < 1000, 0.44 above (Newton's regime),
//                     Re = |u| d / nu
#pragma once
#include <cmath>

#include "brash/core/params.hpp"

namespace brash::core {

// Schiller-Naumann's Newton-regime plateau and where it starts.
inline constexpr double kNewtonRegimeCd = 0.44;
inline constexpr double kNewtonRegimeRe = 1000.0;

// C_D |u| [m/s] of a sphere of diameter d moving at |u| relative to the water.
inline double drag_cd_speed(const FluidParams& p, double speed_m_s, double diameter_m) {
  if (p.drag_law == DragLaw::Constant) return p.drag_coefficient * speed_m_s;
  const double re = speed_m_s * diameter_m / p.kinematic_viscosity_m2_s;
  if (re >= kNewtonRegimeRe) return kNewtonRegimeCd * speed_m_s;
  return 24.0 * p.kinematic_viscosity_m2_s / diameter_m * (1.0 + 0.15 * std::pow(re, 0.687));
}

// C_D itself at |u| > 0 (for reports and tests; the forces use drag_cd_speed).
inline double drag_coefficient(const FluidParams& p, double speed_m_s, double diameter_m) {
  return drag_cd_speed(p, speed_m_s, diameter_m) / speed_m_s;
}

}  // namespace brash::core
