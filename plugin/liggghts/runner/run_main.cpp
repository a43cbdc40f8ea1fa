// brash-liggghts-run CASE_DIR: runs a case with LIGGGHTS end to end and writes the run layout of
// docs/case_format.md (case.yaml, meta.json, hull_force.csv, particles/, restart/, log.txt), then calls
// brash-post on it. Progress with ETA on the terminal.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fmt/format.h>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <unistd.h>

#include "brash/case.hpp"
#include "brash/error.hpp"
#include "brash/hull/mesh.hpp"
#include "brash/packing.hpp"
#include "brash/run_layout.hpp"
#include "liggghts_input.h"

namespace fs = std::filesystem;
using brash::InputError;

namespace {

fs::path bin_dir() { return fs::read_symlink("/proc/self/exe").parent_path(); }

int run_command(const std::string& cmd) {
  const int rc = std::system(cmd.c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : 128;
}

std::string quote(const fs::path& p) { return "'" + p.string() + "'"; }

// hull_force.raw (fix ave/time: "step t fx fy fz") -> hull_force.csv "t_s,fx_N,fy_N,fz_N".
std::size_t convert_hull_force(const fs::path& raw, const fs::path& csv) {
  std::ifstream in(raw);
  std::string line, out = "t_s,fx_N,fy_N,fz_N\n";
  std::size_t n = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ss(line);
    double step, t, fx, fy, fz;
    if (!(ss >> step >> t >> fx >> fy >> fz)) continue;  // a truncated last line of a killed run
    out += fmt::format("{:.9g},{:.9g},{:.9g},{:.9g}\n", t, fx, fy, fz);
    ++n;
  }
  brash::run::write_atomic(csv, out);
  return n;
}

// LIGGGHTS custom dumps -> particles/particles_<step>.csv (sorted by id) + particles/index.csv.
std::size_t convert_dumps(const fs::path& run_dir, const brash::Case& c) {
  std::vector<fs::path> dumps;
  for (const auto& e : fs::directory_iterator(run_dir / "particles"))
    if (e.path().filename().string().rfind("dump.", 0) == 0) dumps.push_back(e.path());
  std::sort(dumps.begin(), dumps.end());
  std::string index = "step,t_s,file,hull_x_m\n";
  for (const auto& dump : dumps) {
    std::ifstream in(dump);
    std::string line;
    long step = -1;
    std::map<long, std::string> rows;
    bool atoms = false;
    while (std::getline(in, line)) {
      if (line.rfind("ITEM: TIMESTEP", 0) == 0) {
        std::getline(in, line);
        step = std::stol(line);
        continue;
      }
      if (line.rfind("ITEM: ATOMS", 0) == 0) {
        atoms = true;
        continue;
      }
      if (line.rfind("ITEM:", 0) == 0) {
        atoms = false;
        continue;
      }
      if (!atoms) continue;
      std::istringstream ss(line);
      long id;
      double v[11];
      ss >> id;
      for (double& x : v) ss >> x;
      if (!ss) continue;
      rows[id] = fmt::format("{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.6g},{:.6g},{:.6g},{:.6g}\n", id,
                             v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10]);
    }
    if (step < 0) continue;
    std::string csv = "id,x,y,z,radius,vx,vy,vz,submerged_fraction,ca_x,ca_y,ca_z\n";
    for (const auto& [id, row] : rows) csv += row;
    const std::string name = fmt::format("particles_{:010d}.csv", step);
    brash::run::write_atomic(run_dir / "particles" / name, csv);
    fs::remove(dump);
    const double t = step * c.run.timestep_s;
    index += fmt::format("{},{:.9g},{},{:.9g}\n", step, t, name, c.hull.start_x_m + c.ship.speed_m_s * t);
  }
  brash::run::write_atomic(run_dir / "particles" / "index.csv", index);
  return dumps.size();
}

struct EngineResult {
  int exit_code = 0;
  double loop_time_s = 0;
  long steps = 0;
  long atoms = 0;
  std::string error;
};

