// The far-field rule (see far_field.hpp). Squared norms: no square roots on the per-piece path.
#include "brash/core/far_field.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace brash::core {

FarFieldZone far_field_zone(const FarFieldWindow& w, double x_m, double y_m) {
  if (x_m > w.hi_x_m) return FarFieldZone::Ahead;
  if (x_m < w.lo_x_m) return FarFieldZone::Behind;
  if (std::abs(y_m - w.centre_y_m) > w.half_width_m) return FarFieldZone::Beside;
  return FarFieldZone::Inside;
}

double wake_force_N(double weight_fraction, double mean_diameter_m, double ice_density_kg_m3,
                    double gravity_m_s2) {
  const double d = mean_diameter_m;
  const double weight_N = ice_density_kg_m3 * (std::numbers::pi / 6.0 * d * d * d) * gravity_m_s2;
  return weight_fraction * weight_N;
}

bool wakes(const WakeRule& rule, double fx_N, double fy_N, FarFieldZone zone) {
  const bool by_force =
      rule.by == WakeBy::Force || (rule.by == WakeBy::PushFront && zone != FarFieldZone::Ahead);
  return by_force && rule.force_N > 0 && fx_N * fx_N + fy_N * fy_N > rule.force_N * rule.force_N;
}

double push_front_x(double bow_x_m, double foremost_moving_x_m, double previous_front_x_m, double ahead_m) {
  return std::max(previous_front_x_m, std::max(bow_x_m, foremost_moving_x_m) + ahead_m);
}

bool wakes_by_neighbour(const WakeRule& rule, const Vec3& v) {
  return rule.reads_neighbour_speed() && v.squaredNorm() > rule.speed_m_s * rule.speed_m_s;
}

bool idle_after_update(const WakeRule& rule, FarFieldZone zone, bool was_idle, bool first_update,
                       const Vec3& v) {
  if (zone == FarFieldZone::Inside) return false;
  if (!rule.enabled()) return true;
  if (zone == FarFieldZone::Ahead) {
    // by push front the bed ahead is held out from the start, moving or not, as the moving window holds it:
    // ice that spreads out of an open channel end far ahead does not take the front there
    if (first_update && rule.front_follows_push()) return true;
    if (!first_update) return was_idle;
  }
  return v.x() * v.x() + v.y() * v.y() + v.z() * v.z() <= rule.speed_m_s * rule.speed_m_s;
}

MovingWindow moving_window(double stern_x_m, double bow_x_m, double foremost_moving_x_m, double previous_front_x_m,
                           double behind_m, double ahead_m) {
  MovingWindow w;
  w.remove_below_x_m = stern_x_m - behind_m;
  w.insert_below_x_m = push_front_x(bow_x_m, foremost_moving_x_m, previous_front_x_m, ahead_m);
  return w;
}

}  // namespace brash::core
