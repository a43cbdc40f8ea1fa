// Channel packing generator (see brash/packing.hpp for the algorithm and the modes).
#include "brash/packing.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <random>
#include <sstream>
#include <unordered_map>

#include "brash/error.hpp"

namespace fs = std::filesystem;

namespace brash {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kOverlapToleranceOverD = 1e-6;  // stated tolerance; rounding to 1 nm gives ~1e-7
constexpr double kCoordQuantum_m = 1e-9;         // files carry 9 decimals (1 nm)

// Uniform and normal variates from mt19937_64 with our own transforms, so a seed gives the same
// bed with any standard library (std::*_distribution are implementation-defined).
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : g_(seed) {}
  double uniform() { return static_cast<double>(g_() >> 11) * 0x1.0p-53; }  // [0, 1)
  double normal() {  // Box-Muller, second variate cached
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    double u1 = 0;
    while (u1 <= 0) u1 = uniform();
    const double rad = std::sqrt(-2.0 * std::log(u1));
    const double th = 2.0 * kPi * uniform();
    spare_ = rad * std::sin(th);
    has_spare_ = true;
    return rad * std::cos(th);
  }

 private:
  std::mt19937_64 g_;
  double spare_ = 0;
  bool has_spare_ = false;
};

double sample_diameter(Rng& rng, double mean, double sd, double k) {
  if (sd <= 0) return mean;
  for (;;) {
    const double z = rng.normal();
    if (std::abs(z) <= k) return mean + sd * z;
  }
}

double submerged_volume(double z, double r, double level) {
  const double h = std::clamp(level - (z - r), 0.0, 2.0 * r);
  return kPi * h * h * (3.0 * r - h) / 3.0;
}

double quantize(double v) { return std::nearbyint(v / kCoordQuantum_m) * kCoordQuantum_m; }

double max_diameter(const PackingRequest& r) { return r.diameter_mean_m + r.truncation_sd * r.diameter_sd_m; }
double min_diameter(const PackingRequest& r) { return r.diameter_mean_m - r.truncation_sd * r.diameter_sd_m; }

// Columns of the channel seen from above; a cell is at least one largest diameter wide so every
// sphere that can touch a point lies in the 3 x 3 cells around it.
struct Ball {
  double x, y, z, r;
};

class ColumnGrid {
 public:
  ColumnGrid(double length_m, double width_m, double min_cell_m)
      : nx_(std::max(1, static_cast<int>(length_m / min_cell_m))),
        ny_(std::max(1, static_cast<int>(width_m / min_cell_m))),
        cx_(length_m / nx_),
        cy_(width_m / ny_),
        y0_(-0.5 * width_m),
        cells_(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_)) {}

  std::size_t cell_count() const { return cells_.size(); }
  void add(const Ball& b) { cells_[index(ix(b.x), iy(b.y))].push_back(b); }

  // Height of the centre of a sphere of radius r dropped at (x, y) onto the floor and the balls.
  double landing_z(double x, double y, double r) const {
    double z = r;
    const int i0 = ix(x), j0 = iy(y);
    for (int i = std::max(0, i0 - 1); i <= std::min(nx_ - 1, i0 + 1); ++i)
      for (int j = std::max(0, j0 - 1); j <= std::min(ny_ - 1, j0 + 1); ++j)
        for (const Ball& b : cells_[index(i, j)]) {
          const double dx = x - b.x, dy = y - b.y, rr = r + b.r;
          const double h2 = dx * dx + dy * dy, rr2 = rr * rr;
          if (h2 < rr2) z = std::max(z, b.z + std::sqrt(rr2 - h2));
        }
    return z;
  }

  template <class F>
  void for_neighbours(double x, double y, F&& f) const {
    const int i0 = ix(x), j0 = iy(y);
    for (int i = std::max(0, i0 - 1); i <= std::min(nx_ - 1, i0 + 1); ++i)
      for (int j = std::max(0, j0 - 1); j <= std::min(ny_ - 1, j0 + 1); ++j)
        for (const Ball& b : cells_[index(i, j)]) f(b);
  }

 private:
  int ix(double x) const { return std::clamp(static_cast<int>(x / cx_), 0, nx_ - 1); }
  int iy(double y) const { return std::clamp(static_cast<int>((y - y0_) / cy_), 0, ny_ - 1); }
  std::size_t index(int i, int j) const {
    return static_cast<std::size_t>(i) * static_cast<std::size_t>(ny_) + static_cast<std::size_t>(j);
  }
  int nx_, ny_;
  double cx_, cy_, y0_;
  std::vector<std::vector<Ball>> cells_;
};

