// brash-ode's check of a packing before a run: overlaps an ODE scene would explode on.
#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <unordered_map>

#include "brash/case.hpp"
#include "brash/core/far_field.hpp"
#include "brash/error.hpp"
#include "ode_internal.hpp"

namespace brash::ode {
namespace fs = std::filesystem;

// Line number (1-based) of each data row of a packing CSV (rows after '#' lines and the header).
std::vector<int> packing_lines(const fs::path& file) {
  std::ifstream in(file);
  std::vector<int> lines;
  std::string s;
  int ln = 0;
  bool header = false;
  while (std::getline(in, s)) {
    ++ln;
    if (s.empty() || s[0] == '#') continue;
    if (!header) {
      header = true;
      continue;
    }
    lines.push_back(ln);
  }
  return lines;
}

// Overlaps beyond tol (m) between spheres and through the side walls; InputError naming file and lines. Returns the
// largest overlap (m, 0 when none), of two spheres or of a sphere and a side wall.
double check_packing(const std::vector<Sphere>& s, const fs::path& file, double tol, double half_width) {
  const auto lines = packing_lines(file);
  auto where = [&](std::size_t i) {
    return fmt::format("{}:{}", file.string(), i < lines.size() ? lines[i] : static_cast<int>(i) + 1);
  };
  double dmax = 0, largest = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto& p = s[i];
    if (!std::isfinite(p.x_m) || !std::isfinite(p.y_m) || !std::isfinite(p.z_m) || !std::isfinite(p.diameter_m) ||
        !(p.diameter_m > 0))
      throw InputError(fmt::format("{}: sphere {} has a non-finite position or a non-positive diameter", where(i), i + 1));
    if (std::abs(p.y_m) + 0.5 * p.diameter_m > half_width + tol)
      throw InputError(fmt::format("{}: sphere {} (y {:.6g} m, d {:.6g} m) pokes {:.3g} m through a side wall at |y| = {:.6g} m",
                                   where(i), i + 1, p.y_m, p.diameter_m,
                                   std::abs(p.y_m) + 0.5 * p.diameter_m - half_width, half_width));
    dmax = std::max(dmax, p.diameter_m);
    largest = std::max(largest, std::abs(p.y_m) + 0.5 * p.diameter_m - half_width);
  }
  // Uniform grid with cell = d_max: neighbours are in the 27 surrounding cells.
  auto key = [&](long a, long b, long c) { return (a * 73856093L) ^ (b * 19349663L) ^ (c * 83492791L); };
  std::unordered_multimap<long, std::size_t> grid;
  grid.reserve(s.size() * 2);
  auto cell = [&](double v) { return static_cast<long>(std::floor(v / dmax)); };
  for (std::size_t i = 0; i < s.size(); ++i) grid.emplace(key(cell(s[i].x_m), cell(s[i].y_m), cell(s[i].z_m)), i);
  std::vector<std::string> bad;
  std::size_t nbad = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const long cx = cell(s[i].x_m), cy = cell(s[i].y_m), cz = cell(s[i].z_m);
    for (long a = -1; a <= 1; ++a)
      for (long b = -1; b <= 1; ++b)
        for (long c = -1; c <= 1; ++c) {
          auto [lo, hi] = grid.equal_range(key(cx + a, cy + b, cz + c));
          for (auto it = lo; it != hi; ++it) {
            const std::size_t j = it->second;
            if (j <= i) continue;
            const double dx = s[i].x_m - s[j].x_m, dy = s[i].y_m - s[j].y_m, dz = s[i].z_m - s[j].z_m;
            const double overlap = 0.5 * (s[i].diameter_m + s[j].diameter_m) - std::sqrt(dx * dx + dy * dy + dz * dz);
            largest = std::max(largest, overlap);
            if (overlap > tol) {
              ++nbad;
              if (bad.size() < 5)
                bad.push_back(fmt::format("{} and line {}: spheres {} and {} overlap by {:.3g} m", where(i),
                                          j < lines.size() ? lines[j] : static_cast<int>(j) + 1, i + 1, j + 1, overlap));
            }
          }
        }
  }
  if (nbad) {
    std::string msg = fmt::format("{}: {} overlapping sphere pairs (tolerance {:.3g} m); an overlapping packing "
                                  "explodes in ODE. First ones:",
                                  file.string(), nbad, tol);
    for (const auto& b : bad) msg += "\n  " + b;
    throw InputError(msg);
  }
  return largest;
}

}  // namespace brash::ode
