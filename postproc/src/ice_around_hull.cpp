// The ice around the hull over the report's window (ice_around_hull.hpp).
#include <brash/post/ice_around_hull.hpp>
#include <brash/post/report.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include <fmt/format.h>

#include <brash/case.hpp>
#include <brash/error.hpp>
#include <brash/hull/flow.hpp>
#include <brash/hull/hydrostatics.hpp>
#include <brash/hull/mesh.hpp>
#include <brash/hull/proximity.hpp>

namespace brash::post {
namespace {

using Eigen::Vector3d;

constexpr int kAheadBands = 8;    // two beams ahead of the stem
constexpr int kBesideBands = 20;  // over the waterline's length
constexpr int kStations = 401;    // the waterline's half-breadth

// The part of triangle (a, b, c) below the plane z = z_max: its area and the x of its centroid (area 0: none).
std::pair<double, double> area_below(const Vector3d& a, const Vector3d& b, const Vector3d& c, double z_max) {
  std::vector<Vector3d> poly;
  const Vector3d v[3] = {a, b, c};
  for (int i = 0; i < 3; ++i) {  // Sutherland-Hodgman against one plane
    const Vector3d& p = v[i];
    const Vector3d& q = v[(i + 1) % 3];
    const bool p_in = p.z() <= z_max, q_in = q.z() <= z_max;
    if (p_in) poly.push_back(p);
    if (p_in != q_in) poly.push_back(p + (q - p) * ((z_max - p.z()) / (q.z() - p.z())));
  }
  double area = 0, x = 0;
  for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
    const double A = 0.5 * (poly[i] - poly[0]).cross(poly[i + 1] - poly[0]).norm();
    area += A;
    x += A * (poly[0].x() + poly[i].x() + poly[i + 1].x()) / 3;
  }
  return {area, area > 0 ? x / area : 0.0};
}

int region_of(double x_m, const std::array<double, 2>& x_par_m) {
  return x_m > x_par_m[1] ? 0 : x_m < x_par_m[0] ? 2 : 1;
}

// The waterline's x extent (the sections of the triangles crossing z = draft) and its half-breadth at stations.
struct Waterline {
  double x_aft_m = 0, x_stem_m = 0;
  std::vector<double> x_m, half_m;
  double half_at(double x) const {
    if (x <= x_m.front() || x >= x_m.back()) return 0;
    const auto it = std::upper_bound(x_m.begin(), x_m.end(), x);
    const auto i = static_cast<std::size_t>(it - x_m.begin());
    const double u = (x - x_m[i - 1]) / (x_m[i] - x_m[i - 1]);
    return half_m[i - 1] + u * (half_m[i] - half_m[i - 1]);
  }
};

Waterline waterline(const hull::Mesh& m, double draft_m) {
  Waterline w;
  w.x_aft_m = INFINITY, w.x_stem_m = -INFINITY;
  for (const auto& f : m.faces)
    for (int e = 0; e < 3; ++e) {
      const Vector3d& p = m.vertices[static_cast<std::size_t>(f[e])];
      const Vector3d& q = m.vertices[static_cast<std::size_t>(f[(e + 1) % 3])];
      if ((p.z() - draft_m) * (q.z() - draft_m) > 0 || p.z() == q.z()) continue;
      const double x = p.x() + (q.x() - p.x()) * (draft_m - p.z()) / (q.z() - p.z());
      w.x_aft_m = std::min(w.x_aft_m, x), w.x_stem_m = std::max(w.x_stem_m, x);
    }
  if (!(w.x_stem_m > w.x_aft_m))
    throw InputError(fmt::format("the hull mesh has no waterline at hull.draft_m = {} m", draft_m));
  for (int i = 0; i < kStations; ++i)
    w.x_m.push_back(w.x_aft_m + (w.x_stem_m - w.x_aft_m) * i / (kStations - 1.0));
  // the end stations lie on the ends' faces: take their neighbours' half-breadth a hair inside
  auto xs = w.x_m;
  const double hair = 1e-6 * (w.x_stem_m - w.x_aft_m);
  xs.front() += hair, xs.back() -= hair;
  const double z[] = {draft_m};
  w.half_m = hull::half_breadths(m, xs, z);
  return w;
}

}  // namespace

