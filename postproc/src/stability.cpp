// Stability analysis of a run directory (see brash/post/stability.hpp).
#include "brash/post/stability.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <brash/case.hpp>
#include <brash/error.hpp>
#include <brash/hull/mesh.hpp>
#include <brash/hull/proximity.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <unordered_map>

#include "brash/post/force_history.hpp"
#include "brash/post/particles.hpp"
#include "brash/post/run_meta.hpp"

namespace fs = std::filesystem;

namespace brash::post {

namespace {

constexpr double kPi = std::numbers::pi;

// Largest r_i + r_j - |x_i - x_j| / (r_i + r_j) over all pairs of one snapshot: uniform cell grid of side
// 2 r_max, each piece tested against the pieces of its own and the 13 "forward" neighbour cells.
struct OverlapMax {
  double value = 0;
  std::size_t i = 0, j = 0;
};
OverlapMax max_pair_overlap(const Snapshot& s) {
  OverlapMax best;
  const std::size_t n = s.size();
  if (n < 2) return best;
  const double rmax = *std::max_element(s.radius.begin(), s.radius.end());
  const double h = 2 * rmax;
  double lo[3] = {s.x[0], s.y[0], s.z[0]};
  for (std::size_t i = 0; i < n; ++i)
    lo[0] = std::min(lo[0], s.x[i]), lo[1] = std::min(lo[1], s.y[i]), lo[2] = std::min(lo[2], s.z[i]);
  auto key = [&](long a, long b, long c) { return (a * 1000003L + b) * 1000033L + c; };
  auto cell = [&](double v, int k) { return static_cast<long>(std::floor((v - lo[k]) / h)); };
  std::unordered_map<long, std::vector<std::size_t>> grid;
  grid.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    grid[key(cell(s.x[i], 0), cell(s.y[i], 1), cell(s.z[i], 2))].push_back(i);
  for (std::size_t i = 0; i < n; ++i) {
    const long a = cell(s.x[i], 0), b = cell(s.y[i], 1), c = cell(s.z[i], 2);
    for (long da = -1; da <= 1; ++da)
      for (long db = -1; db <= 1; ++db)
        for (long dc = -1; dc <= 1; ++dc) {
          const auto it = grid.find(key(a + da, b + db, c + dc));
          if (it == grid.end()) continue;
          for (const std::size_t j : it->second) {
            if (j <= i) continue;
            const double dx = s.x[i] - s.x[j], dy = s.y[i] - s.y[j], dz = s.z[i] - s.z[j];
            const double sum = s.radius[i] + s.radius[j];
            const double ov = (sum - std::sqrt(dx * dx + dy * dy + dz * dz)) / sum;
            if (ov > best.value) best = {ov, i, j};
          }
        }
  }
  return best;
}

bool all_finite(const Snapshot& s) {
  for (const auto* col : {&s.x, &s.y, &s.z, &s.vx, &s.vy, &s.vz})
    for (const double v : *col)
      if (!std::isfinite(v)) return false;
  return true;
}

// The closed hull to test penetration against: the run's hull_full.stl (written with a band or half hull),
// else the case's hull file (the full STL). nullptr with a note when there is none.
std::unique_ptr<hull::Proximity> load_full_hull(const fs::path& run_dir, const Case& c,
                                                std::vector<std::string>& notes) {
  for (const fs::path& f : {run_dir / "hull_full.stl", c.hull.file}) {
    if (f.empty() || !fs::exists(f)) continue;
    try {
      auto p = std::make_unique<hull::Proximity>(hull::read_mesh(f));
      if (!p->closed()) {
        notes.push_back(fmt::format("hull {} is not closed: hull penetration not measured", f.string()));
        return nullptr;
      }
      return p;
    } catch (const std::exception& e) {
      notes.push_back(fmt::format("hull {}: {}", f.string(), e.what()));
      return nullptr;
    }
  }
  notes.push_back("no hull file found (hull_full.stl or the case's hull): hull penetration not measured");
  return nullptr;
}

// Work of the hull on the ice from t = 0 to each requested time: integral of -fx U dt (trapezoids).
std::vector<double> hull_work(const ForceHistory& f, double speed_m_s, const std::vector<double>& times) {
  std::vector<double> out;
  for (const double t : times) {
    double w = 0;
    for (std::size_t k = 1; k < f.t_s.size() && f.t_s[k - 1] < t; ++k) {
      const double t1 = std::min(f.t_s[k], t);
      const double fx1 =
          f.fx_N[k - 1] + (f.fx_N[k] - f.fx_N[k - 1]) * (t1 - f.t_s[k - 1]) / (f.t_s[k] - f.t_s[k - 1]);
      w += -0.5 * (f.fx_N[k - 1] + fx1) * (t1 - f.t_s[k - 1]) * speed_m_s;
    }
    out.push_back(w);
  }
  return out;
}

}  // namespace

double submerged_volume_integral_m4(double r, double h) {
  if (h <= 0) return 0;
  if (h >= 2 * r) return 4 * kPi * std::pow(r, 4) / 3 + 4 * kPi * std::pow(r, 3) / 3 * (h - 2 * r);
  return kPi / 3 * (r * h * h * h - h * h * h * h / 4);
}

std::string guard_of_message(const std::string& reason) {
  static const std::pair<const char*, const char*> kinds[] = {
      {"non-finite", "nan"},        {"left the box", "box"},
      {"above zmax", "zmax"},       {"runaway kinetic energy", "kinetic_energy"},
      {"hull penetration", "hull"}, {"Rayleigh time", "timestep"}};
  for (const auto& [text, kind] : kinds)
    if (reason.find(text) != std::string::npos) return kind;
  return "";
}

StabilityResult analyze_stability(const fs::path& run_dir, const StabilityOptions& opt) {
  StabilityResult r;
  const Case c = load_case(run_dir / "case.yaml");
  RunMeta meta;
  try {
    meta = read_run_meta(run_dir / "meta.json");
  } catch (const std::exception& e) {
    r.notes.push_back(fmt::format("meta.json: {}", e.what()));
    meta.status = "running";  // unknown end: treated as a crash below
  }
  r.engine = meta.engine;
  r.treatment = meta.treatment;
  r.dt_s = meta.dt_s;
  r.message = meta.reason;
  if (meta.status == "complete") {
    r.status = "complete";
  } else if (meta.status == "failed" && !guard_of_message(meta.reason).empty()) {
    r.status = "guard";
    r.guard = guard_of_message(meta.reason);
  } else {
    r.status = "crashed";
    if (meta.status != "failed")
      r.message = fmt::format("run did not finish (meta.json status '{}')", meta.status);
  }
  const bool tolerant = r.status != "complete";  // partial last lines are expected after a crash

  const double L = c.water.level_m, g = c.water.gravity_m_s2, rho_w = c.water.density_kg_m3;
  const double rho_i = c.ice.density_kg_m3, U = c.ship.speed_m_s, half_w = c.channel.width_m / 2;
  r.above_water_m = opt.above_water_m.value_or(2 * c.ice.thickness_m);
  const auto prox = load_full_hull(run_dir, c, r.notes);
  if (prox) r.max_hull_penetration_d = 0.0;

  std::vector<SnapshotEntry> entries;
  try {
    entries = read_snapshot_index(run_dir / "particles", tolerant);
  } catch (const std::exception& e) {
    r.notes.push_back(fmt::format("particles/index.csv: {}", e.what()));
  }
  std::vector<double> times, energy;
  double mass_sum = 0;
  for (const auto& e : entries) {
    if (!fs::exists(e.file)) {
      r.notes.push_back(fmt::format("snapshot {} missing", e.file.filename().string()));
      continue;
    }
    Snapshot s;
    try {
      s = read_snapshot(e.file, tolerant);
    } catch (const std::exception& ex) {  // NaN/Inf are refused by the strict reader
      ++r.non_finite_snapshots;
      r.notes.push_back(fmt::format("snapshot {} unreadable: {}", e.file.filename().string(), ex.what()));
      continue;
    }
    if (!all_finite(s)) {
      ++r.non_finite_snapshots;
      continue;
    }
    ++r.snapshots;
    r.t_last_s = e.t_s;
    r.pieces = std::max(r.pieces, s.size());
    const Eigen::Vector3d origin(e.hull_x_m, 0.0, L - c.hull.draft_m);
    std::size_t escaped = 0, above = 0;
    double E = 0, m_sum = 0, d_sum = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      const double rad = s.radius[i], d = 2 * rad;
      d_sum += d;
      if (prox) {
        const double pen = prox->penetration(Eigen::Vector3d(s.x[i], s.y[i], s.z[i]) - origin, rad) / d;
        if (pen > *r.max_hull_penetration_d)
          r.max_hull_penetration_d = pen, r.max_penetration_piece = s.id[i], r.max_penetration_t_s = e.t_s;
      }
      if (std::abs(s.y[i]) > half_w) ++escaped;
      if (s.z[i] - L > r.above_water_m) ++above;
      const double V = 4 * kPi * rad * rad * rad / 3, m = rho_i * V;
      const double h = std::clamp(L - (s.z[i] - rad), 0.0, 2 * rad);
      const double v_sub = kPi * h * h * (3 * rad - h) / 3;
      const double depth = L - (s.z[i] - rad);  // may exceed 2r (deeper than just submerged)
      E += 0.5 * ((m + rho_w * v_sub * s.ca_x[i]) * s.vx[i] * s.vx[i] +
                  (m + rho_w * v_sub * s.ca_y[i]) * s.vy[i] * s.vy[i] +
                  (m + rho_w * v_sub * s.ca_z[i]) * s.vz[i] * s.vz[i]);
      E += m * g * (s.z[i] - L) + rho_w * g * submerged_volume_integral_m4(rad, depth);
      m_sum += m;
    }
    if (s.size() > 0) {
      const double dmean = d_sum / static_cast<double>(s.size());
      for (std::size_t i = 0; i < s.size(); ++i)
        r.max_height_above_water_d = std::max(r.max_height_above_water_d, (s.z[i] - L) / dmean);
      mass_sum = m_sum;
    }
    r.escaped_max = std::max(r.escaped_max, escaped);
    r.above_water_max = std::max(r.above_water_max, above);
    const auto ov = max_pair_overlap(s);
    if (ov.value > r.max_overlap_d)
      r.max_overlap_d = ov.value, r.max_overlap_pieces[0] = s.id[ov.i], r.max_overlap_pieces[1] = s.id[ov.j],
      r.max_overlap_t_s = e.t_s;
    times.push_back(e.t_s);
    energy.push_back(E);
  }
  if (entries.empty()) r.notes.push_back("no particle snapshots");

