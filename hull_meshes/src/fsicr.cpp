// FSICR bow parameters measured on waterline sections of the mesh (conventions in hydrostatics.hpp).
#include <brash/error.hpp>
#include <brash/hull/hydrostatics.hpp>

#include "section.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace brash::hull {
namespace {

using detail::Segment;

constexpr double kDeg = 180.0 / std::numbers::pi;

// Splits segments that cross the centre plane so |y| is linear along each piece.
std::vector<Segment> split_at_centreline(const std::vector<Segment>& in) {
  std::vector<Segment> out;
  for (const auto& s : in) {
    if ((s.a.y() > 0 && s.b.y() < 0) || (s.a.y() < 0 && s.b.y() > 0)) {
      const Eigen::Vector2d m = s.a + s.a.y() / (s.a.y() - s.b.y()) * (s.b - s.a);
      out.push_back({s.a, m});
      out.push_back({m, s.b});
    } else {
      out.push_back(s);
    }
  }
  return out;
}

// Half-breadth at station x: largest |y| of the section there (0 if none).
double half_breadth(const std::vector<Segment>& segs, double x) {
  double y = 0;
  for (const auto& s : segs) {
    const double x0 = std::min(s.a.x(), s.b.x()), x1 = std::max(s.a.x(), s.b.x());
    if (x < x0 || x > x1) continue;
    const double t = x1 > x0 ? (x - s.a.x()) / (s.b.x() - s.a.x()) : 0.0;
    y = std::max({y, std::abs(s.a.y() + t * (s.b.y() - s.a.y())), x1 > x0 ? 0.0 : std::abs(s.b.y())});
  }
  return y;
}

// Most forward x of the section with |y| >= y_min (the buttock at y_min); -inf if none.
double forward_x_with_breadth(const std::vector<Segment>& segs, double y_min) {
  double best = -std::numeric_limits<double>::infinity();
  for (const auto& s : segs) {
    const double ya = std::abs(s.a.y()), yb = std::abs(s.b.y());
    if (ya >= y_min) best = std::max(best, s.a.x());
    if (yb >= y_min) best = std::max(best, s.b.x());
    if ((ya >= y_min) != (yb >= y_min)) best = std::max(best, s.a.x() + (y_min - ya) / (yb - ya) * (s.b.x() - s.a.x()));
  }
  return best;
}

double max_x(const std::vector<Segment>& segs) {
  double best = -std::numeric_limits<double>::infinity();
  for (const auto& s : segs) best = std::max({best, s.a.x(), s.b.x()});
  return best;
}

// Half-breadth sampled every dx from x0 (sections are polylines: fill each segment's span).
std::vector<double> sample_half_breadth(const std::vector<Segment>& segs, double x0, double dx, std::size_t n) {
  std::vector<double> y(n, 0.0);
  for (const auto& s : segs) {
    const double xa = std::min(s.a.x(), s.b.x()), xb = std::max(s.a.x(), s.b.x());
    const auto i0 = static_cast<long>(std::ceil((xa - x0) / dx));
    const auto i1 = static_cast<long>(std::floor((xb - x0) / dx));
    for (long i = std::max(i0, 0L); i <= std::min(i1, static_cast<long>(n) - 1); ++i) {
      const double x = x0 + static_cast<double>(i) * dx;
      const double t = xb > xa ? (x - s.a.x()) / (s.b.x() - s.a.x()) : 0.0;
      y[i] = std::max(y[i], std::abs(s.a.y() + t * (s.b.y() - s.a.y())));
    }
  }
  return y;
}

}  // namespace