struct Spot {
  double x, y, z;
};

// Lowest of K random drops, then a pattern search on the landing height (8 directions, step halved
// when none is lower) so the sphere rolls into the pocket it fell near.
Spot find_rest(const ColumnGrid& g, Rng& rng, double r, const PackingRequest& q, int drops) {
  const double xlo = r, xhi = q.length_m - r, ylo = -0.5 * q.width_m + r, yhi = 0.5 * q.width_m - r;
  Spot best{0, 0, std::numeric_limits<double>::infinity()};
  for (int k = 0; k < drops; ++k) {
    const double x = xlo + (xhi - xlo) * rng.uniform();
    const double y = ylo + (yhi - ylo) * rng.uniform();
    const double z = g.landing_z(x, y, r);
    if (z < best.z) best = {x, y, z};
  }
  const double turn = rng.uniform() * kPi / 4;
  double step = r;
  for (int evals = 0; step > 1e-3 * r && evals < 64;) {
    Spot cand = best;
    for (int k = 0; k < 8; ++k, ++evals) {
      const double a = turn + k * kPi / 4;
      const double x = std::clamp(best.x + step * std::cos(a), xlo, xhi);
      const double y = std::clamp(best.y + step * std::sin(a), ylo, yhi);
      const double z = g.landing_z(x, y, r);
      if (z < cand.z) cand = {x, y, z};
    }
    if (cand.z < best.z)
      best = cand;
    else
      step *= 0.5;
  }
  return best;
}

// Vertical shift s so that the submerged caps of the bed moved by s carry its weight (bisection;
// buoyancy decreases monotonically as the bed rises).
double floating_shift(const std::vector<Sphere>& s, const PackingRequest& q) {
  double lo_z = std::numeric_limits<double>::infinity(), hi_z = -lo_z, weight = 0;
  for (const auto& b : s) {
    lo_z = std::min(lo_z, b.z_m - 0.5 * b.diameter_m);
    hi_z = std::max(hi_z, b.z_m + 0.5 * b.diameter_m);
    weight += q.ice_density_kg_m3 * sphere_volume_m3(b.diameter_m);
  }
  auto excess = [&](double shift) {
    double f = -weight;
    for (const auto& b : s) f += q.water_density_kg_m3 * submerged_volume(b.z_m + shift, 0.5 * b.diameter_m, q.water_level_m);
    return f;
  };
  double a = q.water_level_m - hi_z, b = q.water_level_m - lo_z;  // all under / all above water
  for (int it = 0; it < 200 && b - a > 1e-14 * std::max(1.0, std::abs(a)); ++it) {
    const double m = 0.5 * (a + b);
    (excess(m) > 0 ? a : b) = m;
  }
  return 0.5 * (a + b);
}

[[noreturn]] void reject(const PackingRequest& r, const std::string& key, const std::string& msg) {
  throw InputError(fmt::format("{}: key '{}': {}", r.source.empty() ? "packing request" : r.source, key, msg));
}

void write_atomically(const fs::path& file, const std::string& text) {
  if (file.has_parent_path()) fs::create_directories(file.parent_path());
  const fs::path tmp = file.string() + fmt::format(".tmp.{}", ::getpid());
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw InputError(tmp.string() + ": cannot open for writing");
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
    if (!out) throw InputError(tmp.string() + ": write failed");
  }
  fs::rename(tmp, file);
}

}  // namespace

