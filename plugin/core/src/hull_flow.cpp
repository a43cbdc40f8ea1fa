// Thin-ship flow around a hull, tabulated (see hull_flow.hpp).
#include "brash/core/hull_flow.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

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

namespace {

// A block of nodes (the table's grid or one brick), x fastest.
struct Block {
  int nx, ny, nz;
  std::size_t size() const { return static_cast<std::size_t>(nx) * ny * nz; }
  std::size_t at(int i, int j, int k) const { return (static_cast<std::size_t>(k) * ny + j) * nx + i; }
  bool inside(int i, int j, int k) const { return i >= 0 && j >= 0 && k >= 0 && i < nx && j < ny && k < nz; }
};

constexpr int kC = FlowTable::kComponents;

// Values of u (first = 0) or Du/Dt (first = 3) at the nodes that are not `known` (inside the body), extrapolated
// linearly from the water side, one layer of nodes at a time (Jacobi: a layer reads only the layers before it).
// A node's value is the mean over the 26 grid directions d with known nodes at +d and +2d of 2 u(+d) - u(+2d)
// (exact for a linear field), or where there is none the mean of its known neighbours. Nodes deeper than
// `layers` keep 0: no cell that holds water reaches them.
void extrapolate_into_body(std::vector<double>& v, std::vector<char> known, const Block& b, int layers, int first) {
  std::vector<std::size_t> layer;
  std::vector<double> layer_u;
  for (int pass = 0; pass < layers; ++pass) {
    layer.clear(), layer_u.clear();
    for (int k = 0; k < b.nz; ++k)
      for (int j = 0; j < b.ny; ++j)
        for (int i = 0; i < b.nx; ++i) {
          const std::size_t n = b.at(i, j, k);
          if (known[n]) continue;
          double lin[3] = {0, 0, 0}, near[3] = {0, 0, 0};
          int n_lin = 0, n_near = 0;
          for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
              for (int dx = -1; dx <= 1; ++dx) {
                if (!dx && !dy && !dz) continue;
                if (!b.inside(i + dx, j + dy, k + dz)) continue;
                const std::size_t n1 = b.at(i + dx, j + dy, k + dz);
                if (!known[n1]) continue;
                if (b.inside(i + 2 * dx, j + 2 * dy, k + 2 * dz) && known[b.at(i + 2 * dx, j + 2 * dy, k + 2 * dz)]) {
                  const std::size_t n2 = b.at(i + 2 * dx, j + 2 * dy, k + 2 * dz);
                  for (int c = 0; c < 3; ++c) lin[c] += 2.0 * v[kC * n1 + first + c] - v[kC * n2 + first + c];
                  ++n_lin;
                } else {
                  for (int c = 0; c < 3; ++c) near[c] += v[kC * n1 + first + c];
                  ++n_near;
                }
              }
          if (n_lin + n_near == 0) continue;
          layer.push_back(n);
          for (int c = 0; c < 3; ++c) layer_u.push_back(n_lin ? lin[c] / n_lin : near[c] / n_near);
        }
    if (layer.empty()) return;
    for (std::size_t q = 0; q < layer.size(); ++q) {
      known[layer[q]] = 1;
      for (int c = 0; c < 3; ++c) v[kC * layer[q] + first + c] = layer_u[3 * q + c];
    }
  }
}

// Du/Dt = ((u - V) . grad) u at every node from the tabulated u (ghost nodes inside a body included): central
// differences inside the block, second-order one-sided ones on its faces.
void fill_acceleration(std::vector<double>& v, const Block& b, const Vec3& h, const Vec3& body_velocity) {
  const int dims[3] = {b.nx, b.ny, b.nz};
  for (int k = 0; k < b.nz; ++k)
    for (int j = 0; j < b.ny; ++j)
      for (int i = 0; i < b.nx; ++i) {
        const int idx[3] = {i, j, k};
        const std::size_t n = b.at(i, j, k);
        double grad[3][3];  // grad[axis][component]
        for (int a = 0; a < 3; ++a) {
          auto node = [&](int off) {
            int q[3] = {i, j, k};
            q[a] += off;
            return b.at(q[0], q[1], q[2]);
          };
          for (int c = 0; c < 3; ++c) grad[a][c] = 0.0;
          if (dims[a] < 2) continue;
          const double inv = 1.0 / h[a];
          for (int c = 0; c < 3; ++c) {
            double d;
            if (idx[a] > 0 && idx[a] + 1 < dims[a])
              d = 0.5 * (v[kC * node(1) + c] - v[kC * node(-1) + c]);
            else if (dims[a] < 3)
              d = idx[a] == 0 ? v[kC * node(1) + c] - v[kC * n + c] : v[kC * n + c] - v[kC * node(-1) + c];
            else if (idx[a] == 0)
              d = -1.5 * v[kC * n + c] + 2.0 * v[kC * node(1) + c] - 0.5 * v[kC * node(2) + c];
            else
              d = 1.5 * v[kC * n + c] - 2.0 * v[kC * node(-1) + c] + 0.5 * v[kC * node(-2) + c];
            grad[a][c] = d * inv;
          }
        }
        const double w[3] = {v[kC * n] - body_velocity.x(), v[kC * n + 1] - body_velocity.y(),
                             v[kC * n + 2] - body_velocity.z()};
        for (int c = 0; c < 3; ++c) v[kC * n + 3 + c] = w[0] * grad[0][c] + w[1] * grad[1][c] + w[2] * grad[2][c];
      }
}

// Building the bricks: the field sampled on the finest lattice (max_factor per cell), each point once.
struct Sampler {
  const FlowField& field;
  Vec3 lo, h_fine;
  double clearance_m;
  struct Sample {
    Vec3 u;
    bool solid, checked;
  };
  std::unordered_map<std::uint64_t, Sample> cache;
  Sample operator()(long I, long J, long K) {
    const std::uint64_t key = (static_cast<std::uint64_t>(K) << 42) | (static_cast<std::uint64_t>(J) << 21) |
                              static_cast<std::uint64_t>(I);
    if (auto it = cache.find(key); it != cache.end()) return it->second;
    const Vec3 p = lo + Vec3(I * h_fine.x(), J * h_fine.y(), K * h_fine.z());
    Sample s{Vec3::Zero(), field.solid && field.solid(p), true};
    if (!s.solid) s.u = field.velocity(p);
    if (!s.solid && clearance_m > 0) s.checked = !(field.distance_m(p) < clearance_m);
    cache.emplace(key, s);
    return s;
  }
};

FlowField velocity_only(const std::function<Vec3(const Vec3&)>& velocity) {
  FlowField f;
  f.velocity = velocity;
  return f;
}

}  // namespace

