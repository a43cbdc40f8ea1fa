#include "yade_engine.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fmt/format.h>
#include <fstream>
#include <iostream>
#include <sstream>

#include "brash/run/child_process.hpp"
#include "brash/error.hpp"
#include "brash/run/force_record.hpp"
#include "brash/run/guard.hpp"
#include "brash/paths.hpp"
#include "brash/run/run_layout.hpp"
#include "brash/run/driver.hpp"
#include "brash/run/runner_setup.hpp"

namespace fs = std::filesystem;

namespace brash::yade {
namespace {

// YADE itself (the launcher found at configure time, a system program) and the scene script (beside the module in
// brash::paths::yade_python_dir()), each overridable.
fs::path env_or(const char* var, const fs::path& fallback) {
  const char* v = std::getenv(var);
  return v && *v ? fs::path(v) : fallback;
}

run::ChildCommand yade_command(const fs::path& run_dir, int threads, const std::string& restart) {
  const fs::path home = std::getenv("HOME") && *std::getenv("HOME") ? fs::path(std::getenv("HOME")) : run_dir / "home";
  fs::create_directories(home);
  return {run_dir,
          fmt::format("HOME={} PYTHONPATH={}${{PYTHONPATH:+:$PYTHONPATH}} OMP_NUM_THREADS={}", run::shell_quote(home),
                      run::shell_quote(paths::yade_python_dir()), threads),
          fmt::format("{} -n -j{} -x {} scene.json{}", run::shell_quote(env_or("BRASH_YADE_EXE", BRASH_YADE_EXE)),
                      threads,
                      run::shell_quote(env_or("BRASH_YADE_SCRIPT", paths::yade_python_dir() / "brash_yade_scene.py")),
                      restart.empty() ? std::string() : " " + run::shell_quote(restart))};
}

}  // namespace

nlohmann::json YadeEngine::meta() const {
  return {{"engine_version", "YADE 2023.02a (Debian yade) + brash_yade PyRunner adapter"},
          {"ranks", 1},
          {"threads", threads_},
          // no hull force split on YADE: its scene sums one total force on the hull (brash-post says the split is
          // not recorded, naming this)
          {"hull_split", "not recorded: the YADE scene records the total hull force only (LIGGGHTS and brash-ode "
                         "record the split)"}};
}

void YadeEngine::load(const Case& c, const fs::path& /*case_file*/, const std::vector<Sphere>& spheres) {
  if (c.fluid.hull_flow != HullFlow::None)
    throw InputError(fmt::format("fluid.hull_flow: {} is implemented on LIGGGHTS and ODE (brash-liggghts-run, "
                                 "brash-ode); brash-yade-run runs in still water (hull_flow: none)",
                                 to_string(c.fluid.hull_flow)));
  // YADE's own rolling law (Law2_ScGeom_MindlinPhys_Mindlin with includeMoment) caps the torque at
  // eta (R_a + R_b) / 2 |F_n|, one eta for every pair: the mean radius, not LIGGGHTS' and ODE's
  // R_a R_b / (R_a + R_b), so an ice-ice contact would get twice their torque or more (docs/physics.md)
  if (c.contact.rolling_friction != 0)
    throw InputError(fmt::format("contact.rolling_friction: {} is implemented on LIGGGHTS and ODE (brash-liggghts-run, "
                                 "brash-ode); brash-yade-run has no rolling resistance (rolling_friction: 0)",
                                 c.contact.rolling_friction));
  case_ = c;
  particles_ = spheres.size();
  full_mesh_ = hull::read_mesh(c.hull.file);
  hull::require_plausible_units(full_mesh_, c.hull.file, c.hull.draft_m, c.hull.lpp_m);
  full_ = hull::check_mesh(full_mesh_);  // extents and closedness of the full hull
  full_closed_ = full_.closed;
  contact_mesh_ = full_mesh_;
  if (c.hull.band_m)
    contact_mesh_ = hull::clip_band(contact_mesh_, c.hull.draft_m - (*c.hull.band_m)[0], c.hull.draft_m + (*c.hull.band_m)[1]);
}

// Run-time guards (brash::guard, docs/stability.md): the LIGGGHTS scene box of the same case (extents of the full
// hull) and the hull penetration check on the full closed hull, also when the contact hull is a band.
nlohmann::json YadeEngine::guards_json(const fs::path& run_dir) const {
  const auto limits = guard::limits_for_case(
      case_, guard::domain_box(case_, full_.min_m.x(), full_.max_m.x(), full_.min_m.z(), full_.max_m.z(),
                               case_.run.duration_s));
  std::string guard_hull;
  if (limits.max_hull_penetration_d && full_closed_) {
    guard_hull = case_.hull.band_m ? "hull_full.stl" : "hull.stl";
    if (case_.hull.band_m) hull::write_stl(run_dir / guard_hull, full_mesh_);
  } else if (!full_closed_) {
    std::cerr << "[brash-yade] note: " << case_.hull.file.string()
              << " is not a closed surface: the hull penetration guard is off\n";
  }
  return {{"every_steps", case_.guards.every_steps},
          {"box", *limits.box},
          {"z_max_m", *limits.z_max_m},
          {"ke_max_J", *limits.ke_max_J},
          {"max_hull_penetration_d",
           guard_hull.empty() ? nlohmann::json(nullptr) : nlohmann::json(*limits.max_hull_penetration_d)},
          {"hull_stl", guard_hull.empty() ? std::string() : fs::absolute(run_dir / guard_hull).string()},
          {"hull_origin_m", {case_.hull.start_x_m, 0.0, -case_.hull.draft_m}},
          {"hull_velocity_m_s", {case_.ship.speed_m_s, 0.0, 0.0}},
          {"max_dt_fraction", kMaxTimestepOverRayleigh}};
}

// On resume, scene.json is written again (the same case; the restart interval of this invocation).
void YadeEngine::write_scene(const fs::path& run_dir, bool /*resume*/) {
  const Case& c = case_;
  hull::write_stl(run_dir / "hull.stl", contact_mesh_);
  const long restart_every_steps =
      std::max(1L, std::lround(run::restart_interval_s(c, restart_every_s_) / c.run.timestep_s));
  const nlohmann::json scene = {
      {"case", c.name},
      {"packing_file", c.ice.packing_file.string()},
      {"ice_density_kg_m3", c.ice.density_kg_m3},
      {"hull_stl", fs::absolute(run_dir / "hull.stl").string()},
      {"draft_m", c.hull.draft_m},
      {"hull_start_x_m", c.hull.start_x_m},
      {"speed_m_s", c.ship.speed_m_s},
      {"channel_width_m", c.channel.width_m},
      {"channel_length_m", c.channel.length_m},
      {"channel_ends", std::string(to_string(c.channel.ends))},
      {"friction", {{"ice_ice", c.friction.ice_ice}, {"ice_hull", c.friction.ice_hull}, {"ice_wall", c.friction.ice_wall}}},
      {"youngs_modulus_pa", c.contact.youngs_modulus_pa},
      {"poisson_ratio", c.contact.poisson_ratio},
      {"restitution", c.contact.restitution},
      {"dt_s", c.run.timestep_s},
      {"duration_s", c.run.duration_s},
      {"output_interval_s", c.run.output_interval_s},
      {"dump_interval_s", c.run.dump_interval_s},
      {"restart_every_steps", restart_every_steps},
      {"guards", guards_json(run_dir)}};
  run::write_atomic(run_dir / "scene.json", scene.dump(1) + "\n");
}

// restart/<10-digit iteration>/ holding scene.yade and state.json (the scene renames a point into place whole),
// newest first.
std::vector<std::string> YadeEngine::restarts(const fs::path& run_dir) const {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(run_dir / "restart", ec)) {
    const std::string name = entry.path().filename().string();
    if (name.size() != 10 || name.find_first_not_of("0123456789") != std::string::npos) continue;
    if (fs::is_regular_file(entry.path() / "scene.yade") && fs::is_regular_file(entry.path() / "state.json"))
      names.push_back(name);
  }
  std::sort(names.rbegin(), names.rend());
  for (auto& n : names) n = "restart/" + n;
  return names;
}