PackingRequest packing_request(const Case& c, const std::string& source) {
  PackingRequest r;
  r.length_m = c.channel.length_m;
  r.width_m = c.channel.width_m;
  r.thickness_m = c.ice.thickness_m;
  r.diameter_mean_m = c.ice.diameter_mean_m;
  r.diameter_sd_m = c.ice.diameter_sd_m;
  r.truncation_sd = c.ice.diameter_truncation_sd;
  r.porosity = c.ice.porosity;
  r.ice_density_kg_m3 = c.ice.density_kg_m3;
  r.water_density_kg_m3 = c.water.density_kg_m3;
  r.water_level_m = c.water.level_m;
  r.mode = c.ice.packing_mode;
  r.seed = c.ice.seed;
  r.source = source;
  return r;
}

void validate_packing_request(const PackingRequest& r) {
  const double dmax = max_diameter(r), dmin = min_diameter(r);
  auto finite_pos = [](double v) { return std::isfinite(v) && v > 0; };
  if (!finite_pos(r.length_m)) reject(r, "channel.length_m", "must be > 0");
  if (!finite_pos(r.width_m)) reject(r, "channel.width_m", "must be > 0");
  if (!finite_pos(r.thickness_m)) reject(r, "ice.thickness_m", "must be > 0");
  if (!finite_pos(r.diameter_mean_m)) reject(r, "ice.diameter_mean_m", "must be > 0");
  if (!(r.porosity > 0 && r.porosity < 1)) reject(r, "ice.porosity", "must be in (0, 1)");
  if (!(dmin > 0)) reject(r, "ice.diameter_sd_m", "mean - truncation_sd * sd must be > 0");
  if (!(r.ice_density_kg_m3 > 0 && r.ice_density_kg_m3 < r.water_density_kg_m3))
    reject(r, "ice.density_kg_m3", "must be > 0 and below the water density (the bed must float)");
  if (r.width_m < dmax)
    reject(r, "channel.width_m",
           fmt::format("channel width {} m is narrower than the largest sphere (d_max = {} m)", r.width_m, dmax));
  if (r.length_m < dmax)
    reject(r, "channel.length_m",
           fmt::format("channel length {} m is shorter than the largest sphere (d_max = {} m)", r.length_m, dmax));
  if (r.drops_per_sphere < 1) reject(r, "drops_per_sphere", "must be >= 1");
  const double target = (1 - r.porosity) * r.length_m * r.width_m * r.thickness_m;
  const double approx_count = target / sphere_volume_m3(r.diameter_mean_m);
  if (approx_count > 3.0e7)
    reject(r, "ice.diameter_mean_m",
           fmt::format("about {:.3g} spheres requested; the generator is limited to 3e7 (memory)", approx_count));
  if (r.mode == PackingMode::StrictTwoLayer) {
    if (r.thickness_m < dmax)
      reject(r, "ice.thickness_m",
             fmt::format("strict_two_layer: thickness {} m is thinner than the largest sphere (d_max = {} m)",
                         r.thickness_m, dmax));
    if (r.thickness_m >= 3 * dmin)
      reject(r, "ice.thickness_m",
             fmt::format("strict_two_layer: thickness {} m would hold three layers (3 d_min = {} m); use "
                         "packing_mode: volume or a thickness near 2 d",
                         r.thickness_m, 3 * dmin));
    // Two layers, each at most a hexagonal monolayer (disc coverage pi / (2 sqrt 3)) of spheres whose
    // volume per disc area is 2 d / 3: solid fraction <= (2 pi / (3 sqrt 3)) d / thickness.
    const double m2 = r.diameter_mean_m * r.diameter_mean_m + r.diameter_sd_m * r.diameter_sd_m;
    const double m3 = r.diameter_mean_m * (r.diameter_mean_m * r.diameter_mean_m + 3 * r.diameter_sd_m * r.diameter_sd_m);
    const double phi_max = std::min(2 * kPi / (3 * std::sqrt(3.0)) * (m3 / m2) / r.thickness_m, kPi / std::sqrt(18.0));
    if (1 - r.porosity > phi_max)
      reject(r, "ice.porosity",
             fmt::format("strict_two_layer: porosity {} (solid fraction {:.4f}) is impossible for two layers of "
                         "d = {} m in {} m: two hexagonal layers reach at most {:.4f} (porosity >= {:.4f}); the "
                         "mode fills to the densest bed it reaches, so ask for porosity >= {:.4f} or use "
                         "packing_mode: volume",
                         r.porosity, 1 - r.porosity, r.diameter_mean_m, r.thickness_m, phi_max, 1 - phi_max,
                         1 - phi_max));
  }
}

