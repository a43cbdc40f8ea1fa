// Specialised array kernel (see kernel.hpp). One template instance per (drag?, added mass?, implicit?).
#include "brash/core/kernel.hpp"

#include <cmath>
#include <numbers>

#include "brash/core/immersion.hpp"

namespace brash::core {
namespace {

// kReplay and kMasked are hoisted out of the loop (template parameters, not per-sphere branches): the
// normal step (no replay, group all) then costs only the physics. Scalars instead of small arrays keep
// everything in registers.
template <bool kDrag, bool kAddedMass, bool kImplicit, bool kReplay, bool kMasked, bool kSymXY>
void kernel(const FluidParams& p, const KernelArrays& a, double dt_s) {
  constexpr double kPi = std::numbers::pi;
  const double rho = p.water_density_kg_m3;
  const double rho_g = rho * p.gravity_m_s2;
  const double zw = p.water_level_m;
  const double g_applied = p.apply_gravity ? p.gravity_m_s2 : 0.0;
  const double inv_dt = dt_s > 0 ? 1.0 / dt_s : 0.0;
  const CaTable& t = p.ca;
  const double ux0 = p.flow_velocity_m_s.x(), uy0 = p.flow_velocity_m_s.y(), uz0 = p.flow_velocity_m_s.z();

  for (std::size_t i = 0; i < a.n; ++i) {
    if constexpr (kMasked)
      if (!(a.mask[i] & a.groupbit)) continue;
    const double r = a.radius_m[i];
    const double m = a.mass_kg[i];
    const double z = a.x_m[3 * i + 2];
    double* st = a.state + kStateStride * i;
    double* f = a.f_N + 3 * i;
    bool replaying = false;
    if constexpr (kReplay) replaying = st[3] != 0.0;
    // velocity and history of this evaluation
    double vx, vy, vz;
    bool reversed;
    double ax = 0, ay = 0, az = 0;
    if (replaying) {
      vx = st[0], vy = st[1], vz = st[2];
      reversed = st[4] != 0.0;
      ax = st[5], ay = st[6], az = st[7];
    } else {
      const double* vv = a.v_m_s + 3 * i;
      vx = vv[0], vy = vv[1], vz = vv[2];
      // A sphere without history has an all-zero state (engines zero new rows), so st[2] = 0 and the
      // product test alone says "not reversed"; only the explicit acceleration needs the flag itself.
      reversed = vz * st[2] < 0.0;
      if constexpr (!kImplicit && kAddedMass)
        if (st[3] != 0.0) ax = (vx - st[0]) * inv_dt, ay = (vy - st[1]) * inv_dt, az = (vz - st[2]) * inv_dt;
    }

    const double two_r = 2.0 * r;
    double h = zw - z + r;
    h = h < 0.0 ? 0.0 : (h > two_r ? two_r : h);
    const double vs = kPi / 3.0 * h * h * (3.0 * r - h);
    double Fx = 0.0, Fy = 0.0, Fz = rho_g * vs - m * g_applied;
    double cax = 0.0, cay = 0.0, caz = 0.0;
    double sx = 1.0, sy = 1.0, sz = 1.0;

    if (h > 0.0) {
      if constexpr (kDrag) {
        const double ux = vx - ux0, uy = vy - uy0, uz = vz - uz0;
        const double speed2 = ux * ux + uy * uy + uz * uz;
        if (speed2 > 0.0) {
          const double speed = std::sqrt(speed2);
          Immersion im;
          im.height_m = h;
          im.waterline_radius_sq_m2 = h * (two_r - h);
          const double area = projected_area(r, im, uz / speed);
          double cd_speed;  // C_D |u|
          if (p.drag_law == DragLaw::Constant) {
            cd_speed = p.drag_coefficient * speed;
          } else {
            const double re = speed * two_r / p.kinematic_viscosity_m2_s;
            cd_speed = re >= 1000.0 ? 0.44 * speed
                                    : 24.0 * p.kinematic_viscosity_m2_s / two_r * (1.0 + 0.15 * std::pow(re, 0.687));
          }
          const double k = -0.5 * rho * cd_speed * area;
          Fx += k * ux, Fy += k * uy, Fz += k * uz;
        }
      }
      if constexpr (kAddedMass) {
        if (h >= two_r) {
          const Vec3& c = reversed ? t.submerged_reversed : t.submerged;
          cax = c.x(), cay = c.y(), caz = c.z();
        } else if (reversed) {
          cax = t.partial_reversed.x(), cay = t.partial_reversed.y(), caz = t.partial_reversed.z();
        } else {
          cax = t.partial.x(), cay = t.partial.y(), caz = t.partial.z() * h / two_r;
        }
        const double rho_vs = rho * vs;
        if constexpr (kImplicit) {
          sx = m / (m + rho_vs * cax);
          if constexpr (kSymXY)
            sy = sx;
          else
            sy = m / (m + rho_vs * cay);
          sz = m / (m + rho_vs * caz);
        } else {
          Fx -= rho_vs * cax * ax, Fy -= rho_vs * cay * ay, Fz -= rho_vs * caz * az;
        }
      }
    } else if constexpr (kAddedMass) {
      cax = t.above.x(), cay = t.above.y(), caz = t.above.z();
    }

    if constexpr (kDrag || !kAddedMass || !kImplicit) {
      f[0] = (f[0] + Fx) * sx, f[1] = (f[1] + Fy) * sy;
    } else {  // implicit added mass alone: no horizontal force of ours, only the scale
      f[0] *= sx, f[1] *= sy;
    }
    f[2] = (f[2] + Fz) * sz;
    if (!replaying) {
      // Implicit added mass alone never reads the horizontal velocity back (no drag, no lagged acceleration).
      if constexpr (kDrag || !kImplicit) st[0] = vx, st[1] = vy;
      st[2] = vz, st[3] = 1.0, st[4] = reversed ? 1.0 : 0.0;
      if constexpr (!kImplicit) st[5] = ax, st[6] = ay, st[7] = az;
    }
    if (a.output) {
      double* o = a.output + kOutputStride * i;
      o[0] = h * h * (3.0 * r - h) / (4.0 * r * r * r);
      o[1] = cax, o[2] = cay, o[3] = caz;
    }
  }
}

// Every row of the table has Ca_x = Ca_y (true for table1, text and uniform): one implicit scale serves both.
bool symmetric_xy(const CaTable& t) {
  for (const Vec3* c : {&t.above, &t.submerged, &t.submerged_reversed, &t.partial, &t.partial_reversed})
    if (c->x() != c->y()) return false;
  return true;
}

template <bool kDrag, bool kAddedMass, bool kImplicit, bool kSymXY>
void dispatch_loop(const FluidParams& p, const KernelArrays& a, double dt_s, bool replay) {
  if (replay) {
    if (a.mask) return kernel<kDrag, kAddedMass, kImplicit, true, true, kSymXY>(p, a, dt_s);
    return kernel<kDrag, kAddedMass, kImplicit, true, false, kSymXY>(p, a, dt_s);
  }
  if (a.mask) return kernel<kDrag, kAddedMass, kImplicit, false, true, kSymXY>(p, a, dt_s);
  return kernel<kDrag, kAddedMass, kImplicit, false, false, kSymXY>(p, a, dt_s);
}

template <bool kDrag, bool kAddedMass>
void dispatch_treatment(const FluidParams& p, const KernelArrays& a, double dt_s, bool replay) {
  if (p.treatment == Treatment::Explicit) return dispatch_loop<kDrag, kAddedMass, false, false>(p, a, dt_s, replay);
  if (kAddedMass && symmetric_xy(p.ca)) return dispatch_loop<kDrag, kAddedMass, true, true>(p, a, dt_s, replay);
  dispatch_loop<kDrag, kAddedMass, true, false>(p, a, dt_s, replay);
}

}  // namespace

void apply_kernel(const FluidParams& p, const KernelArrays& a, double dt_s, bool replay) {
  switch (p.model) {
    case FluidModel::Drag: return dispatch_treatment<true, false>(p, a, dt_s, replay);
    case FluidModel::AddedMass: return dispatch_treatment<false, true>(p, a, dt_s, replay);
    case FluidModel::Both: return dispatch_treatment<true, true>(p, a, dt_s, replay);
  }
}

}  // namespace brash::core
