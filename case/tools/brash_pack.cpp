// brash-pack CASE_DIR [--out FILE]: generates the case's channel packing (ice.packing_file by
// default) and packing.json with its statistics next to it. See case/include/brash/packing.hpp.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <optional>

#include "brash/case.hpp"
#include "brash/error.hpp"
#include "brash/packing.hpp"

namespace fs = std::filesystem;

int main(int argc, char** argv) {
  CLI::App app{"brash-pack: channel packing of ice spheres at floating equilibrium for a case", "brash-pack"};
  std::string case_arg, out_arg, mode_arg;
  std::optional<std::uint64_t> seed;
  std::optional<double> porosity;
  int drops = 8;
  app.add_option("CASE", case_arg, "case folder (with case.yaml) or a case.yaml")->required();
  app.add_option("--out", out_arg, "packing CSV to write (default: the case's ice.packing_file)");
  app.add_option("--mode", mode_arg, "override ice.packing_mode")
      ->check(CLI::IsMember({"volume", "strict_two_layer"}));
  app.add_option("--seed", seed, "override ice.seed");
  app.add_option("--porosity", porosity, "override ice.porosity");
  app.add_option("--drops", drops, "random drop positions tried per sphere (K)")->check(CLI::Range(1, 1000));
  CLI11_PARSE(app, argc, argv);

  try {
    const fs::path case_yaml = fs::is_directory(case_arg) ? fs::path(case_arg) / "case.yaml" : fs::path(case_arg);
    // the packing does not depend on the fluid model: a case run with --model packs (the runner checks the
    // model keys after the override)
    const brash::Case c = brash::load_case(case_yaml, /*check_model_keys=*/false);
    brash::PackingRequest q = brash::packing_request(c, case_yaml.string());
    if (!mode_arg.empty())
      q.mode = mode_arg == "volume" ? brash::PackingMode::Volume : brash::PackingMode::StrictTwoLayer;
    if (seed) q.seed = *seed;
    if (porosity) q.porosity = *porosity;
    q.drops_per_sphere = drops;
    const fs::path out = out_arg.empty() ? c.ice.packing_file : fs::path(out_arg);

    const brash::Packing p = brash::generate_packing(q);
    brash::write_packing_csv(out, p);
    const fs::path json = out.parent_path() / (out.stem().string() + ".json");
    brash::write_packing_json(json, p.stats);
    const auto& s = p.stats;
    fmt::print("brash-pack: {} spheres ({} mode, seed {}) in {:.1f} s\n", s.count, s.mode, s.seed, s.wall_time_s);
    fmt::print("  ice volume per area {:.6f} m (target {:.6f}), thickness {:.5f} m = {:.2f} d, porosity {:.4f}\n",
               s.ice_volume_per_area_m, s.target_ice_volume_m3 / (q.length_m * q.width_m), s.thickness_m,
               s.thickness_m / s.d_mean_m, s.porosity);
    fmt::print("  interior solid fraction {:.4f}, equivalent thickness {:.5f} m = {:.2f} d\n", s.bulk_solid_fraction,
               s.equivalent_thickness_m, s.equivalent_thickness_m / s.d_mean_m);
    fmt::print("  d mean {:.6f} m sd {:.6f} m [{:.6f}, {:.6f}], max overlap / d {:.2e} ({} pairs above {:.0e}), "
               "contacts/sphere {:.2f}\n",
               s.d_mean_m, s.d_sd_m, s.d_min_m, s.d_max_m, s.max_overlap_over_d, s.overlapping_pairs,
               s.overlap_tolerance_over_d, s.mean_contacts);
    fmt::print("  floating: z in [{:.5f}, {:.5f}] m, buoyancy / weight - 1 = {:.2e}\n", s.bottom_z_m, s.top_z_m,
               s.buoyancy_N / s.weight_N - 1);
    fmt::print("  wrote {} and {}\n", out.string(), json.string());
    return 0;
  } catch (const brash::InputError& e) {
    std::cerr << "brash-pack: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "brash-pack: error: " << e.what() << "\n";
    return 1;
  }
}
