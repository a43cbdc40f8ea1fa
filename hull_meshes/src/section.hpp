// Internal: horizontal sections of a mesh and clipping of triangles below a plane.
#pragma once
#include <brash/hull/mesh.hpp>

#include <vector>

namespace brash::hull::detail {

struct Segment {
  Eigen::Vector2d a, b;  // (x, y) ends
};

// Intersection of the mesh with the plane z = z0, as segments. A vertex exactly at z0 counts as above,
// so every crossing is found once.
std::vector<Segment> section(const Mesh& mesh, double z0);

// The part of triangle (p0, p1, p2) with z <= z0, as a polygon of 0, 3 or 4 points.
std::vector<Eigen::Vector3d> clip_below(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                        const Eigen::Vector3d& p2, double z0);

}  // namespace brash::hull::detail
