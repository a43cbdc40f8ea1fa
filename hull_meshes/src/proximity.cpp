// Sphere-hull overlap queries (proximity.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <brash/error.hpp>
#include <brash/hull/proximity.hpp>
#include <cmath>

namespace brash::hull {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

// Closest point to p on the segment [a, b].
Vector3d closest_on_segment(const Vector3d& p, const Vector3d& a, const Vector3d& b) {
  const Vector3d ab = b - a;
  const double len2 = ab.squaredNorm();
  if (!(len2 > 0)) return a;
  const double t = std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
  return a + t * ab;
}

// Sign (+1, -1, or 0 for a degenerate edge) of the 2D orientation of p against the directed edge u -> v,
// after shifting p by (+eps, +eps^2). The cross product is evaluated with the endpoints in lexicographic
// order and negated for the other direction, so the two triangles sharing an edge get exactly opposite
// values.
int edge_side(const Vector2d& u, const Vector2d& v, const Vector2d& p, double& value) {
  const bool canonical = u.x() < v.x() || (u.x() == v.x() && u.y() < v.y());
  const Vector2d& s = canonical ? u : v;
  const Vector2d& e = canonical ? v : u;
  const double c = (e.x() - s.x()) * (p.y() - s.y()) - (e.y() - s.y()) * (p.x() - s.x());
  value = canonical ? c : -c;
  if (value > 0) return 1;
  if (value < 0) return -1;
  // On the line through u, v: cross(v - u, (eps, eps^2)) = (vx - ux) eps^2 - (vy - uy) eps.
  if (v.y() != u.y()) return v.y() < u.y() ? 1 : -1;
  if (v.x() != u.x()) return v.x() > u.x() ? 1 : -1;
  return 0;
}

}  // namespace

Vector3d closest_point_on_triangle(const Vector3d& p, const Vector3d& a, const Vector3d& b,
                                   const Vector3d& c) {
  const Vector3d n = (b - a).cross(c - a);
  const double n2 = n.squaredNorm();
  if (n2 > 0) {
    // Foot of the perpendicular from p on the plane; it is the answer when it lies inside the triangle
    // (on the inner side of all three edges).
    const Vector3d q = p - n * (n.dot(p - a) / n2);
    if (n.dot((b - a).cross(q - a)) >= 0 && n.dot((c - b).cross(q - b)) >= 0 &&
        n.dot((a - c).cross(q - c)) >= 0)
      return q;
  }
  // Otherwise (or for a degenerate triangle) the closest point lies on the boundary.
  Vector3d best = closest_on_segment(p, a, b);
  double best2 = (best - p).squaredNorm();
  for (const Vector3d& cand : {closest_on_segment(p, b, c), closest_on_segment(p, c, a)}) {
    const double d2 = (cand - p).squaredNorm();
    if (d2 < best2) best2 = d2, best = cand;
  }
  return best;
}

Proximity::Proximity(const Mesh& mesh) {
  if (mesh.faces.empty()) throw InputError("hull proximity: the mesh has no triangles");
  tri_.reserve(mesh.faces.size());
  bounds_.setEmpty();
  double size_sum = 0;
  for (const auto& f : mesh.faces) {
    Tri t{mesh.vertices.at(f[0]), mesh.vertices.at(f[1]), mesh.vertices.at(f[2])};
    if (!t.a.allFinite() || !t.b.allFinite() || !t.c.allFinite())
      throw InputError(fmt::format("hull proximity: triangle {} has a non-finite vertex", tri_.size() + 1));
    Eigen::AlignedBox3d tb(t.a);
    tb.extend(t.b).extend(t.c);
    size_sum += tb.sizes().maxCoeff();
    bounds_.extend(tb);
    tri_.push_back(t);
  }
  closed_ = check_mesh(mesh).closed;

  // Cubic cells about the mean triangle size, at most 256 per axis and 4 M in all.
  const Vector3d ext = bounds_.sizes().cwiseMax(1e-9);
  double h = std::max(size_sum / double(tri_.size()), ext.maxCoeff() / 256);
  auto counts = [&](double hh) {
    std::array<long, 3> n{};
    for (int a = 0; a < 3; ++a) n[a] = std::max(1L, static_cast<long>(std::ceil(ext[a] / hh)));
    return n;
  };
  while (true) {
    n_ = counts(h);
    if (n_[0] * n_[1] * n_[2] <= 4'000'000) break;
    h *= 1.25;
  }
  origin_ = bounds_.min();
  for (int a = 0; a < 3; ++a) h_[a] = ext[a] / double(n_[a]);
  n2_ = {n_[0], n_[1]};
  h2_ = Vector2d(h_[0], h_[1]);

  // Compressed rows: count, prefix sum, fill.
  auto fill = [&](auto&& for_each_cell, std::size_t cells, std::vector<std::size_t>& start,
                  std::vector<int>& ids) {
    start.assign(cells + 1, 0);
    for (std::size_t t = 0; t < tri_.size(); ++t) for_each_cell(t, [&](long c) { ++start[c + 1]; });
    for (std::size_t c = 0; c < cells; ++c) start[c + 1] += start[c];
    ids.assign(start[cells], 0);
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    for (std::size_t t = 0; t < tri_.size(); ++t)
      for_each_cell(t, [&](long c) { ids[next[c]++] = static_cast<int>(t); });
  };
  auto tri_box = [&](std::size_t t) {
    Eigen::AlignedBox3d b(tri_[t].a);
    b.extend(tri_[t].b).extend(tri_[t].c);
    return b;
  };
  fill(
      [&](std::size_t t, auto&& add) {
        const auto b = tri_box(t);
        const auto lo = cell_of(b.min()), hi = cell_of(b.max());
        for (long k = lo[2]; k <= hi[2]; ++k)
          for (long j = lo[1]; j <= hi[1]; ++j)
            for (long i = lo[0]; i <= hi[0]; ++i) add(cell_index(i, j, k));
      },
      static_cast<std::size_t>(n_[0] * n_[1] * n_[2]), start_, ids_);
  fill(
      [&](std::size_t t, auto&& add) {
        const auto b = tri_box(t);
        const auto lo = cell_of(b.min()), hi = cell_of(b.max());
        for (long j = lo[1]; j <= hi[1]; ++j)
          for (long i = lo[0]; i <= hi[0]; ++i) add(j * n2_[0] + i);
      },
      static_cast<std::size_t>(n2_[0] * n2_[1]), start2_, ids2_);
}