FlowTable::FlowTable(std::span<const PointSource> sources, const Vec3& lo, const Vec3& hi, double spacing_m,
                     double core_radius_m, bool mirror_y)
    : FlowTable([&](const Vec3& p) { return induced_velocity(sources, p, core_radius_m); }, lo, hi, spacing_m,
                mirror_y) {}

FlowTable::FlowTable(const std::function<Vec3(const Vec3&)>& field, const Vec3& lo, const Vec3& hi,
                     double spacing_m, bool mirror_y)
    : FlowTable(velocity_only(field), lo, hi, spacing_m, mirror_y) {}

void FlowTable::set_grid(const Vec3& lo, const Vec3& hi, const Eigen::Vector3i& nodes) {
  lo_ = lo, hi_ = hi, n_ = nodes;
  for (int a = 0; a < 3; ++a) h_[a] = (hi[a] - lo[a]) / (n_[a] - 1), inv_h_[a] = 1.0 / h_[a];
}

Eigen::Vector3i FlowTable::grid_nodes(const Vec3& lo, const Vec3& hi, double spacing_m) {
  if (!(spacing_m > 0) || !((hi - lo).minCoeff() > 0))
    throw InputError("flow table: needs a box with hi > lo on every axis and a spacing > 0");
  Eigen::Vector3i n;
  for (int a = 0; a < 3; ++a) n[a] = std::max(2, static_cast<int>(std::ceil((hi[a] - lo[a]) / spacing_m)) + 1);
  return n;
}