IceAroundHull analyze_ice_around_hull(const std::vector<SnapshotEntry>& entries, std::array<double, 2> window_s,
                                      const PostCase& c, const hull::Mesh& mesh, std::array<double, 2> x_par_m,
                                      const std::optional<FsicrBrash>& fsicr, bool run_in_progress) {
  IceAroundHull r;
  r.window_s = window_s;
  r.x_par_m = x_par_m;
  r.draft_m = c.draft_m;
  r.ice_thickness_m = c.ice_thickness_m;
  if (fsicr && c.scale_lambda > 0) {
    r.H_F_fsicr_model_m = fsicr->H_F_m / c.scale_lambda;
    r.H_M_model_m = fsicr->H_M_m / c.scale_lambda;
  }
  const hull::Proximity prox(mesh);
  const Waterline wl = waterline(mesh, c.draft_m);
  const double solid = 1 - c.ice_porosity;
  // the half channel of speedups.symmetry_y holds one side of the hull's ice only
  const double sides = c.symmetry_y ? 1.0 : 2.0;
  const double half_channel = 0.5 * c.channel_width_m;
  const double half_beam = 0.5 * c.beam_m;

  // patches: ahead of the stem over the beam, and a strip beside the waterline on either side
  r.band_m = 0.25 * c.beam_m;
  r.strip_m = 0.25 * c.beam_m;
  const double ahead_width = sides * std::min(half_beam, half_channel);
  const double beside_band = (wl.x_stem_m - wl.x_aft_m) / kBesideBands;
  std::vector<double> ahead_area(kAheadBands, r.band_m * ahead_width), beside_area(kBesideBands);
  for (int k = 0; k < kBesideBands; ++k) {
    const double y0 = wl.half_at(wl.x_aft_m + (k + 0.5) * beside_band);
    beside_area[k] = sides * beside_band * std::max(0.0, std::min(r.strip_m, half_channel - y0));
  }
  std::vector<double> ahead_volume(kAheadBands, 0.0), beside_volume(kBesideBands, 0.0);

  // the wetted surface per region and each triangle's area and outward normal
  const std::size_t nt = mesh.faces.size();
  std::vector<double> tri_area(nt);
  std::vector<Vector3d> tri_normal(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    const auto& f = mesh.faces[t];
    const Vector3d &a = mesh.vertices[static_cast<std::size_t>(f[0])], &b = mesh.vertices[static_cast<std::size_t>(f[1])],
                   &cc = mesh.vertices[static_cast<std::size_t>(f[2])];
    const Vector3d n = (b - a).cross(cc - a);
    tri_area[t] = 0.5 * n.norm();
    tri_normal[t] = n.norm() > 0 ? Vector3d(n.normalized()) : Vector3d::Zero();
    const auto [wet, x] = area_below(a, b, cc, c.draft_m);
    if (wet > 0) r.wetted_area_m2[static_cast<std::size_t>(region_of(x, x_par_m))] += wet;
  }
  for (const double A : r.wetted_area_m2) r.wetted_area_all_m2 += A;
  std::vector<double> tri_cover(nt, 0.0), tri_push(nt, 0.0);
  bool forces = true;

  std::array<double, 3> cover_sum{};
  double cover_all_sum = 0, touching = 0, on_bottom = 0, below_keel = 0;
  const double keel_z = c.water_level_m - c.draft_m;  // channel frame
  for (const auto& e : entries) {
    if (e.t_s < window_s[0] - 1e-9 || e.t_s > window_s[1] + 1e-9 || !std::filesystem::exists(e.file)) continue;
    const Snapshot s = read_snapshot(e, run_in_progress);
    ++r.snapshots;
    forces = forces && s.with_hull_force;
    std::array<double, 3> cover{};
    double deepest = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      const double rad = s.radius[i], vol = 4.0 / 3.0 * std::numbers::pi * rad * rad * rad;
      const Vector3d p(s.x[i] - e.hull_x_m, s.y[i], s.z[i] - c.water_level_m + c.draft_m);  // hull frame
      const double ay = std::abs(s.y[i]);
      // thickness patches (by the centre)
      if (const double ahead = p.x() - wl.x_stem_m; ahead >= 0 && ay < half_beam) {
        if (const auto k = static_cast<int>(ahead / r.band_m); k < kAheadBands) ahead_volume[k] += vol;
      } else if (p.x() >= wl.x_aft_m && p.x() < wl.x_stem_m) {
        const double y0 = wl.half_at(p.x());
        if (ay >= y0 && ay < y0 + r.strip_m)
          beside_volume[std::min(kBesideBands - 1, static_cast<int>((p.x() - wl.x_aft_m) / beside_band))] += vol;
      }
      // below the keel within the hull's plan
      if (const double below = keel_z - (s.z[i] - rad);
          below > 0 && ay < half_beam && p.x() >= prox.bounds().min().x() && p.x() <= prox.bounds().max().x()) {
        below_keel += 1;
        r.below_keel_deepest_m = std::max(r.below_keel_deepest_m, below);
      }
      // touching the hull
      const double reach = rad * (1 + kContactTolerance);
      if (prox.bounds().exteriorDistance(p) > reach) continue;
      auto near = prox.nearest(p, reach);
      if (near.triangle < 0 && prox.inside(p)) near = prox.nearest(p);
      if (near.triangle < 0) continue;
      const auto t = static_cast<std::size_t>(near.triangle);
      const double section = std::numbers::pi * rad * rad;
      touching += 1;
      tri_cover[t] += section;
      if (tri_normal[t].z() < kBottomNormalZ) on_bottom += 1;
      if (forces) tri_push[t] -= tri_normal[t].dot(Vector3d(s.hull_fx_N[i], s.hull_fy_N[i], s.hull_fz_N[i]));
      deepest = std::max(deepest, c.water_level_m - (s.z[i] - rad));
      if (near.point.z() <= c.draft_m) cover[static_cast<std::size_t>(region_of(near.point.x(), x_par_m))] += section;
    }
    double all = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      all += cover[k];
      if (r.wetted_area_m2[k] > 0) cover_sum[k] += std::min(1.0, cover[k] / r.wetted_area_m2[k]);
    }
    if (r.wetted_area_all_m2 > 0) cover_all_sum += std::min(1.0, all / r.wetted_area_all_m2);
    r.deepest_touching_mean_m += deepest;
    r.deepest_touching_max_m = std::max(r.deepest_touching_max_m, deepest);
  }
  if (r.snapshots == 0)
    throw InputError(fmt::format("no particle snapshot in the window [{:.3f}, {:.3f}] s", window_s[0], window_s[1]));
  const double n = static_cast<double>(r.snapshots);
  for (int k = 0; k < kAheadBands; ++k)
    r.ahead.push_back({k * r.band_m, (k + 1) * r.band_m, ahead_volume[k] / (n * ahead_area[k] * solid)});
  for (int k = 0; k < kBesideBands; ++k)
    r.beside.push_back({wl.x_aft_m + k * beside_band, wl.x_aft_m + (k + 1) * beside_band,
                        beside_area[k] > 0 ? beside_volume[k] / (n * beside_area[k] * solid) : 0.0});
  r.H_F_measured_m = r.ahead.front().thickness_m;
  for (std::size_t k = 0; k < 3; ++k) r.contact_fraction[k] = cover_sum[k] / n;
  r.contact_fraction_all = cover_all_sum / n;
  r.touching_pieces_mean = touching / n;
  r.on_bottom_share = touching > 0 ? on_bottom / touching : 0.0;
  r.deepest_touching_mean_m /= n;
  r.below_keel_pieces_mean = below_keel / n;
  r.triangle_contact_fraction.resize(nt);
  for (std::size_t t = 0; t < nt; ++t)
    r.triangle_contact_fraction[t] = tri_area[t] > 0 ? tri_cover[t] / (n * tri_area[t]) : 0.0;
  if (forces) {
    r.triangle_pressure_Pa.resize(nt);
    for (std::size_t t = 0; t < nt; ++t)
      r.triangle_pressure_Pa[t] = tri_area[t] > 0 ? tri_push[t] / (n * tri_area[t]) : 0.0;
  } else {
    r.pressure_missing =
        "the particle snapshots carry no force of each piece on the hull (columns hull_fx_N, hull_fy_N, hull_fz_N: "
        "LIGGGHTS runs write them; brash-ode, YADE and LIGGGHTS runs from before them do not), so hull.vtu holds the "
        "touched share alone";
  }
  return r;
}

}  // namespace brash::post

