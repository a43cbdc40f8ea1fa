// Stability map of the engine-independent core (docs/stability.md): one ice sphere integrated by
// brash::core::ReferenceSphere (velocity Verlet exactly as LIGGGHTS' nve/sphere + fix icefluid) from an
// "impact" (velocity (v0, 0, -v0), as a piece pushed forward and down by the bow) at floating equilibrium.
// A run is unstable when the state stops being finite, the speed grows beyond 5 (sqrt(2) v0 + 1 m/s)
// (no physical force in the scene can do that: buoyancy, gravity and drag only take energy out of
// the impact), or the piece flies more than 1 m above the water.
#pragma once
#include <algorithm>
#include <cmath>
#include <string>

#include "brash/core/reference.hpp"

namespace brash::stability {

struct Cell {
  double dt_s = 5e-5;
  double ca = 0.5;                 // uniform added-mass coefficient (all axes, all states); < 0: use `table`
  core::CaTable table = core::CaTable::table1();
  core::Treatment treatment = core::Treatment::Implicit;
  double density_ratio = 0.9;      // rho_i / rho_w
  double impact_m_s = 0.482;       // v0
  double duration_s = 2.0;
  double radius_m = 0.008789;      // paper: d = 0.017578 m
};

struct Result {
  bool stable = true;
  std::string cause;               // why unstable ("" if stable)
  long steps = 0;                  // steps run (until the failure)
  double max_speed_m_s = 0;
  double max_submerged_fraction = 0;
  double max_added_mass_ratio = 0; // max over the run of m_a / m = Ca_z rho_w s / rho_i (z axis, largest)
  double final_speed_m_s = 0;
};

inline Result run_cell(const Cell& c) {
  core::ReferenceSphere s;
  s.params.model = core::FluidModel::Both;
  s.params.treatment = c.treatment;
  s.params.ca = c.ca >= 0 ? core::CaTable::uniform(c.ca) : c.table;
  s.radius_m = c.radius_m;
  s.density_kg_m3 = c.density_ratio * s.params.water_density_kg_m3;
  s.dt_s = c.dt_s;
  // Floating equilibrium: submerged fraction = density ratio.
  const double h = core::analytic::height_for_fraction(c.radius_m, c.density_ratio);
  s.x_m = core::Vec3(0, 0, s.params.water_level_m - h + c.radius_m);
  s.v_m_s = core::Vec3(c.impact_m_s, 0, -c.impact_m_s);
  s.setup();
  Result r;
  const double bound = 5.0 * (std::sqrt(2.0) * c.impact_m_s + 1.0);
  const long n = std::lround(c.duration_s / c.dt_s);
  const double m = s.mass_kg();
  for (long i = 0; i < n; ++i) {
    s.step();
    r.steps = i + 1;
    const double speed = s.v_m_s.norm();
    r.max_speed_m_s = std::max(r.max_speed_m_s, speed);
    r.max_submerged_fraction = std::max(r.max_submerged_fraction, s.last.immersion.fraction);
    const double ma = s.params.water_density_kg_m3 * s.last.immersion.volume_m3 * s.last.ca.maxCoeff();
    r.max_added_mass_ratio = std::max(r.max_added_mass_ratio, ma / m);
    if (!s.x_m.allFinite() || !s.v_m_s.allFinite() || !s.f_N.allFinite()) {
      r.stable = false, r.cause = "non-finite state";
      break;
    }
    if (speed > bound) {
      r.stable = false, r.cause = "speed runaway";
      break;
    }
    if (s.x_m.z() - s.params.water_level_m > 1.0) {
      r.stable = false, r.cause = "jumped > 1 m above the water";
      break;
    }
  }
  r.final_speed_m_s = s.v_m_s.norm();
  return r;
}

// Largest uniform Ca for which the explicit treatment is stable (bisection on [lo, hi], tolerance tol).
inline double explicit_critical_ca(Cell c, double lo = 0.0, double hi = 10.0, double tol = 1e-3) {
  c.treatment = core::Treatment::Explicit;
  c.ca = hi;
  if (run_cell(c).stable) return hi;
  while (hi - lo > tol) {
    c.ca = 0.5 * (lo + hi);
    (run_cell(c).stable ? lo : hi) = c.ca;
  }
  return lo;
}

}  // namespace brash::stability