FlowTable::FlowTable(const FlowField& field, const Vec3& lo, const Vec3& hi, double spacing_m, bool mirror_y,
                     const FlowRefinement& r)
    : FlowTable(field, lo, hi, grid_nodes(lo, hi, spacing_m), mirror_y, r) {}

FlowTable::FlowTable(const FlowField& field, const Vec3& lo, const Vec3& hi, const Eigen::Vector3i& n,
                     bool mirror_y, const FlowRefinement& r)
    : mirror_y_(mirror_y), acceleration_(field.acceleration) {
  if (!((hi - lo).minCoeff() > 0) || n.minCoeff() < 2)
    throw InputError("flow table: needs a box with hi > lo on every axis and >= 2 nodes per axis");
  if (mirror_y && lo.y() != 0.0) throw InputError("flow table: a y-mirrored table starts at y = 0");
  const bool refine = r.band_m > 0 && field.distance_m;
  if (refine && (r.max_factor < 2 || (r.max_factor & (r.max_factor - 1)) != 0 || r.max_factor > 64 ||
                 !(r.tolerance_m_s > 0)))
    throw InputError("flow table: refinement needs a tolerance > 0 and a power-of-2 factor from 2 to 64");
  set_grid(lo, hi, n);
  const Block grid{n_.x(), n_.y(), n_.z()};
  values_.assign(kC * grid.size(), 0.0);
  std::vector<char> fluid(grid.size(), 1);
  for (int iz = 0; iz < n_.z(); ++iz)
    for (int iy = 0; iy < n_.y(); ++iy)
      for (int ix = 0; ix < n_.x(); ++ix) {
        const std::size_t k = grid.at(ix, iy, iz);
        const Vec3 p = lo_ + Vec3(ix * h_.x(), iy * h_.y(), iz * h_.z());
        if (field.solid && field.solid(p)) {
          fluid[k] = 0;
          continue;
        }
        const Vec3 u = field.velocity(p);
        max_speed_ = std::max(max_speed_, u.norm());
        values_[kC * k] = u.x(), values_[kC * k + 1] = u.y(), values_[kC * k + 2] = u.z();
      }
  extrapolate_into_body(values_, fluid, grid, 2, 0);
  if (acceleration_) {
    fill_acceleration(values_, grid, h_, field.body_velocity_m_s);
    extrapolate_into_body(values_, fluid, grid, 2, 3);
  }
  if (!refine) return;

  const int fine = r.max_factor;
  Sampler sample{field, lo_, h_ / fine, r.clearance_m, {}};
  const Block cells{n_.x() - 1, n_.y() - 1, n_.z() - 1};
  cell_brick_.assign(cells.size(), -1);
  const double half_diagonal = 0.5 * h_.norm();
  std::vector<double> v;
  std::vector<char> solid, unchecked, brick_fluid;
  for (int cz = 0; cz < cells.nz; ++cz)
    for (int cy = 0; cy < cells.ny; ++cy)
      for (int cx = 0; cx < cells.nx; ++cx) {
        const Vec3 centre = lo_ + Vec3((cx + 0.5) * h_.x(), (cy + 0.5) * h_.y(), (cz + 0.5) * h_.z());
        const double d = field.distance_m(centre);
        if (d > r.band_m + half_diagonal) continue;
        if (d > half_diagonal && field.solid && field.solid(centre)) continue;  // all inside: no water there
        // sample the cell at m = 2, 4, ... per axis until the m/2 lattice interpolates the m lattice's
        // further nodes within tolerance
        for (int m = 2; m <= fine; m *= 2) {
          const Block b{m + 1, m + 1, m + 1};
          v.assign(kC * b.size(), 0.0), solid.assign(b.size(), 0), unchecked.assign(b.size(), 0);
          bool any_water = false, corner_solid = false;
          for (int k = 0; k <= m; ++k)
            for (int j = 0; j <= m; ++j)
              for (int i = 0; i <= m; ++i) {
                const int step = fine / m;
                const std::size_t q = b.at(i, j, k);
                const Sampler::Sample s = sample(static_cast<long>(cx) * fine + i * step,
                                                 static_cast<long>(cy) * fine + j * step,
                                                 static_cast<long>(cz) * fine + k * step);
                solid[q] = s.solid, unchecked[q] = !s.checked;
                any_water |= !s.solid;
                if ((i == 0 || i == m) && (j == 0 || j == m) && (k == 0 || k == m)) corner_solid |= s.solid;
                for (int c = 0; c < 3; ++c) v[kC * q + c] = s.u[c];
              }
          if (!any_water) continue;  // a sliver of water finer than this lattice, or none
          brick_fluid.assign(solid.size(), 0);
          for (std::size_t q = 0; q < solid.size(); ++q) brick_fluid[q] = !solid[q];
          extrapolate_into_body(v, brick_fluid, b, m + 1, 0);
          // the largest error of the m/2 lattice's trilinear interpolation at the water nodes of the m lattice
          double err = 0;
          for (int k = 0; k <= m; ++k)
            for (int j = 0; j <= m; ++j)
              for (int i = 0; i <= m; ++i) {
                if (!(i % 2 || j % 2 || k % 2) || solid[b.at(i, j, k)] || unchecked[b.at(i, j, k)]) continue;
                const int ci = std::min(i / 2, m / 2 - 1), cj = std::min(j / 2, m / 2 - 1),
                          ck = std::min(k / 2, m / 2 - 1);
                const double wx = 0.5 * (i - 2 * ci), wy = 0.5 * (j - 2 * cj), wz = 0.5 * (k - 2 * ck);
                Vec3 e = Vec3::Zero();
                for (int dz = 0; dz <= 1; ++dz)
                  for (int dy = 0; dy <= 1; ++dy)
                    for (int dx = 0; dx <= 1; ++dx) {
                      const double w = (dx ? wx : 1 - wx) * (dy ? wy : 1 - wy) * (dz ? wz : 1 - wz);
                      const std::size_t q = b.at(2 * (ci + dx), 2 * (cj + dy), 2 * (ck + dz));
                      e += w * Vec3(v[kC * q], v[kC * q + 1], v[kC * q + 2]);
                    }
                const std::size_t q = b.at(i, j, k);
                err = std::max(err, (e - Vec3(v[kC * q], v[kC * q + 1], v[kC * q + 2])).norm());
              }
          const bool pass = err <= r.tolerance_m_s;
          if (!pass && m < fine) continue;
          if (acceleration_) {  // from the brick's own lattice (its ghost nodes' u included), then extended
            fill_acceleration(v, b, h_ / m, field.body_velocity_m_s);
            extrapolate_into_body(v, brick_fluid, b, m + 1, 3);
          }
          const int keep = pass ? m / 2 : m;  // the lattice that met the tolerance (or the finest)
          if (keep == 1 && !corner_solid) {
            break;  // the cell's own nodes serve
          }
          const int step = m / keep;
          cell_brick_[cells.at(cx, cy, cz)] = static_cast<std::int32_t>(bricks_.size());
          bricks_.push_back({brick_values_.size(), keep});
          for (int k = 0; k <= keep; ++k)
            for (int j = 0; j <= keep; ++j)
              for (int i = 0; i <= keep; ++i) {
                const std::size_t q = b.at(i * step, j * step, k * step);
                if (!solid[q]) max_speed_ = std::max(max_speed_, Vec3(v[kC * q], v[kC * q + 1], v[kC * q + 2]).norm());
                for (int c = 0; c < kC; ++c) brick_values_.push_back(v[kC * q + c]);
              }
          break;
        }
      }
}

