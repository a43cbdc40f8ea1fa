// Test helpers: analytic hulls (box barge, wedge bow) built as closed outward meshes.
#pragma once
#include <brash/hull/mesh.hpp>

#include <cmath>
#include <numbers>
#include <vector>

namespace brash::hull::test {

// Closed prism between two horizontal polygons (same vertex count, counter-clockwise seen from above):
// bottom at z = 0, top at z = depth. Quads are split into triangles.
inline Mesh prism(const std::vector<Eigen::Vector2d>& bottom, const std::vector<Eigen::Vector2d>& top, double depth) {
  Mesh m;
  const int n = static_cast<int>(bottom.size());
  for (const auto& p : bottom) m.vertices.emplace_back(p.x(), p.y(), 0.0);
  for (const auto& p : top) m.vertices.emplace_back(p.x(), p.y(), depth);
  for (int i = 1; i + 1 < n; ++i) {
    m.faces.push_back({0, i + 1, i});          // bottom, normal -z
    m.faces.push_back({n, n + i, n + i + 1});  // top, normal +z
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    m.faces.push_back({i, j, n + j});
    m.faces.push_back({i, n + j, n + i});
  }
  return m;
}

inline Mesh box(double L, double B, double D) {
  const std::vector<Eigen::Vector2d> s{{0, -B / 2}, {L, -B / 2}, {L, B / 2}, {0, B / 2}};
  return prism(s, s, D);
}

// Box stern + parallel body, bow side is one plane per side: y = tan(alpha) (x_stem(z) - x) with the stem
// line x_stem(z) = x_stem_T + (z - T) / tan(phi). So entrance angle = alpha at every z, and both the stem
// and every buttock rake at phi from the horizontal.
struct Wedge {
  double L_par_T, B, T, D, alpha_deg, phi_deg;
  double tan_a() const { return std::tan(alpha_deg * std::numbers::pi / 180); }
  double l_bow() const { return B / 2 / tan_a(); }
  double x_stem(double z) const { return L_par_T + l_bow() + (z - T) / std::tan(phi_deg * std::numbers::pi / 180); }
  Mesh mesh() const {
    auto section = [&](double z) {
      const double xs = x_stem(z), xp = xs - l_bow();
      return std::vector<Eigen::Vector2d>{{0, -B / 2}, {xp, -B / 2}, {xs, 0}, {xp, B / 2}, {0, B / 2}};
    };
    return prism(section(0), section(D), D);
  }
};

}  // namespace brash::hull::test
