// brash-yade-run CASE_DIR: runs a case with YADE and writes the run layout of docs/case_format.md
// (case.yaml, meta.json, hull_force.csv, particles/, log.txt; restart/ stays empty: no YADE restarts yet).
// It prepares the inputs (packing via brash-pack if missing, the hull clipped to the case's band as
// hull.stl, scene.json), launches `yade -n -j<N> -x brash_yade_scene.py scene.json` in the run directory
// with brash_yade on PYTHONPATH, mirrors its output to log.txt with progress on the terminal, fills in
// meta.json and calls brash-post when it was built.
// The run-time guards (brash::guard) are checked by the scene every guards.every_steps iterations; a stop
// ends the run with "[brash-yade] ERROR: guard: step N (t = T s): piece ID: cause", recorded in meta.json.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <unistd.h>
#include <cstdlib>
#include <fmt/format.h>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "brash/case.hpp"
#include "brash/error.hpp"
#include "brash/guard.hpp"
#include "brash/hull/mesh.hpp"
#include "brash/packing.hpp"
#include "brash/run_layout.hpp"
#include "brash/runner_setup.hpp"

namespace fs = std::filesystem;
using brash::InputError;

namespace {

// Where the scene script and the module are: next to the build by default, overridable.
fs::path env_or(const char* var, const char* fallback) {
  const char* v = std::getenv(var);
  return v && *v ? fs::path(v) : fs::path(fallback);
}

struct EngineResult {
  int exit_code = 0;
  std::string error;
};

EngineResult run_yade(const fs::path& run_dir, int threads) {
  const fs::path home = std::getenv("HOME") && *std::getenv("HOME") ? fs::path(std::getenv("HOME")) : run_dir / "home";
  fs::create_directories(home);
  const std::string cmd = fmt::format(
      "cd {} && HOME={} PYTHONPATH={}${{PYTHONPATH:+:$PYTHONPATH}} OMP_NUM_THREADS={} {} -n -j{} -x {} scene.json 2>&1",
      brash::run::shell_quote(run_dir), brash::run::shell_quote(home), brash::run::shell_quote(env_or("BRASH_YADE_PYDIR", BRASH_YADE_PYDIR)), threads,
      brash::run::shell_quote(env_or("BRASH_YADE_EXE", BRASH_YADE_EXE)), threads, brash::run::shell_quote(env_or("BRASH_YADE_SCRIPT", BRASH_YADE_SCRIPT)));
  EngineResult res;
  std::ofstream log(run_dir / "log.txt");
  FILE* pipe = ::popen(cmd.c_str(), "r");
  if (!pipe) throw std::runtime_error("cannot start " + cmd);
  char buf[8192];
  // Progress: rewritten in place on a terminal; into a file, a line of its own every 30 s at most.
  const bool tty = ::isatty(::fileno(stderr)) != 0;
  auto last_print = std::chrono::steady_clock::now() - std::chrono::hours(1);
  bool line_open = false;  // a progress line without its newline is on the terminal
  while (std::fgets(buf, sizeof buf, pipe)) {
    std::string line = buf;
    log << line << std::flush;
    if (line.rfind("[brash-yade] t = ", 0) == 0) {
      line.erase(line.find_last_not_of("\r\n") + 1);
      const auto now = std::chrono::steady_clock::now();
      if (tty) {
        std::fprintf(stderr, "\r%s   ", line.c_str());
        line_open = true;
      } else if (now - last_print >= std::chrono::seconds(30)) {
        last_print = now;
        std::fprintf(stderr, "%s\n", line.c_str());
      }
    } else if (line.rfind("[brash-yade] ERROR", 0) == 0 && res.error.empty()) {
      res.error = line.substr(20, line.find('\n') - 20);  // after "[brash-yade] ERROR: "
    } else if (line.rfind("[brash-yade]", 0) == 0) {
      std::fprintf(stderr, "%s%s", line_open ? "\n" : "", line.c_str());
      line_open = false;
    }
  }
  if (line_open) std::fprintf(stderr, "\n");
  const int rc = ::pclose(pipe);
  res.exit_code = WIFEXITED(rc) ? WEXITSTATUS(rc) : 128;
  return res;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"brash-yade-run: run a case directory with YADE and write the brash run layout"};
  fs::path case_dir, out_dir, runs_root = "runs";
  int threads = 1;
  double duration = -1;
  std::string model, treatment;
  bool no_post = false, prepare_only = false;
  app.add_option("case_dir", case_dir, "case folder holding case.yaml")->required();
  app.add_option("--out", out_dir, "run directory (default: runs/<case>-yade-<model>-<stamp>)");
  app.add_option("--runs-root", runs_root, "where run directories are created");
  app.add_option("--duration", duration, "simulated time [s] (default: the case's run.duration_s)");
  app.add_option("--model", model, "override fluid.model: drag | added_mass | both");
  app.add_option("--treatment", treatment, "override fluid.treatment: implicit | explicit");
  app.add_option("-j,--threads", threads, "YADE OpenMP threads")->check(CLI::Range(1, 256));
  app.add_flag("--no-post", no_post, "do not run brash-post afterwards");
  app.add_flag("--prepare-only", prepare_only, "write the run directory's inputs (scene.json, hull.stl) and stop");
  CLI11_PARSE(app, argc, argv);

