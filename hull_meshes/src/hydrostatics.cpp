// Hydrostatics at a draft: clipped-triangle integrals (divergence theorem), exact for the mesh.
#include <brash/hull/hydrostatics.hpp>

#include "section.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <limits>

namespace brash::hull {
namespace detail {

std::vector<Segment> section(const Mesh& mesh, double z0) {
  std::vector<Segment> out;
  for (const auto& f : mesh.faces) {
    std::array<Eigen::Vector2d, 2> pts;
    int n = 0;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d& a = mesh.vertices[f[k]];
      const Eigen::Vector3d& b = mesh.vertices[f[(k + 1) % 3]];
      if ((a.z() >= z0) == (b.z() >= z0)) continue;
      const double t = (z0 - a.z()) / (b.z() - a.z());
      if (n < 2) pts[n] = (a + t * (b - a)).head<2>();
      ++n;
    }
    if (n == 2) out.push_back({pts[0], pts[1]});
  }
  return out;
}

std::vector<Eigen::Vector3d> clip_below(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                        const Eigen::Vector3d& p2, double z0) {
  const std::array<Eigen::Vector3d, 3> p{p0, p1, p2};
  std::vector<Eigen::Vector3d> out;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d& a = p[k];
    const Eigen::Vector3d& b = p[(k + 1) % 3];
    const bool a_in = a.z() <= z0, b_in = b.z() <= z0;
    if (a_in) out.push_back(a);
    if (a_in != b_in) out.push_back(a + (z0 - a.z()) / (b.z() - a.z()) * (b - a));
  }
  return out;
}

}  // namespace detail

Hydrostatics hydrostatics(const Mesh& mesh, double draft_m, double lpp_m) {
  const double T = draft_m;
  Hydrostatics h;
  double mx = 0, mz = 0, fx = 0;  // first moments of volume (x, z) and of the waterplane (x)
  for (const auto& f : mesh.faces) {
    const auto poly = detail::clip_below(mesh.vertices[f[0]], mesh.vertices[f[1]], mesh.vertices[f[2]], T);
    for (std::size_t k = 1; k + 1 < poly.size(); ++k) {
      const std::array<Eigen::Vector3d, 3> t{poly[0], poly[k], poly[k + 1]};
      const Eigen::Vector3d av = 0.5 * (t[1] - t[0]).cross(t[2] - t[0]);  // area vector
      double sx = 0, sg = 0, sxg = 0, sz = 0, szz = 0;
      for (const auto& p : t) {
        const double g = p.z() - T;
        sx += p.x();
        sg += g;
        sxg += p.x() * g;
        sz += p.z();
        szz += p.z() * p.z();
      }
      // For linear f, g on a triangle: mean(f g) = (sum f_i g_i + sum f sum g) / 12.
      h.volume_m3 += av.z() * sg / 3.0;                       // F = (0, 0, z - T)
      mx += av.z() * (sxg + sx * sg) / 12.0;                  // F = (0, 0, x (z - T))
      mz += av.z() * 0.5 * ((szz + sz * sz) / 12.0 - T * T);  // F = (0, 0, (z^2 - T^2) / 2)
      h.waterplane_area_m2 -= av.z();                         // closed body: lid = -sum of n_z dA
      fx -= av.z() * sx / 3.0;
      h.wetted_surface_m2 += av.norm();
    }
  }
  if (h.volume_m3 != 0) {
    h.lcb_x_m = mx / h.volume_m3;
    h.kb_m = mz / h.volume_m3;
  }
  if (h.waterplane_area_m2 != 0) h.lcf_x_m = fx / h.waterplane_area_m2;
  const auto segs = detail::section(mesh, T);
  if (!segs.empty()) {
    Eigen::Vector2d lo = segs.front().a, hi = lo;
    for (const auto& s : segs) {
      lo = lo.cwiseMin(s.a).cwiseMin(s.b);
      hi = hi.cwiseMax(s.a).cwiseMax(s.b);
    }
    h.lwl_m = hi.x() - lo.x();
    h.bwl_m = hi.y() - lo.y();
  }
  const double L = lpp_m > 0 ? lpp_m : h.lwl_m;
  if (L > 0 && h.bwl_m > 0 && T > 0) h.cb = h.volume_m3 / (L * h.bwl_m * T);
  return h;
}

}  // namespace brash::hull
