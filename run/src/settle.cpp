#include "brash/run/settle.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <fstream>
#include <iostream>
#include <iterator>

#include "brash/error.hpp"
#include "brash/core/fnv1a.hpp"
#include "brash/run/runner_setup.hpp"

namespace fs = std::filesystem;

namespace brash {

std::string settle_inputs(const Case& c) {
  const auto& f = c.fluid;
  std::string s = fmt::format(
      "settle_speed_m_s={:.17g} ice_density={:.17g} water={:.17g},{:.17g},{:.17g},{:.17g} friction={:.17g},{:.17g},"
      "{:.17g} contact={:.17g},{:.17g},{:.17g} fluid={},{},{:.17g},{},{} channel={:.17g},{:.17g} dt={:.17g} "
      "skin_d={:.17g}",
      c.ice.settle_speed_m_s, c.ice.density_kg_m3, c.water.density_kg_m3, c.water.level_m, c.water.gravity_m_s2,
      c.water.kinematic_viscosity_m2_s, c.friction.ice_ice, c.friction.ice_hull, c.friction.ice_wall,
      c.contact.youngs_modulus_pa, c.contact.poisson_ratio, c.contact.restitution, to_string(f.model),
      to_string(f.treatment), f.drag_coefficient, to_string(f.drag_law), to_string(f.ca_table), c.channel.length_m,
      c.channel.width_m, c.run.timestep_s, c.speedups.neighbor_skin_d);
  // only when on: a bed settled without rolling resistance keeps its file name
  if (c.contact.rolling_friction != 0) s += fmt::format(" rolling={:.17g}", c.contact.rolling_friction);
  return s;
}

fs::path settled_packing_file(const Case& c) {
  std::ifstream in(c.ice.packing_file, std::ios::binary);
  if (!in) throw InputError(c.ice.packing_file.string() + ": cannot open packing file");
  const std::string bytes{std::istreambuf_iterator<char>(in), {}};
  const std::uint64_t h = core::fnv1a(settle_inputs(c), core::fnv1a(bytes));
  return c.ice.packing_file.parent_path() / fmt::format("settled-{:016x}.csv", h);
}

}  // namespace brash

namespace brash::run {

StartingPacking starting_packing(const Case& c, const std::string& tag) {
  if (!c.ice.settle) return {c.ice.packing_file};
  const fs::path settled = settled_packing_file(c);
  if (fs::exists(settled)) return {settled};
  // brash-settle reads the run's case (overrides applied) from a file beside the bed it writes
  const fs::path case_file = fs::path(settled).replace_extension(".case.yaml");
  std::ofstream(case_file) << dump_case_yaml(c);
  std::cerr << tag << " settling the packing into " << settled.string() << " (once; cached)\n";
  const int rc = run_shell(shell_quote(executable_dir() / "brash-settle") + " " + shell_quote(case_file) + " --out " +
                           shell_quote(settled));
  if (rc != 0 || !fs::exists(settled))
    throw InputError(fmt::format("{}: brash-settle failed (exit {}) to settle the packing {} (ice.settle: true)",
                                 case_file.string(), rc, c.ice.packing_file.string()));
  return {settled, true};
}

}  // namespace brash::run
