// brash-ode's run options in meta.json (ode_options), for --resume; the --cull wake in SI units.
#include <fmt/format.h>

#include <algorithm>
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

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Every option that shapes the run, stored in meta.json so that --resume rebuilds the same scene.
nlohmann::json options_json(const RunOptions& o) {
  const auto& st = o.stepper;
  const auto& k = o.skips;
  return {{"case_dir", fs::absolute(o.case_dir).lexically_normal().string()},
          {"duration_s", o.duration_s},
          {"model", o.model},
          {"treatment", o.treatment},
          {"dt_s", st.dt_s},
          {"iterations", st.iterations},
          {"erp", st.erp},
          {"cfm", st.cfm},
          {"contact_surface_layer_m", st.contact_surface_layer},
          {"max_contacts_per_pair", st.max_contacts_per_pair},
          {"angular_damping", st.angular_damping},
          {"broad_phase", to_string(st.broad_phase)},
          {"sphere_order", to_string(o.sphere_order)},
          {"auto_disable", k.auto_disable},
          {"disable_linear_m_s", k.disable_linear_m_s},
          {"disable_angular_rad_s", k.disable_angular_rad_s},
          {"disable_steps", k.disable_steps},
          {"auto_disable_far_only", k.auto_disable_far_only},
          {"cull", k.cull},
          {"cull_ahead_m", o.cull_ahead_m},
          {"cull_behind_m", o.cull_behind_m},
          {"cull_side_m", o.cull_side_m},
          {"cull_every", k.cull_every},
          {"cull_geoms", k.cull_geoms},
          {"cull_wake_force_weight", o.cull_wake_force_weight},
          {"cull_wake_speed_m_s", o.cull_wake_speed_m_s},
          {"implicit", o.implicit_mode == ImplicitMode::EffectiveMass ? "effective_mass" : "scale_forces"},
          {"end_walls", o.end_walls},
          {"settle_s", o.settle_s},
          {"settle_damping", o.settle_damping},
          {"overlap_tolerance_over_d", o.overlap_tolerance_over_d},
          {"restart_every_s", o.restart_every_s},
          {"scene_from", o.scene_from.empty() ? std::string() : fs::absolute(o.scene_from).lexically_normal().string()},
          {"scene_time_s", o.scene_time_s}};
}

// A particle dump (particles/*.csv of any engine's run: a header naming id,x,y,z,radius and optionally vx,vy,vz):
// the pieces in the file's order with their velocities (zero without the columns). InputError naming file, line
// and column.
SceneFromDump read_scene_dump(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(fmt::format("--scene-from {}: cannot be read", file.string()));
  std::string line;
  int ln = 0;
  std::unordered_map<std::string, std::size_t> col;
  while (std::getline(in, line)) {
    ++ln;
    if (line.empty() || line[0] == '#') continue;
    std::stringstream ss(line);
    std::string name;
    for (std::size_t i = 0; std::getline(ss, name, ','); ++i) col[name] = i;
    break;
  }
  for (const char* need : {"x", "y", "z", "radius"})
    if (!col.count(need))
      throw InputError(fmt::format("{}:{}: no column \"{}\" in the header (a particle dump: id,x,y,z,radius,vx,vy,vz)",
                                   file.string(), ln, need));
  const bool has_v = col.count("vx") && col.count("vy") && col.count("vz");
  SceneFromDump out;
  std::vector<double> v;
  while (std::getline(in, line)) {
    ++ln;
    if (line.empty() || line[0] == '#') continue;
    v.clear();
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) {
      char* end = nullptr;
      v.push_back(std::strtod(cell.c_str(), &end));
      if (end == cell.c_str() || !std::isfinite(v.back()))
        throw InputError(fmt::format("{}:{}: \"{}\" is not a finite number", file.string(), ln, cell));
    }
    if (v.size() < col.size()) throw InputError(fmt::format("{}:{}: {} values, the header names {}", file.string(), ln, v.size(), col.size()));
    const double r = v[col["radius"]];
    if (!(r > 0)) throw InputError(fmt::format("{}:{}: radius {} is not > 0", file.string(), ln, r));
    out.spheres.push_back({v[col["x"]], v[col["y"]], v[col["z"]], 2 * r});
    out.velocity_m_s.emplace_back(has_v ? v[col["vx"]] : 0.0, has_v ? v[col["vy"]] : 0.0, has_v ? v[col["vz"]] : 0.0);
  }
  if (out.spheres.empty()) throw InputError(fmt::format("{}: no pieces", file.string()));
  return out;
}

