// Closed triangulated test bodies for the panel method: a unit icosphere (subdivided icosahedron, vertices on
// the sphere, faces counter-clockwise seen from outside) and a UV sphere with a ring of vertices on its
// equator.
#pragma once
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

#include "brash/core/panel_flow.hpp"

namespace brash::test {

using core::Triangle;
using core::Vec3;

// 20 * 4^levels triangles on the unit sphere
inline std::vector<Triangle> icosphere(int levels) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> v = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                         {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  for (Vec3& p : v) p.normalize();
  std::vector<std::array<int, 3>> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                       {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                       {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                       {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      if (auto it = mid.find(key); it != mid.end()) return it->second;
      v.push_back((v[a] + v[b]).normalized());
      return mid[key] = static_cast<int>(v.size()) - 1;
    };
    std::vector<std::array<int, 3>> next;
    for (const auto& t : f) {
      const int a = midpoint(t[0], t[1]), b = midpoint(t[1], t[2]), c = midpoint(t[2], t[0]);
      next.insert(next.end(), {{t[0], a, c}, {t[1], b, a}, {t[2], c, b}, {a, b, c}});
    }
    f = std::move(next);
  }
  std::vector<Triangle> out;
  for (const auto& t : f) out.push_back({{v[t[0]], v[t[1]], v[t[2]]}});
  return out;
}

// A unit sphere of nu longitudes and nv latitude bands (nv even: a vertex ring on the equator z = 0); the
// polar bands are triangles, the others quads split in two.
inline std::vector<Triangle> uv_sphere(int nu, int nv) {
  auto p = [&](int i, int j) {
    const double th = std::numbers::pi * j / nv, ph = 2.0 * std::numbers::pi * i / nu;
    return Vec3(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
  };
  std::vector<Triangle> out;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const Vec3 a = p(i, j), b = p(i, j + 1), c = p(i + 1, j + 1), d = p(i + 1, j);
      if (j > 0) out.push_back({{a, b, d}});
      if (j < nv - 1) out.push_back({{b, c, d}});
    }
  return out;
}

// scaled by (sx, sy, sz): a sphere into an ellipsoid
inline std::vector<Triangle> scaled(std::vector<Triangle> t, const Vec3& s) {
  for (Triangle& x : t)
    for (Vec3& p : x.v) p = p.cwiseProduct(s);
  return t;
}

inline core::PanelBody one_panel_each(std::vector<Triangle> t, bool mirror_z = false) {
  core::PanelBody b;
  b.triangles = std::move(t);
  b.first.clear();
  for (std::size_t i = 0; i <= b.triangles.size(); ++i) b.first.push_back(i);
  b.mirror_z = mirror_z;
  return b;
}

}  // namespace brash::test