  if (!energy.empty()) {
    r.energy_first_J = energy.front();
    r.energy_last_J = energy.back();
    r.energy_ref_J = 0.5 * mass_sum * U * U;
    try {
      const auto f = read_force_history(run_dir / "hull_force.csv", tolerant);
      const auto w = hull_work(f, U, times);
      if (!f.t_s.empty() && f.t_s.back() + 1e-9 < times.back())
        r.notes.push_back(fmt::format("hull_force.csv ends at {} s, before the last snapshot ({} s)",
                                      f.t_s.back(), times.back()));
      r.work_hull_J = w.back();
      double ex = -std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < energy.size(); ++k) ex = std::max(ex, energy[k] - energy.front() - w[k]);
      if (r.energy_ref_J > 0) r.energy_excess = ex / r.energy_ref_J;
    } catch (const std::exception& e) {
      r.notes.push_back(fmt::format("hull_force.csv: {}: no energy balance", e.what()));
    }
  }

  // Verdict.
  if (r.status == "complete") {
    auto& why = r.silent_reasons;
    if (r.max_hull_penetration_d && *r.max_hull_penetration_d > opt.silent_penetration_d)
      why.push_back(fmt::format("hull penetration {:.3g} d > {:g} d (piece {} at t = {:g} s)",
                                *r.max_hull_penetration_d, opt.silent_penetration_d, r.max_penetration_piece,
                                r.max_penetration_t_s));
    if (r.max_overlap_d > opt.silent_overlap_d)
      why.push_back(fmt::format("sphere overlap {:.3g} d > {:g} d (pieces {}, {} at t = {:g} s)",
                                r.max_overlap_d, opt.silent_overlap_d, r.max_overlap_pieces[0],
                                r.max_overlap_pieces[1], r.max_overlap_t_s));
    if (r.escaped_max > 0) why.push_back(fmt::format("{} piece(s) beyond the channel walls", r.escaped_max));
    if (r.above_water_max > 0)
      why.push_back(
          fmt::format("{} piece(s) more than {:g} m above the water", r.above_water_max, r.above_water_m));
    if (r.non_finite_snapshots > 0)
      why.push_back(fmt::format("{} snapshot(s) with NaN/Inf", r.non_finite_snapshots));
    if (r.energy_excess && *r.energy_excess > opt.silent_energy_excess)
      why.push_back(fmt::format("energy created: E - E0 - W = {:.3g} x N 1/2 m U^2 > {:g}", *r.energy_excess,
                                opt.silent_energy_excess));
    if (r.snapshots == 0) why.push_back("no readable particle snapshot");
    r.verdict = why.empty() ? "stable" : "silent";
  } else {
    r.verdict = r.status;
  }
  return r;
}

