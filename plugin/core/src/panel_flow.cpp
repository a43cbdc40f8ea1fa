// Source panel method for a body moving through still water (see panel_flow.hpp).
#include "brash/core/panel_flow.hpp"

#include <fmt/format.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "brash/error.hpp"

namespace brash::core {
namespace {

constexpr double kInv4Pi = 0.25 / std::numbers::pi;

// a point source of flux q at c, seen from p
Vec3 point_source(double q, const Vec3& c, const Vec3& p) {
  const Vec3 d = p - c;
  const double r2 = d.squaredNorm();
  return r2 > 0 ? Vec3(d * (q * kInv4Pi / (r2 * std::sqrt(r2)))) : Vec3(Vec3::Zero());
}

Vec3 mirror(const Vec3& p) {
  return {p.x(), p.y(), -p.z()};
}

// Unit-density velocity of panel j at p (its own triangles only, no mirror image).
Vec3 panel_unit_velocity(const PanelSolution& s, std::size_t j, const Vec3& p) {
  const double far = s.settings.far_factor;
  if ((p - s.centroid_m[j]).norm() > far * 2.0 * s.radius_m[j])
    return point_source(s.area_m2[j], s.centroid_m[j], p);
  Vec3 u = Vec3::Zero(), far_sum = Vec3::Zero();
  for (std::size_t k = s.body.first[j]; k < s.body.first[j + 1]; ++k) {
    const Vec3 d = p - s.triangle_centroid_m[k];
    const double r2 = d.squaredNorm();
    if (r2 > s.triangle_reach2_m2[k])
      far_sum += d * (s.triangle_area_m2[k] / (r2 * std::sqrt(r2)));
    else
      u += triangle_source_velocity(s.body.triangles[k], p);
  }
  u += far_sum * kInv4Pi;
  return u;
}

// per panel: area, area centroid, radius about it, area-mean normal
void panel_geometry(PanelSolution& s) {
  const std::size_t n = s.body.panels();
  s.area_m2.assign(n, 0.0), s.radius_m.assign(n, 0.0);
  s.centroid_m.assign(n, Vec3::Zero()), s.normal.assign(n, Vec3::Zero());
  for (const Triangle& t : s.body.triangles) {
    const double edge = std::max({(t.v[1] - t.v[0]).norm(), (t.v[2] - t.v[1]).norm(), (t.v[0] - t.v[2]).norm()});
    s.triangle_centroid_m.push_back(triangle_centroid(t)), s.triangle_area_m2.push_back(triangle_area(t));
    s.triangle_reach2_m2.push_back(std::pow(s.settings.far_factor * edge, 2));
  }
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t b = s.body.first[j], e = s.body.first[j + 1];
    for (std::size_t k = b; k < e; ++k) {
      const Triangle& t = s.body.triangles[k];
      const double a = triangle_area(t);
      s.area_m2[j] += a, s.centroid_m[j] += a * triangle_centroid(t), s.normal[j] += a * triangle_normal(t);
    }
    if (!(s.area_m2[j] > 0) || !(s.normal[j].norm() > 0))
      throw InputError(fmt::format("panel flow: panel {} has no area", j));
    s.centroid_m[j] /= s.area_m2[j], s.normal[j].normalize();
    for (std::size_t k = b; k < e; ++k)
      for (const Vec3& v : s.body.triangles[k].v)
        s.radius_m[j] = std::max(s.radius_m[j], (v - s.centroid_m[j]).norm());
  }
}

struct FluxPoint {
  Vec3 p;
  Vec3 weighted_normal;  // n A_k / A_panel
};

// the quadrature of the flux through panel i (panel_flow.hpp)
std::vector<FluxPoint> flux_points(const PanelSolution& s, std::size_t i) {
  std::vector<FluxPoint> out;
  const std::size_t b = s.body.first[i], e = s.body.first[i + 1];
  for (std::size_t k = b; k < e; ++k) {
    const Triangle& t = s.body.triangles[k];
    const Vec3 wn = triangle_normal(t) * triangle_area(t) / s.area_m2[i];
    if (e - b > 1) {
      out.push_back({triangle_centroid(t), wn});
      continue;
    }
    for (int v = 0; v < 3; ++v)
      out.push_back({(4.0 * t.v[v] + t.v[(v + 1) % 3] + t.v[(v + 2) % 3]) / 6.0, wn / 3.0});
  }
  return out;
}

// Entry (i, j) of the system: the flux of panel j's unit density (and its image) through panel i, by panel
// i's quadrature; for a pair far apart (beyond far_factor diameters of either) panel j is a point source and
// panel i's flux the mean normal at its centroid.
double system_entry(const PanelSolution& s, std::size_t i, const std::vector<FluxPoint>& points,
                    const Vec3& mean_normal, std::size_t j) {
  const double reach = s.settings.far_factor * 2.0 * std::max(s.radius_m[i], s.radius_m[j]);
  double a = 0;
  for (int side = 0; side < (s.body.mirror_z ? 2 : 1); ++side) {
    auto image = [&](const Vec3& v) { return side == 0 ? v : mirror(v); };
    const Vec3 ci = image(s.centroid_m[i]);
    if ((ci - s.centroid_m[j]).norm() > reach) {
      a += mean_normal.dot(image(point_source(s.area_m2[j], s.centroid_m[j], ci)));
      continue;
    }
    for (const FluxPoint& q : points)
      a += q.weighted_normal.dot(image(panel_unit_velocity(s, j, image(q.p))));
  }
  return a;
}

}  // namespace

