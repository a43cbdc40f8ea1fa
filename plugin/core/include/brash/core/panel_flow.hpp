// Potential flow around a body moving through still water, from a first-order source panel method
// (fluid.hull_flow: panel; docs/physics.md "Panel flow").
//
// Method (Hess & Smith 1967, "Calculation of potential flow about arbitrary bodies", Prog. Aero. Sci. 8;
// Katz & Plotkin, "Low-Speed Aerodynamics", 2nd ed., §9.3 and §10.4): the body surface is covered by flat
// triangles grouped into panels; each panel carries one constant source density sigma (volume flux per area).
// A triangle of unit density induces, at p (Katz & Plotkin's constant-source element written with the edges'
// in-plane normals m_k and the signed solid angle Omega of the triangle seen from p),
//     u(p) = (1 / 4 pi) [ sum_k m_k ln((r_k + r_k+1 + d_k) / (r_k + r_k+1 - d_k)) + n Omega(p) ],
// r_k the distances from p to the vertices, d_k the edge lengths, n the outward normal; Omega is from Van
// Oosterom & Strackee (1983, IEEE Trans. Biomed. Eng. 30) and tends to 2 pi on the fluid side of the
// triangle, so the normal velocity there is sigma / 2. Far from a triangle (or a whole panel) its field is
// that of a point source of the same flux at its centroid (the dipole moment about the centroid vanishes; the
// error is O((size / distance)^2)).
//
// The body moves at V in still water; its surface lets no water through: the flux of u - V through each panel
// is zero, by quadrature over the panel's triangles (a one-triangle panel: its three interior Gauss points
// (1/6, 1/6, 2/3), weights A/3; a larger panel: its triangles' centroids, weights A_t), one dense linear
// system (Eigen's partial-pivot LU). Collocating at each triangle's centroid alone, the classical Hess-Smith
// choice, leaves a flow error of 1.9 % of U at 1.1 radii from a 1280-panel sphere; the panel flux gives 0.3
// %. u is the water's velocity in the still-water frame, given at positions in the body's frame. With
// mirror_z the body is a double body: every triangle has a mirror image about z = 0 (the rigid-lid water
// surface) with the same density, so the flow has no vertical component at z = 0.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstddef>
#include <vector>

#include "brash/core/hull_flow.hpp"

namespace brash::core {

// A flat triangle; the vertices run counter-clockwise seen from the fluid, so (b - a) x (c - a) points into
// it.
struct Triangle {
  std::array<Vec3, 3> v;
};

Vec3 triangle_normal(const Triangle& t);  // unit; zero for a degenerate triangle
double triangle_area(const Triangle& t);
Vec3 triangle_centroid(const Triangle& t);
Triangle mirrored_z(const Triangle& t);  // the image about z = 0, still oriented towards the fluid

// Exact velocity induced at p by the unit source density on t. On the triangle itself (within a relative
// 1e-12 of its plane and inside): the limit from the fluid side (normal part 1/2).
Vec3 triangle_source_velocity(const Triangle& t, const Vec3& p);

// A body: triangles grouped into panels of one source density each; panel i holds the triangles
// [first[i], first[i + 1]). A panel of one triangle is a Hess-Smith panel; larger panels let a fine surface
// mesh keep its exact geometry with few unknowns.
struct PanelBody {
  std::vector<Triangle> triangles;
  std::vector<std::size_t> first = {0};
  bool mirror_z = false;  // double body about z = 0
  std::size_t panels() const { return first.size() - 1; }
};

struct PanelSettings {
  double far_factor = 5.0;  // point source beyond this many element diameters (triangle or panel)
};

// A solved body: per panel its area-mean normal, area, area centroid and radius about it, and source density.
struct PanelSolution {
  PanelBody body;
  PanelSettings settings;
  Vec3 body_velocity_m_s = Vec3::Zero();
  std::vector<Vec3> normal, centroid_m;
  std::vector<double> area_m2, radius_m;
  Eigen::VectorXd sigma_m_s;  // source density per panel
  // per triangle: centroid, area, squared reach of its exact field ((far_factor x longest edge)^2)
  std::vector<Vec3> triangle_centroid_m;
  std::vector<double> triangle_area_m2, triangle_reach2_m2;
};

// The flow of a body moving at body_velocity_m_s through still water. Throws brash::InputError on an empty
// body, malformed panel offsets or a singular system.
PanelSolution solve_panel_flow(PanelBody body, const Vec3& body_velocity_m_s,
                               const PanelSettings& settings = {});

// The water's velocity at p (body frame, still-water velocity), mirror images included; the fluid-side limit
// on the surface.
Vec3 panel_velocity(const PanelSolution& s, const Vec3& p);

// The mean normal velocity of the water relative to the body over panel i, from the field at the panel's
// quadrature points (what the solve sets to zero).
double panel_relative_normal_velocity(const PanelSolution& s, std::size_t i);

// Total source flux sum sigma_i A_i of the body (without its mirror image): 0 for a closed rigid body.
double panel_net_flux(const PanelSolution& s);

// The field tabulated like the thin-ship flow (hull_flow.hpp's FlowTable, y mirrored) on the box lo..hi.
FlowTable panel_flow_table(const PanelSolution& s, const Vec3& lo, const Vec3& hi, double spacing_m);

}  // namespace brash::core
