// Exact sphere-hull overlap queries on a closed triangle mesh (the run-time hull penetration guard).
//
// Built once from the hull Mesh in its own frame (STL frame: keel z = 0). Two uniform grids bin the
// triangles:
//   - a 3D grid (triangle bounding boxes) for the unsigned distance to the surface, searched in growing
//     shells of cells around the point until no unsearched cell can hold a closer triangle;
//   - a 2D grid over x, y (projected bounding boxes) for inside/outside: a vertical ray from the point
//     upwards crosses the closed surface an odd number of times iff the point is inside. Points on a
//     projected edge or vertex are decided by a fixed infinitesimal shift of the point (+eps in x, +eps^2 in
//     y), the same for every triangle, and each edge's orientation test is computed from its endpoints in a
//     canonical order, so two triangles sharing an edge always agree: a crossing through an edge or vertex is
//     counted once.
// Queries are const and allocate nothing: one Proximity can serve any number of threads.
//
// penetration(p, r) for a sphere of radius r centred at p:
//   r - d   if p is outside the closed hull at unsigned distance d < r (the sphere overlaps the surface),
//   r + d   if p is inside the closed hull (d = distance from p to the surface),
//   0       otherwise.
// The inside test needs a closed mesh (check_mesh(mesh).closed); on an open mesh closed() is false and
// penetration() only reports r - d (a sphere with its centre behind an open surface is not recognised).
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <limits>
#include <vector>

#include "brash/hull/mesh.hpp"

namespace brash::hull {

// The point of triangle (a, b, c) closest to p (Voronoi regions of the vertices, edges and face).
Eigen::Vector3d closest_point_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                          const Eigen::Vector3d& b, const Eigen::Vector3d& c);

class Proximity {
 public:
  // Throws brash::InputError for a mesh without faces or with non-finite vertices.
  explicit Proximity(const Mesh& mesh);

  // Unsigned distance from p to the surface; +inf when it is larger than max_distance_m (faster search).
  double distance(const Eigen::Vector3d& p,
                  double max_distance_m = std::numeric_limits<double>::infinity()) const;
  // The surface's point nearest to p and its triangle (the mesh's face index): what a piece touching the hull
  // touches. distance_m = +inf and triangle = -1 when no point is within max_distance_m.
  struct Nearest {
    double distance_m = std::numeric_limits<double>::infinity();
    int triangle = -1;
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
  };
  Nearest nearest(const Eigen::Vector3d& p,
                  double max_distance_m = std::numeric_limits<double>::infinity()) const;
  // Inside the closed surface (parity of the crossings of the ray from p towards +z). Always false when
  // the mesh is not closed.
  bool inside(const Eigen::Vector3d& p) const;
  // Overlap depth of a sphere with the hull (see above), >= 0.
  double penetration(const Eigen::Vector3d& p, double radius_m) const;

  bool closed() const { return closed_; }
  const Eigen::AlignedBox3d& bounds() const { return bounds_; }
  std::size_t triangles() const { return tri_.size(); }

 private:
  struct Tri {
    Eigen::Vector3d a, b, c;
  };
  std::array<long, 3> cell_of(const Eigen::Vector3d& p) const;  // clamped to the grid
  long cell_index(long i, long j, long k) const { return (k * n_[1] + j) * n_[0] + i; }
  // Ray-crossing test of triangle t against the vertical line through (x, y); on a crossing returns true and
  // the surface height there in z.
  bool vertical_crossing(const Tri& t, double x, double y, double& z) const;

  std::vector<Tri> tri_;
  Eigen::AlignedBox3d bounds_;
  bool closed_ = false;
  // 3D grid: cell (i, j, k) holds ids_[start_[c] .. start_[c + 1]).
  Eigen::Vector3d origin_, h_;
  std::array<long, 3> n_{1, 1, 1};
  std::vector<std::size_t> start_;
  std::vector<int> ids_;
  // 2D (x, y) grid for the ray test.
  std::array<long, 2> n2_{1, 1};
  Eigen::Vector2d h2_;
  std::vector<std::size_t> start2_;
  std::vector<int> ids2_;
};

}  // namespace brash::hull
