// JBC hull generator: offsets interpolation (PCHIP), profile-clipped (x, z) grid by marching squares,
// two half-breadth sheets and closing strips. Built at data scale (1:40), scaled at the end.
#include <brash/error.hpp>
#include <brash/hull/jbc.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace brash::hull {
namespace {

// ---------- monotone cubic (PCHIP, Fritsch-Carlson/Butland) ----------

// Node slopes of the monotone cubic through (x, y): no overshoot, so zeros outside the hull stay >= 0
// and flat parallel-body values stay flat.
std::vector<double> pchip_slopes(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();
  std::vector<double> h(n - 1), del(n - 1), d(n, 0.0);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    h[i] = x[i + 1] - x[i];
    del[i] = (y[i + 1] - y[i]) / h[i];
  }
  for (std::size_t i = 1; i + 1 < n; ++i) {
    if (del[i - 1] * del[i] <= 0) continue;
    const double w1 = 2 * h[i] + h[i - 1], w2 = h[i] + 2 * h[i - 1];
    d[i] = (w1 + w2) / (w1 / del[i - 1] + w2 / del[i]);
  }
  auto end_slope = [](double h0, double h1, double d0, double d1) {
    double s = ((2 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
    if (s * d0 <= 0) return 0.0;
    if (d0 * d1 <= 0 && std::abs(s) > 3 * std::abs(d0)) return 3 * d0;
    return s;
  };
  if (n >= 3) {
    d[0] = end_slope(h[0], h[1], del[0], del[1]);
    d[n - 1] = end_slope(h[n - 2], h[n - 3], del[n - 2], del[n - 3]);
  } else {
    d[0] = d[n - 1] = del[0];
  }
  return d;
}

// Interval index i with x[i] <= t < x[i+1], clamped to the table.
std::size_t interval(const std::vector<double>& x, double t) {
  const auto it = std::upper_bound(x.begin(), x.end(), t);
  const auto i = static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - x.begin() - 1, 0));
  return std::min(i, x.size() - 2);
}

double hermite(double x0, double x1, double y0, double y1, double d0, double d1, double t) {
  const double h = x1 - x0, s = std::clamp((t - x0) / h, 0.0, 1.0);
  const double s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * y0 + (s3 - 2 * s2 + s) * h * d0 + (-2 * s3 + 3 * s2) * y1 + (s3 - s2) * h * d1;
}

// Y(x, z): PCHIP along x on every waterline (slopes precomputed), then PCHIP along z.
class HalfBreadth {
 public:
  explicit HalfBreadth(const JbcData& d) : d_(d) {
    for (Eigen::Index k = 0; k < d.half_breadth_m.cols(); ++k) {
      std::vector<double> y(d.station_x_m.size());
      for (std::size_t i = 0; i < y.size(); ++i) y[i] = d.half_breadth_m(static_cast<Eigen::Index>(i), k);
      rows_.push_back(y);
      slopes_.push_back(pchip_slopes(d.station_x_m, y));
    }
  }
  double operator()(double x, double z) const {
    const auto& xs = d_.station_x_m;
    const std::size_t i = interval(xs, x);
    std::vector<double> col(rows_.size());
    for (std::size_t k = 0; k < rows_.size(); ++k)
      col[k] = hermite(xs[i], xs[i + 1], rows_[k][i], rows_[k][i + 1], slopes_[k][i], slopes_[k][i + 1], x);
    const auto& zs = d_.waterline_z_m;
    const auto dz = pchip_slopes(zs, col);
    const std::size_t k = interval(zs, z);
    return std::max(0.0, hermite(zs[k], zs[k + 1], col[k], col[k + 1], dz[k], dz[k + 1], z));
  }

 private:
  const JbcData& d_;
  std::vector<std::vector<double>> rows_, slopes_;
};

// ---------- profile: is (x, z) inside the hull's centre-plane outline? ----------

bool inside_profile(const JbcData& d, double x, double z) {
  const auto& px = d.profile_x_m;
  if (x < px.front() || x > px.back()) return false;
  const std::size_t i = interval(px, x);
  const auto& a = d.profile_z_m[i];
  const auto& b = d.profile_z_m[i + 1];
  const double s = (x - px[i]) / (px[i + 1] - px[i]);
  if (a.size() == b.size()) {  // same topology: interpolate the interval ends
    for (std::size_t k = 0; k < a.size(); ++k) {
      const double lo = a[k].first + s * (b[k].first - a[k].first);
      const double hi = a[k].second + s * (b[k].second - a[k].second);
      if (z >= lo && z <= hi) return true;
    }
    return false;
  }
  for (const auto& [lo, hi] : s < 0.5 ? a : b)  // topology changes (boss end, stem/bulb): nearest station
    if (z >= lo && z <= hi) return true;
  return false;
}

