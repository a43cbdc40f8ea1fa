// The far-field rule (see far_field.hpp). Squared norms: no square roots on the per-piece path.
#include "brash/core/far_field.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
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

// A breadth-first search from the pieces at the bow over a grid of x-y cells no smaller than the largest reach,
// so that touching pieces lie in the same or neighbouring cells.
double foremost_of_push(const std::vector<MovingPiece>& moving, double bow_x_m, double gap_m) {
  double foremost = -std::numeric_limits<double>::infinity();
  if (moving.empty()) return foremost;
  double max_r = 0;
  for (const auto& p : moving) max_r = std::max(max_r, p.radius_m);
  const double cell = std::max(2.0 * max_r + gap_m, 1e-9);
  const auto cell_of = [cell](double v) { return static_cast<std::int64_t>(std::floor(v / cell)); };
  struct Entry {
    std::int64_t ix, iy;
    std::uint32_t piece;
  };
  std::vector<Entry> grid(moving.size());
  for (std::size_t i = 0; i < moving.size(); ++i)
    grid[i] = {cell_of(moving[i].x_m), cell_of(moving[i].y_m), static_cast<std::uint32_t>(i)};
  const auto before = [](const Entry& a, const Entry& b) {
    return a.ix != b.ix ? a.ix < b.ix : (a.iy != b.iy ? a.iy < b.iy : a.piece < b.piece);
  };
  std::sort(grid.begin(), grid.end(), before);
  std::vector<char> reached(moving.size(), 0);
  std::vector<std::uint32_t> queue;
  for (std::size_t i = 0; i < moving.size(); ++i)
    if (moving[i].x_m - moving[i].radius_m < bow_x_m + gap_m) reached[i] = 1, queue.push_back(static_cast<std::uint32_t>(i));
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const MovingPiece& a = moving[queue[q]];
    foremost = std::max(foremost, a.x_m);
    const std::int64_t ix = cell_of(a.x_m), iy = cell_of(a.y_m);
    for (std::int64_t jx = ix - 1; jx <= ix + 1; ++jx)
      for (std::int64_t jy = iy - 1; jy <= iy + 1; ++jy) {
        auto it = std::lower_bound(grid.begin(), grid.end(), Entry{jx, jy, 0}, before);
        for (; it != grid.end() && it->ix == jx && it->iy == jy; ++it) {
          const MovingPiece& b = moving[it->piece];
          if (reached[it->piece] ||
              !touching(a.x_m - b.x_m, a.y_m - b.y_m, a.z_m - b.z_m, a.radius_m + gap_m, b.radius_m))
            continue;
          reached[it->piece] = 1;
          queue.push_back(it->piece);
        }
      }
  }
  return foremost;
}

bool wakes_by_neighbour(const WakeRule& rule, const Vec3& v) {
  return rule.reads_neighbour_speed() && v.squaredNorm() > rule.speed_m_s * rule.speed_m_s;
}

bool idle_after_update(const WakeRule& rule, FarFieldZone zone, bool was_idle, bool first_update,
                       const Vec3& v) {
  if (zone == FarFieldZone::Inside) return false;
  if (!rule.enabled()) return true;
  if (zone == FarFieldZone::Ahead) {
    // by push front the bed ahead is held out from the start, moving or not, as the moving window holds it: ice
    // that spreads out of an open channel end far ahead does not take the front there
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
