// Specialised array kernel (see kernel.hpp). One template instance per (drag?, added mass?, implicit?).
#include "brash/core/kernel.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "brash/core/flow_acceleration.hpp"
#include "brash/core/fluid.hpp"
#include "brash/core/immersion.hpp"

namespace brash::core {
namespace {

// Ca of a wetted sphere (h > 0): select_ca() of fluid.hpp without its dry branch and with scalars, for the
// hot loop (the implicit added-mass path has no dry-sphere test at all).
struct CaRow {
  double x, y, z;
};
inline CaRow wetted_ca(const CaTable& t, double h, double two_r, bool reversed) {
  if (h >= two_r) {
    const Vec3& c = reversed ? t.submerged_reversed : t.submerged;
    return {c.x(), c.y(), c.z()};
  }
  if (reversed) return {t.partial_reversed.x(), t.partial_reversed.y(), t.partial_reversed.z()};
  return {t.partial.x(), t.partial.y(), t.partial.z() * h / two_r};
}

// State flag [3]: 0 = never evaluated, 1 = evaluated, 2 = evaluated and the motion was reversed.
inline bool reversed_flag(const double* st) { return st[3] > 1.5; }
inline constexpr double kEvaluatedFlag[2] = {1.0, 2.0};  // indexed by the reversal: a load, not a select

// kReplay, kMasked and kGravity are hoisted out of the loop (template parameters, not per-sphere branches):
// the normal step (no replay, group all, the engine's own gravity) then costs only the physics. Scalars
// instead of small arrays keep everything in registers. The per-atom output is filled by a separate pass
// (fill_output) on the steps that need it.
template <bool kDrag, bool kAddedMass, bool kImplicit, bool kReplay, bool kMasked, bool kSymXY, bool kGravity>
void kernel(const FluidParams& p, const KernelArrays& a, double dt_s) {
  constexpr double kPiOver3 = std::numbers::pi / 3.0;
  const double rho = p.water_density_kg_m3;
  const double rho_pi3 = rho * kPiOver3;                     // V_s = pi/3 h^2 (3r - h)
  const double rho_g_pi3 = rho * p.gravity_m_s2 * kPiOver3;  // buoyancy per h^2 (3r - h)
  const double zw = p.water_level_m;
  const double g = p.gravity_m_s2;
  const double inv_dt = dt_s > 0 ? 1.0 / dt_s : 0.0;
  const CaTable& t = p.ca;
  const double ux0 = p.flow_velocity_m_s.x(), uy0 = p.flow_velocity_m_s.y(), uz0 = p.flow_velocity_m_s.z();
  // The water's acceleration (flow_acceleration.hpp): per sphere, uniform, or none (still water: no term at all,
  // so the forces are bit for bit those of the model without it). A branch that is the same for every sphere.
  const double* flow_accel = a.flow_acceleration_m_s2;
  const double ax0 = p.flow_acceleration_m_s2.x(), ay0 = p.flow_acceleration_m_s2.y(),
               az0 = p.flow_acceleration_m_s2.z();
  const bool has_flow_accel = flow_accel || !p.flow_acceleration_m_s2.isZero();

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
      // Restart files written before the flags were merged hold the reversal in [4]: read it, and store the
      // row in the current layout (same content; replay steps only, so the normal step pays nothing).
      reversed = reversed_flag(st) || st[4] != 0.0;
      st[3] = kEvaluatedFlag[reversed], st[4] = 0.0;
      ax = st[5], ay = st[6], az = st[7];
    } else {
      const double* vv = a.v_m_s + 3 * i;
      vx = vv[0], vy = vv[1], vz = vv[2];
      // A sphere without history has an all-zero state (engines zero new rows), so st[2] = 0 and the
      // product test alone says "not reversed"; only the explicit acceleration needs the flag itself. The
      // reversal is of the motion relative to the water (motion_reversed, fluid.hpp): uz = 0 in still water.
      // With a flow a sphere without history would compare with uz: it needs its evaluated flag (st[3] != 0).
      const double uz = a.flow_m_s ? a.flow_m_s[3 * i + 2] : uz0;
      reversed = (vz - uz) * (st[2] - uz) < 0.0 && (uz == 0.0 || st[3] != 0.0);
      if constexpr (!kImplicit && kAddedMass)
        if (st[3] != 0.0) ax = (vx - st[0]) * inv_dt, ay = (vy - st[1]) * inv_dt, az = (vz - st[2]) * inv_dt;
    }