nlohmann::json stability_json(const StabilityResult& r) {
  auto opt = [](const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); };
  return {{"status", r.status},
          {"guard", r.guard},
          {"message", r.message},
          {"verdict", r.verdict},
          {"silent_reasons", r.silent_reasons},
          {"engine", r.engine},
          {"treatment", r.treatment},
          {"dt_s", opt(r.dt_s)},
          {"snapshots", r.snapshots},
          {"pieces", r.pieces},
          {"t_last_s", r.t_last_s},
          {"max_hull_penetration_d", opt(r.max_hull_penetration_d)},
          {"max_penetration_piece", r.max_penetration_piece},
          {"max_penetration_t_s", r.max_penetration_t_s},
          {"max_overlap_d", r.max_overlap_d},
          {"max_overlap_pieces", {r.max_overlap_pieces[0], r.max_overlap_pieces[1]}},
          {"max_overlap_t_s", r.max_overlap_t_s},
          {"escaped_max", r.escaped_max},
          {"above_water_max", r.above_water_max},
          {"above_water_m", r.above_water_m},
          {"max_height_above_water_d", r.max_height_above_water_d},
          {"non_finite_snapshots", r.non_finite_snapshots},
          {"energy_first_J", r.energy_first_J},
          {"energy_last_J", r.energy_last_J},
          {"work_hull_J", opt(r.work_hull_J)},
          {"energy_ref_J", r.energy_ref_J},
          {"energy_excess", opt(r.energy_excess)},
          {"notes", r.notes}};
}

}  // namespace brash::post
