// Particle snapshot reading.
#include <brash/post/particles.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <string_view>

#include <fmt/format.h>

#include <brash/error.hpp>
#include <brash/post/csv.hpp>
#include <brash/post/native_dump.hpp>

namespace brash::post {

std::vector<SnapshotEntry> read_snapshot_index(const std::filesystem::path& dir, bool run_in_progress) {
  static constexpr std::array<std::string_view, 4> kHeader{"step", "t_s", "file", "hull_x_m"};
  const auto path = dir / "index.csv";
  std::vector<SnapshotEntry> out;
  if (!std::filesystem::exists(path)) return out;
  const auto text = read_text_file(path);
  scan_csv(path, text, kHeader, run_in_progress, [&](std::size_t line, std::span<const std::string_view> f) {
    SnapshotEntry e;
    const double step = parse_finite(f[0], path, line, kHeader[0]);
    if (step < 0 || step != std::floor(step))
      throw InputError(fmt::format("{}:{}: column 'step': '{}' is not a non-negative integer", path.string(), line, f[0]));
    e.step = static_cast<long long>(step);
    e.t_s = parse_finite(f[1], path, line, kHeader[1]);
    if (f[2].empty() || f[2].find('/') != std::string_view::npos)
      throw InputError(fmt::format("{}:{}: column 'file': '{}' must be a file name in particles/", path.string(), line, f[2]));
    e.file = dir / std::string(f[2]);
    e.hull_x_m = parse_finite(f[3], path, line, kHeader[3]);
    out.push_back(e);
  });
  return out;
}

namespace {

// The snapshot's pieces in the scene only (state kScene); the state column stays, all kScene.
void keep_scene_pieces(Snapshot& s) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.state[i] != kScene) continue;
    for (auto* c : {&s.x, &s.y, &s.z, &s.radius, &s.vx, &s.vy, &s.vz, &s.submerged_fraction, &s.ca_x, &s.ca_y, &s.ca_z})
      (*c)[n] = (*c)[i];
    s.id[n] = s.id[i];
    s.active[n] = s.active[i];
    s.state[n] = s.state[i];
    if (!s.hull_fx_N.empty())
      for (auto* c : {&s.hull_fx_N, &s.hull_fy_N, &s.hull_fz_N}) (*c)[n] = (*c)[i];
    ++n;
  }
  for (auto* c : {&s.x, &s.y, &s.z, &s.radius, &s.vx, &s.vy, &s.vz, &s.submerged_fraction, &s.ca_x, &s.ca_y, &s.ca_z})
    c->resize(n);
  s.id.resize(n);
  s.active.resize(n);
  s.state.resize(n);
  if (!s.hull_fx_N.empty())
    for (auto* c : {&s.hull_fx_N, &s.hull_fy_N, &s.hull_fz_N}) c->resize(n);
}

}  // namespace