std::array<long, 3> Proximity::cell_of(const Vector3d& p) const {
  std::array<long, 3> c{};
  for (int a = 0; a < 3; ++a) {
    const double u = (p[a] - origin_[a]) / h_[a];
    c[a] = u <= 0 ? 0 : std::min(n_[a] - 1, static_cast<long>(u));
  }
  return c;
}

double Proximity::distance(const Vector3d& p, double max_distance_m) const {
  return nearest(p, max_distance_m).distance_m;
}

Proximity::Nearest Proximity::nearest(const Vector3d& p, double max_distance_m) const {
  const auto c0 = cell_of(p);
  double best2 = std::numeric_limits<double>::infinity();
  int best_tri = -1;
  Vector3d best_point = Vector3d::Zero();
  const long kmax = std::max({n_[0], n_[1], n_[2]});
  for (long k = 0; k <= kmax; ++k) {
    std::array<long, 3> lo{}, hi{};
    for (int a = 0; a < 3; ++a) lo[a] = std::max(0L, c0[a] - k), hi[a] = std::min(n_[a] - 1, c0[a] + k);
    // The shell of cells at Chebyshev index distance k from c0 (clipped to the grid).
    auto visit = [&](long i, long j, long kk) {
      const long c = cell_index(i, j, kk);
      for (std::size_t s = start_[c]; s < start_[c + 1]; ++s) {
        const Tri& t = tri_[ids_[s]];
        const Vector3d q = closest_point_on_triangle(p, t.a, t.b, t.c);
        // ties (an edge two triangles share) go to the lower index, whichever cell is searched first
        if (const double d2 = (q - p).squaredNorm(); d2 < best2 || (d2 == best2 && ids_[s] < best_tri))
          best2 = d2, best_tri = ids_[s], best_point = q;
      }
    };
    for (long kk = lo[2]; kk <= hi[2]; ++kk)
      for (long j = lo[1]; j <= hi[1]; ++j) {
        if (std::abs(kk - c0[2]) == k || std::abs(j - c0[1]) == k) {
          for (long i = lo[0]; i <= hi[0]; ++i) visit(i, j, kk);
        } else {  // inside the shell in y and z: only its two x faces
          if (c0[0] - k >= 0) visit(c0[0] - k, j, kk);
          if (k > 0 && c0[0] + k < n_[0]) visit(c0[0] + k, j, kk);
        }
      }
    // Every triangle not yet seen lies in a cell outside the searched block, so at least `bound` from p.
    double bound = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
      if (lo[a] > 0) bound = std::min(bound, std::max(0.0, p[a] - (origin_[a] + double(lo[a]) * h_[a])));
      if (hi[a] < n_[a] - 1)
        bound = std::min(bound, std::max(0.0, origin_[a] + double(hi[a] + 1) * h_[a] - p[a]));
    }
    if (!std::isfinite(bound) || best2 <= bound * bound || bound > max_distance_m) break;
  }
  const double d = std::sqrt(best2);
  if (!(d <= max_distance_m)) return {};
  return {d, best_tri, best_point};
}

bool Proximity::vertical_crossing(const Tri& t, double x, double y, double& z) const {
  const Vector2d p(x, y), a(t.a.x(), t.a.y()), b(t.b.x(), t.b.y()), c(t.c.x(), t.c.y());
  double eab = 0, ebc = 0, eca = 0;
  const int sab = edge_side(a, b, p, eab), sbc = edge_side(b, c, p, ebc), sca = edge_side(c, a, p, eca);
  if (sab == 0 || sab != sbc || sab != sca) return false;
  // Barycentric weights from the (unshifted) edge values; they sum to the projected doubled area.
  const double sum = eab + ebc + eca;
  if (sum == 0) {
    z = (t.a.z() + t.b.z() + t.c.z()) / 3;
  } else {
    z = (ebc * t.a.z() + eca * t.b.z() + eab * t.c.z()) / sum;
  }
  return true;
}

bool Proximity::inside(const Vector3d& p) const {
  if (!closed_ || !bounds_.contains(p)) return false;
  const auto c = cell_of(p);
  const long cell = c[1] * n2_[0] + c[0];
  bool in = false;
  for (std::size_t s = start2_[cell]; s < start2_[cell + 1]; ++s) {
    double z = 0;
    if (vertical_crossing(tri_[ids2_[s]], p.x(), p.y(), z) && z > p.z()) in = !in;
  }
  return in;
}

double Proximity::penetration(const Vector3d& p, double radius_m) const {
  if (!(radius_m > 0) || !p.allFinite()) return 0;
  if (bounds_.exteriorDistance(p) >= radius_m) return 0;  // outside the box: outside the hull and too far
  if (inside(p)) return radius_m + distance(p);
  const double d = distance(p, radius_m);
  return d < radius_m ? radius_m - d : 0;
}

}  // namespace brash::hull
