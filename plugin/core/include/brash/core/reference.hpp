// Single-sphere reference integrator: the oracle for engine adapters and the analytic tests.
// It integrates exactly as LIGGGHTS' nve/sphere does (velocity Verlet: half kick, drift, forces,
// fluid fix last, half kick), with gravity applied as an engine force before the fluid forces.
#pragma once
#include "brash/core/fluid.hpp"

namespace brash::core {

struct ReferenceSphere {
  FluidParams params;
  double radius_m = 0.008789;
  double density_kg_m3 = 900.0;
  double dt_s = 1e-4;
  bool engine_gravity = true;           // -m g as an "other" force (like fix gravity)
  Vec3 external_force_N = Vec3::Zero(); // any further constant force

  double t_s = 0;
  Vec3 x_m = Vec3::Zero();
  Vec3 v_m_s = Vec3::Zero();
  Vec3 f_N = Vec3::Zero();
  FluidState state;
  FluidOutput last;

  double mass_kg() const;
  void setup();   // forces at t = 0 (call once after setting x, v)
  void step();
  void run(long steps) {
    for (long i = 0; i < steps; ++i) step();
  }

 private:
  void compute_forces();
};

// Closed forms used as references by the tests (sphere of radius r, density rho_i, water rho_w).
namespace analytic {
double sphere_volume(double r);
// Submerged height h for a submerged fraction s (bisection on the cap volume).
double height_for_fraction(double r, double s);
// Fully submerged rise from rest with quadratic drag and added mass: v(t) = v_t tanh(t / tau).
struct Rise {
  double terminal_velocity_m_s, time_constant_s;
};
Rise rise(double r, double rho_i, double rho_w, double g, double cd, double ca_z);
// Linearised heave period about floating equilibrium, Ca_z the added-mass coefficient there.
double heave_period(double r, double rho_i, double rho_w, double g, double ca_z_at_equilibrium);
// A solid sphere (I = 2/5 m R^2) rolling without slip on a level wall in air, with a constant rolling torque
// mu_r R m g against its rolling (contact.rolling_friction, the wall's R_eff = R): its deceleration
// a = mu_r g / (1 + I / (m R^2)) = 5/7 mu_r g (docs/physics.md, "Rolling resistance").
double rolling_deceleration(double mu_r, double g);
}  // namespace analytic

}  // namespace brash::core
