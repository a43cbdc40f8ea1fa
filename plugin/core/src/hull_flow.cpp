// Thin-ship flow around a hull, tabulated (see hull_flow.hpp).
#include "brash/core/hull_flow.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "brash/error.hpp"

namespace brash::core {

Vec3 induced_velocity(std::span<const PointSource> sources, const Vec3& p, double core_radius_m) {
  const double eps2 = core_radius_m * core_radius_m;
  double ux = 0, uy = 0, uz = 0;
  for (const PointSource& s : sources) {
    const double dx = p.x() - s.position_m.x(), dy = p.y() - s.position_m.y(), dz = p.z() - s.position_m.z();
    const double r2 = dx * dx + dy * dy + dz * dz + eps2;
    if (r2 == 0.0) continue;  // exactly on an unregularised source: no direction
    const double k = s.strength_m3_s / (r2 * std::sqrt(r2));
    ux += k * dx, uy += k * dy, uz += k * dz;
  }
  const double inv_4pi = 0.25 / std::numbers::pi;
  return Vec3(ux, uy, uz) * inv_4pi;
}

std::vector<PointSource> thin_ship_sources(const HalfBreadthGrid& g, double ship_speed_m_s) {
  const std::size_t nx = g.x_m.size(), nz = g.z_m.size();
  if (nx < 3 || nz < 1 || g.y_m.size() != nx * nz)
    throw InputError(
        fmt::format("thin-ship sheet: a grid of {} x nodes and {} z nodes needs {} half-breadths, has {}", nx,
                    nz, nx * nz, g.y_m.size()));
  for (std::size_t i = 1; i < nx; ++i)
    if (!(g.x_m[i] > g.x_m[i - 1]))
      throw InputError("thin-ship sheet: the x nodes must be strictly ascending");
  double dz = 0;
  if (nz > 1) {
    dz = g.z_m[1] - g.z_m[0];
    for (std::size_t j = 1; j < nz; ++j)
      if (!(std::abs(g.z_m[j] - g.z_m[j - 1] - dz) <= 1e-9 * std::abs(dz)) || !(dz > 0))
        throw InputError("thin-ship sheet: the z nodes must be ascending and uniformly spaced");
  } else {
    dz = -2.0 * g.z_m[0];  // one layer from the water level down to 2 |z0|
  }
  for (std::size_t j = 0; j < nz; ++j)
    if (!(g.z_m[j] + 0.5 * dz <= 1e-12))
      throw InputError("thin-ship sheet: the z nodes must lie under the water (z < 0)");
  for (double y : g.y_m)
    if (!std::isfinite(y) || y < 0)
      throw InputError("thin-ship sheet: half-breadths must be finite and >= 0");

  std::vector<PointSource> out;
  out.reserve(2 * (nx - 1) * nz);
  for (std::size_t j = 0; j < nz; ++j) {
    for (std::size_t i = 0; i + 1 < nx; ++i) {
      const double dx = g.x_m[i + 1] - g.x_m[i];
      const double y_x = (g.at(i + 1, j) - g.at(i, j)) / dx;
      const double q = -2.0 * ship_speed_m_s * y_x * dx * dz;  // sigma dx dz, sigma = -2 U Y_x
      if (q == 0.0) continue;
      const double xc = 0.5 * (g.x_m[i] + g.x_m[i + 1]);
      out.push_back({Vec3(xc, 0.0, g.z_m[j]), q});
      out.push_back({Vec3(xc, 0.0, -g.z_m[j]), q});  // the mirror image above the rigid lid
    }
  }
  return out;
}

FlowTable::FlowTable(std::span<const PointSource> sources, const Vec3& lo, const Vec3& hi, double spacing_m,
                     double core_radius_m, bool mirror_y)
    : FlowTable([&](const Vec3& p) { return induced_velocity(sources, p, core_radius_m); }, lo, hi, spacing_m,
                mirror_y) {}

FlowTable::FlowTable(const std::function<Vec3(const Vec3&)>& field, const Vec3& lo, const Vec3& hi,
                     double spacing_m, bool mirror_y)
    : lo_(lo), hi_(hi), mirror_y_(mirror_y) {
  if (!(spacing_m > 0) || !((hi - lo).minCoeff() > 0))
    throw InputError("flow table: needs a box with hi > lo on every axis and a spacing > 0");
  if (mirror_y && lo.y() != 0.0) throw InputError("flow table: a y-mirrored table starts at y = 0");
  for (int a = 0; a < 3; ++a) {
    n_[a] = std::max(2, static_cast<int>(std::ceil((hi[a] - lo[a]) / spacing_m)) + 1);
    h_[a] = (hi[a] - lo[a]) / (n_[a] - 1);
    inv_h_[a] = 1.0 / h_[a];
  }
  values_.resize(3 * static_cast<std::size_t>(n_.prod()));
  std::size_t k = 0;
  for (int iz = 0; iz < n_.z(); ++iz)
    for (int iy = 0; iy < n_.y(); ++iy)
      for (int ix = 0; ix < n_.x(); ++ix) {
        const Vec3 u = field(lo_ + Vec3(ix * h_.x(), iy * h_.y(), iz * h_.z()));
        max_speed_ = std::max(max_speed_, u.norm());
        values_[k++] = u.x(), values_[k++] = u.y(), values_[k++] = u.z();
      }
}

FlowTable FlowTable::from_values(const Vec3& lo, const Vec3& hi, const Eigen::Vector3i& nodes, bool mirror_y,
                                 std::vector<double> values) {
  if (!((hi - lo).minCoeff() > 0) || nodes.minCoeff() < 2 ||
      values.size() != 3 * static_cast<std::size_t>(nodes.prod()) || (mirror_y && lo.y() != 0.0))
    throw InputError(
        fmt::format("flow table: {} values do not make a table of {} x {} x {} nodes on a valid box",
                    values.size(), nodes.x(), nodes.y(), nodes.z()));
  FlowTable t;
  t.lo_ = lo, t.hi_ = hi, t.n_ = nodes, t.mirror_y_ = mirror_y;
  for (int a = 0; a < 3; ++a) t.h_[a] = (hi[a] - lo[a]) / (nodes[a] - 1), t.inv_h_[a] = 1.0 / t.h_[a];
  for (std::size_t k = 0; k + 2 < values.size(); k += 3)
    t.max_speed_ = std::max(t.max_speed_, Vec3(values[k], values[k + 1], values[k + 2]).norm());
  t.values_ = std::move(values);
  return t;
}

Vec3 FlowTable::at(const Vec3& p) const {
  if (values_.empty()) return Vec3::Zero();
  const bool flip = mirror_y_ && p.y() < 0;
  const Vec3 q(p.x(), flip ? -p.y() : p.y(), p.z());
  // outside (or NaN): no flow; the grid's last node is inclusive
  if (!(q.x() >= lo_.x() && q.x() <= hi_.x() && q.y() >= lo_.y() && q.y() <= hi_.y() && q.z() >= lo_.z() &&
        q.z() <= hi_.z()))
    return Vec3::Zero();
  int i[3];
  double w[3];
  for (int a = 0; a < 3; ++a) {
    const double s = (q[a] - lo_[a]) * inv_h_[a];
    i[a] = std::min(static_cast<int>(s), n_[a] - 2);
    w[a] = s - i[a];
  }
  const std::size_t sx = 3, sy = 3 * static_cast<std::size_t>(n_.x()), sz = sy * n_.y();
  const double* v0 = values_.data() + i[0] * sx + i[1] * sy + i[2] * sz;
  double u[3];
  for (int c = 0; c < 3; ++c) {
    const double* v = v0 + c;
    const double c00 = v[0] + w[0] * (v[sx] - v[0]);
    const double c10 = v[sy] + w[0] * (v[sy + sx] - v[sy]);
    const double c01 = v[sz] + w[0] * (v[sz + sx] - v[sz]);
    const double c11 = v[sz + sy] + w[0] * (v[sz + sy + sx] - v[sz + sy]);
    const double c0 = c00 + w[1] * (c10 - c00), c1 = c01 + w[1] * (c11 - c01);
    u[c] = c0 + w[2] * (c1 - c0);
  }
  return Vec3(u[0], flip ? -u[1] : u[1], u[2]);
}

FlowTable hull_flow_table(std::span<const PointSource> sources, double half_breadth_max_m, double margin_m,
                          double spacing_m) {
  if (sources.empty())
    throw InputError("hull flow: the hull gives no thin-ship sources (no half-breadth change)");
  if (!(spacing_m > 0) || !(margin_m > 0) || !(half_breadth_max_m >= 0))
    throw InputError("hull flow: the table needs a spacing > 0, a margin > 0 and a half-breadth >= 0");
  Vec3 lo = sources[0].position_m, hi = lo;
  for (const PointSource& s : sources) lo = lo.cwiseMin(s.position_m), hi = hi.cwiseMax(s.position_m);
  // Pieces float at the water level or are pushed down along the hull: the table reaches from margin below
  // the keel to a little above the water (a piece whose centre is higher is barely wet and feels no drag).
  const Vec3 box_lo(lo.x() - margin_m, 0.0, lo.z() - margin_m);
  const Vec3 box_hi(hi.x() + margin_m, half_breadth_max_m + margin_m,
                    std::max(2.0 * spacing_m, 0.25 * margin_m));
  return FlowTable(sources, box_lo, box_hi, spacing_m, spacing_m, true);
}

}  // namespace brash::core
