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

// Closed loft through horizontal sections (same vertex count, counter-clockwise from above, convex ends)
// at increasing heights z[k]. Between two levels each quad is split into two triangles.
inline Mesh loft(const std::vector<std::vector<Eigen::Vector2d>>& sections, const std::vector<double>& z) {
  Mesh m;
  const int n = static_cast<int>(sections.front().size()), levels = static_cast<int>(z.size());
  for (int k = 0; k < levels; ++k)
    for (const auto& p : sections[k]) m.vertices.emplace_back(p.x(), p.y(), z[k]);
  const int top = (levels - 1) * n;
  for (int i = 1; i + 1 < n; ++i) {
    m.faces.push_back({0, i + 1, i});
    m.faces.push_back({top, top + i, top + i + 1});
  }
  for (int k = 0; k + 1 < levels; ++k)
    for (int i = 0; i < n; ++i) {
      const int a = k * n + i, b = k * n + (i + 1) % n;
      m.faces.push_back({a, b, b + n});
      m.faces.push_back({a, b + n, a + n});
    }
  return m;
}

// Bow with a vertical shoulder at x = x_shoulder and a stem raked at phi1: the bow side is the ruled
// surface of straight waterlines from the shoulder (B/2) to the stem (0). On the levels z = T - dz, T,
// T + dz (dz as in measure_fsicr) the sections are exact, so the buttock at B/4 rakes at
// phi2 = atan(2 tan(phi1)) and the entrance angle at T is atan(B/2 / (x_stem(T) - x_shoulder)).
struct RakedStem {
  double x_shoulder, l_bow_T, B, T, D, phi1_deg, lpp;
  double x_stem(double z) const { return x_shoulder + l_bow_T + (z - T) / std::tan(phi1_deg * std::numbers::pi / 180); }
  std::vector<double> levels() const {
    const double dz = 5e-3 * (lpp / 7.0);
    return {0.0, T - dz, T, T + dz, D};
  }
  Mesh mesh() const {
    std::vector<std::vector<Eigen::Vector2d>> sections;
    for (double z : levels())
      sections.push_back({{0, -B / 2}, {x_shoulder, -B / 2}, {x_stem(z), 0}, {x_shoulder, B / 2}, {0, B / 2}});
    return loft(sections, levels());
  }
};

}  // namespace brash::hull::test
