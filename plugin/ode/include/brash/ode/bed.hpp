// Small synthetic floating beds for the rest test and the benchmark: two hexagonal layers of spheres
// (diameters normal, truncated) inside a box of walls, placed near their floating height.
#pragma once
#include <cstdint>
#include <vector>

#include "brash/ode/world.hpp"

namespace brash::ode {

struct LatticeBedSpec {
  int nx = 12, ny = 10;            // spheres per row (x) and rows (y) of the lower layer
  double diameter_mean_m = 0.017578;
  double diameter_sd_m = 0.017578 * 0.05;
  double truncation_sd = 2.0;
  double spacing_factor = 1.02;    // lattice spacing = factor * largest diameter (no initial overlap)
  std::uint64_t seed = 1;
  double water_level_m = 0.0;
};

struct Bed {
  std::vector<Vec3> position_m;
  std::vector<double> radius_m;
  double length_x_m = 0, width_y_m = 0;   // walls at x = 0, length and y = +-width/2
};

Bed make_lattice_bed(const LatticeBedSpec& spec);

// Thin fixed boxes: side walls at y = +-half_width (x from x0 to x1), and end walls at x0 and x1 if asked.
// Walls span z in [z_lo, z_hi]; thickness 0.05 m outside the channel.
void add_channel_walls(World& w, double x0, double x1, double half_width, bool end_walls, double z_lo = -0.5,
                       double z_hi = 0.5);

}  // namespace brash::ode