double total_buoyancy_N(const std::vector<Sphere>& s, const PackingRequest& r) {
  double v = 0;
  for (const auto& b : s) v += submerged_volume(b.z_m, 0.5 * b.diameter_m, r.water_level_m);
  return r.water_density_kg_m3 * 9.81 * v;
}

double total_weight_N(const std::vector<Sphere>& s, const PackingRequest& r) {
  double v = 0;
  for (const auto& b : s) v += sphere_volume_m3(b.diameter_m);
  return r.ice_density_kg_m3 * 9.81 * v;
}

Packing generate_packing(const PackingRequest& q) {
  validate_packing_request(q);
  const auto t0 = std::chrono::steady_clock::now();
  const double dmax = max_diameter(q);
  const double target = (1 - q.porosity) * q.length_m * q.width_m * q.thickness_m;
  const bool strict = q.mode == PackingMode::StrictTwoLayer;

  Rng rng(q.seed);
  ColumnGrid grid(q.length_m, q.width_m, dmax);
  const std::size_t max_failures = std::max<std::size_t>(2000, grid.cell_count());
  std::vector<Sphere> out;
  out.reserve(static_cast<std::size_t>(1.05 * target / sphere_volume_m3(q.diameter_mean_m)) + 16);
  double volume = 0;
  std::size_t failures = 0;
  double d = sample_diameter(rng, q.diameter_mean_m, q.diameter_sd_m, q.truncation_sd);
  for (;;) {
    const double v = sphere_volume_m3(d);
    // Stop at the count whose volume is closest to the target.
    if (volume + v > target && (volume + v - target) > (target - volume)) break;
    const double r = 0.5 * d;
    const Spot s = find_rest(grid, rng, r, q, q.drops_per_sphere);
    if (strict && s.z + r > q.thickness_m) {
      if (++failures > max_failures) break;  // jammed: no room found for a long time
      continue;                              // same diameter again, so sizes are not biased small
    }
    failures = 0;
    grid.add({s.x, s.y, s.z, r});
    out.push_back({s.x, s.y, s.z, d});
    volume += v;
    d = sample_diameter(rng, q.diameter_mean_m, q.diameter_sd_m, q.truncation_sd);
  }

  // Quantize to what the file holds, then float the bed as a whole.
  for (auto& b : out) b = {quantize(b.x_m), quantize(b.y_m), b.z_m, quantize(b.diameter_m)};
  const double shift = floating_shift(out, q);
  for (auto& b : out) b.z_m = quantize(b.z_m + shift);

  Packing p{std::move(out), {}};
  p.stats = measure_packing(p.spheres, q);
  p.stats.float_shift_m = shift;
  p.stats.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return p;
}

