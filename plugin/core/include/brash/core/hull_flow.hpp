// Flow of the water around a hull moving through otherwise still water: the U_flow of the paper's Eq. 1 near
// the ship (fluid.hull_flow: thin_ship; docs/physics.md "Flow around the hull").
//
// Model: thin-ship (Michell) theory, double body. The ship moves at U e_x. In its frame the water streams at
// -U e_x; a side y = +Y(x, z) with normal ~ (-Y_x, 1, 0) lets no water through when, to first order in the
// slope, phi_y = -U Y_x there. A source sheet on the centre plane y = 0 with density sigma gives phi_y(0+) =
// sigma / 2, so sigma(x, z) = -2 U Y_x(x, z): sources where the hull widens towards the bow (water pushed
// ahead and aside), sinks where it narrows aft (water following the stern). The free surface is a rigid lid
// (Froude number U / sqrt(g L) = 0.058 for the paper case: waves negligible): the underwater sheet is
// mirrored about the water level. The perturbation velocity grad(phi) is the same in the still-water frame,
// so it is the flow velocity U_flow that an ice piece at that place relative to the hull sees.
//
// The sheet is discretised into point sources, each regularised over a core radius of the order of the sheet
// spacing (no singularity where a piece touches the stem), and the field is tabulated once on a regular grid
// in the hull frame (FlowTable): per sphere and step the engine pays one trilinear interpolation.
#pragma once
#include <Eigen/Core>
#include <functional>
#include <span>
#include <vector>

namespace brash::core {

using Vec3 = Eigen::Vector3d;

struct PointSource {
  Vec3 position_m = Vec3::Zero();
  double strength_m3_s = 0.0;  // volume flux out of the source
};

// Velocity induced at p: sum of q (p - s) / (4 pi (|p - s|^2 + eps^2)^(3/2)) (a Plummer-regularised source;
// eps = 0 is the exact point source).
Vec3 induced_velocity(std::span<const PointSource> sources, const Vec3& p, double core_radius_m);

// Half-breadths of the hull under water, Y(x_i, z_j) >= 0, on ascending grids x_m (nx >= 3) and z_m (nz >= 1,
// all below the water level 0 of the hull frame used here). y_m is z-major: y_m[j * nx + i].
struct HalfBreadthGrid {
  std::vector<double> x_m, z_m, y_m;
  double at(std::size_t i, std::size_t j) const { return y_m[j * x_m.size() + i]; }
};

// The thin-ship sheet of a hull moving at ship_speed_m_s along +x (negative: along -x), as point sources at
// the centres of the cells between neighbouring x nodes, one per z node, each of strength sigma dx dz (dz the
// spacing of z_m, which must be uniform; the cell's depth range is z_j +- dz / 2), and their mirror images
// about z = 0. Throws brash::InputError on a malformed grid.
std::vector<PointSource> thin_ship_sources(const HalfBreadthGrid& grid, double ship_speed_m_s);

// A velocity field tabulated on a regular grid of the box [lo, hi] (spacing about spacing_m per axis), zero
// outside it. With mirror_y the grid covers y >= 0 only (lo.y() must be 0) and a point at y < 0 takes the
// mirror image (u_y reversed): the field of a hull symmetric about y = 0.
class FlowTable {
 public:
  FlowTable() = default;
  FlowTable(std::span<const PointSource> sources, const Vec3& lo, const Vec3& hi, double spacing_m,
            double core_radius_m, bool mirror_y);
  // The same grid filled with any field (the panel flow, panel_flow.hpp).
  FlowTable(const std::function<Vec3(const Vec3&)>& field, const Vec3& lo, const Vec3& hi, double spacing_m,
            bool mirror_y);
  // A table from its node values (a cached table read back): >= 2 nodes per axis, 3 values per node, x
  // fastest. Throws brash::InputError when the sizes disagree.
  static FlowTable from_values(const Vec3& lo, const Vec3& hi, const Eigen::Vector3i& nodes, bool mirror_y,
                               std::vector<double> values);

  // trilinear interpolation; zero outside the box (and for a default-constructed table)
  Vec3 at(const Vec3& p) const;

  bool empty() const { return values_.empty(); }
  const Vec3& lo() const { return lo_; }
  const Vec3& hi() const { return hi_; }
  Eigen::Vector3i nodes() const { return n_; }
  Vec3 spacing() const { return h_; }
  double max_speed_m_s() const { return max_speed_; }
  bool mirror_y() const { return mirror_y_; }
  const std::vector<double>& values() const { return values_; }

 private:
  Vec3 lo_ = Vec3::Zero(), hi_ = Vec3::Zero(), h_ = Vec3::Ones(), inv_h_ = Vec3::Ones();
  Eigen::Vector3i n_ = Eigen::Vector3i::Zero();
  bool mirror_y_ = false;
  double max_speed_ = 0.0;
  std::vector<double> values_;  // 3 per node, x fastest
};

// The table for a hull: the box around the sheet's sources (x range, y from 0, z down to the deepest source)
// widened by margin_m on every side but the centre plane, y mirrored, spacing spacing_m, core radius =
// spacing_m. Throws brash::InputError on an empty source list or a non-positive spacing or margin.
FlowTable hull_flow_table(std::span<const PointSource> sources, double half_breadth_max_m, double margin_m,
                          double spacing_m);

}  // namespace brash::core