Snapshot read_snapshot(const std::filesystem::path& path, bool run_in_progress, Pieces pieces) {
  // YADE's files and those of older runs end at ca_z; LIGGGHTS' and ODE's have the active column, LIGGGHTS' with
  // the moving window the state column too
  // (and, where the engine writes them, each piece's force on the hull last)
  static constexpr std::array<std::string_view, 14> kHeader{
      "id", "x", "y", "z", "radius", "vx", "vy", "vz", "submerged_fraction", "ca_x", "ca_y", "ca_z", "active", "state"};
  static constexpr std::string_view kHullForce = ",hull_fx_N,hull_fy_N,hull_fz_N";
  const auto text = read_text_file(path);
  auto first_line = std::string_view(text).substr(0, text.find('\n'));
  if (first_line.ends_with('\r')) first_line.remove_suffix(1);
  const bool with_force = first_line.ends_with(kHullForce);
  if (with_force) first_line.remove_suffix(kHullForce.size());
  const bool with_state = first_line.ends_with(",active,state");
  const bool with_active = with_state || first_line.ends_with(",active");
  const std::size_t n_base = with_state ? 14 : with_active ? 13 : 12;
  std::vector<std::string_view> header(kHeader.begin(), kHeader.begin() + static_cast<std::ptrdiff_t>(n_base));
  if (with_force) header.insert(header.end(), {"hull_fx_N", "hull_fy_N", "hull_fz_N"});
  Snapshot s;
  std::array<std::vector<double>*, 11> cols{&s.x, &s.y, &s.z, &s.radius, &s.vx, &s.vy, &s.vz,
                                            &s.submerged_fraction, &s.ca_x, &s.ca_y, &s.ca_z};
  const auto scan = scan_csv(path, text, header, run_in_progress, [&](std::size_t line, std::span<const std::string_view> f) {
    const double id = parse_finite(f[0], path, line, kHeader[0]);
    if (id != std::floor(id)) throw InputError(fmt::format("{}:{}: column 'id': '{}' is not an integer", path.string(), line, f[0]));
    s.id.push_back(static_cast<std::int64_t>(id));
    for (std::size_t c = 0; c < cols.size(); ++c) cols[c]->push_back(parse_finite(f[c + 1], path, line, kHeader[c + 1]));
    if (s.radius.back() <= 0) throw InputError(fmt::format("{}:{}: column 'radius': must be > 0", path.string(), line));
    if (with_force)
      for (std::size_t c = 0; c < 3; ++c)
        (c == 0 ? s.hull_fx_N : c == 1 ? s.hull_fy_N : s.hull_fz_N)
            .push_back(parse_finite(f[n_base + c], path, line, header[n_base + c]));
    if (!with_active) return;
    const double active = parse_finite(f[12], path, line, kHeader[12]);
    if (active != 0 && active != 1)
      throw InputError(fmt::format("{}:{}: column 'active': '{}' is not 0 (idle) or 1 (integrated)", path.string(),
                                   line, f[12]));
    s.active.push_back(static_cast<std::uint8_t>(active));
    if (!with_state) return;
    const double state = parse_finite(f[13], path, line, kHeader[13]);
    if (state != kScene && state != kHeldOut && state != kRemoved)
      throw InputError(fmt::format("{}:{}: column 'state': '{}' is not 0 (in the scene), 1 (held out) or 2 (removed)",
                                   path.string(), line, f[13]));
    s.state.push_back(static_cast<std::uint8_t>(state));
  });
  s.tail_dropped = scan.tail_dropped;
  s.with_hull_force = with_force;
  if (with_state && pieces == Pieces::Scene) keep_scene_pieces(s);
  return s;
}

std::vector<std::size_t> nearest_snapshots(const std::vector<SnapshotEntry>& entries, const std::vector<double>& times_s) {
  std::vector<std::size_t> out;
  if (entries.empty()) return out;
  for (const double t : times_s) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < entries.size(); ++i)
      if (std::abs(entries[i].t_s - t) < std::abs(entries[best].t_s - t)) best = i;
    if (std::find(out.begin(), out.end(), best) == out.end()) out.push_back(best);
  }
  return out;
}

BandCheck check_contact_band(const std::vector<SnapshotEntry>& entries, double band_below_m, double water_level_m,
                             bool run_in_progress) {
  BandCheck b;
  b.band_below_m = band_below_m;
  for (const auto& e : entries) {
    if (!std::filesystem::exists(e.file)) continue;
    const Snapshot s = read_snapshot(e, run_in_progress);
    ++b.snapshots;
    std::size_t below = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      const double depth = water_level_m - (s.z[i] - s.radius[i]);
      if (depth > b.deepest_bottom_m) b.deepest_bottom_m = depth, b.deepest_t_s = e.t_s;
      if (depth > band_below_m) ++below;
    }
    if (below > b.pieces_below_max) b.pieces_below_max = below, b.pieces_below_t_s = e.t_s;
  }
  return b;
}

Snapshot read_snapshot(const SnapshotEntry& entry, bool run_in_progress, Pieces pieces) {
  return entry.native ? read_native_dump(entry.file, entry.water_level_m)
                      : read_snapshot(entry.file, run_in_progress, pieces);
}

}  // namespace brash::post