FlowTable FlowTable::from_values(const Vec3& lo, const Vec3& hi, const Eigen::Vector3i& nodes, bool mirror_y,
                                 std::vector<double> values, bool acceleration) {
  const std::size_t count = nodes.minCoeff() >= 2 ? static_cast<std::size_t>(nodes.prod()) : 0;
  if (!((hi - lo).minCoeff() > 0) || nodes.minCoeff() < 2 ||
      (values.size() != 3 * count && values.size() != kC * count) || (mirror_y && lo.y() != 0.0))
    throw InputError(
        fmt::format("flow table: {} values do not make a table of {} x {} x {} nodes on a valid box",
                    values.size(), nodes.x(), nodes.y(), nodes.z()));
  FlowTable t;
  t.set_grid(lo, hi, nodes);
  t.mirror_y_ = mirror_y;
  if (values.size() == 3 * count) {  // u only: no acceleration
    t.values_.assign(kC * count, 0.0);
    for (std::size_t k = 0; k < count; ++k)
      for (int c = 0; c < 3; ++c) t.values_[kC * k + c] = values[3 * k + c];
  } else {
    t.values_ = std::move(values);
    t.acceleration_ = acceleration;
  }
  for (std::size_t k = 0; k < count; ++k)
    t.max_speed_ = std::max(t.max_speed_, Vec3(t.values_[kC * k], t.values_[kC * k + 1], t.values_[kC * k + 2]).norm());
  return t;
}

