// Single-sphere scenes through ODE (brash::ode::World with one body, no contacts), compared with the
// reference integrator (brash::core::ReferenceSphere, velocity Verlet) and the closed forms of
// brash::core::analytic. Used by tests/ode and by `brash-ode --single SCENE`.
#pragma once
#include <string>

#include "brash/ode/world.hpp"

namespace brash::ode::single {

struct Options {
  double dt_s = 5e-4;
  double radius_m = 0.008789;
  double density_kg_m3 = 900.0;
  ImplicitMode mode = ImplicitMode::EffectiveMass;
  core::Treatment treatment = core::Treatment::Implicit;
};

// Rise from rest, fully submerged, drag + added mass (Ca_z 0.5): v(t) = v_t tanh(t / tau).
// Samples every 0.1 s for 1 s; errors relative to the analytic velocity at each sample.
struct Rise {
  double terminal_velocity_m_s = 0, time_constant_s = 0;
  double worst_rel_error_analytic = 0;   // max_k |v_ode / v_analytic - 1|
  double worst_rel_error_reference = 0;  // max_k |v_ode / v_reference - 1| (reference at the same dt)
  double v_end_m_s = 0;
};
Rise rise(const Options& o);

// Floating equilibrium: released at z = r/2 (above its draft), drag (Schiller-Naumann, linear at small speed)
// + added mass, run `duration_s`; reports the final submerged fraction (expected rho_i / rho_w = 0.9).
struct Float {
  double fraction = 0, z_m = 0, z_expected_m = 0, speed_m_s = 0;
};
Float floating(const Options& o, double duration_s = 250.0);

// Heave period: added mass only (undamped), released at z_eq + amplitude; period from upward zero crossings.
struct Heave {
  double period_ode_s = 0, period_reference_s = 0, period_analytic_s = 0;
  int crossings = 0;
};
Heave heave(const Options& o, double amplitude_m = 1e-3 * 0.008789, double duration_s = 4.0);

std::string report(const Rise& r);
std::string report(const Float& f);
std::string report(const Heave& h);

}  // namespace brash::ode::single
