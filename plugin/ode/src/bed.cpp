// Synthetic lattice beds and channel walls (bed.hpp).
#include "brash/ode/bed.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace brash::ode {

Bed make_lattice_bed(const LatticeBedSpec& s) {
  std::mt19937_64 rng(s.seed);
  std::normal_distribution<double> nd(s.diameter_mean_m, s.diameter_sd_m);
  auto draw = [&] {
    for (;;) {
      const double d = nd(rng);
      if (std::abs(d - s.diameter_mean_m) <= s.truncation_sd * s.diameter_sd_m) return d;
    }
  };
  const double dmax = s.diameter_mean_m + s.truncation_sd * s.diameter_sd_m;
  const double a = s.spacing_factor * dmax;
  const double row = a * std::sqrt(3.0) / 2.0;
  const double rmax = 0.5 * dmax;
  Bed bed;
  bed.length_x_m = (s.nx - 1) * a + 0.5 * a + 2 * rmax + 0.1 * a;
  bed.width_y_m = (s.ny - 1) * row + 2 * rmax + 0.1 * a;
  const double y0 = -0.5 * bed.width_y_m + rmax + 0.05 * a;
  const double x0 = rmax + 0.05 * a;
  // Lower layer centre a little below the waterline, upper layer one tetrahedral height above it.
  const double z_low = s.water_level_m - 0.6 * rmax;
  const double z_up = z_low + std::sqrt(2.0 / 3.0) * a;
  for (int layer = 0; layer < 2; ++layer) {
    for (int j = 0; j < s.ny; ++j) {
      for (int i = 0; i < s.nx; ++i) {
        double x = x0 + i * a + ((j % 2) ? 0.5 * a : 0.0);
        double y = y0 + j * row;
        if (layer == 1) {
          x += 0.5 * a;
          y += row / 3.0;
          if (x + rmax > bed.length_x_m || y + rmax > 0.5 * bed.width_y_m) continue;
        }
        bed.position_m.emplace_back(x, y, layer ? z_up : z_low);
        bed.radius_m.push_back(0.5 * draw());
      }
    }
  }
  return bed;
}

void add_channel_walls(World& w, double x0, double x1, double hw, bool end_walls, double z_lo, double z_hi) {
  constexpr double t = 0.05;
  const double zc = 0.5 * (z_lo + z_hi), zh = z_hi - z_lo;
  const double len = x1 - x0 + 2 * t;
  w.add_wall_box(Vec3(0.5 * (x0 + x1), hw + 0.5 * t, zc), Vec3(len, t, zh));
  w.add_wall_box(Vec3(0.5 * (x0 + x1), -hw - 0.5 * t, zc), Vec3(len, t, zh));
  if (end_walls) {
    w.add_wall_box(Vec3(x0 - 0.5 * t, 0, zc), Vec3(t, 2 * hw, zh));
    w.add_wall_box(Vec3(x1 + 0.5 * t, 0, zc), Vec3(t, 2 * hw, zh));
  }
}

}  // namespace brash::ode
