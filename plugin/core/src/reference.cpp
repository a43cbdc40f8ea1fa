// Single-sphere velocity-Verlet integrator and closed-form references.
#include "brash/core/reference.hpp"

#include <cmath>
#include <numbers>

namespace brash::core {

double ReferenceSphere::mass_kg() const { return density_kg_m3 * analytic::sphere_volume(radius_m); }

void ReferenceSphere::compute_forces() {
  const double m = mass_kg();
  f_N = external_force_N;
  if (engine_gravity) f_N.z() -= m * params.gravity_m_s2;
  last = evaluate(params, Sphere{radius_m, m, x_m, v_m_s}, state, dt_s);
  f_N = total_force(f_N, last);
  state = advance(state, v_m_s);
}

void ReferenceSphere::setup() { compute_forces(); }

void ReferenceSphere::step() {
  const double m = mass_kg();
  v_m_s += 0.5 * dt_s / m * f_N;
  x_m += dt_s * v_m_s;
  compute_forces();
  v_m_s += 0.5 * dt_s / m * f_N;
  t_s += dt_s;
}

namespace analytic {

double sphere_volume(double r) { return 4.0 / 3.0 * std::numbers::pi * r * r * r; }

double height_for_fraction(double r, double s) {
  double lo = 0, hi = 2 * r;
  for (int i = 0; i < 200; ++i) {
    const double h = 0.5 * (lo + hi);
    const double frac = h * h * (3 * r - h) / (4 * r * r * r);
    (frac < s ? lo : hi) = h;
  }
  return 0.5 * (lo + hi);
}

Rise rise(double r, double rho_i, double rho_w, double g, double cd, double ca_z) {
  const double v = sphere_volume(r);
  const double net = (rho_w - rho_i) * v * g;
  const double k = 0.5 * rho_w * cd * std::numbers::pi * r * r;
  const double m_eff = (rho_i + ca_z * rho_w) * v;
  return {std::sqrt(net / k), m_eff / std::sqrt(net * k)};
}

double heave_period(double r, double rho_i, double rho_w, double g, double ca_z) {
  const double h = height_for_fraction(r, rho_i / rho_w);
  const double v = sphere_volume(r);
  const double a_wp = std::numbers::pi * h * (2 * r - h);
  const double m = rho_i * v;
  const double m_a = ca_z * rho_w * (rho_i / rho_w) * v;
  return 2 * std::numbers::pi * std::sqrt((m + m_a) / (rho_w * g * a_wp));
}

double rolling_deceleration(double mu_r, double g) {
  constexpr double inertia_over_m_r2 = 2.0 / 5.0;  // solid sphere
  return mu_r * g / (1 + inertia_over_m_r2);
}

}  // namespace analytic
}  // namespace brash::core
