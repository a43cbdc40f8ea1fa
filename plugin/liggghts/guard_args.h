// Arguments of fix brash/guard (see fix_brash_guard.h for the syntax), parsed without LIGGGHTS so the
// parser can be unit-tested and fuzzed on its own. Header-only; throws brash::InputError.
#pragma once
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "brash/error.hpp"

namespace brash::liggghts {

struct GuardConfig {
  long every = 0;                                // check every N steps (>= 1)
  std::optional<std::array<double, 6>> box;      // xlo xhi ylo yhi zlo zhi: atoms must stay inside
  std::optional<double> z_max_m;                 // atoms must stay below (centre z)
  std::optional<double> ke_max_J;                // kinetic energy per atom (translation + rotation)
  std::optional<double> youngs_modulus_pa;       // contact time-step check (Rayleigh time)
  double poisson_ratio = 0.3;
  std::optional<double> density_kg_m3;           // default: each atom's own density
  std::optional<double> r_min_m;                 // default: each atom's own radius
  double max_dt_fraction = 0.3;                  // largest accepted dt / T_R
  // Hull penetration: the full closed hull (STL, its own frame) whose frame origin is at hull_origin_m at
  // time 0 and moves at hull_velocity_m_s; stop when a sphere overlaps it by more than
  // max_penetration x its diameter.
  std::string hull_file;                         // empty = no hull guard
  std::array<double, 3> hull_origin_m{};
  std::array<double, 3> hull_velocity_m_s{};
  std::optional<double> max_penetration;         // default 0.5 (centre on the surface) when hull is given
};

namespace guard_detail {

[[noreturn]] inline void fail(const std::string& what) { throw InputError("fix brash/guard: " + what); }

inline double number(const std::string& key, const std::string& text) {
  const char* s = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(s, &end);
  if (end == s || *end != '\0') fail("keyword '" + key + "' expects a number, got '" + text + "'");
  if (!std::isfinite(v) || errno == ERANGE) fail("keyword '" + key + "' expects a finite number, got '" + text + "'");
  return v;
}

}  // namespace guard_detail

// `args` are the words after "fix ID group brash/guard".
inline GuardConfig parse_guard_args(const std::vector<std::string>& args) {
  using guard_detail::fail;
  using guard_detail::number;
  GuardConfig c;
  bool have_every = false;
  for (std::size_t i = 0; i < args.size();) {
    const std::string& key = args[i];
    auto need = [&](std::size_t n) {
      if (i + n >= args.size()) fail("keyword '" + key + "' needs " + std::to_string(n) + " value(s)");
    };
    auto num = [&](std::size_t k) { return number(key, args[i + k]); };
    auto positive = [&](double v) {
      if (!(v > 0)) fail("keyword '" + key + "' must be > 0, got " + args[i + 1]);
      return v;
    };
    if (key == "every") {
      need(1);
      const double v = num(1);
      if (!(v >= 1 && v <= 1e9 && v == std::floor(v))) fail("keyword 'every' expects an integer >= 1, got '" + args[i + 1] + "'");
      c.every = static_cast<long>(v), have_every = true, i += 2;
    } else if (key == "box") {
      need(6);
      std::array<double, 6> b{};
      for (std::size_t k = 0; k < 6; ++k) b[k] = num(k + 1);
      if (!(b[0] < b[1] && b[2] < b[3] && b[4] < b[5])) fail("keyword 'box' needs xlo < xhi, ylo < yhi, zlo < zhi");
      c.box = b, i += 7;
    } else if (key == "zmax") {
      need(1), c.z_max_m = num(1), i += 2;
    } else if (key == "ke_max") {
      need(1), c.ke_max_J = positive(num(1)), i += 2;
    } else if (key == "youngs") {
      need(1), c.youngs_modulus_pa = positive(num(1)), i += 2;
    } else if (key == "poisson") {
      need(1);
      const double v = num(1);
      if (!(v > -1 && v < 0.5)) fail("keyword 'poisson' must be in (-1, 0.5), got " + args[i + 1]);
      c.poisson_ratio = v, i += 2;
    } else if (key == "density") {
      need(1), c.density_kg_m3 = positive(num(1)), i += 2;
    } else if (key == "rmin") {
      need(1), c.r_min_m = positive(num(1)), i += 2;
    } else if (key == "max_dt_fraction") {
      need(1), c.max_dt_fraction = positive(num(1)), i += 2;
    } else if (key == "hull") {
      need(7);
      if (args[i + 1].empty()) fail("keyword 'hull' needs a file name");
      c.hull_file = args[i + 1];
      for (std::size_t k = 0; k < 3; ++k) c.hull_origin_m[k] = num(k + 2), c.hull_velocity_m_s[k] = num(k + 5);
      i += 8;
    } else if (key == "max_penetration") {
      need(1), c.max_penetration = positive(num(1)), i += 2;
    } else {
      fail("unknown keyword '" + key +
           "' (expected every, box, zmax, ke_max, youngs, poisson, density, rmin, max_dt_fraction, hull, "
           "max_penetration)");
    }
  }
  if (!have_every) fail("missing 'every N' (how often to check)");
  if (c.max_penetration && c.hull_file.empty()) fail("'max_penetration' belongs to the hull check, which needs 'hull FILE ...'");
  if (!c.hull_file.empty() && !c.max_penetration) c.max_penetration = 0.5;
  if (!c.youngs_modulus_pa && (c.density_kg_m3 || c.r_min_m))
    fail("'density' and 'rmin' belong to the time-step check, which needs 'youngs E'");
  return c;
}

}  // namespace brash::liggghts