Vec3 triangle_normal(const Triangle& t) {
  const Vec3 c = (t.v[1] - t.v[0]).cross(t.v[2] - t.v[0]);
  const double n = c.norm();
  return n > 0 ? Vec3(c / n) : Vec3(Vec3::Zero());
}

double triangle_area(const Triangle& t) {
  return 0.5 * (t.v[1] - t.v[0]).cross(t.v[2] - t.v[0]).norm();
}

Vec3 triangle_centroid(const Triangle& t) {
  return (t.v[0] + t.v[1] + t.v[2]) / 3.0;
}

Triangle mirrored_z(const Triangle& t) {
  return {{mirror(t.v[0]), mirror(t.v[2]), mirror(t.v[1])}};
}

Vec3 triangle_source_velocity(const Triangle& t, const Vec3& p) {
  const Vec3 n = triangle_normal(t);
  const Vec3 a[3] = {t.v[0] - p, t.v[1] - p, t.v[2] - p};
  const double r[3] = {a[0].norm(), a[1].norm(), a[2].norm()};
  // in-plane part: the integral of grad(1/r) over the triangle is a sum over its edges of the outward edge
  // normal m_k times the integral of 1/r along the edge
  Vec3 tangential = Vec3::Zero();
  for (int k = 0; k < 3; ++k) {
    const int j = (k + 1) % 3;
    const Vec3 e = t.v[j] - t.v[k];
    const double d = e.norm();
    if (!(d > 0)) continue;
    const double sum = r[k] + r[j];
    const double gap = std::max(sum - d, 1e-15 * (sum + d));  // 0 on the edge itself (log singular there)
    tangential += e.cross(n) / d * std::log((sum + d) / gap);
  }
  // normal part: the solid angle of the triangle seen from p, positive on the fluid side (Van Oosterom &
  // Strackee); on the triangle's plane inside it, the fluid side's limit 2 pi
  const double num = a[0].dot(a[1].cross(a[2]));
  const double den =
      r[0] * r[1] * r[2] + a[0].dot(a[1]) * r[2] + a[0].dot(a[2]) * r[1] + a[1].dot(a[2]) * r[0];
  double omega = -2.0 * std::atan2(num, den);
  if (den < 0 && std::abs(num) <= 1e-12 * r[0] * r[1] * r[2]) omega = 2.0 * std::numbers::pi;
  return (tangential + n * omega) * kInv4Pi;
}