PackingStats measure_packing(const std::vector<Sphere>& s, const PackingRequest& q) {
  PackingStats st;
  st.mode = std::string(to_string(q.mode));
  st.seed = q.seed;
  st.count = s.size();
  st.requested_porosity = q.porosity;
  st.target_ice_volume_m3 = (1 - q.porosity) * q.length_m * q.width_m * q.thickness_m;
  st.overlap_tolerance_over_d = kOverlapToleranceOverD;
  if (s.empty()) return st;

  double sum = 0, sum2 = 0, vol = 0;
  st.d_min_m = std::numeric_limits<double>::infinity();
  st.bottom_z_m = std::numeric_limits<double>::infinity();
  st.top_z_m = -st.bottom_z_m;
  for (const auto& b : s) {
    sum += b.diameter_m;
    vol += sphere_volume_m3(b.diameter_m);
    st.d_min_m = std::min(st.d_min_m, b.diameter_m);
    st.d_max_m = std::max(st.d_max_m, b.diameter_m);
    st.bottom_z_m = std::min(st.bottom_z_m, b.z_m - 0.5 * b.diameter_m);
    st.top_z_m = std::max(st.top_z_m, b.z_m + 0.5 * b.diameter_m);
  }
  const double n = static_cast<double>(s.size());
  st.d_mean_m = sum / n;
  for (const auto& b : s) sum2 += (b.diameter_m - st.d_mean_m) * (b.diameter_m - st.d_mean_m);
  st.d_sd_m = s.size() > 1 ? std::sqrt(sum2 / (n - 1)) : 0.0;
  st.ice_volume_m3 = vol;
  st.ice_volume_per_area_m = vol / (q.length_m * q.width_m);

  // Thickness: bed top = mean over 2 d columns of the highest sphere top (every such column holds a
  // top-layer sphere), bottom = lowest sphere bottom.
  {
    const double cell = 2 * st.d_mean_m;
    const int nx = std::max(1, static_cast<int>(q.length_m / cell));
    const int ny = std::max(1, static_cast<int>(q.width_m / cell));
    std::vector<double> top(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny),
                            -std::numeric_limits<double>::infinity());
    for (const auto& b : s) {
      const int i = std::clamp(static_cast<int>(b.x_m / q.length_m * nx), 0, nx - 1);
      const int j = std::clamp(static_cast<int>((b.y_m + 0.5 * q.width_m) / q.width_m * ny), 0, ny - 1);
      double& t = top[static_cast<std::size_t>(i) * static_cast<std::size_t>(ny) + static_cast<std::size_t>(j)];
      t = std::max(t, b.z_m + 0.5 * b.diameter_m);
    }
    double tsum = 0;
    std::size_t used = 0;
    for (const double t : top)
      if (std::isfinite(t)) tsum += t, ++used;
    // Strict mode: the bed is the slab of the requested thickness by construction.
    st.thickness_m = q.mode == PackingMode::StrictTwoLayer ? q.thickness_m
                                                            : tsum / static_cast<double>(used) - st.bottom_z_m;
    st.porosity = 1 - vol / (q.length_m * q.width_m * st.thickness_m);
    // Interior solid fraction: mean covered area of horizontal sections at least one d away from the
    // floor-side bottom and the mean top (the middle section if the bed is thinner than that).
    const double z0 = st.bottom_z_m + st.d_mean_m, z1 = st.bottom_z_m + st.thickness_m - st.d_mean_m;
    constexpr int kPlanes = 16;
    double covered = 0;
    for (int k = 0; k < kPlanes; ++k) {
      const double zc = z1 > z0 ? z0 + (z1 - z0) * (k + 0.5) / kPlanes : 0.5 * (st.bottom_z_m + st.top_z_m);
      for (const auto& b : s) {
        const double h = b.z_m - zc, r = 0.5 * b.diameter_m;
        if (std::abs(h) < r) covered += kPi * (r * r - h * h);
      }
    }
    st.bulk_solid_fraction = covered / (kPlanes * q.length_m * q.width_m);
    st.equivalent_thickness_m = st.ice_volume_per_area_m / st.bulk_solid_fraction;
  }

  // Overlaps and contacts (pairs found through the column grid), walls.
  {
    ColumnGrid g(q.length_m, q.width_m, std::max(st.d_max_m, 1e-12));
    for (std::size_t i = 0; i < s.size(); ++i)
      g.add({s[i].x_m, s[i].y_m, s[i].z_m, static_cast<double>(i)});  // r carries the index here
    double max_ov = -std::numeric_limits<double>::infinity();
    std::size_t over = 0, contacts = 0;
    const double tol = kOverlapToleranceOverD * st.d_mean_m, touch = 1e-6 * st.d_mean_m;
    for (std::size_t i = 0; i < s.size(); ++i) {
      const Sphere& a = s[i];
      g.for_neighbours(a.x_m, a.y_m, [&](const Ball& nb) {
        const auto j = static_cast<std::size_t>(nb.r);
        if (j <= i) return;
        const Sphere& b = s[j];
        const double dx = a.x_m - b.x_m, dy = a.y_m - b.y_m, dz = a.z_m - b.z_m;
        const double rr = 0.5 * (a.diameter_m + b.diameter_m);
        const double d2 = dx * dx + dy * dy + dz * dz;
        if (d2 > (rr + touch) * (rr + touch)) return;
        const double ov = rr - std::sqrt(d2);
        max_ov = std::max(max_ov, ov);
        if (ov > tol) ++over;
        if (ov > -touch) ++contacts;
      });
    }
    st.max_overlap_over_d = std::isfinite(max_ov) ? max_ov / st.d_mean_m : 0.0;
    st.overlapping_pairs = over;
    st.mean_contacts = 2.0 * static_cast<double>(contacts) / n;
    double wall = -std::numeric_limits<double>::infinity();
    for (const auto& b : s) {
      const double r = 0.5 * b.diameter_m;
      wall = std::max({wall, r - b.x_m, b.x_m + r - q.length_m, b.y_m + r - 0.5 * q.width_m,
                       -0.5 * q.width_m - (b.y_m - r)});
    }
    st.max_wall_overlap_over_d = wall / st.d_mean_m;
  }
  st.buoyancy_N = total_buoyancy_N(s, q);
  st.weight_N = total_weight_N(s, q);
  return st;
}