namespace brash::post {

void add_ice_around_hull(RunAnalysis& a, const std::vector<SnapshotEntry>& entries) {
  const auto& w = a.window.used_s;
  const auto in_window = std::count_if(entries.begin(), entries.end(), [&](const SnapshotEntry& e) {
    return e.t_s >= w[0] - 1e-9 && e.t_s <= w[1] + 1e-9 && std::filesystem::exists(e.file);
  });
  if (entries.empty()) {
    a.ice_around_missing = "the run has no particle snapshots (no particles/index.csv, no LIGGGHTS dump file)";
    return;
  }
  if (in_window == 0) {
    a.ice_around_missing = fmt::format("no particle snapshot lies in the window [{:.3f}, {:.3f}] s", w[0], w[1]);
    return;
  }
  hull::Mesh mesh;
  try {
    mesh = hull::read_mesh(a.case_.hull_file);
  } catch (const std::exception& e) {
    a.ice_around_missing = fmt::format("the hull mesh could not be read ({})", e.what());
    return;
  }
  std::array<double, 2> x_par{-INFINITY, INFINITY};
  std::string regions_note;
  if (a.meta.hull_split_par_m) {
    x_par = *a.meta.hull_split_par_m;
  } else {
    try {
      const auto d = hull::measure_fsicr_detail(mesh, a.case_.draft_m, a.case_.lpp_m);
      x_par = {d.x_par_aft_m, d.x_par_fwd_m};
    } catch (const std::exception& e) {
      regions_note = fmt::format("the parallel mid-body could not be measured ({}): the whole hull counts as the "
                                 "mid-body",
                                 e.what());
    }
  }
  std::optional<FsicrBrash> fsicr;
  if (const auto& r = a.fsicr.result) {
    fsicr = FsicrBrash{r->H_F_m, r->H_M_m};
  } else if (a.case_.beam_m > 0) {
    const double H_M = h_m_for_ice_class(parse_ice_class(a.case_.ice_class));
    fsicr = FsicrBrash{FsicrConstants{}.HF_offset_m + std::sqrt(a.case_.beam_m * a.case_.scale_lambda * H_M), H_M};
  }
  try {
    a.ice_around = analyze_ice_around_hull(entries, w, a.case_, mesh, x_par, fsicr, a.meta.in_progress());
  } catch (const InputError& e) {
    a.ice_around_missing = e.what();
    return;
  }
  if (!regions_note.empty()) a.ice_around->notes.push_back(regions_note);
  a.ice_around_missing.clear();
}

}  // namespace brash::post
