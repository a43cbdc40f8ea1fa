// Geometry of a sphere cut by a horizontal water plane: submerged height, volume, fraction and
// the projected area of the submerged part. Pure functions, no allocation (hot path of every engine).
#pragma once
#include <algorithm>
#include <cmath>
#include <numbers>

namespace brash::core {

struct Immersion {
  double height_m = 0;     // submerged height h in [0, 2r]
  double volume_m3 = 0;    // V_s = pi h^2 (3r - h) / 3
  double fraction = 0;     // s = V_s / V
  double waterline_radius_sq_m2 = 0;  // squared radius of the circle cut by the water plane (0 if not cut);
                                      // kept squared so the hot path needs no sqrt
};

// Sphere of radius r with centre height z_c, water surface at z_w.
inline Immersion immersion(double radius_m, double centre_z_m, double water_level_m) {
  const double r = radius_m;
  const double h = std::clamp(water_level_m - (centre_z_m - r), 0.0, 2.0 * r);
  Immersion im;
  im.height_m = h;
  im.volume_m3 = std::numbers::pi * h * h * (3.0 * r - h) / 3.0;
  im.fraction = h * h * (3.0 * r - h) / (4.0 * r * r * r);
  im.waterline_radius_sq_m2 = h * (2.0 * r - h);
  return im;
}

// Area of the submerged part projected on a horizontal plane (seen along z):
// the waterline disc while the centre is above water, the full disc once it is below.
inline double projected_area_vertical(double radius_m, const Immersion& im) {
  const double r = radius_m;
  if (im.height_m <= r) return std::numbers::pi * im.waterline_radius_sq_m2;
  return std::numbers::pi * r * r;
}

// Area of the submerged part projected on a vertical plane (seen along a horizontal direction):
// a circular segment of height h.
inline double projected_area_horizontal(double radius_m, const Immersion& im) {
  const double r = radius_m;
  const double h = im.height_m;
  if (h <= 0) return 0;
  if (h >= 2 * r) return std::numbers::pi * r * r;
  const double c = std::clamp((r - h) / r, -1.0, 1.0);
  return r * r * std::acos(c) - (r - h) * std::sqrt(im.waterline_radius_sq_m2);
}

// Projected submerged area normal to a direction with vertical direction cosine cos_z:
// A = A_vert cos^2 + A_horiz sin^2. Exact for the two principal directions, continuous in between
// and across the surface (both areas go to 0 at h = 0 and to pi r^2 at h = 2r).
inline double projected_area(double radius_m, const Immersion& im, double cos_z) {
  const double c2 = std::clamp(cos_z * cos_z, 0.0, 1.0);
  return projected_area_vertical(radius_m, im) * c2 + projected_area_horizontal(radius_m, im) * (1.0 - c2);
}

}  // namespace brash::core