std::string packing_csv(const Packing& p) {
  const PackingStats& s = p.stats;
  fmt::memory_buffer buf;
  fmt::format_to(std::back_inserter(buf),
                 "# brash-pack mode={} seed={} count={} ice_volume_per_area_m={:.9g} thickness_m={:.9g} "
                 "porosity={:.6f} d_mean_m={:.9g} d_sd_m={:.9g} max_overlap_over_d={:.3g} "
                 "bottom_z_m={:.9g} top_z_m={:.9g} units=m\n",
                 s.mode, s.seed, s.count, s.ice_volume_per_area_m, s.thickness_m, s.porosity, s.d_mean_m, s.d_sd_m,
                 s.max_overlap_over_d, s.bottom_z_m, s.top_z_m);
  fmt::format_to(std::back_inserter(buf), "id,x,y,z,diameter\n");
  for (std::size_t i = 0; i < p.spheres.size(); ++i) {
    const Sphere& b = p.spheres[i];
    fmt::format_to(std::back_inserter(buf), "{},{:.9f},{:.9f},{:.9f},{:.9f}\n", i + 1, b.x_m, b.y_m, b.z_m,
                   b.diameter_m);
  }
  return fmt::to_string(buf);
}

void write_packing_csv(const fs::path& file, const Packing& p) { write_atomically(file, packing_csv(p)); }

std::string packing_json(const PackingStats& s) {
  const nlohmann::ordered_json j = {
      {"mode", s.mode},
      {"seed", s.seed},
      {"count", s.count},
      {"requested_porosity", s.requested_porosity},
      {"target_ice_volume_m3", s.target_ice_volume_m3},
      {"ice_volume_m3", s.ice_volume_m3},
      {"ice_volume_per_area_m", s.ice_volume_per_area_m},
      {"thickness_m", s.thickness_m},
      {"porosity", s.porosity},
      {"bulk_solid_fraction", s.bulk_solid_fraction},
      {"equivalent_thickness_m", s.equivalent_thickness_m},
      {"bottom_z_m", s.bottom_z_m},
      {"top_z_m", s.top_z_m},
      {"d_mean_m", s.d_mean_m},
      {"d_sd_m", s.d_sd_m},
      {"d_min_m", s.d_min_m},
      {"d_max_m", s.d_max_m},
      {"max_overlap_over_d", s.max_overlap_over_d},
      {"overlapping_pairs", s.overlapping_pairs},
      {"overlap_tolerance_over_d", s.overlap_tolerance_over_d},
      {"max_wall_overlap_over_d", s.max_wall_overlap_over_d},
      {"mean_contacts", s.mean_contacts},
      {"buoyancy_N", s.buoyancy_N},
      {"weight_N", s.weight_N},
      {"float_shift_m", s.float_shift_m},
      {"wall_time_s", s.wall_time_s},
  };
  return j.dump(2) + "\n";
}

void write_packing_json(const fs::path& file, const PackingStats& s) { write_atomically(file, packing_json(s)); }