// ---------- grids ----------

struct Band {
  double from, to, spacing;  // data units (m at 1:40)
};

// Grid through every `required` coordinate, each gap filled evenly with spacing <= the band's.
std::vector<double> graded_grid(std::vector<double> required, const std::vector<Band>& bands, double factor) {
  std::sort(required.begin(), required.end());
  std::vector<double> req;
  for (double r : required)
    if (req.empty() || r - req.back() > 1e-3) req.push_back(r);
  auto spacing_at = [&](double t) {
    for (const auto& b : bands)
      if (t >= b.from && t <= b.to) return b.spacing * factor;
    return bands.back().spacing * factor;
  };
  std::vector<double> g{req.front()};
  for (std::size_t i = 0; i + 1 < req.size(); ++i) {
    const double a = req[i], b = req[i + 1];
    const double h = std::min(spacing_at(a + 1e-9), spacing_at(b - 1e-9));
    const int n = std::max(1, static_cast<int>(std::ceil((b - a) / h - 1e-9)));
    for (int j = 1; j <= n; ++j) g.push_back(a + (b - a) * j / n);
  }
  return g;
}

// ---------- planar triangulation of the profile region (marching squares) ----------

struct Planar {
  std::vector<Eigen::Vector2d> points;        // (x, z)
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise in (x, z)
};

Planar triangulate_profile(const JbcData& d, const std::vector<double>& gx, const std::vector<double>& gz) {
  const int nx = static_cast<int>(gx.size()), nz = static_cast<int>(gz.size());
  auto node = [&](int i, int k) { return i * nz + k; };
  std::vector<char> in(static_cast<std::size_t>(nx * nz));
  for (int i = 0; i < nx; ++i)
    for (int k = 0; k < nz; ++k) in[node(i, k)] = inside_profile(d, gx[i], gz[k]);

  Planar p;
  std::map<int, int> node_point;                    // grid node -> point index
  std::map<std::pair<int, int>, int> edge_point;    // grid edge (node a < node b) -> point index
  auto node_index = [&](int n) {
    auto [it, fresh] = node_point.try_emplace(n, static_cast<int>(p.points.size()));
    if (fresh) p.points.emplace_back(gx[n / nz], gz[n % nz]);
    return it->second;
  };
  const double snap = 1e-5;  // 10 um at 1:40: closer cut points merge with the grid node (float32 safety)
  auto cut_index = [&](int na, int nb) {
    const std::pair<int, int> key{std::min(na, nb), std::max(na, nb)};
    if (auto it = edge_point.find(key); it != edge_point.end()) return it->second;
    const int n_in = in[na] ? na : nb, n_out = in[na] ? nb : na;
    Eigen::Vector2d lo(gx[n_in / nz], gz[n_in % nz]), hi(gx[n_out / nz], gz[n_out % nz]);
    const Eigen::Vector2d a = lo, b = hi;
    while ((hi - lo).norm() > 1e-10) {  // bisection: lo stays inside, hi outside
      const Eigen::Vector2d m = 0.5 * (lo + hi);
      (inside_profile(d, m.x(), m.y()) ? lo : hi) = m;
    }
    int idx;
    if ((lo - a).norm() < snap) idx = node_index(n_in);
    else if ((lo - b).norm() < snap) idx = node_index(n_out);
    else {
      idx = static_cast<int>(p.points.size());
      p.points.push_back(lo);
    }
    edge_point.emplace(key, idx);
    return idx;
  };
  for (int i = 0; i + 1 < nx; ++i) {
    for (int k = 0; k + 1 < nz; ++k) {
      const std::array<int, 4> c{node(i, k), node(i + 1, k), node(i + 1, k + 1), node(i, k + 1)};  // CCW
      std::vector<int> poly;
      for (int j = 0; j < 4; ++j) {
        const int a = c[j], b = c[(j + 1) % 4];
        if (in[a]) poly.push_back(node_index(a));
        if (in[a] != in[b]) poly.push_back(cut_index(a, b));
      }
      std::vector<int> clean;  // drop repeats left by snapping
      for (int v : poly)
        if (clean.empty() || clean.back() != v) clean.push_back(v);
      while (clean.size() > 1 && clean.front() == clean.back()) clean.pop_back();
      for (std::size_t j = 1; j + 1 < clean.size(); ++j) p.triangles.push_back({clean[0], clean[j], clean[j + 1]});
    }
  }
  return p;
}

}  // namespace