PanelSolution solve_panel_flow(PanelBody body, const Vec3& body_velocity_m_s, const PanelSettings& settings) {
  const std::size_t n = body.panels();
  if (body.first.empty() || n == 0 || body.first.front() != 0 || body.first.back() != body.triangles.size() ||
      !std::is_sorted(body.first.begin(), body.first.end()))
    throw InputError(fmt::format("panel flow: {} triangles in {} panels: malformed panel offsets",
                                 body.triangles.size(), n));
  if (!(settings.far_factor > 1)) throw InputError("panel flow: far_factor must be > 1");
  PanelSolution s;
  s.body = std::move(body), s.settings = settings, s.body_velocity_m_s = body_velocity_m_s;
  panel_geometry(s);
  // no flux through any panel: sum_k w_k n_k . (sum_j sigma_j u_j(p_k) - V) = 0
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::vector<FluxPoint> points = flux_points(s, i);
    Vec3 mean_normal = Vec3::Zero();
    for (const FluxPoint& q : points) mean_normal += q.weighted_normal;
    for (std::size_t j = 0; j < n; ++j) a(i, j) = system_entry(s, i, points, mean_normal, j);
    rhs(i) = mean_normal.dot(body_velocity_m_s);
  }
  s.sigma_m_s = a.partialPivLu().solve(rhs);
  const double residual = (a * s.sigma_m_s - rhs).norm(), scale = rhs.norm() + 1e-300;
  if (!s.sigma_m_s.allFinite() || residual > 1e-6 * scale)
    throw InputError(fmt::format("panel flow: the system of {} panels is singular (relative residual {:.3g})",
                                 n, residual / scale));
  return s;
}

Vec3 panel_velocity(const PanelSolution& s, const Vec3& p) {
  // the hot loop of a table: far panels as point sources inline, the squared distance tested first
  const std::size_t n = s.body.panels();
  const double far2 = 4.0 * s.settings.far_factor * s.settings.far_factor;
  Vec3 u = Vec3::Zero();
  for (int side = 0; side < (s.body.mirror_z ? 2 : 1); ++side) {
    const Vec3 q = side == 0 ? p : mirror(p);
    Vec3 far_sum = Vec3::Zero(), near_sum = Vec3::Zero();
    for (std::size_t j = 0; j < n; ++j) {
      const double sigma = s.sigma_m_s(static_cast<Eigen::Index>(j));
      const Vec3 d = q - s.centroid_m[j];
      const double r2 = d.squaredNorm();
      if (r2 > far2 * s.radius_m[j] * s.radius_m[j])
        far_sum += d * (sigma * s.area_m2[j] / (r2 * std::sqrt(r2)));
      else
        near_sum += sigma * panel_unit_velocity(s, j, q);
    }
    const Vec3 us = far_sum * kInv4Pi + near_sum;
    u += side == 0 ? us : mirror(us);
  }
  return u;
}

double panel_relative_normal_velocity(const PanelSolution& s, std::size_t i) {
  double f = 0;
  for (const FluxPoint& q : flux_points(s, i))
    f += q.weighted_normal.dot(panel_velocity(s, q.p) - s.body_velocity_m_s);
  return f;
}

double panel_net_flux(const PanelSolution& s) {
  double q = 0;
  for (std::size_t j = 0; j < s.body.panels(); ++j)
    q += s.sigma_m_s(static_cast<Eigen::Index>(j)) * s.area_m2[j];
  return q;
}

FlowTable panel_flow_table(const PanelSolution& s, const Vec3& lo, const Vec3& hi, double spacing_m) {
  return FlowTable([&](const Vec3& p) { return panel_velocity(s, p); }, lo, hi, spacing_m, true);
}

}  // namespace brash::core