    const double two_r = 2.0 * r;
    // min/max in this operand order compile to minsd/maxsd and keep a NaN height NaN (the guards see it)
    const double h = std::min(std::max(zw - z + r, 0.0), two_r);
    const double h2_3r_minus_h = h * h * (3.0 * r - h);  // 3 V_s / pi
    double Fx = 0.0, Fy = 0.0, Fz = rho_g_pi3 * h2_3r_minus_h;
    if constexpr (kGravity) Fz -= m * g;
    double sx = 1.0, sy = 1.0, sz = 1.0;

    // Implicit added mass alone needs no dry-sphere branch: at h = 0, V_s = 0 and every scale is exactly 1.
    constexpr bool kWetTest = kDrag || !kImplicit;
    if (!kWetTest || h > 0.0) {
      if constexpr (kDrag) {
        double ux = vx - ux0, uy = vy - uy0, uz = vz - uz0;
        if (a.flow_m_s) {  // the flow around a hull (hull_flow.hpp); a well-predicted branch
          const double* fl = a.flow_m_s + 3 * i;
          ux = vx - fl[0], uy = vy - fl[1], uz = vz - fl[2];
        }
        const double speed2 = ux * ux + uy * uy + uz * uz;
        if (speed2 > 0.0) {
          const double speed = std::sqrt(speed2);
          Immersion im;
          im.height_m = h;
          im.waterline_radius_sq_m2 = h * (two_r - h);
          const double area = projected_area(r, im, uz / speed);
          const double cd_speed = drag_cd_speed(p, speed, two_r);  // C_D |u| (drag.hpp)
          const double k = -0.5 * rho * cd_speed * area;
          Fx += k * ux, Fy += k * uy, Fz += k * uz;
        }
      }
      CaRow ca{0.0, 0.0, 0.0};
      const double rho_vs = rho_pi3 * h2_3r_minus_h;
      if constexpr (kAddedMass) {
        ca = wetted_ca(t, h, two_r, reversed);
        if constexpr (kImplicit) {
          sx = implicit_scale(m, added_mass_kg(rho_vs, ca.x));
          if constexpr (kSymXY)
            sy = sx;
          else
            sy = implicit_scale(m, added_mass_kg(rho_vs, ca.y));
          sz = implicit_scale(m, added_mass_kg(rho_vs, ca.z));
        } else {
          Fx -= added_mass_kg(rho_vs, ca.x) * ax, Fy -= added_mass_kg(rho_vs, ca.y) * ay,
              Fz -= added_mass_kg(rho_vs, ca.z) * az;
        }
      }
      if (has_flow_accel) {
        const double* da = flow_accel ? flow_accel + 3 * i : nullptr;
        Fx += flow_acceleration_force_N(rho_vs, ca.x, da ? da[0] : ax0);
        Fy += flow_acceleration_force_N(rho_vs, ca.y, da ? da[1] : ay0);
        Fz += flow_acceleration_force_N(rho_vs, ca.z, da ? da[2] : az0);
      }
    }

    if (kDrag || !kAddedMass || !kImplicit || has_flow_accel) {
      f[0] = scaled_total_force(f[0], Fx, sx), f[1] = scaled_total_force(f[1], Fy, sy);
    } else {  // implicit added mass alone: no horizontal force of ours, only the scale (no + 0.0 to pay)
      f[0] *= sx, f[1] *= sy;
    }
    f[2] = scaled_total_force(f[2], Fz, sz);
    if (!replaying) {
      // Implicit added mass alone never reads the horizontal velocity back (no drag, no lagged acceleration).
      if constexpr (kDrag || !kImplicit) st[0] = vx, st[1] = vy;
      st[2] = vz, st[3] = kEvaluatedFlag[reversed];
      if constexpr (!kImplicit) st[5] = ax, st[6] = ay, st[7] = az;
    }
  }
}