namespace {

// Overlapping spheres in a packing read from a file: the first pair (in file order) whose overlap
// exceeds `tolerance` of the smaller diameter is an error. A DEM engine would start with a huge contact force
// there (the generator's beds overlap by < 1e-6 d). Hash grid, cell = largest d.
void check_no_overlap(const fs::path& file, const std::vector<Sphere>& s, const std::vector<std::size_t>& lines,
                      const std::vector<double>& ids, double tolerance) {
  if (s.size() < 2) return;
  double dmax = 0;
  for (const auto& b : s) dmax = std::max(dmax, b.diameter_m);
  auto cell_of = [dmax](double v) { return static_cast<std::int64_t>(std::floor(v / dmax)); };
  auto key = [](std::int64_t i, std::int64_t j, std::int64_t k) {
    return (static_cast<std::uint64_t>(i) * 73856093u) ^ (static_cast<std::uint64_t>(j) * 19349663u) ^
           (static_cast<std::uint64_t>(k) * 83492791u);
  };
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> grid;
  grid.reserve(s.size());
  for (std::size_t n = 0; n < s.size(); ++n) {
    const auto& a = s[n];
    const auto ci = cell_of(a.x_m), cj = cell_of(a.y_m), ck = cell_of(a.z_m);
    for (std::int64_t di = -1; di <= 1; ++di)
      for (std::int64_t dj = -1; dj <= 1; ++dj)
        for (std::int64_t dk = -1; dk <= 1; ++dk) {
          const auto it = grid.find(key(ci + di, cj + dj, ck + dk));
          if (it == grid.end()) continue;
          for (const std::size_t m : it->second) {
            const auto& b = s[m];
            const double dx = a.x_m - b.x_m, dy = a.y_m - b.y_m, dz = a.z_m - b.z_m;
            const double ov = 0.5 * (a.diameter_m + b.diameter_m) - std::sqrt(dx * dx + dy * dy + dz * dz);
            if (ov > tolerance * std::min(a.diameter_m, b.diameter_m))
              throw InputError(fmt::format(
                  "{}:{}: sphere id {:g} overlaps sphere id {:g} (line {}) by {:.3g} m = {:.3g} of its diameter "
                  "(tolerance {:g}); a packing must not overlap (regenerate it with brash-pack)",
                  file.string(), lines[n], ids[n], ids[m], lines[m], ov, ov / std::min(a.diameter_m, b.diameter_m),
                  tolerance));
          }
        }
    grid[key(ci, cj, ck)].push_back(n);
  }
}

}  // namespace

namespace {

// A packing file's pieces with the line and the id each came from.
struct PackingRows {
  std::vector<Sphere> spheres;
  std::vector<std::size_t> lines;
  std::vector<double> ids;
};

PackingRows read_rows(const fs::path& file, double overlap_tolerance_over_d = kPackingMaxOverlapOverD) {
  if (fs::is_directory(file)) throw InputError(file.string() + ": is a directory, not a packing file");
  std::ifstream in(file);
  if (!in) throw InputError(file.string() + ": cannot open packing file");
  PackingRows rows;
  std::unordered_map<double, std::size_t> id_line;  // id -> the line that gave it first
  std::string line;
  bool header = false;
  for (std::size_t ln = 1; std::getline(in, line); ++ln) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      if (line != "id,x,y,z,diameter")
        throw InputError(fmt::format("{}:{}: expected header 'id,x,y,z,diameter', got '{}'", file.string(), ln, line));
      header = true;
      continue;
    }
    const auto columns = 1 + std::count(line.begin(), line.end(), ',');
    if (columns != 5)
      throw InputError(fmt::format("{}:{}: expected 5 columns (id,x,y,z,diameter), got {} in '{}'{}", file.string(),
                                   ln, columns, line, columns < 5 ? " (truncated line?)" : ""));
    double v[5];
    const char* p = line.data();
    const char* end = line.data() + line.size();
    for (int k = 0; k < 5; ++k) {
      const auto [next, ec] = std::from_chars(p, end, v[k]);
      if (ec != std::errc() || !std::isfinite(v[k]) || (k < 4 && (next == end || *next != ',')) ||
          (k == 4 && next != end))
        throw InputError(fmt::format("{}:{}: column {} is not a finite number in '{}'", file.string(), ln, k + 1, line));
      p = next + 1;
    }
    if (!(v[4] > 0)) throw InputError(fmt::format("{}:{}: diameter must be > 0", file.string(), ln));
    // The engines number the pieces by these ids (particle files, guard messages): one id, one piece.
    if (const auto [at, fresh] = id_line.emplace(v[0] == 0 ? 0.0 : v[0], ln); !fresh)
      throw InputError(fmt::format("{}:{}: piece id {:g} is given twice (first at line {}); ids must be unique",
                                   file.string(), ln, v[0], at->second));
    rows.spheres.push_back({v[1], v[2], v[3], v[4]});
    rows.lines.push_back(ln);
    rows.ids.push_back(v[0]);
  }
  if (!header) throw InputError(file.string() + ": no 'id,x,y,z,diameter' header");
  check_no_overlap(file, rows.spheres, rows.lines, rows.ids, overlap_tolerance_over_d);
  return rows;
}

}  // namespace

