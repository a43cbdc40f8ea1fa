// Per-sphere fluid forces of the paper (buoyancy, Eq. 1 drag, Eq. 2 added mass with Table 1) and the
// two acceleration treatments. Engine adapters call `evaluate` (or `apply_to_arrays`) once per sphere
// per step, after every other force on the sphere is known:
//
//   out = evaluate(params, sphere, state, dt);
//   f_total = total_force(f_other, out);   // (f_other + out.force_N) scaled; scale = 1 unless implicit
//   state = advance(state, sphere.velocity);
//
// Implicit treatment solves (m + m_a) a = F per axis, i.e. scales the force the integrator divides by m
// with m / (m + m_a) (added_mass.hpp); explicit adds F_a = -m_a a with the lagged a = (v - v_prev) / dt.
// In a flow that accelerates (FluidParams::flow_acceleration_m_s2, the hull's flow) F also holds
// rho V_s (1 + C_a) Du/Dt (flow_acceleration.hpp): the added mass then acts on the acceleration relative to
// the water, and the drag on the velocity relative to it.
#pragma once
#include <cmath>
#include <cstddef>

#include "brash/core/added_mass.hpp"
#include "brash/core/drag.hpp"
#include "brash/core/flow_acceleration.hpp"
#include "brash/core/immersion.hpp"
#include "brash/core/params.hpp"

namespace brash::core {

struct Sphere {
  double radius_m = 0;
  double mass_kg = 0;
  Vec3 position_m = Vec3::Zero();
  Vec3 velocity_m_s = Vec3::Zero();
};

// What a sphere must remember between steps (engines store it per particle, across migration/restart).
struct FluidState {
  Vec3 velocity_prev_m_s = Vec3::Zero();
  bool has_prev = false;
};

struct FluidOutput {
  Vec3 force_N = Vec3::Zero();   // buoyancy + drag + explicit added mass (+ gravity if apply_gravity)
  Vec3 scale = Vec3::Ones();     // implicit added mass: m / (m + m_a) per axis
  Vec3 ca = Vec3::Zero();        // added-mass coefficients used this step
  Vec3 added_mass_kg = Vec3::Zero();  // m_a = Ca rho_w V_s per axis (with added mass)
  Immersion immersion;
  bool reversed = false;
};

// "Motion reversed": the vertical velocity relative to the water changed sign over the last step (no
// hysteresis). The water's vertical velocity flow_z at the last step is taken as this step's (it changes by
// O(dt Du/Dt) in a step); in still water (flow_z = 0) this is exactly the sign change of v_z.
inline bool motion_reversed(const FluidState& st, const Vec3& v, double flow_z_m_s = 0.0) {
  return st.has_prev && (v.z() - flow_z_m_s) * (st.velocity_prev_m_s.z() - flow_z_m_s) < 0.0;
}

// Table 1: coefficients for the sphere's immersion state.
inline Vec3 select_ca(const CaTable& t, double radius_m, const Immersion& im, bool reversed) {
  if (im.height_m <= 0.0) return t.above;
  if (im.height_m >= 2.0 * radius_m) return reversed ? t.submerged_reversed : t.submerged;
  if (reversed) return t.partial_reversed;
  return Vec3(t.partial.x(), t.partial.y(), t.partial.z() * im.height_m / (2.0 * radius_m));
}

// Eq. 1 on the submerged projected area: F = -1/2 rho C_D A |u| u, u = v - U_flow (the law: drag.hpp).
inline Vec3 drag_force(const FluidParams& p, double radius_m, const Immersion& im, const Vec3& velocity) {
  if (im.height_m <= 0.0) return Vec3::Zero();
  const Vec3 u = velocity - p.flow_velocity_m_s;
  const double speed = u.norm();
  if (speed <= 0.0) return Vec3::Zero();
  const double area = projected_area(radius_m, im, u.z() / speed);
  return -0.5 * p.water_density_kg_m3 * drag_cd_speed(p, speed, 2.0 * radius_m) * area * u;
}

inline Vec3 buoyancy_force(const FluidParams& p, const Immersion& im) {
  return Vec3(0.0, 0.0, p.water_density_kg_m3 * p.gravity_m_s2 * im.volume_m3);
}

inline FluidOutput evaluate(const FluidParams& p, const Sphere& s, const FluidState& st, double dt_s) {
  FluidOutput out;
  out.immersion = immersion(s.radius_m, s.position_m.z(), p.water_level_m);
  out.force_N = buoyancy_force(p, out.immersion);
  if (p.apply_gravity) out.force_N.z() -= s.mass_kg * p.gravity_m_s2;
  if (p.has_drag()) out.force_N += drag_force(p, s.radius_m, out.immersion, s.velocity_m_s);
  if (p.has_added_mass()) {
    out.reversed = motion_reversed(st, s.velocity_m_s, p.flow_velocity_m_s.z());
    out.ca = select_ca(p.ca, s.radius_m, out.immersion, out.reversed);
    out.added_mass_kg = added_mass_kg(p.water_density_kg_m3 * out.immersion.volume_m3, out.ca);
    if (p.treatment == Treatment::Implicit) {
      out.scale = implicit_scale(s.mass_kg, out.added_mass_kg);
    } else if (st.has_prev && dt_s > 0.0) {
      const Vec3 accel = (s.velocity_m_s - st.velocity_prev_m_s) / dt_s;
      out.force_N -= out.added_mass_kg.cwiseProduct(accel);
    }
  }
  if (!p.flow_acceleration_m_s2.isZero()) {  // the water's acceleration (flow_acceleration.hpp)
    const double rho_vs = p.water_density_kg_m3 * out.immersion.volume_m3;
    for (int k = 0; k < 3; ++k)
      out.force_N[k] += flow_acceleration_force_N(rho_vs, out.ca[k], p.flow_acceleration_m_s2[k]);
  }
  return out;
}

inline FluidState advance(const FluidState&, const Vec3& velocity_m_s) { return {velocity_m_s, true}; }

// The total force for an integrator that divides by m: every other force plus the fluid's, scaled.
inline Vec3 total_force(const Vec3& other_N, const FluidOutput& out) {
  return scaled_total_force(other_N, out.force_N, out.scale);
}

// Array form for engines that keep particles in flat arrays (LIGGGHTS): x, v, f are n x 3 row-major.
// f holds every other force on entry and the total on exit; state is updated in place.
// Returns nothing; no allocation. `mask` (may be null) selects spheres (nonzero = apply).
void apply_to_arrays(const FluidParams& p, std::size_t n, const double* radius_m, const double* mass_kg,
                     const double (*x_m)[3], const double (*v_m_s)[3], double (*f_N)[3], FluidState* state,
                     double dt_s, const int* mask = nullptr);

}  // namespace brash::core