  fs::path run_dir;
  nlohmann::json meta;
  try {
    const fs::path case_file = fs::is_directory(case_dir) ? case_dir / "case.yaml" : case_dir;
    brash::run::CaseOverrides overrides{model, treatment, duration};
    const brash::Case c = brash::run::load_case_with_overrides(case_file, overrides, "[brash-yade]");
    brash::run::prepare_case_inputs(c, case_file, "[brash-yade]");
    const auto spheres = brash::read_case_packing(c);  // checked against the case before any output
    auto mesh = brash::hull::read_mesh(c.hull.file);
    brash::hull::require_plausible_units(mesh, c.hull.file, c.hull.draft_m, c.hull.lpp_m);
    // Run-time guards (brash::guard, docs/stability.md): the LIGGGHTS scene box of the same case (extents of
    // the full hull) and the hull penetration check on the full closed hull, also when the contact hull is a
    // band.
    const brash::hull::Mesh full_mesh = mesh;
    const brash::hull::MeshCheck full = brash::hull::check_mesh(full_mesh);  // extents and closedness
    const bool full_closed = full.closed;
    const auto limits = brash::guard::limits_for_case(
        c, brash::guard::domain_box(c, full.min_m.x(), full.max_m.x(), full.min_m.z(), full.max_m.z(),
                                    c.run.duration_s));
    if (c.fluid.hull_flow != brash::HullFlow::None)
      throw brash::InputError(
          fmt::format("fluid.hull_flow: {} is implemented on LIGGGHTS and ODE "
                      "(brash-liggghts-run, brash-ode); brash-yade-run runs in still water (hull_flow: none)",
                      to_string(c.fluid.hull_flow)));
    if (c.hull.band_m)
      mesh = brash::hull::clip_band(mesh, c.hull.draft_m - (*c.hull.band_m)[0], c.hull.draft_m + (*c.hull.band_m)[1]);

    run_dir = out_dir.empty() ? brash::run::make_run_dir(runs_root, c.name, "yade", std::string(to_string(c.fluid.model)))
                              : out_dir;
    fs::create_directories(run_dir / "particles");
    fs::create_directories(run_dir / "restart");
    brash::run::write_atomic(run_dir / "case.yaml", brash::dump_case_yaml(c));
    brash::hull::write_stl(run_dir / "hull.stl", mesh);
    std::string guard_hull;
    if (limits.max_hull_penetration_d && full_closed) {
      guard_hull = c.hull.band_m ? "hull_full.stl" : "hull.stl";
      if (c.hull.band_m) brash::hull::write_stl(run_dir / guard_hull, full_mesh);
    } else if (!full_closed) {
      std::cerr << "[brash-yade] note: " << c.hull.file.string()
                << " is not a closed surface: the hull penetration guard is off\n";
    }
    const nlohmann::json guards = {
        {"every_steps", c.guards.every_steps},
        {"box", *limits.box},
        {"z_max_m", *limits.z_max_m},
        {"ke_max_J", *limits.ke_max_J},
        {"max_hull_penetration_d",
         guard_hull.empty() ? nlohmann::json(nullptr) : nlohmann::json(*limits.max_hull_penetration_d)},
        {"hull_stl", guard_hull.empty() ? std::string() : fs::absolute(run_dir / guard_hull).string()},
        {"hull_origin_m", {c.hull.start_x_m, 0.0, -c.hull.draft_m}},
        {"hull_velocity_m_s", {c.ship.speed_m_s, 0.0, 0.0}},
        {"max_dt_fraction", brash::kMaxTimestepOverRayleigh}};
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
        {"friction", {{"ice_ice", c.friction.ice_ice}, {"ice_hull", c.friction.ice_hull}, {"ice_wall", c.friction.ice_wall}}},
        {"youngs_modulus_pa", c.contact.youngs_modulus_pa},
        {"poisson_ratio", c.contact.poisson_ratio},
        {"restitution", c.contact.restitution},
        {"dt_s", c.run.timestep_s},
        {"duration_s", c.run.duration_s},
        {"output_interval_s", c.run.output_interval_s},
        {"dump_interval_s", c.run.dump_interval_s},
        {"guards", guards}};
    brash::run::write_atomic(run_dir / "scene.json", scene.dump(1) + "\n");
    if (prepare_only) {
      std::cout << run_dir.string() << "\n";
      return 0;
    }