std::vector<Sphere> read_packing_csv(const fs::path& file) { return read_rows(file).spheres; }

std::vector<Sphere> read_case_packing(const Case& c, double max_overlap_over_d) {
  const fs::path& file = c.ice.packing_file;
  PackingRows rows = read_rows(file, max_overlap_over_d);
  const double L = c.channel.length_m, half_w = 0.5 * c.channel.width_m, level = c.water.level_m;
  const double above = kPackingMaxBottomAboveWaterOverD * c.ice.diameter_mean_m;
  const double below = kPackingMaxCentreBelowWaterOverThickness * c.ice.thickness_m;
  for (std::size_t n = 0; n < rows.spheres.size(); ++n) {
    const Sphere& b = rows.spheres[n];
    // a settled bed's pieces rest against the walls as against each other: the same overlap is allowed there
    const double r = 0.5 * b.diameter_m,
                 tol = std::max(kPackingChannelToleranceOverD, max_overlap_over_d) * b.diameter_m;
    const auto where = [&] {
      return fmt::format("{}:{}: piece id {:g} (x {:g}, y {:g}, z {:g} m, d {:g} m)", file.string(), rows.lines[n],
                         rows.ids[n], b.x_m, b.y_m, b.z_m, b.diameter_m);
    };
    std::string out;
    if (b.x_m - r < -tol)
      out = fmt::format("x - d/2 = {:g} m < 0", b.x_m - r);
    else if (b.x_m + r > L + tol)
      out = fmt::format("x + d/2 = {:g} m > channel.length_m = {:g} m", b.x_m + r, L);
    else if (std::abs(b.y_m) + r > half_w + tol)
      out = fmt::format("|y| + d/2 = {:g} m > channel.width_m / 2 = {:g} m", std::abs(b.y_m) + r, half_w);
    if (!out.empty())
      throw InputError(fmt::format("{} lies outside the channel [0, {:g}] x [{:g}, {:g}] m: {}; every piece must lie "
                                   "inside it (brash-pack writes the case's packing)",
                                   where(), L, -half_w, half_w, out));
    if (b.z_m - r > level + above)
      throw InputError(fmt::format(
          "{} is far above the water: its bottom is {:g} m above water.level_m = {:g} m, more than {:g} x "
          "ice.diameter_mean_m = {:g} m; a packing's pieces float in the water (brash-pack writes the case's packing)",
          where(), b.z_m - r - level, level, kPackingMaxBottomAboveWaterOverD, above));
    if (b.z_m < level - below)
      throw InputError(fmt::format(
          "{} is far below the water: its centre is {:g} m below water.level_m = {:g} m, more than {:g} x "
          "ice.thickness_m = {:g} m; a packing's pieces float in the water (brash-pack writes the case's packing)",
          where(), level - b.z_m, level, kPackingMaxCentreBelowWaterOverThickness, below));
  }
  return std::move(rows.spheres);
}

}  // namespace brash
