// The water's flow around a hull (fluid.hull_flow: thin_ship): the hull's half-breadths under water, measured
// on the mesh, made into brash_core's thin-ship source sheet and tabulated (plugin/core hull_flow.hpp). Every
// engine adapter that moves ice past a hull builds its table here, so the engines see the same field.
#pragma once
#include <brash/core/hull_flow.hpp>
#include <brash/fluid_options.hpp>
#include <brash/hull/mesh.hpp>
#include <brash/hull/proximity.hpp>
#include <functional>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace brash::hull {

// Half-breadth max |y| of the mesh's section at height z_j (mesh frame) where it crosses x_i, 0 where the
// section does not reach x_i; z-major (out[j * nx + i]).
std::vector<double> half_breadths(const Mesh& mesh, std::span<const double> x_m, std::span<const double> z_m);

// The table along the hull (core::FlowRefinement): cells within band x draft of the hull's surface are
// subdivided until the interpolation error is below tolerance x ship speed.
struct NearHullSettings {
  double band_fraction_of_draft = 0.25;
  double tolerance_fraction_of_speed = 0.005;
  int max_factor = 8;
  // core::FlowRefinement::clearance_m: no piece's centre comes closer to the hull than about its radius
  double clearance_m = 0.0;
  // Full: the table above with Du/Dt; Drag: the same without Du/Dt; DragRegularTable: a regular table that samples
  // the field inside the hull too, without Du/Dt (the coupling of earlier versions).
  HullFlowCoupling coupling = HullFlowCoupling::Full;
};

// The body of the double-body flows: the hull under the water and its mirror image above it, in the table's
// frame (z = 0 at the water level). Holds a Proximity of the mesh; its FlowField's functions refer to it.
class DoubleBody {
 public:
  DoubleBody(const Mesh& mesh, double water_z_m);
  bool solid(const core::Vec3& p) const;
  double distance_m(const core::Vec3& p, double max_distance_m) const;
  // solid and distance_m (searched up to max_distance_m) for a core::FlowField
  core::FlowField field(double max_distance_m) const;

 private:
  Proximity proximity_;
  double water_z_m_;
};

// The table of a hull's `velocity` (water's velocity, still-water frame, at points of the table's frame) on the
// grid `grid` for a hull moving at body_velocity_m_s with the water at water_z_m of the mesh's frame: nodes
// inside the hull (or within the clearance) never sampled, cells within band x draft refined, Du/Dt per node, as
// `settings` ask.
struct TableGrid;
core::FlowTable hull_table(const std::function<core::Vec3(const core::Vec3&)>& velocity, const Mesh& mesh,
                           double water_z_m, double draft_m, const core::Vec3& body_velocity_m_s,
                           const TableGrid& grid, const NearHullSettings& settings);

// Part of a table: only the cells of the whole table's grid that meet [lo, hi] (what a test looks at).
using TableWindow = std::optional<std::pair<core::Vec3, core::Vec3>>;

// The grid of a whole table (box lo..hi at spacing_m) cut down to a window: the box of the cells meeting it
// and its nodes per axis.
struct TableGrid {
  core::Vec3 lo, hi;
  Eigen::Vector3i nodes;
};
TableGrid window_grid(const core::Vec3& lo, const core::Vec3& hi, double spacing_m, const TableWindow& window);

struct ThinShipSettings {
  int cells_along = 120;                           // sheet cells over the hull's length
  int cells_deep = 10;                             // sheet cells over the draft
  double table_spacing_fraction_of_draft = 0.125;  // table spacing = this x draft (also the core radius)
  double margin_fraction_of_breadth = 1.0;         // table box beyond the hull, in hull breadths
  NearHullSettings near_hull{};
  TableWindow window{};                            // none: the whole table
};

// The flow table of `mesh` with the water at height water_z_m of the mesh's frame, moving at ship_speed_m_s
// along x. The table's frame is the mesh's shifted by water_z_m: x, y as the mesh's, z = 0 at the water
// level. Nodes inside the hull are never sampled; cells along it are refined (NearHullSettings); each node
// holds Du/Dt too. Throws brash::InputError when the water level is not between the mesh's keel and top or the hull has
// no breadth under water.
core::FlowTable thin_ship_flow(const Mesh& mesh, double water_z_m, double ship_speed_m_s,
                               const ThinShipSettings& settings = {});

// The sheet that table samples: its sources (table frame), their core radius (the table's spacing) and the
// largest half-breadth; the field is core::induced_velocity(sources, p, core_radius_m).
struct ThinShipSheet {
  std::vector<core::PointSource> sources;
  double core_radius_m = 0.0, half_breadth_max_m = 0.0, draft_m = 0.0;
};
ThinShipSheet thin_ship_sheet(const Mesh& mesh, double water_z_m, double ship_speed_m_s,
                              const ThinShipSettings& settings = {});

}  // namespace brash::hull
