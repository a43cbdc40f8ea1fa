// Run-time guards shared by every engine (guard.hpp).
#include "brash/run/guard.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace brash::guard {

Box domain_box(const Case& c, double hull_x_min_m, double hull_x_max_m, double hull_z_min_m,
               double hull_z_max_m, double duration_s) {
  const double travel = c.ship.speed_m_s * duration_s;
  const double d = c.ice.diameter_mean_m;
  Box b{};
  b[0] = std::min(0.0, c.hull.start_x_m + hull_x_min_m) - 10 * d;
  // Ice pushed ahead of the bow leaves the channel end into open water: leave room for it. A packed bed is
  // pushed ahead as a plug, at most at the ship's speed: room for the ship's whole travel.
  const double open_water = std::max({0.5, 0.1 * c.channel.length_m, travel});
  b[1] = std::max(c.channel.length_m + open_water, c.hull.start_x_m + hull_x_max_m + travel) + 10 * d;
  b[2] = c.speedups.symmetry_y ? -2 * d : -0.5 * c.channel.width_m - 2 * d;
  b[3] = 0.5 * c.channel.width_m + 2 * d;
  b[4] = std::min(hull_z_min_m - c.hull.draft_m, -6 * c.ice.thickness_m) - 2 * d;
  b[5] = std::max(hull_z_max_m - c.hull.draft_m, 6 * c.ice.thickness_m) + 2 * d;
  return b;
}

Limits limits_for_case(const Case& c, const Box& domain) {
  Limits l;
  const double gd = 0.25 * c.ice.diameter_mean_m;
  l.box = Box{domain[0] + gd, domain[1] - gd, domain[2] + gd, domain[3] - gd, domain[4] + gd, domain[5] - gd};
  l.z_max_m = std::min(domain[5] - gd, c.water.level_m + 5 * c.ice.thickness_m);
  const double dmax = 2 * max_radius_m(c);
  const double vmax = std::max(20 * c.ship.speed_m_s, 5.0);
  l.ke_max_J = 0.5 * c.ice.density_kg_m3 * sphere_volume_m3(dmax) * vmax * vmax;
  if (c.guards.max_hull_penetration_d > 0) l.max_hull_penetration_d = c.guards.max_hull_penetration_d;
  return l;
}

std::optional<std::string> check_piece(const Piece& p, const Limits& limits, const HullNow* hull) {
  static const char* const kAxis[3] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    if (!std::isfinite(p.x_m[k])) return fmt::format("non-finite position: {} = {}", kAxis[k], p.x_m[k]);
    if (!std::isfinite(p.v_m_s[k])) return fmt::format("non-finite velocity: v{} = {}", kAxis[k], p.v_m_s[k]);
    if (p.force_N && !std::isfinite((*p.force_N)[k]))
      return fmt::format("non-finite force: f{} = {}", kAxis[k], (*p.force_N)[k]);
    if (!std::isfinite(p.omega_rad_s[k]))
      return fmt::format("non-finite angular velocity: w{} = {}", kAxis[k], p.omega_rad_s[k]);
  }
  if (limits.box) {
    const Box& b = *limits.box;
    for (int k = 0; k < 3; ++k) {
      if (p.x_m[k] < b[2 * k])
        return fmt::format("left the box: {} = {:.6g} < {}lo = {:.6g} (m)", kAxis[k], p.x_m[k], kAxis[k],
                           b[2 * k]);
      if (p.x_m[k] > b[2 * k + 1])
        return fmt::format("left the box: {} = {:.6g} > {}hi = {:.6g} (m)", kAxis[k], p.x_m[k], kAxis[k],
                           b[2 * k + 1]);
    }
  }
  if (limits.z_max_m && p.x_m.z() > *limits.z_max_m)
    return fmt::format("above zmax: z = {:.6g} > {:.6g} m (jumped out of the water)", p.x_m.z(),
                       *limits.z_max_m);
  if (limits.ke_max_J) {
    const double ke = 0.5 * p.mass_kg * p.v_m_s.squaredNorm() +
                      0.5 * 0.4 * p.mass_kg * p.radius_m * p.radius_m * p.omega_rad_s.squaredNorm();
    if (ke > *limits.ke_max_J)
      return fmt::format("runaway kinetic energy: {:.4g} J > ke_max = {:.4g} J (|v| = {:.4g} m/s)", ke,
                         *limits.ke_max_J, p.v_m_s.norm());
  }
  if (limits.max_hull_penetration_d && hull && hull->proximity) {
    const Eigen::Vector3d q = p.x_m - hull->origin_m;  // hull frame
    const double pen = hull->proximity->penetration(q, p.radius_m);
    const double d = 2 * p.radius_m;
    if (pen > *limits.max_hull_penetration_d * d) {
      const bool inside = pen > p.radius_m;
      return fmt::format(
          "hull penetration: {:.4g} m = {:.0f} % of its diameter {:.4g} m > max_hull_penetration_d {:g} "
          "(centre {} "
          "the hull{}; hull frame x = {:.4f}, y = {:.4f}, z = {:.4f} m)",
          pen, 100 * pen / d, d, *limits.max_hull_penetration_d, inside ? "inside" : "outside",
          inside ? fmt::format(", {:.4g} m from its surface", pen - p.radius_m) : std::string(), q.x(), q.y(),
          q.z());
    }
  }
  return std::nullopt;
}

std::optional<std::string> check_timestep(double dt_s, double radius_m, double density_kg_m3,
                                          double youngs_modulus_pa, double poisson_ratio,
                                          double max_fraction) {
  const double tr = rayleigh_time_s(radius_m, density_kg_m3, youngs_modulus_pa, poisson_ratio);
  if (!(dt_s > max_fraction * tr)) return std::nullopt;
  return fmt::format(
      "timestep {:g} s is too large for the contact stiffness: {:.0f} % of the Rayleigh time {:.4g} s (r = "
      "{:g} m, "
      "rho = {:g} kg/m^3, E = {:g} Pa, nu = {:g}); limit {:.0f} %, use dt <= {:.4g} s",
      dt_s, 100 * dt_s / tr, tr, radius_m, density_kg_m3, youngs_modulus_pa, poisson_ratio,
      100 * max_fraction, max_fraction * tr);
}

std::string stop_message(long step, double t_s, long piece_id, std::string_view cause) {
  return fmt::format("guard: step {} (t = {:.6g} s): piece {}: {}", step, t_s, piece_id, cause);
}

}  // namespace brash::guard
