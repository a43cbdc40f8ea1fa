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
// in the hull frame (FlowTable): per sphere and step the engine pays one trilinear interpolation. Nodes inside
// the hull are never sampled, and the cells along the hull are refined (FlowRefinement): a piece touching the
// hull sees the field of the water side, not an average across the hull's surface.
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <span>
#include <utility>
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

// What a flow table is made of: the water's velocity (still-water frame, at points of the body's frame), the
// body's velocity (the field moves with the body), and optionally the body itself.
struct FlowField {
  std::function<Vec3(const Vec3&)> velocity;
  // With it the table also holds the water's acceleration in the earth frame, Du/Dt = du/dt + (u . grad) u
  // with du/dt = -(V . grad) u (a field steady in the body's frame): Du/Dt = ((u - V) . grad) u.
  Vec3 body_velocity_m_s = Vec3::Zero();
  bool acceleration = false;
  // Inside the body: such a point is never sampled (the field there is not the flow); its nodes take values
  // extrapolated linearly from the water side. Empty: no body.
  std::function<bool(const Vec3&)> solid;
  // Unsigned distance to the body's surface (which cells lie near it); needed with solid for refinement.
  std::function<double(const Vec3&)> distance_m;
};

// Cells near the body's surface, where a piece touching the hull sits well inside one cell of the regular grid
// and the flow changes fast (the stem's stagnation, the bilge), are subdivided until trilinear interpolation
// is within tolerance_m_s of the field at the midpoints of the subdivision (checked against the field sampled
// twice as fine), up to max_factor subdivisions per axis.
struct FlowRefinement {
  double band_m = 0.0;         // cells whose centre is within this distance (+ half a cell's diagonal) of the surface
  double tolerance_m_s = 0.0;  // largest interpolation error allowed there
  int max_factor = 16;         // a power of 2
  // Nodes closer than this to the surface are sampled but not checked: no piece's centre comes there (it stays
  // about its radius off the hull), and there a panel method's own near field (its panels' edges and corners)
  // would keep every cell at max_factor to no use.
  double clearance_m = 0.0;
};

// A velocity field tabulated on a regular grid of the box [lo, hi] (spacing about spacing_m per axis), zero
// outside it, with finer bricks in the cells near a body (FlowRefinement). With mirror_y the grid covers
// y >= 0 only (lo.y() must be 0) and a point at y < 0 takes the mirror image (u_y reversed): the field of a
// hull symmetric about y = 0. Each node holds u and, for a FlowField with acceleration, Du/Dt (from central
// differences of the tabulated u: no further samples of the field).
class FlowTable {
 public:
  static constexpr int kComponents = 6;  // per node: u (3), then Du/Dt (3)

  FlowTable() = default;
  FlowTable(std::span<const PointSource> sources, const Vec3& lo, const Vec3& hi, double spacing_m,
            double core_radius_m, bool mirror_y);
  // The same grid filled with any field (the panel flow, panel_flow.hpp).
  FlowTable(const std::function<Vec3(const Vec3&)>& field, const Vec3& lo, const Vec3& hi, double spacing_m,
            bool mirror_y);
  FlowTable(const FlowField& field, const Vec3& lo, const Vec3& hi, double spacing_m, bool mirror_y,
            const FlowRefinement& refinement = {});
  // ... with `nodes` nodes per axis (>= 2 each): part of a larger table's grid
  FlowTable(const FlowField& field, const Vec3& lo, const Vec3& hi, const Eigen::Vector3i& nodes, bool mirror_y,
            const FlowRefinement& refinement = {});
  // the nodes per axis of a box at about spacing_m: ceil(extent / spacing) + 1, at least 2
  static Eigen::Vector3i grid_nodes(const Vec3& lo, const Vec3& hi, double spacing_m);
  // A table from its node values (a cached table read back): >= 2 nodes per axis, 3 values per node (u only,
  // a table of the first file version: no acceleration) or kComponents (u, then Du/Dt when `acceleration`),
  // x fastest. Throws brash::InputError when the sizes disagree.
  static FlowTable from_values(const Vec3& lo, const Vec3& hi, const Eigen::Vector3i& nodes, bool mirror_y,
                               std::vector<double> values, bool acceleration = false);

  // A refined cell: its brick of (factor + 1)^3 nodes, kComponents values each from brick_values()[offset],
  // x fastest.
  struct Brick {
    std::uint64_t offset = 0;
    std::int32_t factor = 0;
  };
  // The refinement of a table read back: per cell ((n - 1) per axis, x fastest) its brick's index or -1.
  // Throws brash::InputError when the parts disagree.
  void set_bricks(std::vector<std::int32_t> cell_brick, std::vector<Brick> bricks, std::vector<double> values);

  // trilinear interpolation; zero outside the box (and for a default-constructed table)
  Vec3 at(const Vec3& p) const;
  // u and Du/Dt (zero without acceleration) at p
  void at(const Vec3& p, Vec3& u_m_s, Vec3& a_m_s2) const;

  bool empty() const { return values_.empty(); }
  bool has_acceleration() const { return acceleration_; }
  const Vec3& lo() const { return lo_; }
  const Vec3& hi() const { return hi_; }
  Eigen::Vector3i nodes() const { return n_; }
  Vec3 spacing() const { return h_; }
  double max_speed_m_s() const { return max_speed_; }
  bool mirror_y() const { return mirror_y_; }
  const std::vector<double>& values() const { return values_; }  // kComponents per node
  const std::vector<std::int32_t>& cell_bricks() const { return cell_brick_; }
  const std::vector<Brick>& bricks() const { return bricks_; }
  const std::vector<double>& brick_values() const { return brick_values_; }
  std::size_t brick_nodes() const { return brick_values_.size() / kComponents; }

 private:
  template <int kC>
  void interpolate(const Vec3& p, double* out) const;
  void set_grid(const Vec3& lo, const Vec3& hi, const Eigen::Vector3i& nodes);

  Vec3 lo_ = Vec3::Zero(), hi_ = Vec3::Zero(), h_ = Vec3::Ones(), inv_h_ = Vec3::Ones();
  Eigen::Vector3i n_ = Eigen::Vector3i::Zero();
  bool mirror_y_ = false, acceleration_ = false;
  double max_speed_ = 0.0;
  std::vector<double> values_;  // kComponents per node, x fastest
  std::vector<std::int32_t> cell_brick_;  // empty: no refinement
  std::vector<Brick> bricks_;
  std::vector<double> brick_values_;
};

// The table for a hull: the box around the sheet's sources (x range, y from 0, z down to the deepest source)
// widened by margin_m on every side but the centre plane, y mirrored, spacing spacing_m, core radius =
// spacing_m. Throws brash::InputError on an empty source list or a non-positive spacing or margin.
FlowTable hull_flow_table(std::span<const PointSource> sources, double half_breadth_max_m, double margin_m,
                          double spacing_m);
// The box of hull_flow_table: lo, hi.
std::pair<Vec3, Vec3> hull_flow_box(const Vec3& sources_lo, const Vec3& sources_hi, double half_breadth_max_m,
                                    double margin_m, double spacing_m);

}  // namespace brash::core
