// Half-breadths of a hull mesh and its thin-ship flow table (flow.hpp).
#include <brash/hull/flow.hpp>

#include "section.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "brash/error.hpp"

namespace brash::hull {

std::vector<double> half_breadths(const Mesh& mesh, std::span<const double> x_m,
                                  std::span<const double> z_m) {
  const std::size_t nx = x_m.size();
  std::vector<double> out(nx * z_m.size(), 0.0);
  for (std::size_t j = 0; j < z_m.size(); ++j) {
    double* row = out.data() + j * nx;
    for (const detail::Segment& s : detail::section(mesh, z_m[j])) {
      const double xa = s.a.x(), xb = s.b.x();
      const double lo = std::min(xa, xb), hi = std::max(xa, xb);
      // the x nodes inside the segment's x range (x_m ascending)
      auto it = std::lower_bound(x_m.begin(), x_m.end(), lo);
      for (; it != x_m.end() && *it <= hi; ++it) {
        const double t = hi > lo ? (*it - xa) / (xb - xa) : 0.0;
        const double y = std::abs(s.a.y() + t * (s.b.y() - s.a.y()));
        double& cell = row[it - x_m.begin()];
        cell = std::max(cell, y);
      }
    }
  }
  return out;
}

core::FlowTable thin_ship_flow(const Mesh& mesh, double water_z_m, double ship_speed_m_s,
                               const ThinShipSettings& st) {
  if (mesh.vertices.empty()) throw InputError("hull flow: empty hull mesh");
  if (st.cells_along < 2 || st.cells_deep < 1 || !(st.table_spacing_fraction_of_draft > 0) ||
      !(st.margin_fraction_of_breadth > 0))
    throw InputError("hull flow: needs >= 2 cells along, >= 1 deep, and a positive table spacing and margin");
  Eigen::Vector3d lo = mesh.vertices[0], hi = lo;
  for (const auto& v : mesh.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  const double water = water_z_m, draft_m = water - lo.z();
  if (!(draft_m > 0) || !(water < hi.z()))
    throw InputError(
        fmt::format("hull flow: the water level z = {} m of the hull's frame is not between its keel "
                    "(z = {} m) and its top (z = {} m)",
                    water, lo.z(), hi.z()));
  core::HalfBreadthGrid g;
  // one node beyond each end, where the half-breadth is 0: a blunt end (a transom, a box) closes the body
  // there
  const double dx = (hi.x() - lo.x()) / st.cells_along;
  for (int i = -1; i <= st.cells_along + 1; ++i) g.x_m.push_back(lo.x() + i * dx);
  const double dz = draft_m / st.cells_deep;
  std::vector<double> z_mesh;
  for (int j = 0; j < st.cells_deep; ++j) {
    g.z_m.push_back(-(st.cells_deep - j - 0.5) * dz);  // ascending, cell centres, water level 0
    z_mesh.push_back(water + g.z_m.back());
  }
  g.y_m = half_breadths(mesh, g.x_m, z_mesh);
  const double y_max = *std::max_element(g.y_m.begin(), g.y_m.end());
  if (!(y_max > 0)) throw InputError("hull flow: the hull has no breadth under the water");
  std::vector<core::PointSource> sources = core::thin_ship_sources(g, ship_speed_m_s);
  // into the table's frame: x as the mesh's, y = 0 the centre plane, z = 0 the water level (sources already)
  return core::hull_flow_table(sources, y_max, st.margin_fraction_of_breadth * 2.0 * y_max,
                               st.table_spacing_fraction_of_draft * draft_m);
}

}  // namespace brash::hull