// Per-atom output of the last evaluation (submerged fraction, Ca used, active), from positions and the state flag;
// a sphere outside the mask (idle) floats all the same: its immersion is its position's, its Ca 0 (no fluid force).
// Not on the hot path: the readable immersion() and select_ca() of the reference serve.
void fill_output(const FluidParams& p, const KernelArrays& a) {
  const bool added_mass = p.model != FluidModel::Drag;
  for (std::size_t i = 0; i < a.n; ++i) {
    const bool active = !a.mask || (a.mask[i] & a.groupbit);
    const double r = a.radius_m[i];
    const Immersion im = immersion(r, a.x_m[3 * i + 2], p.water_level_m);
    const Vec3 ca = added_mass && active ? select_ca(p.ca, r, im, reversed_flag(a.state + kStateStride * i))
                                         : Vec3::Zero();
    double* o = a.output + kOutputStride * i;
    o[0] = im.fraction, o[1] = ca.x(), o[2] = ca.y(), o[3] = ca.z(), o[4] = active ? 1.0 : 0.0;
  }
}

// Every row of the table has Ca_x = Ca_y (true for table1, text and uniform): one implicit scale serves both.
bool symmetric_xy(const CaTable& t) {
  for (const Vec3* c : {&t.above, &t.submerged, &t.submerged_reversed, &t.partial, &t.partial_reversed})
    if (c->x() != c->y()) return false;
  return true;
}

template <bool kDrag, bool kAddedMass, bool kImplicit, bool kSymXY, bool kGravity>
void dispatch_loop(const FluidParams& p, const KernelArrays& a, double dt_s, bool replay) {
  if (replay) {
    if (a.mask) return kernel<kDrag, kAddedMass, kImplicit, true, true, kSymXY, kGravity>(p, a, dt_s);
    return kernel<kDrag, kAddedMass, kImplicit, true, false, kSymXY, kGravity>(p, a, dt_s);
  }
  if (a.mask) return kernel<kDrag, kAddedMass, kImplicit, false, true, kSymXY, kGravity>(p, a, dt_s);
  return kernel<kDrag, kAddedMass, kImplicit, false, false, kSymXY, kGravity>(p, a, dt_s);
}

template <bool kDrag, bool kAddedMass, bool kImplicit, bool kSymXY>
void dispatch_gravity(const FluidParams& p, const KernelArrays& a, double dt_s, bool replay) {
  if (p.apply_gravity) return dispatch_loop<kDrag, kAddedMass, kImplicit, kSymXY, true>(p, a, dt_s, replay);
  dispatch_loop<kDrag, kAddedMass, kImplicit, kSymXY, false>(p, a, dt_s, replay);
}

template <bool kDrag, bool kAddedMass>
void dispatch_treatment(const FluidParams& p, const KernelArrays& a, double dt_s, bool replay) {
  if (p.treatment == Treatment::Explicit) return dispatch_gravity<kDrag, kAddedMass, false, false>(p, a, dt_s, replay);
  if (kAddedMass && symmetric_xy(p.ca)) return dispatch_gravity<kDrag, kAddedMass, true, true>(p, a, dt_s, replay);
  dispatch_gravity<kDrag, kAddedMass, true, false>(p, a, dt_s, replay);
}

}  // namespace

void apply_kernel(const FluidParams& p, const KernelArrays& a, double dt_s, bool replay) {
  switch (p.model) {
    case FluidModel::Drag: dispatch_treatment<true, false>(p, a, dt_s, replay); break;
    case FluidModel::AddedMass: dispatch_treatment<false, true>(p, a, dt_s, replay); break;
    case FluidModel::Both: dispatch_treatment<true, true>(p, a, dt_s, replay); break;
  }
  if (a.output) fill_output(p, a);
}

}  // namespace brash::core