FsicrDetail measure_fsicr_detail(const Mesh& mesh, double draft_m, double lpp_m) {
  const double T = draft_m;
  if (lpp_m <= 0) throw InputError(fmt::format("measure_fsicr: Lpp {} m is not positive", lpp_m));
  const double scale = lpp_m / 7.0;  // conventions were set on the 7 m JBC model
  const double dx_diff = 1e-3 * scale, dz = 5e-3 * scale;
  const auto wl = split_at_centreline(detail::section(mesh, T));
  if (wl.empty()) throw InputError(fmt::format("measure_fsicr: the mesh does not cross the waterline z = {} m", T));

  FsicrDetail d;
  FsicrParams& p = d.params;
  double half_b = 0;
  for (const auto& s : wl) half_b = std::max({half_b, std::abs(s.a.y()), std::abs(s.b.y())});
  p.L_m = lpp_m;
  p.B_m = 2 * half_b;
  p.T_m = T;

  // alpha at the B/4 point of the waterline.
  d.x_b4_m = forward_x_with_breadth(wl, p.B_m / 4);
  const double dy = half_breadth(wl, d.x_b4_m - dx_diff) - half_breadth(wl, d.x_b4_m + dx_diff);
  p.alpha_deg = std::atan2(dy, 2 * dx_diff) * kDeg;

  // phi2 (buttock at B/4) and phi1 (stem) from sections at T +- dz.
  const auto lo = split_at_centreline(detail::section(mesh, T - dz));
  const auto hi = split_at_centreline(detail::section(mesh, T + dz));
  p.phi2_deg = std::atan2(2 * dz, forward_x_with_breadth(hi, p.B_m / 4) - forward_x_with_breadth(lo, p.B_m / 4)) * kDeg;
  d.x_stem_m = max_x(wl);
  d.phi1_geometric_deg = std::atan2(2 * dz, max_x(hi) - max_x(lo)) * kDeg;
  double x_fwd_below = -std::numeric_limits<double>::infinity();
  for (const auto& v : mesh.vertices)
    if (v.z() < T - dz) x_fwd_below = std::max(x_fwd_below, v.x());
  // FSICR: bulbous bow -> phi1 = 90. A bulb is a point below T ahead of the stem at T or, at a draft whose
  // waterline cuts the bulb, a stem that recedes going up (geometric phi1 > 90 deg: no stem does that but the top
  // of a bulb).
  d.bulbous_bow = x_fwd_below > d.x_stem_m + 0.01 * lpp_m || d.phi1_geometric_deg > 90;
  p.phi1_deg = d.bulbous_bow ? 90.0 : d.phi1_geometric_deg;
  p.psi_deg = std::atan(std::tan(p.phi2_deg / kDeg) / std::sin(p.alpha_deg / kDeg)) * kDeg;

  // Parallel mid-body: longest run with Y >= B/2 - tol on a fine sampling of the waterline.
  double x_min = std::numeric_limits<double>::infinity();
  for (const auto& s : wl) x_min = std::min({x_min, s.a.x(), s.b.x()});
  const double dx = lpp_m / 70000.0;
  const auto n = static_cast<std::size_t>((d.x_stem_m - x_min) / dx) + 1;
  const auto y = sample_half_breadth(wl, x_min, dx, n);
  const double tol = 1e-5 * p.B_m;
  std::size_t best_i = 0, best_len = 0;
  for (std::size_t i = 0; i < n;) {
    if (y[i] < half_b - tol) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < n && y[j] >= half_b - tol) ++j;
    if (j - i > best_len) best_i = i, best_len = j - i;
    i = j;
  }
  d.x_par_aft_m = x_min + static_cast<double>(best_i) * dx;
  d.x_par_fwd_m = x_min + static_cast<double>(best_i + best_len - 1) * dx;
  p.L_par_m = d.x_par_fwd_m - d.x_par_aft_m;
  p.L_bow_m = d.x_stem_m - d.x_par_fwd_m;
  double area = 0;  // trapezoids from the end of the parallel body to the last sample, then to the stem
  const std::size_t i_end = best_i + best_len - 1;
  for (std::size_t i = i_end; i + 1 < n; ++i) area += 0.5 * (y[i] + y[i + 1]) * dx;
  area += 0.5 * y[n - 1] * (d.x_stem_m - (x_min + static_cast<double>(n - 1) * dx));
  p.A_wf_m2 = 2 * area;
  return d;
}

FsicrParams measure_fsicr(const Mesh& mesh, double draft_m, double lpp_m) {
  return measure_fsicr_detail(mesh, draft_m, lpp_m).params;
}

}  // namespace brash::hull