// The skips with --cull's wake rule in SI units: the case's unless given (brash/core/far_field.hpp).
Skips cull_skips(const RunOptions& o, const Case& c) {
  Skips k = o.skips;
  const SpeedupSpec& sp = c.speedups;
  const Skips defaults;
  const auto pick = [&](double given, double from_case, double otherwise) {
    return given >= 0 ? given : sp.farfield ? from_case : otherwise;
  };
  k.cull = k.cull || sp.farfield;
  k.cull_ahead_m = pick(o.cull_ahead_m, sp.farfield_ahead_m, defaults.cull_ahead_m);
  k.cull_behind_m = pick(o.cull_behind_m, sp.farfield_behind_m, defaults.cull_behind_m);
  k.cull_side_m = pick(o.cull_side_m, sp.farfield_beside_m.value_or(defaults.cull_side_m), defaults.cull_side_m);
  // the case's membership period in model time (farfield_every_steps DEM steps) in ODE steps
  if (sp.farfield)
    k.cull_every = std::max(1, static_cast<int>(std::lround(sp.farfield_every_steps * c.run.timestep_s / o.stepper.dt_s)));
  const double weight =
      o.cull_wake_force_weight >= 0 ? o.cull_wake_force_weight : c.speedups.farfield_wake_force_weight;
  k.wake_force_N = core::wake_force_N(weight, c.ice.diameter_mean_m, c.ice.density_kg_m3, c.water.gravity_m_s2);
  k.wake_speed_m_s = o.cull_wake_speed_m_s >= 0 ? o.cull_wake_speed_m_s : c.speedups.farfield_wake_speed_m_s;
  k.wake_by = c.speedups.farfield_wake_by;
  k.front_speed_m_s = c.speedups.farfield_front_speed_m_s;
  return k;
}

RunOptions options_from_meta(const fs::path& run_dir, const RunOptions& cli) {
  const fs::path mf = run_dir / "meta.json";
  if (!fs::exists(mf)) throw InputError(fmt::format("--resume {}: no meta.json there (not a run directory?)", run_dir.string()));
  nlohmann::json meta;
  try {
    meta = nlohmann::json::parse(read_text(mf));
  } catch (const std::exception& e) {
    throw InputError(fmt::format("{}: unreadable: {}", mf.string(), e.what()));
  }
  if (meta.value("engine", "") != "ode" || !meta.contains("ode_options"))
    throw InputError(fmt::format("{}: not a brash-ode run with restart support (no \"ode_options\")", mf.string()));
  const auto& j = meta["ode_options"];
  RunOptions o;
  try {
    o.case_dir = j.at("case_dir").get<std::string>();
    o.duration_s = j.at("duration_s");
    o.model = j.at("model");
    o.treatment = j.at("treatment");
    o.stepper.dt_s = j.at("dt_s");
    o.stepper.iterations = j.at("iterations");
    o.stepper.erp = j.at("erp");
    o.stepper.cfm = j.at("cfm");
    o.stepper.contact_surface_layer = j.at("contact_surface_layer_m");
    o.stepper.max_contacts_per_pair = j.at("max_contacts_per_pair");
    o.stepper.angular_damping = j.at("angular_damping");
    // Runs before the switch existed used sap; grid gives the same contacts (see world.hpp), so they go on with it.
    o.stepper.broad_phase = j.value("broad_phase", to_string(BroadPhase::Grid)) == to_string(BroadPhase::Sap) ? BroadPhase::Sap : BroadPhase::Grid;
    // runs before the switch existed were all in the spatial order
    o.sphere_order =
        j.value("sphere_order", "spatial") == "packing" ? SphereOrder::Packing : SphereOrder::Spatial;
    o.skips.auto_disable = j.at("auto_disable");
    o.skips.disable_linear_m_s = j.at("disable_linear_m_s");
    o.skips.disable_angular_rad_s = j.at("disable_angular_rad_s");
    o.skips.disable_steps = j.at("disable_steps");
    o.skips.auto_disable_far_only = j.at("auto_disable_far_only");
    o.skips.cull = j.at("cull");
    o.cull_ahead_m = j.at("cull_ahead_m");  // (runs before the case's far field on ODE: the values they ran with)
    o.cull_behind_m = j.at("cull_behind_m");
    o.cull_side_m = j.at("cull_side_m");
    o.skips.cull_every = j.at("cull_every");
    o.skips.cull_geoms = j.value("cull_geoms", true);  // runs before the switch existed: same contacts either way
    o.cull_wake_force_weight = j.value("cull_wake_force_weight", 0.0);  // runs before the wake: the window alone
    o.cull_wake_speed_m_s = j.value("cull_wake_speed_m_s", 0.0);
    o.implicit_mode = j.at("implicit") == "scale_forces" ? ImplicitMode::ScaleForces : ImplicitMode::EffectiveMass;
    o.end_walls = j.at("end_walls");
    o.settle_s = j.at("settle_s");
    o.settle_damping = j.value("settle_damping", 0.0);  // runs before the option: undamped
    o.overlap_tolerance_over_d = j.at("overlap_tolerance_over_d");
    o.restart_every_s = j.at("restart_every_s");
    o.scene_from = j.value("scene_from", std::string());  // runs before the option: from their packing
    o.scene_time_s = j.value("scene_time_s", 0.0);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(fmt::format("{}: ode_options: {}", mf.string(), e.what()));
  }
  o.out_dir = run_dir;
  o.progress = cli.progress;
  o.crash_after_step = cli.crash_after_step;
  o.stop_after_step = cli.stop_after_step;
  return o;
}

}  // namespace brash::ode