Mesh make_jbc(const JbcData& data, const JbcOptions& options) {
  if (!(options.lpp_m > 0)) throw InputError(fmt::format("JBC: Lpp {} m is not positive", options.lpp_m));
  if (!(options.grid_factor >= 0.2 && options.grid_factor <= 5))
    throw InputError(fmt::format("JBC: grid factor {} outside [0.2, 5]", options.grid_factor));
  const double T = JbcData::draft_m, D = JbcData::depth_m;
  const double x_aft = data.profile_x_m.front(), x_fwd = data.profile_x_m.back();

  // Stations: fine where the outline turns fast (transom, shaft boss, bow, bulb), coarse in the parallel body.
  std::vector<double> rx{x_aft, x_fwd, 0.0, JbcData::lpp_m};
  for (double x : data.station_x_m)
    if (x > x_aft + 1e-3 && x < x_fwd - 1e-3) rx.push_back(x);
  const auto gx = graded_grid(rx, {{x_aft, 0.35, 0.007}, {0.35, 1.6, 0.03}, {1.6, 5.5, 0.175},
                                   {5.5, 6.6, 0.03}, {6.6, x_fwd, 0.006}}, options.grid_factor);
  // Waterlines: the table's, the bilge radius (45 mm) and the shaft boss refined, T exactly.
  std::vector<double> rz{0.0, T, D, 0.06, 0.10, 0.16, T - 0.03, T + 0.03};
  for (double z : data.waterline_z_m)
    if (z < D - 1e-3) rz.push_back(z);
  const auto gz = graded_grid(rz, {{0, 0.06, 0.006}, {0.10, 0.16, 0.01}, {T - 0.03, T + 0.03, 0.0075},
                                   {0.06, D, 0.021}}, options.grid_factor);

  const Planar p = triangulate_profile(data, gx, gz);
  const HalfBreadth Y(data);

  // Boundary edges of the planar region (one triangle), directed as in that triangle.
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : p.triangles)
    for (int j = 0; j < 3; ++j) ++uses[{std::min(t[j], t[(j + 1) % 3]), std::max(t[j], t[(j + 1) % 3])}];
  std::vector<std::pair<int, int>> boundary;
  std::vector<char> on_boundary(p.points.size(), 0);
  for (const auto& t : p.triangles)
    for (int j = 0; j < 3; ++j) {
      const int a = t[j], b = t[(j + 1) % 3];
      if (uses[{std::min(a, b), std::max(a, b)}] == 1) {
        boundary.emplace_back(a, b);
        on_boundary[a] = on_boundary[b] = 1;
      }
    }

  // Half-breadths. Boundary points with Y below y_weld lie on the centre plane (stem, keel, counter) and
  // are shared by both sheets; elsewhere Y >= y_min keeps the sheets apart. An interior edge may not have
  // both ends welded (its four faces would share one edge), so one end is un-welded.
  const double y_weld = 5e-4, y_min = 2e-4;
  std::vector<double> y(p.points.size());
  std::vector<char> welded(p.points.size(), 0);
  for (std::size_t v = 0; v < p.points.size(); ++v) {
    y[v] = Y(p.points[v].x(), p.points[v].y());
    welded[v] = on_boundary[v] && y[v] < y_weld;
  }
  for (const auto& [e, n] : uses)
    if (n == 2 && welded[e.first] && welded[e.second]) welded[y[e.first] > y[e.second] ? e.first : e.second] = 0;
  for (std::size_t v = 0; v < p.points.size(); ++v) y[v] = welded[v] ? 0.0 : std::max(y[v], y_min);

  // 3D vertices: +Y sheet, and -Y sheet for the unwelded points.
  const double s = options.lpp_m / JbcData::lpp_m;
  Mesh m;
  std::vector<int> plus(p.points.size()), minus(p.points.size());
  for (std::size_t v = 0; v < p.points.size(); ++v) {
    plus[v] = static_cast<int>(m.vertices.size());
    m.vertices.emplace_back(s * p.points[v].x(), s * y[v], s * p.points[v].y());
    if (welded[v]) {
      minus[v] = plus[v];
    } else {
      minus[v] = static_cast<int>(m.vertices.size());
      m.vertices.emplace_back(s * p.points[v].x(), -s * y[v], s * p.points[v].y());
    }
  }
  auto add = [&](int a, int b, int c) {
    if (a != b && b != c && a != c) m.faces.push_back({a, b, c});
  };
  for (const auto& t : p.triangles) {
    if (welded[t[0]] && welded[t[1]] && welded[t[2]]) continue;  // zero-thickness island: no volume
    add(plus[t[0]], plus[t[2]], plus[t[1]]);    // CCW in (x, z) -> reversed for the +y normal
    add(minus[t[0]], minus[t[1]], minus[t[2]]);
  }
  for (const auto& [a, b] : boundary) {  // strips closing the sheets along the outline
    add(plus[a], plus[b], minus[b]);
    add(plus[a], minus[b], minus[a]);
  }
  return m;
}

}  // namespace brash::hull