    meta = {{"engine", "yade"},
            {"engine_version", "YADE 2023.02a (Debian yade) + brash_yade PyRunner adapter"},
            {"fluid_model", to_string(c.fluid.model)},
            {"treatment", to_string(c.fluid.treatment)},
            {"dt_s", c.run.timestep_s},
            {"ranks", 1},
            {"threads", threads},
            {"particles", spheres.size()},
            {"wall_time_s", 0.0},
            {"particle_steps", 0},
            {"git_commit", brash::run::git_commit()},
            {"status", "running"},
            {"reason", ""}};
    brash::run::write_meta(run_dir, meta);
    std::cerr << "[brash-yade] " << spheres.size() << " spheres, " << mesh.faces.size() << " hull triangles -> "
              << run_dir.string() << "\n";

    const auto t0 = std::chrono::steady_clock::now();
    const auto res = run_yade(run_dir, threads);
    meta["wall_time_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const fs::path summary_file = run_dir / "yade_summary.json";
    if (fs::exists(summary_file)) {
      std::ifstream in(summary_file);
      const auto summary = nlohmann::json::parse(in);
      meta["particle_steps"] = summary.at("particle_steps");
      meta["loop_time_s"] = summary.at("loop_time_s");
      meta["fluid_us_per_particle_step"] = summary.at("fluid_us_per_particle_step");
      meta["hull_facets"] = summary.at("hull_facets");
    }
    if (res.exit_code != 0 || !res.error.empty() || !fs::exists(summary_file)) {
      meta["status"] = "failed";
      meta["reason"] = res.error.empty() ? fmt::format("yade exited with code {}", res.exit_code) : res.error;
      brash::run::write_meta(run_dir, meta);
      std::cerr << "[brash-yade] run failed: " << meta["reason"].get<std::string>() << " (see "
                << (run_dir / "log.txt").string() << ")\n";
      return 1;
    }
    meta["status"] = "complete";
    brash::run::write_meta(run_dir, meta);
  } catch (const std::exception& e) {
    std::cerr << "brash-yade-run: error: " << e.what() << "\n";
    if (!run_dir.empty() && !meta.empty()) {
      meta["status"] = "failed";
      meta["reason"] = e.what();
      brash::run::write_meta(run_dir, meta);
    }
    return 1;
  }
  std::cout << run_dir.string() << "\n";
  return no_post ? 0 : brash::run::run_postprocessor(run_dir, "[brash-yade]");
}