// The scene writes hull_force_yade.csv as it goes (a resumed scene first rewrites it with the rows before its
// restart point); the driver makes hull_force.csv of it. The scene's writes are buffered: its last line may be
// cut (read while it writes, or the scene was killed) and is left out. No file yet: no rows. The total only: the
// scene records no hull force split (meta.json "hull_split" says so).
run::ForceRecord YadeEngine::force_record(const fs::path& run_dir, double t_max_s) const {
  const fs::path file = run_dir / "hull_force_yade.csv";
  if (!fs::exists(file)) return {};
  run::ForceRecord record;
  record.rows = run::read_hull_force_csv(file, /*drop_unterminated_tail=*/true).rows;
  std::erase_if(record.rows, [&](const run::ForceRow& r) { return r.t_s > t_max_s; });
  return record;
}

// Runs YADE, mirrors its output to log.txt, its "[brash-yade] t = T / D s ..." lines to the monitor and its other
// "[brash-yade]" lines to the terminal; the summary it writes at its end completes meta.json.
// A resumed attempt appends to log.txt and passes its restart point to the scene.
run::Attempt YadeEngine::advance(const fs::path& run_dir, const std::string& restart, run::Monitor& monitor) {
  std::ofstream log(run_dir / "log.txt", restart.empty() ? std::ios::trunc : std::ios::app);
  std::error_code ec;
  fs::remove(run_dir / "yade_summary.json", ec);  // written by the scene at its end: only this attempt's counts
  run::Attempt a;
  long first_step = 0;
  const auto on_line = [&](const std::string& line) {
    log << line << std::flush;
    double t, duration;
    long step;
    if (std::sscanf(line.c_str(), "[brash-yade] t = %lf / %lf s step %ld", &t, &duration, &step) == 3) {
      a.started = true;
      a.t_last_s = t;
      if (a.t_first_s < 0) a.t_first_s = t;
      a.particle_steps = double(particles_) * double(step - first_step);
      return monitor.progress(t, a.particle_steps);
    }
    if (std::sscanf(line.c_str(), "[brash-yade] resumed from %*s iteration %ld", &first_step) == 1)
      std::fputs(line.c_str(), stderr);
    else if (line.rfind("[brash-yade] ERROR", 0) == 0 && a.error.empty())
      a.error = line.substr(20, line.find('\n') - 20);  // after "[brash-yade] ERROR: "
    else if (line.rfind("[brash-yade]", 0) == 0)
      std::fputs(line.c_str(), stderr);
    return false;
  };
  const int exit_code =
      run::run_child(yade_command(run_dir, threads_, restart), {[&](long pid) { monitor.engine_process(pid); }, on_line})
          .code;
  const fs::path summary_file = run_dir / "yade_summary.json";
  if (fs::exists(summary_file)) {
    const auto summary = nlohmann::json::parse(std::ifstream(summary_file));
    a.particle_steps = summary.at("particle_steps");
    for (const char* key : {"loop_time_s", "fluid_us_per_particle_step", "hull_facets"}) a.meta[key] = summary.at(key);
  }
  if (a.error.empty() && (exit_code != 0 || !fs::exists(summary_file)))
    a.error = fmt::format("yade exited with code {}", exit_code);
  return a;
}

}  // namespace brash::yade
