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

ThinShipSheet thin_ship_sheet(const Mesh& mesh, double water_z_m, double ship_speed_m_s,
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
  ThinShipSheet sheet;
  sheet.sources = core::thin_ship_sources(g, ship_speed_m_s);  // table frame: z = 0 the water level
  if (sheet.sources.empty())
    throw InputError("hull flow: the hull gives no thin-ship sources (no half-breadth change)");
  sheet.core_radius_m = st.table_spacing_fraction_of_draft * draft_m;
  sheet.half_breadth_max_m = y_max, sheet.draft_m = draft_m;
  return sheet;
}

core::FlowTable thin_ship_flow(const Mesh& mesh, double water_z_m, double ship_speed_m_s,
                               const ThinShipSettings& st) {
  const ThinShipSheet sheet = thin_ship_sheet(mesh, water_z_m, ship_speed_m_s, st);
  // into the table's frame: x as the mesh's, y = 0 the centre plane, z = 0 the water level (sources already)
  const double spacing = sheet.core_radius_m, margin = st.margin_fraction_of_breadth * 2.0 * sheet.half_breadth_max_m;
  Eigen::Vector3d s_lo = sheet.sources[0].position_m, s_hi = s_lo;
  for (const auto& s : sheet.sources) s_lo = s_lo.cwiseMin(s.position_m), s_hi = s_hi.cwiseMax(s.position_m);
  const auto [box_lo, box_hi] = core::hull_flow_box(s_lo, s_hi, sheet.half_breadth_max_m, margin, spacing);
  const TableGrid w = window_grid(box_lo, box_hi, spacing, st.window);
  // the sheet's field, regularised over the table's spacing (hull_flow.hpp)
  const auto velocity = [&](const Eigen::Vector3d& p) { return core::induced_velocity(sheet.sources, p, spacing); };
  return hull_table(velocity, mesh, water_z_m, sheet.draft_m, Eigen::Vector3d(ship_speed_m_s, 0, 0), w,
                    st.near_hull);
}

core::FlowTable hull_table(const std::function<core::Vec3(const core::Vec3&)>& velocity, const Mesh& mesh,
                           double water_z_m, double draft_m, const core::Vec3& body_velocity_m_s,
                           const TableGrid& w, const NearHullSettings& st) {
  const bool mirror_y = w.lo.y() == 0.0;
  if (st.coupling == HullFlowCoupling::DragRegularTable) {
    core::FlowField plain;
    plain.velocity = velocity;
    return core::FlowTable(plain, w.lo, w.hi, w.nodes, mirror_y);
  }
  if (!(st.clearance_m >= 0)) throw InputError("hull flow: the table's clearance from the hull must be >= 0");
  const double band = st.band_fraction_of_draft * draft_m;
  const DoubleBody body(mesh, water_z_m);
  core::FlowField f = body.field(2 * band);
  f.velocity = velocity;
  f.body_velocity_m_s = body_velocity_m_s, f.acceleration = st.coupling == HullFlowCoupling::Full;
  const core::FlowRefinement refine{.band_m = band,
                                    .tolerance_m_s = st.tolerance_fraction_of_speed * body_velocity_m_s.norm(),
                                    .max_factor = st.max_factor,
                                    .clearance_m = st.clearance_m};
  return core::FlowTable(f, w.lo, w.hi, w.nodes, mirror_y, refine);
}

DoubleBody::DoubleBody(const Mesh& mesh, double water_z_m) : proximity_(mesh), water_z_m_(water_z_m) {}

// a point of the table's frame in the mesh's, above the water mirrored below it (the double body)
static Eigen::Vector3d below(const core::Vec3& p, double water_z_m) {
  return {p.x(), p.y(), water_z_m - std::abs(p.z())};
}

bool DoubleBody::solid(const core::Vec3& p) const { return proximity_.inside(below(p, water_z_m_)); }

double DoubleBody::distance_m(const core::Vec3& p, double max_distance_m) const {
  return proximity_.distance(below(p, water_z_m_), max_distance_m);
}

core::FlowField DoubleBody::field(double max_distance_m) const {
  core::FlowField f;
  f.solid = [this](const core::Vec3& p) { return solid(p); };
  f.distance_m = [this, max_distance_m](const core::Vec3& p) { return distance_m(p, max_distance_m); };
  return f;
}

TableGrid window_grid(const core::Vec3& lo, const core::Vec3& hi, double spacing_m, const TableWindow& window) {
  const Eigen::Vector3i n = core::FlowTable::grid_nodes(lo, hi, spacing_m);
  if (!window) return {lo, hi, n};
  TableGrid g{lo, hi, n};
  for (int a = 0; a < 3; ++a) {
    const double h = (hi[a] - lo[a]) / (n[a] - 1);
    const int i0 = std::clamp(static_cast<int>(std::floor((window->first[a] - lo[a]) / h)), 0, n[a] - 2);
    const int i1 = std::clamp(static_cast<int>(std::ceil((window->second[a] - lo[a]) / h)), i0 + 1, n[a] - 1);
    g.lo[a] = lo[a] + i0 * h, g.hi[a] = lo[a] + i1 * h, g.nodes[a] = i1 - i0 + 1;
  }
  return g;
}

}  // namespace brash::hull
