// Specialised array kernel (see kernel.hpp). One template instance per (drag?, added mass?, implicit?).
#include "brash/core/kernel.hpp"

#include <cmath>
#include <numbers>

#include "brash/core/immersion.hpp"

namespace brash::core {
namespace {

template <bool kDrag, bool kAddedMass, bool kImplicit>
void kernel(const FluidParams& p, const KernelArrays& a, double dt_s, bool replay) {
  constexpr double kPi = std::numbers::pi;
  const double rho = p.water_density_kg_m3;
  const double rho_g = rho * p.gravity_m_s2;
  const double zw = p.water_level_m;
  const double g_applied = p.apply_gravity ? p.gravity_m_s2 : 0.0;
  const double inv_dt = dt_s > 0 ? 1.0 / dt_s : 0.0;
  const CaTable& t = p.ca;

  for (std::size_t i = 0; i < a.n; ++i) {
    if (a.mask && !(a.mask[i] & a.groupbit)) continue;
    const double r = a.radius_m[i];
    const double m = a.mass_kg[i];
    const double* x = a.x_m + 3 * i;
    double* st = a.state + kStateStride * i;
    double* f = a.f_N + 3 * i;
    const bool replaying = replay && st[3] != 0.0;
    // velocity and history of this evaluation
    double v[3];
    bool reversed;
    double acc[3] = {0, 0, 0};
    if (replaying) {
      v[0] = st[0], v[1] = st[1], v[2] = st[2];
      reversed = st[4] != 0.0;
      acc[0] = st[5], acc[1] = st[6], acc[2] = st[7];
    } else {
      const double* vv = a.v_m_s + 3 * i;
      v[0] = vv[0], v[1] = vv[1], v[2] = vv[2];
      const bool has_prev = st[3] != 0.0;
      reversed = has_prev && v[2] * st[2] < 0.0;
      if (!kImplicit && kAddedMass && has_prev)
        for (int k = 0; k < 3; ++k) acc[k] = (v[k] - st[k]) * inv_dt;
    }

    double h = zw - x[2] + r;
    h = h < 0.0 ? 0.0 : (h > 2.0 * r ? 2.0 * r : h);
    const double vs = kPi / 3.0 * h * h * (3.0 * r - h);
    double F[3] = {0.0, 0.0, rho_g * vs - m * g_applied};
    double ca[3] = {0.0, 0.0, 0.0};
    double s[3] = {1.0, 1.0, 1.0};

    if (h > 0.0) {
      if constexpr (kDrag) {
        const double u[3] = {v[0] - p.flow_velocity_m_s.x(), v[1] - p.flow_velocity_m_s.y(),
                             v[2] - p.flow_velocity_m_s.z()};
        const double speed2 = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
        if (speed2 > 0.0) {
          const double speed = std::sqrt(speed2);
          Immersion im;
          im.height_m = h;
          im.waterline_radius_sq_m2 = h * (2.0 * r - h);
          const double area = projected_area(r, im, u[2] / speed);
          double cd_speed;  // C_D |u|
          if (p.drag_law == DragLaw::Constant) {
            cd_speed = p.drag_coefficient * speed;
          } else {
            const double d = 2.0 * r;
            const double re = speed * d / p.kinematic_viscosity_m2_s;
            cd_speed = re >= 1000.0 ? 0.44 * speed
                                    : 24.0 * p.kinematic_viscosity_m2_s / d * (1.0 + 0.15 * std::pow(re, 0.687));
          }
          const double k = -0.5 * rho * cd_speed * area;
          F[0] += k * u[0], F[1] += k * u[1], F[2] += k * u[2];
        }
      }
      if constexpr (kAddedMass) {
        if (h >= 2.0 * r) {
          const Vec3& c = reversed ? t.submerged_reversed : t.submerged;
          ca[0] = c.x(), ca[1] = c.y(), ca[2] = c.z();
        } else if (reversed) {
          ca[0] = t.partial_reversed.x(), ca[1] = t.partial_reversed.y(), ca[2] = t.partial_reversed.z();
        } else {
          ca[0] = t.partial.x(), ca[1] = t.partial.y(), ca[2] = t.partial.z() * h / (2.0 * r);
        }
        const double rho_vs = rho * vs;
        if constexpr (kImplicit) {
          s[0] = m / (m + rho_vs * ca[0]);
          s[1] = ca[1] == ca[0] ? s[0] : m / (m + rho_vs * ca[1]);
          s[2] = m / (m + rho_vs * ca[2]);
        } else {
          for (int k = 0; k < 3; ++k) F[k] -= rho_vs * ca[k] * acc[k];
        }
      }
    } else if constexpr (kAddedMass) {
      ca[0] = t.above.x(), ca[1] = t.above.y(), ca[2] = t.above.z();
    }

    for (int k = 0; k < 3; ++k) f[k] = (f[k] + F[k]) * s[k];
    if (!replaying) {
      st[0] = v[0], st[1] = v[1], st[2] = v[2], st[3] = 1.0, st[4] = reversed ? 1.0 : 0.0;
      if constexpr (!kImplicit) st[5] = acc[0], st[6] = acc[1], st[7] = acc[2];
    }
    if (a.output) {
      double* o = a.output + kOutputStride * i;
      o[0] = h * h * (3.0 * r - h) / (4.0 * r * r * r);
      o[1] = ca[0], o[2] = ca[1], o[3] = ca[2];
    }
  }
}

template <bool kDrag, bool kAddedMass>
void dispatch_treatment(const FluidParams& p, const KernelArrays& a, double dt_s, bool replay) {
  if (p.treatment == Treatment::Implicit)
    kernel<kDrag, kAddedMass, true>(p, a, dt_s, replay);
  else
    kernel<kDrag, kAddedMass, false>(p, a, dt_s, replay);
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
