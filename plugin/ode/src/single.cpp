// Single-sphere scenes through ODE vs the reference integrator and closed forms (single.hpp).
#include "brash/ode/single.hpp"

#include <fmt/format.h>

#include <cmath>
#include <vector>

#include "brash/core/reference.hpp"

namespace brash::ode::single {
namespace {

constexpr double kRhoW = 1000.0, kG = 9.81;

core::FluidParams params(const Options& o, core::FluidModel model, core::DragLaw law = core::DragLaw::Constant) {
  core::FluidParams p;
  p.model = model;
  p.treatment = o.treatment;
  p.drag_law = law;
  p.water_density_kg_m3 = kRhoW;
  p.gravity_m_s2 = kG;
  return p;
}

// Upward zero crossings of z - z_eq, linearly interpolated.
struct Crossings {
  std::vector<double> t;
  double prev = NAN;
  void add(double t0, double dt, double cur) {
    if (prev < 0 && cur >= 0) t.push_back(t0 + dt * (-prev) / (cur - prev));
    prev = cur;
  }
  double period() const {
    if (t.size() < 2) return NAN;
    return (t.back() - t.front()) / double(t.size() - 1);
  }
};

}  // namespace

Rise rise(const Options& o) {
  const auto p = params(o, core::FluidModel::Both);
  World w(p, StepperSettings{.dt_s = o.dt_s}, Frictions{}, Skips{}, o.mode);
  w.add_sphere(Vec3(0, 0, -1.0), o.radius_m, o.density_kg_m3);
  core::ReferenceSphere ref;
  ref.params = p;
  ref.radius_m = o.radius_m;
  ref.density_kg_m3 = o.density_kg_m3;
  ref.dt_s = o.dt_s;
  ref.x_m = Vec3(0, 0, -1.0);
  ref.setup();
  const auto an = core::analytic::rise(o.radius_m, o.density_kg_m3, kRhoW, kG, p.drag_coefficient, 0.5);
  Rise r{an.terminal_velocity_m_s, an.time_constant_s, 0, 0, 0};
  const long per_sample = std::lround(0.1 / o.dt_s);
  for (int k = 1; k <= 10; ++k) {
    for (long i = 0; i < per_sample; ++i) {
      w.step();
      ref.step();
    }
    const double t = w.stats().t_s;
    const double v = w.velocity(0).z();
    const double expect = an.terminal_velocity_m_s * std::tanh(t / an.time_constant_s);
    r.worst_rel_error_analytic = std::max(r.worst_rel_error_analytic, std::abs(v / expect - 1));
    r.worst_rel_error_reference = std::max(r.worst_rel_error_reference, std::abs(v / ref.v_m_s.z() - 1));
    r.v_end_m_s = v;
  }
  return r;
}

Float floating(const Options& o, double duration_s) {
  const auto p = params(o, core::FluidModel::Both, core::DragLaw::SchillerNaumann);
  World w(p, StepperSettings{.dt_s = o.dt_s}, Frictions{}, Skips{}, o.mode);
  w.add_sphere(Vec3(0, 0, 0.5 * o.radius_m), o.radius_m, o.density_kg_m3);
  const long steps = std::lround(duration_s / o.dt_s);
  for (long i = 0; i < steps; ++i) w.step();
  Float f;
  f.z_m = w.position(0).z();
  f.fraction = core::immersion(o.radius_m, f.z_m, 0.0).fraction;
  const double h = core::analytic::height_for_fraction(o.radius_m, o.density_kg_m3 / kRhoW);
  f.z_expected_m = o.radius_m - h;
  f.speed_m_s = w.velocity(0).norm();
  return f;
}

Heave heave(const Options& o, double amplitude_m, double duration_s) {
  const auto p = params(o, core::FluidModel::AddedMass);
  const double h = core::analytic::height_for_fraction(o.radius_m, o.density_kg_m3 / kRhoW);
  const double z_eq = o.radius_m - h;
  World w(p, StepperSettings{.dt_s = o.dt_s}, Frictions{}, Skips{}, o.mode);
  w.add_sphere(Vec3(0, 0, z_eq + amplitude_m), o.radius_m, o.density_kg_m3);
  core::ReferenceSphere ref;
  ref.params = p;
  ref.radius_m = o.radius_m;
  ref.density_kg_m3 = o.density_kg_m3;
  ref.dt_s = o.dt_s;
  ref.x_m = Vec3(0, 0, z_eq + amplitude_m);
  ref.setup();
  Crossings c_ode, c_ref;
  const long steps = std::lround(duration_s / o.dt_s);
  for (long i = 0; i < steps; ++i) {
    const double t0 = w.stats().t_s;
    w.step();
    ref.step();
    c_ode.add(t0, o.dt_s, w.position(0).z() - z_eq);
    c_ref.add(t0, o.dt_s, ref.x_m.z() - z_eq);
  }
  Heave out;
  out.period_ode_s = c_ode.period();
  out.period_reference_s = c_ref.period();
  out.period_analytic_s = core::analytic::heave_period(o.radius_m, o.density_kg_m3, kRhoW, kG, 0.5 * h / (2 * o.radius_m));
  out.crossings = static_cast<int>(c_ode.t.size());
  return out;
}

std::string report(const Rise& r) {
  return fmt::format("rise: v_t {:.6f} m/s tau {:.6f} s, v(1 s) {:.6f} m/s, worst |v/v_analytic-1| {:.3e}, "
                     "worst |v/v_reference-1| {:.3e}",
                     r.terminal_velocity_m_s, r.time_constant_s, r.v_end_m_s, r.worst_rel_error_analytic,
                     r.worst_rel_error_reference);
}
std::string report(const Float& f) {
  return fmt::format("float: submerged fraction {:.6f} (expected 0.9), z {:.6e} m vs {:.6e} m, |v| {:.2e} m/s",
                     f.fraction, f.z_m, f.z_expected_m, f.speed_m_s);
}
std::string report(const Heave& h) {
  return fmt::format("heave: period ODE {:.6f} s, reference {:.6f} s, analytic {:.6f} s ({} crossings); "
                     "ODE/reference-1 {:.3e}, ODE/analytic-1 {:.3e}",
                     h.period_ode_s, h.period_reference_s, h.period_analytic_s, h.crossings,
                     h.period_ode_s / h.period_reference_s - 1, h.period_ode_s / h.period_analytic_s - 1);
}

}  // namespace brash::ode::single