// Runs the engine, copies its screen output to log.txt and prints progress with an ETA.
EngineResult run_engine(const fs::path& run_dir, int ranks, double duration_s) {
  std::string cmd = "cd " + quote(run_dir) + " && ";
  if (ranks > 1) cmd += fmt::format("mpirun --allow-run-as-root --oversubscribe -np {} ", ranks);
  cmd += quote(bin_dir() / "brash-liggghts") + " -in in.lmp -log none 2>&1";
  EngineResult res;
  std::ofstream log(run_dir / "log.txt");
  FILE* pipe = ::popen(cmd.c_str(), "r");
  if (!pipe) throw std::runtime_error("cannot start " + cmd);
  const auto start = std::chrono::steady_clock::now();
  char buf[4096];
  double last_print = -1;
  bool in_thermo = false;
  while (std::fgets(buf, sizeof buf, pipe)) {
    const std::string line = buf;
    log << line;
    if (line.rfind("Step ", 0) == 0 || line.find(" Step ") != std::string::npos) in_thermo = true;
    if (line.rfind("ERROR", 0) == 0 && res.error.empty()) res.error = line.substr(0, line.find('\n'));
    if (line.rfind("Loop time of", 0) == 0) {
      in_thermo = false;
      std::sscanf(line.c_str(), "Loop time of %lf on %*d procs for %ld steps with %ld atoms", &res.loop_time_s,
                  &res.steps, &res.atoms);
    }
    if (!in_thermo) continue;
    long step;
    double t;
    if (std::sscanf(line.c_str(), " %ld %lf", &step, &t) == 2) {
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (elapsed - last_print >= 2.0 && t > 0) {
        last_print = elapsed;
        const double eta = elapsed * (duration_s - t) / t;
        std::fprintf(stderr, "\r[brash-liggghts] t = %.2f / %.2f s (%3.0f%%)  elapsed %.0f s  ETA %.0f s   ", t,
                     duration_s, 100 * t / duration_s, elapsed, eta);
      }
    }
  }
  std::fprintf(stderr, "\n");
  const int rc = ::pclose(pipe);
  res.exit_code = WIFEXITED(rc) ? WEXITSTATUS(rc) : 128;
  return res;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"brash-liggghts-run: run a case directory with LIGGGHTS and write the brash run layout"};
  fs::path case_dir, out_dir, runs_root = "runs";
  int ranks = 1;
  double duration = -1;
  std::string model, treatment;
  bool no_post = false, prepare_only = false;
  app.add_option("case_dir", case_dir, "case folder holding case.yaml")->required();
  app.add_option("--np", ranks, "MPI ranks")->check(CLI::Range(1, 1024));
  app.add_option("--out", out_dir, "run directory (default: runs/<case>-liggghts-<model>-<stamp>)");
  app.add_option("--runs-root", runs_root, "where run directories are created");
  app.add_option("--duration", duration, "simulated time [s] (default: the case's run.duration_s)");
  app.add_option("--model", model, "override fluid.model: drag | added_mass | both");
  app.add_option("--treatment", treatment, "override fluid.treatment: implicit | explicit");
  app.add_flag("--no-post", no_post, "do not run brash-post afterwards");
  app.add_flag("--prepare-only", prepare_only, "write the run directory's inputs (in.lmp, packing.data, hull.stl) and stop");
  CLI11_PARSE(app, argc, argv);

  fs::path run_dir;
  nlohmann::json meta;
  try {
    const fs::path case_file = fs::is_directory(case_dir) ? case_dir / "case.yaml" : case_dir;
    const fs::path case_root = case_file.parent_path();
    // Overrides go through the YAML text so they are validated like any case key.
    brash::Case c = brash::load_case(case_file);
    std::string yaml = brash::dump_case_yaml(c);
    auto set_key = [&](const std::string& section, const std::string& key, const std::string& value) {
      const std::string pat = "\n  " + key + ":";
      const auto sec = yaml.find("\n" + section + ":");
      const auto pos = yaml.find(pat, sec);
      if (sec == std::string::npos || pos == std::string::npos) throw InputError("cannot override " + key);
      const auto eol = yaml.find('\n', pos + 1);
      yaml.replace(pos, eol - pos, pat + " " + value);
    };
    if (!model.empty()) set_key("fluid", "model", model);
    if (!treatment.empty()) set_key("fluid", "treatment", treatment);
    if (duration > 0) {
      set_key("run", "duration_s", fmt::format("{}", duration));
      if (duration < c.run.window_s[1]) {  // keep the window inside a shortened run, and say so
        const double start = std::min(c.run.window_s[0], 0.5 * duration);
        set_key("run", "window_s", fmt::format("[{}, {}]", start, duration));
        std::cerr << fmt::format("[brash-liggghts] --duration {} s is shorter than the window: window set to [{}, {}] s\n",
                                 duration, start, duration);
      }
    }
    c = brash::parse_case(yaml, case_root, case_file.string() + " (with command-line overrides)");
    const double run_duration = c.run.duration_s;

    // Inputs: packing (generated on first use, cached in the case folder) and hull.
    if (!fs::exists(c.ice.packing_file)) {
      std::cerr << "[brash-liggghts] generating the packing " << c.ice.packing_file << "\n";
      if (run_command(quote(bin_dir() / "brash-pack") + " " + quote(case_root)) != 0)
        throw InputError(case_file.string() + ": brash-pack failed to generate " + c.ice.packing_file.string());
    }
    if (!fs::exists(c.hull.file))
      throw InputError(fmt::format("{}: hull.file {} not found (searched the case folder, $BRASH_HULL_DIR, "
                                   "<build>/hull_meshes, <repo>/hull_meshes); build it with `make build`",
                                   case_file.string(), c.hull.file.string()));
    auto spheres = brash::read_packing_csv(c.ice.packing_file);
    if (c.speedups.symmetry_y) spheres = brash::liggghts::half_channel_spheres(spheres);
    auto mesh = brash::hull::read_mesh(c.hull.file);
    brash::hull::require_plausible_units(mesh, c.hull.file, c.hull.draft_m, c.hull.lpp_m);
    double xmin = 1e300, xmax = -1e300, zmin = 1e300, zmax = -1e300;
    for (const auto& v : mesh.vertices) {
      xmin = std::min(xmin, v.x()), xmax = std::max(xmax, v.x());
      zmin = std::min(zmin, v.z()), zmax = std::max(zmax, v.z());
    }
    if (c.hull.band_m) mesh = brash::hull::clip_band(mesh, c.hull.draft_m - (*c.hull.band_m)[0], c.hull.draft_m + (*c.hull.band_m)[1]);
    if (c.speedups.symmetry_y) mesh = brash::liggghts::half_hull(mesh);

    run_dir = out_dir.empty() ? brash::run::make_run_dir(runs_root, c.name, "liggghts", std::string(to_string(c.fluid.model)))
                              : out_dir;
    fs::create_directories(run_dir / "particles");
    fs::create_directories(run_dir / "restart");
    brash::run::write_atomic(run_dir / "case.yaml", brash::dump_case_yaml(c));
    brash::hull::write_stl(run_dir / "hull.stl", mesh);
    const auto box = brash::liggghts::scene_box(c, xmin, xmax, zmin, zmax, run_duration);
    brash::run::write_atomic(run_dir / "packing.data", brash::liggghts::data_file(spheres, box, c.ice.density_kg_m3,
                                                                                 c.speedups.symmetry_y ? 4 : 3));
    brash::liggghts::SceneOptions opt;
    opt.duration_s = run_duration;
    opt.ranks = ranks;
    opt.hull_x_min_m = xmin;
    opt.hull_x_max_m = xmax;
    opt.restart_every_steps = std::max(1L, std::lround(run_duration / 10 / c.run.timestep_s));
    brash::run::write_atomic(run_dir / "in.lmp", brash::liggghts::input_script(c, box, opt));

    if (prepare_only) {
      std::cout << run_dir.string() << "\n";
      return 0;
    }
    meta = {{"engine", "liggghts"},
            {"engine_version", "LIGGGHTS 3.8.0 (Debian libliggghts) + fix icefluid"},
            {"fluid_model", to_string(c.fluid.model)},
            {"treatment", to_string(c.fluid.treatment)},
            {"dt_s", c.run.timestep_s},
            {"ranks", ranks},
            {"particles", spheres.size()},
            {"wall_time_s", 0.0},
            {"particle_steps", 0},
            {"git_commit", brash::run::git_commit()},
            {"status", "running"},
            {"reason", ""}};
    brash::run::write_meta(run_dir, meta);
    std::cerr << "[brash-liggghts] " << spheres.size() << " spheres, " << mesh.faces.size() << " hull triangles, "
              << ranks << " rank(s) -> " << run_dir.string() << "\n";

    const auto t0 = std::chrono::steady_clock::now();
    const auto res = run_engine(run_dir, ranks, run_duration);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const auto rows = fs::exists(run_dir / "hull_force.raw") ? convert_hull_force(run_dir / "hull_force.raw", run_dir / "hull_force.csv") : 0;
    convert_dumps(run_dir, c);
    meta["wall_time_s"] = wall;
    meta["loop_time_s"] = res.loop_time_s;
    meta["particle_steps"] = static_cast<double>(res.atoms) * static_cast<double>(res.steps);
    meta["hull_force_rows"] = rows;
    if (res.exit_code != 0 || !res.error.empty()) {
      meta["status"] = "failed";
      meta["reason"] = res.error.empty() ? fmt::format("LIGGGHTS exited with code {}", res.exit_code) : res.error;
      brash::run::write_meta(run_dir, meta);
      std::cerr << "[brash-liggghts] run failed: " << meta["reason"].get<std::string>() << " (see "
                << (run_dir / "log.txt").string() << ")\n";
      return 1;
    }
    meta["status"] = "complete";
    brash::run::write_meta(run_dir, meta);
    std::cerr << fmt::format("[brash-liggghts] done in {:.1f} s ({:.3g} particle-steps/s)\n", wall,
                             res.loop_time_s > 0 ? res.atoms * double(res.steps) / res.loop_time_s : 0.0);
  } catch (const std::exception& e) {
    std::cerr << "brash-liggghts-run: error: " << e.what() << "\n";
    if (!run_dir.empty()) {
      meta["status"] = "failed";
      meta["reason"] = e.what();
      brash::run::write_meta(run_dir, meta);
    }
    return 1;
  }
  std::cout << run_dir.string() << "\n";
  if (!no_post) {
    const auto post = bin_dir() / "brash-post";
    if (!fs::exists(post)) {
      std::cerr << "[brash-liggghts] brash-post not built; skipping the report\n";
      return 0;
    }
    return run_command(quote(post) + " " + quote(run_dir));
  }
  return 0;
}