void FlowTable::set_bricks(std::vector<std::int32_t> cell_brick, std::vector<Brick> bricks,
                           std::vector<double> values) {
  const std::size_t cells = static_cast<std::size_t>((n_ - Eigen::Vector3i::Ones()).prod());
  if (!cell_brick.empty() && cell_brick.size() != cells)
    throw InputError(fmt::format("flow table: {} cell entries for {} cells", cell_brick.size(), cells));
  for (std::int32_t b : cell_brick)
    if (b < -1 || b >= static_cast<std::int32_t>(bricks.size()))
      throw InputError("flow table: a cell names a brick that does not exist");
  for (const Brick& b : bricks) {
    const std::uint64_t side = static_cast<std::uint64_t>(b.factor) + 1;
    if (b.factor < 1 || b.offset % kC != 0 || b.offset + kC * side * side * side > values.size())
      throw InputError("flow table: a brick reaches beyond its values");
  }
  cell_brick_ = std::move(cell_brick), bricks_ = std::move(bricks), brick_values_ = std::move(values);
  for (std::size_t k = 0; k + kC <= brick_values_.size(); k += kC)
    max_speed_ = std::max(max_speed_, Vec3(brick_values_[k], brick_values_[k + 1], brick_values_[k + 2]).norm());
}

template <int kN>
void FlowTable::interpolate(const Vec3& p, double* out) const {
  for (int c = 0; c < kN; ++c) out[c] = 0.0;
  if (values_.empty()) return;
  const bool flip = mirror_y_ && p.y() < 0;
  const Vec3 q(p.x(), flip ? -p.y() : p.y(), p.z());
  // outside (or NaN): no flow; the grid's last node is inclusive
  if (!(q.x() >= lo_.x() && q.x() <= hi_.x() && q.y() >= lo_.y() && q.y() <= hi_.y() && q.z() >= lo_.z() &&
        q.z() <= hi_.z()))
    return;
  int i[3];
  double w[3];
  for (int a = 0; a < 3; ++a) {
    const double s = (q[a] - lo_[a]) * inv_h_[a];
    i[a] = std::min(static_cast<int>(s), n_[a] - 2);
    w[a] = s - i[a];
  }
  std::size_t sx = kC, sy = kC * static_cast<std::size_t>(n_.x()), sz = sy * n_.y();
  const double* v0 = values_.data() + i[0] * sx + i[1] * sy + i[2] * sz;
  if (!cell_brick_.empty()) {
    const std::int32_t b = cell_brick_[i[0] + static_cast<std::size_t>(n_.x() - 1) *
                                                  (i[1] + static_cast<std::size_t>(n_.y() - 1) * i[2])];
    if (b >= 0) {  // a cell along the body: its own finer lattice
      const Brick& br = bricks_[static_cast<std::size_t>(b)];
      const int f = br.factor;
      int j[3];
      for (int a = 0; a < 3; ++a) {
        const double s = w[a] * f;
        j[a] = std::min(static_cast<int>(s), f - 1);
        w[a] = s - j[a];
      }
      sy = kC * static_cast<std::size_t>(f + 1), sz = sy * (f + 1);
      v0 = brick_values_.data() + br.offset + j[0] * sx + j[1] * sy + j[2] * sz;
    }
  }
  for (int c = 0; c < kN; ++c) {
    const double* v = v0 + c;
    const double c00 = v[0] + w[0] * (v[sx] - v[0]);
    const double c10 = v[sy] + w[0] * (v[sy + sx] - v[sy]);
    const double c01 = v[sz] + w[0] * (v[sz + sx] - v[sz]);
    const double c11 = v[sz + sy] + w[0] * (v[sz + sy + sx] - v[sz + sy]);
    const double c0 = c00 + w[1] * (c10 - c00), c1 = c01 + w[1] * (c11 - c01);
    out[c] = c0 + w[2] * (c1 - c0);
  }
  if (flip) {
    out[1] = -out[1];
    if constexpr (kN > 3) out[4] = -out[4];
  }
}

