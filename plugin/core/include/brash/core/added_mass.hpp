// Added mass and its implicit treatment, coded once for every engine: evaluate() (fluid.hpp), the array
// kernel (LIGGGHTS), the reference integrator, the YADE module and the ODE world all compose through these.
//
// Added mass per axis: m_a,i = Ca_i rho_w V_s, Ca times the mass of the water the sphere displaces.
// The implicit treatment solves (m + m_a,i) a_i = F_i per axis, F = every force on the sphere:
//   - an integrator that divides by m gets it by scaling the total force with s_i = m / (m + m_a,i)
//     (implicit_scale, scaled_total_force);
//   - a solver that takes one isotropic mass per body (ODE) gives the body M = m + (m_a,x + m_a,y) / 2
//     (isotropic_body_mass_kg) and applies F_i s_i M / m (force_for_body_mass): forces known outside the
//     solver get exactly F_i / (m + m_a,i), contact forces solved inside it see the horizontal added inertia.
// Scalar forms serve the hot kernel (no Eigen temporaries); the Vec3 forms apply them per axis.
#pragma once
#include "brash/core/params.hpp"

namespace brash::core {

// Is the implicit treatment in force (a model with added mass, treated implicitly)?
inline bool implicit_added_mass(const FluidParams& p) {
  return p.has_added_mass() && p.treatment == Treatment::Implicit;
}

constexpr double added_mass_kg(double displaced_water_kg, double ca) { return displaced_water_kg * ca; }
inline Vec3 added_mass_kg(double displaced_water_kg, const Vec3& ca) { return displaced_water_kg * ca; }

// s = m / (m + m_a): 1 for a dry sphere (m_a = 0).
constexpr double implicit_scale(double mass_kg, double added_mass_kg) {
  return mass_kg / (mass_kg + added_mass_kg);
}
inline Vec3 implicit_scale(double mass_kg, const Vec3& added_mass_kg) {
  return {implicit_scale(mass_kg, added_mass_kg.x()), implicit_scale(mass_kg, added_mass_kg.y()),
          implicit_scale(mass_kg, added_mass_kg.z())};
}

// What an integrator dividing by m must apply: (every other force + the fluid's) times the scale
// (s = 1 without the implicit treatment).
constexpr double scaled_total_force(double other_N, double fluid_N, double scale) {
  return (other_N + fluid_N) * scale;
}
inline Vec3 scaled_total_force(const Vec3& other_N, const Vec3& fluid_N, const Vec3& scale) {
  return {scaled_total_force(other_N.x(), fluid_N.x(), scale.x()),
          scaled_total_force(other_N.y(), fluid_N.y(), scale.y()),
          scaled_total_force(other_N.z(), fluid_N.z(), scale.z())};
}

// One isotropic mass per body: the horizontal added mass (Table 1 has Ca_x = Ca_y) joins the body.
inline double isotropic_body_mass_kg(double mass_kg, const Vec3& added_mass_kg) {
  return mass_kg + 0.5 * (added_mass_kg.x() + added_mass_kg.y());
}

// The force to apply to a body of mass M so that it accelerates as the scaled total force on mass m would.
inline Vec3 force_for_body_mass(const Vec3& scaled_total_N, double mass_kg, double body_mass_kg) {
  return scaled_total_N * (body_mass_kg / mass_kg);
}

}  // namespace brash::core