Vec3 FlowTable::at(const Vec3& p) const {
  double u[3];
  interpolate<3>(p, u);
  return Vec3(u[0], u[1], u[2]);
}

void FlowTable::at(const Vec3& p, Vec3& u_m_s, Vec3& a_m_s2) const {
  double u[kC];
  interpolate<kC>(p, u);
  u_m_s = Vec3(u[0], u[1], u[2]), a_m_s2 = Vec3(u[3], u[4], u[5]);
}

FlowTable hull_flow_table(std::span<const PointSource> sources, double half_breadth_max_m, double margin_m,
                          double spacing_m) {
  if (sources.empty())
    throw InputError("hull flow: the hull gives no thin-ship sources (no half-breadth change)");
  if (!(spacing_m > 0) || !(margin_m > 0) || !(half_breadth_max_m >= 0))
    throw InputError("hull flow: the table needs a spacing > 0, a margin > 0 and a half-breadth >= 0");
  Vec3 lo = sources[0].position_m, hi = lo;
  for (const PointSource& s : sources) lo = lo.cwiseMin(s.position_m), hi = hi.cwiseMax(s.position_m);
  const auto [box_lo, box_hi] = hull_flow_box(lo, hi, half_breadth_max_m, margin_m, spacing_m);
  return FlowTable(sources, box_lo, box_hi, spacing_m, spacing_m, true);
}

std::pair<Vec3, Vec3> hull_flow_box(const Vec3& lo, const Vec3& hi, double half_breadth_max_m, double margin_m,
                                    double spacing_m) {
  // Pieces float at the water level or are pushed down along the hull: the table reaches from margin below
  // the keel to a little above the water (a piece whose centre is higher is barely wet and feels no drag).
  return {Vec3(lo.x() - margin_m, 0.0, lo.z() - margin_m),
          Vec3(hi.x() + margin_m, half_breadth_max_m + margin_m, std::max(2.0 * spacing_m, 0.25 * margin_m))};
}

}  // namespace brash::core
