// brash-liggghts-run CASE_DIR: runs a case with LIGGGHTS end to end and writes the run layout of
// docs/case_format.md (case.yaml, meta.json, hull_force.csv, particles/, restart/, log.txt), then calls
// brash-post on it. Progress with ETA on the terminal.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fmt/format.h>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <regex>
#include <sstream>
#include <csignal>
#include <unistd.h>

#include "brash/case.hpp"
#include "brash/error.hpp"
#include "brash/hull/mesh.hpp"
#include "brash/packing.hpp"
#include "brash/run_layout.hpp"
#include "brash/runner_setup.hpp"
#include "brash/stats/early_stop.hpp"
#include "liggghts_input.h"

namespace fs = std::filesystem;
using brash::InputError;

namespace {

// SIGTERM / SIGINT / SIGHUP sent to the runner alone (a batch system, `kill`, a closed terminal) are forwarded to
// the engine, which would otherwise run on orphaned; the run then ends as `interrupted`, resumable.
std::atomic<long> g_engine_pid{0};  // lock-free: read in the signal handler
volatile std::sig_atomic_t g_signal = 0;
extern "C" void forward_signal(int sig) {
  g_signal = sig;
  if (const long pid = g_engine_pid.load(); pid > 0) ::kill(static_cast<pid_t>(pid), SIGTERM);
}
void install_signal_forwarding() {
  struct sigaction sa {};
  sa.sa_handler = forward_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;  // the engine's output keeps being read until it exits
  for (int sig : {SIGTERM, SIGINT, SIGHUP}) ::sigaction(sig, &sa, nullptr);
}

struct ForceRow {
  double t, fx, fy, fz;
};

// Rows of hull_force*.raw (fix ave/time: "step t fx fy fz") by step. The raw files of a resumed run are read in
// order; a later file's row for a step replaces an earlier one.
std::map<long, ForceRow> read_hull_force_raws(const std::vector<fs::path>& raws) {
  std::map<long, ForceRow> rows;
  for (const auto& raw : raws) {
    std::ifstream in(raw);
    std::string line;
    long first_step = -1;
    while (std::getline(in, line)) {
      if (line.empty() || line[0] == '#') continue;
      std::istringstream ss(line);
      long step;
      double t, fx, fy, fz;
      if (!(ss >> step >> t >> fx >> fy >> fz)) continue;  // a truncated last line of a killed run
      if (first_step < 0) first_step = step;
      // A resumed attempt's first row is its set-up (no contact force summed yet: 0): never a record. The
      // earlier attempt's row for that step is kept; without one the step is missing, which brash-post names
      // as a gap (the paper run had two such zero rows where an earlier attempt's rows were lost).
      if (step == first_step && &raw != &raws.front()) continue;
      rows[step] = {t, fx, fy, fz};
    }
  }
  return rows;
}

// -> hull_force.csv "t_s,fx_N,fy_N,fz_N" (atomic), rows up to t_max_s; the number of rows. While a resumed run
// goes, an earlier attempt's rows beyond the current time are not (yet) this run's: t_max_s leaves them out.
std::size_t convert_hull_force(const std::vector<fs::path>& raws, const fs::path& csv,
                               double t_max_s = std::numeric_limits<double>::infinity()) {
  std::string out = "t_s,fx_N,fy_N,fz_N\n";
  std::size_t n = 0;
  for (const auto& [step, r] : read_hull_force_raws(raws))
    if (r.t <= t_max_s) out += fmt::format("{:.9g},{:.9g},{:.9g},{:.9g}\n", r.t, r.fx, r.fy, r.fz), ++n;
  brash::run::write_atomic(csv, out);
  return n;
}

// Raw hull-force files of earlier (killed) attempts, oldest first, then the current one.
std::vector<fs::path> hull_force_raws(const fs::path& run_dir) {
  std::vector<fs::path> parts;
  for (int k = 1; fs::exists(run_dir / fmt::format("hull_force.part{}.raw", k)); ++k)
    parts.push_back(run_dir / fmt::format("hull_force.part{}.raw", k));
  if (fs::exists(run_dir / "hull_force.raw")) parts.push_back(run_dir / "hull_force.raw");
  return parts;
}

// Periodic restart files of a run, newest first (LIGGGHTS alternates between a and b; a kill while
// one is written leaves the other intact).
std::vector<std::string> restart_candidates(const fs::path& run_dir) {
  std::vector<std::pair<fs::file_time_type, std::string>> found;
  for (const char* name : {"restart/a.restart", "restart/b.restart"})
    if (fs::exists(run_dir / name) && fs::file_size(run_dir / name) > 0)
      found.emplace_back(fs::last_write_time(run_dir / name), name);
  std::sort(found.begin(), found.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  std::vector<std::string> out;
  for (const auto& f : found) out.push_back(f.second);
  return out;
}

// particles/index.csv from every particles_<step>.csv in the folder, by step: the snapshots of all attempts
// of a resumed run (a resumed attempt rewrites those after its restart; the ones before it stay valid).
void write_snapshot_index(const fs::path& run_dir, const brash::Case& c) {
  std::map<long, std::string> snapshots;
  const std::regex name_re(R"(particles_([0-9]+)\.csv)");
  std::smatch m;
  for (const auto& e : fs::directory_iterator(run_dir / "particles")) {
    const std::string name = e.path().filename().string();
    if (std::regex_match(name, m, name_re)) snapshots[std::stol(m[1])] = name;
  }
  std::string index = "step,t_s,file,hull_x_m\n";
  for (const auto& [step, name] : snapshots) {
    const double t = step * c.run.timestep_s;
    index += fmt::format("{},{:.9g},{},{:.9g}\n", step, t, name, c.hull.start_x_m + c.ship.speed_m_s * t);
  }
  brash::run::write_atomic(run_dir / "particles" / "index.csv", index);
}

// LIGGGHTS custom dumps -> particles/particles_<step>.csv (sorted by id), then particles/index.csv.
std::size_t convert_dumps(const fs::path& run_dir, const brash::Case& c) {
  std::vector<fs::path> dumps;
  for (const auto& e : fs::directory_iterator(run_dir / "particles"))
    if (e.path().filename().string().rfind("dump.", 0) == 0) dumps.push_back(e.path());
  std::sort(dumps.begin(), dumps.end());
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
  }
  write_snapshot_index(run_dir, c);
  return dumps.size();
}

// Early stop (speedups.early_stop_rel_ci): the windowed mean resistance is known well enough.
struct EarlyStop {
  double rel_ci = 0;            // stop when ci95 < rel_ci * |mean| (0 = off)
  double t0 = 0, t1 = 0;        // averaging window
  bool trend_check = true;      // speedups.early_stop_trend_check
  bool stopped = false;
  double t_stop = 0, mean = 0, ci95 = 0;
};

// Resistance samples (-fx) with t0 <= t <= t_now from the (growing) raw hull-force files, those of earlier
// attempts of a resumed run included.
std::vector<double> resistance_since(const std::vector<fs::path>& raws, double t0, double t_now) {
  std::vector<double> r;
  for (const auto& [step, row] : read_hull_force_raws(raws))
    if (row.t >= t0 && row.t <= t_now) r.push_back(-row.fx);
  return r;
}

// fix brash/exit's line "fix brash/exit: step S: K piece(s) left ... ; N in all" -> N (the fix's count is
// kept in restart files, so the last line of a resumed run is the run's total); -1 for any other line.
long exit_total(const std::string& line) {
  if (line.rfind("fix brash/exit: step", 0) != 0) return -1;
  const auto at = line.rfind("; ");
  long n = -1;
  if (at == std::string::npos || std::sscanf(line.c_str() + at, "; %ld in all", &n) != 1) return -1;
  return n;
}

struct EngineResult {
  int exit_code = 0;
  double loop_time_s = 0;
  long steps = 0;
  long atoms = 0;
  bool run_started = false;  // the thermo header came: the input (and a restart file) was read, the run began
  // atoms x steps summed over the thermo lines (also for a run killed before its end)
  double particle_steps = 0;
  double t_first_s = -1, t_last_s = -1;  // model time of the first and the last thermo line (-1: none)
  long exits = -1;  // fix brash/exit's count of pieces gone through the channel's ends ("N in all"; -1: none)
  std::string error;
};

// Called by run_engine at every refresh of hull_force.csv: the model time this engine started from and has
// reached [s], and the particle-steps it has done so far.
using ProgressHook = std::function<void(double t_first_s, double t_s, double particle_steps)>;

// Runs the engine, copies its screen output to log.txt and prints progress with an ETA.
// hull_force.csv is refreshed with the record so far every 30 s of wall time and at every restart time
// (csv_every_model_s), so that brash-post can look at a long run while it goes; on_progress is called then
// too.
EngineResult run_engine(const fs::path& run_dir, int ranks, double duration_s, const std::string& input,
                        EarlyStop* early, double csv_every_model_s, const ProgressHook& on_progress) {
  // exec: the shell's pid becomes the engine's (mpirun's), so an early stop can signal it
  std::string cmd = "cd " + brash::run::shell_quote(run_dir) + " && echo $$ > engine.pid && exec ";
  if (ranks > 1) cmd += fmt::format("mpirun --allow-run-as-root --oversubscribe -np {} ", ranks);
  cmd += brash::run::shell_quote(brash::run::executable_dir() / "brash-liggghts") + " -in " + input + " -log none 2>&1";
  EngineResult res;
  std::ofstream log(run_dir / "log.txt", std::ios::app);
  FILE* pipe = ::popen(cmd.c_str(), "r");
  if (!pipe) throw std::runtime_error("cannot start " + cmd);
  const auto start = std::chrono::steady_clock::now();
  char buf[4096];
  double last_print = -1, last_csv = 0;
  long prev_step = -1;
  double next_csv_t = csv_every_model_s > 0 ? csv_every_model_s : std::numeric_limits<double>::infinity();
  bool in_thermo = false;
  // On a terminal the progress line is rewritten in place every 2 s; into a file (nohup, a study's log) it is a
  // line of its own every 30 s, so that the log stays readable.
  const bool tty = ::isatty(::fileno(stderr)) != 0;
  const double print_every_s = tty ? 2.0 : 30.0;
  g_engine_pid = 0;
  while (std::fgets(buf, sizeof buf, pipe)) {
    const std::string line = buf;
    log << line << std::flush;       // a runner killed outright (kill -9, a session end) loses no line
    if (g_engine_pid.load() == 0) {  // the shell wrote engine.pid before its first output line
      std::ifstream pidf(run_dir / "engine.pid");
      long pid = 0;
      if (pidf >> pid && pid > 0) {
        g_engine_pid = pid;
        if (g_signal != 0) ::kill(static_cast<pid_t>(pid), SIGTERM);  // a signal that came before the pid
      }
    }
    if (line.rfind("Step ", 0) == 0 || line.find(" Step ") != std::string::npos)
      in_thermo = res.run_started = true;
    if (line.rfind("ERROR", 0) == 0 && res.error.empty()) res.error = line.substr(0, line.find('\n'));
    if (const long n = exit_total(line); n >= 0) res.exits = n;
    if (line.rfind("Loop time of", 0) == 0) {
      in_thermo = false;
      std::sscanf(line.c_str(), "Loop time of %lf on %*d procs for %ld steps with %ld atoms", &res.loop_time_s,
                  &res.steps, &res.atoms);
    }
    if (!in_thermo) continue;
    long step, atoms;
    double t;
    if (std::sscanf(line.c_str(), " %ld %lf %ld", &step, &t, &atoms) == 3) {  // thermo: step v_t atoms ...
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (prev_step >= 0 && step > prev_step) res.particle_steps += double(atoms) * double(step - prev_step);
      prev_step = step;
      res.t_last_s = t;
      if (res.t_first_s < 0) res.t_first_s = t;  // a resumed run starts at its restart time
      if (early && early->rel_ci > 0 && !early->stopped &&
          t >= early->t0 + brash::stats::kEarlyStopFirstCheckFraction * (early->t1 - early->t0)) {
        const auto r = resistance_since(hull_force_raws(run_dir), early->t0, t);
        const auto v = brash::stats::early_stop_verdict(r, t, early->t0, early->t1, early->rel_ci, early->trend_check);
        const auto& b = v.blocking;
        if (v.stop) {
          early->stopped = true, early->t_stop = t, early->mean = b.mean, early->ci95 = b.ci95;
          std::ifstream pidf(run_dir / "engine.pid");
          long pid = 0;
          if (pidf >> pid && pid > 0) ::kill(static_cast<pid_t>(pid), SIGTERM);
          std::fprintf(stderr, "\n[brash-liggghts] early stop at t = %.3f s: window mean %.4g N, 95 %% CI +-%.3g N "
                       "(%.2f %% < %.2f %%)\n", t, b.mean, b.ci95, 100 * b.ci95 / std::abs(b.mean), 100 * early->rel_ci);
        }
      }
      if (elapsed - last_csv >= 30.0 || t >= next_csv_t - 1e-9) {
        // the record so far (meta.json says running; the final conversion at the end replaces it)
        last_csv = elapsed;
        while (next_csv_t <= t + 1e-9) next_csv_t += csv_every_model_s;
        convert_hull_force(hull_force_raws(run_dir), run_dir / "hull_force.csv", t);
        if (on_progress) on_progress(res.t_first_s, t, res.particle_steps);
      }
      if (elapsed - last_print >= print_every_s && t > res.t_first_s) {
        last_print = elapsed;
        const double eta = elapsed * (duration_s - t) / (t - res.t_first_s);
        std::fprintf(stderr, "%s[brash-liggghts] t = %.2f / %.2f s (%3.0f%%)  elapsed %.0f s  ETA %.0f s%s", tty ? "\r" : "",
                     t, duration_s, 100 * t / duration_s, elapsed, eta, tty ? "   " : "\n");
      }
    }
  }
  if (tty) std::fprintf(stderr, "\n");
  const int rc = ::pclose(pipe);
  g_engine_pid = 0;
  res.exit_code = WIFEXITED(rc) ? WEXITSTATUS(rc) : 128;
  return res;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"brash-liggghts-run: run a case directory with LIGGGHTS and write the brash run layout"};
  fs::path case_dir, out_dir, runs_root = "runs";
  int ranks = 1;
  double duration = -1, restart_every_s = -1;
  std::string model, treatment;
  bool no_post = false, prepare_only = false;
  fs::path resume_dir;
  auto* case_opt = app.add_option("case_dir", case_dir, "case folder holding case.yaml");
  auto* resume_opt = app.add_option("--resume", resume_dir,
                                    "continue an interrupted run directory from its newest restart file");
  case_opt->excludes(resume_opt);
  app.add_option("--np", ranks, "MPI ranks")->check(CLI::Range(1, 1024));
  app.add_option("--out", out_dir, "run directory (default: runs/<case>-liggghts-<model>-<stamp>)");
  app.add_option("--runs-root", runs_root, "where run directories are created");
  app.add_option("--duration", duration, "simulated time [s] (default: the case's run.duration_s)");
  app.add_option("--model", model, "override fluid.model: drag | added_mass | both");
  app.add_option("--treatment", treatment, "override fluid.treatment: implicit | explicit");
  app.add_option("--restart-every", restart_every_s,
                 "model time [s] between restart files (default: a tenth of the run; also on --resume)")
      ->check(CLI::PositiveNumber);
  app.add_flag("--no-post", no_post, "do not run brash-post afterwards");
  app.add_flag("--prepare-only", prepare_only, "write the run directory's inputs (in.lmp, packing.data, hull.stl) and stop");
  fs::path rebuild_dir;
  auto* rebuild_opt = app.add_option("--rebuild-record", rebuild_dir,
                                     "rewrite a run directory's hull_force.csv from its raw force files (all "
                                     "attempts) with this runner's rules, then run brash-post");
  rebuild_opt->excludes(case_opt)->excludes(resume_opt);
  CLI11_PARSE(app, argc, argv);
  if (!rebuild_dir.empty()) {
    const auto raws = hull_force_raws(rebuild_dir);
    if (raws.empty()) {
      std::cerr << "brash-liggghts-run: error: " << rebuild_dir.string()
                << ": no hull_force.raw or hull_force.part*.raw to rebuild the record from\n";
      return 1;
    }
    try {
      const brash::run::RunDirLock lock(rebuild_dir);  // not while a runner writes it
      const auto rows = convert_hull_force(raws, rebuild_dir / "hull_force.csv");
      std::cerr << "[brash-liggghts] " << (rebuild_dir / "hull_force.csv").string() << ": " << rows
                << " rows from " << raws.size() << " raw file(s)\n";
      // the snapshot index too (dumps a killed attempt left unconverted, and every attempt's snapshots)
      if (fs::is_directory(rebuild_dir / "particles")) {
        const brash::Case c = brash::load_case(rebuild_dir / "case.yaml");
        const std::size_t converted = convert_dumps(rebuild_dir, c);
        std::cerr << "[brash-liggghts] " << (rebuild_dir / "particles" / "index.csv").string()
                  << ": every particles_<step>.csv"
                  << (converted ? fmt::format(" ({} dump(s) converted)", converted) : "") << "\n";
      }
      // and the count of pieces gone through the channel's ends, from the engine's log
      long exits = -1;
      std::ifstream log(rebuild_dir / "log.txt");
      for (std::string line; std::getline(log, line);)
        if (const long n = exit_total(line); n >= 0) exits = n;
      if (exits >= 0) {
        auto meta = nlohmann::json::parse(std::ifstream(rebuild_dir / "meta.json"), nullptr, false);
        if (meta.is_object()) {
          meta["exits"] = exits;
          brash::run::write_meta(rebuild_dir, meta);
          std::cerr << "[brash-liggghts] " << exits
                    << " piece(s) gone through the channel's ends (log.txt)\n";
        }
      }
    } catch (const std::exception& e) {
      std::cerr << "brash-liggghts-run: error: " << e.what() << "\n";
      return 1;
    }
    return no_post ? 0 : brash::run::run_postprocessor(rebuild_dir, "[brash-liggghts]");
  }
  if (case_dir.empty() && resume_dir.empty()) {
    std::cerr << "brash-liggghts-run: error: case_dir (a folder with case.yaml) or --resume RUN_DIR is required\n";
    return 2;
  }
  const bool resume = !resume_dir.empty();
  if (resume && (!model.empty() || !treatment.empty() || duration > 0 || !out_dir.empty())) {
    std::cerr << "brash-liggghts-run: error: --resume continues a run as it was set up; it takes no "
                 "--model/--treatment/--duration/--out\n";
    return 2;
  }

  fs::path run_dir;
  std::optional<brash::run::RunDirLock> run_lock;  // held for the whole run (and by the engine it starts)
  nlohmann::json meta;
  try {
    const fs::path case_file = resume                        ? resume_dir / "case.yaml"
                               : fs::is_directory(case_dir) ? case_dir / "case.yaml"
                                                            : case_dir;
    if (resume && !fs::exists(case_file))
      throw InputError(resume_dir.string() + ": not a run directory (no case.yaml)");
    // Overrides go through the YAML text so they are validated like any case key.
    brash::run::CaseOverrides overrides{model, treatment, duration};
    const brash::Case c = brash::run::load_case_with_overrides(case_file, overrides, "[brash-liggghts]");
    brash::run::prepare_case_inputs(c, case_file, "[brash-liggghts]");
    const double run_duration = c.run.duration_s;
    auto spheres = brash::read_case_packing(c);  // checked against the case before any output
    if (c.speedups.symmetry_y) spheres = brash::liggghts::half_channel_spheres(spheres);
    auto mesh = brash::hull::read_mesh(c.hull.file);
    brash::hull::require_plausible_units(mesh, c.hull.file, c.hull.draft_m, c.hull.lpp_m);
    // Extents and closedness of the full hull (the guard's hull; the contact mesh may be a band or a half).
    const brash::hull::MeshCheck full = brash::hull::check_mesh(mesh);
    const double xmin = full.min_m.x(), xmax = full.max_m.x(), zmin = full.min_m.z(), zmax = full.max_m.z();
    const double hull_half_beam = std::max(std::abs(full.min_m.y()), std::abs(full.max_m.y()));
    if (2 * hull_half_beam >= c.channel.width_m)
      throw InputError(fmt::format("{}: channel.width_m = {} m is not wider than the hull ({} m across in {}): the "
                                   "channel walls would cut the hull",
                                   case_file.string(), c.channel.width_m, 2 * hull_half_beam, c.hull.file.string()));
    const brash::hull::Mesh full_mesh = mesh;
    const bool full_closed = full.closed;
    if (c.hull.band_m) mesh = brash::hull::clip_band(mesh, c.hull.draft_m - (*c.hull.band_m)[0], c.hull.draft_m + (*c.hull.band_m)[1]);
    if (c.speedups.symmetry_y) mesh = brash::liggghts::half_hull(mesh);
    const bool reduced_mesh = c.hull.band_m || c.speedups.symmetry_y;

    const auto box = brash::liggghts::scene_box(c, xmin, xmax, zmin, zmax, run_duration);
    std::vector<std::string> restarts;
    if (resume) {
      // a run still going (another runner, or its orphaned engine) is refused before run_dir is set, so that the
      // refusal does not touch its meta.json
      run_lock.emplace(resume_dir);
      run_dir = resume_dir;
      const auto old_meta = nlohmann::json::parse(std::ifstream(run_dir / "meta.json"), nullptr, false);
      if (!old_meta.is_discarded() && old_meta.value("status", "") == "complete")
        throw InputError(run_dir.string() + ": the run is complete; nothing to resume");
      restarts = restart_candidates(run_dir);
      if (restarts.empty())
        throw InputError(
            run_dir.string() +
            ": no restart file (restart/a.restart, restart/b.restart) to resume from: the run stopped "
            "before its first one was written; run the case again");
    } else {
      const fs::path dir = out_dir.empty() ? brash::run::make_run_dir(runs_root, c.name, "liggghts",
                                                                      std::string(to_string(c.fluid.model)))
                                           : out_dir;
      fs::create_directories(dir / "particles");
      fs::create_directories(dir / "restart");
      run_lock.emplace(dir);  // --out into a run still going is refused (before run_dir is set, as above)
      run_dir = dir;
      brash::run::write_atomic(run_dir / "case.yaml", brash::dump_case_yaml(c));
      brash::hull::write_stl(run_dir / "hull.stl", mesh);
      brash::run::write_atomic(run_dir / "packing.data",
                               brash::liggghts::data_file(spheres, box, c.ice.density_kg_m3,
                                                          c.speedups.symmetry_y ? 4 : 3));
    }
    // The full hull in the run dir, for the guard and the hull flow: hull.stl itself unless the contact mesh is
    // reduced, else hull_full.stl, written once per runner (also on resume when an older run dir lacks it).
    bool full_hull_written = false;
    auto full_hull_file = [&]() -> std::string {
      if (!reduced_mesh) return "hull.stl";
      if (!full_hull_written && (!resume || !fs::exists(run_dir / "hull_full.stl")))
        brash::hull::write_stl(run_dir / "hull_full.stl", full_mesh);
      full_hull_written = true;
      return "hull_full.stl";
    };
    brash::liggghts::SceneOptions opt;
    if (!full_closed || c.guards.max_hull_penetration_d <= 0) {
      opt.guard_hull_file.clear();
      if (!full_closed)
        std::cerr << "[brash-liggghts] note: " << c.hull.file.string()
                  << " is not a closed surface: the hull penetration guard is off\n";
    } else {
      opt.guard_hull_file = full_hull_file();
    }
    // the thin-ship sheet needs the whole hull under water, not the band or the half
    if (c.fluid.hull_flow != brash::HullFlow::None) opt.flow_hull_file = full_hull_file();
    opt.duration_s = run_duration;
    opt.ranks = ranks;
    opt.hull_x_min_m = xmin;
    opt.hull_x_max_m = xmax;
    opt.restart_every_steps = std::max(
        1L, std::lround((restart_every_s > 0 ? restart_every_s : run_duration / 10) / c.run.timestep_s));
    const double restart_every_model_s = static_cast<double>(opt.restart_every_steps) * c.run.timestep_s;
    if (!resume) brash::run::write_atomic(run_dir / "in.lmp", brash::liggghts::input_script(c, box, opt));

    if (prepare_only) {
      std::cout << run_dir.string() << "\n";
      return 0;
    }
    // Wall time and particle-steps are totals over the run's attempts: a resume adds to the last ones
    // recorded (meta.json is refreshed while an engine runs, so a killed attempt counts up to its last
    // refresh), and "attempts" lists each one (start or restart file, model time from and to, wall time).
    double wall_before = 0, particle_steps_before = 0;
    nlohmann::json attempts = nlohmann::json::array();
    if (resume) {
      const auto old_meta = nlohmann::json::parse(std::ifstream(run_dir / "meta.json"), nullptr, false);
      if (old_meta.is_object()) {
        wall_before = old_meta.value("wall_time_s", 0.0);
        particle_steps_before = old_meta.value("particle_steps", 0.0);
        if (old_meta.contains("attempts") && old_meta["attempts"].is_array()) attempts = old_meta["attempts"];
      }
    }
    meta = {{"engine", "liggghts"},
            {"engine_version", "LIGGGHTS 3.8.0 (Debian libliggghts) + fix icefluid"},
            {"fluid_model", to_string(c.fluid.model)},
            {"treatment", to_string(c.fluid.treatment)},
            {"dt_s", c.run.timestep_s},
            {"ranks", ranks},
            {"particles", spheres.size()},
            {"wall_time_s", wall_before},
            {"particle_steps", particle_steps_before},
            {"git_commit", brash::run::git_commit()},
            {"status", "running"},
            {"reason", ""}};
    brash::run::write_meta(run_dir, meta);
    std::cerr << "[brash-liggghts] " << spheres.size() << " spheres, " << mesh.faces.size() << " hull triangles, "
              << ranks << " rank(s) -> " << run_dir.string() << "\n";

    // From here on an engine may run: a signal to the runner is forwarded to it (before, nothing is left behind
    // and the default action ends the runner at once).
    install_signal_forwarding();
    const auto t0 = std::chrono::steady_clock::now();
    attempts.push_back({{"from", resume ? "restart" : "start"},
                        {"t_from_s", nullptr},
                        {"t_to_s", nullptr},
                        {"wall_s", 0.0}});
    meta["attempts"] = attempts;
    const ProgressHook on_progress = [&](double t_first, double t, double particle_steps) {
      auto& a = meta["attempts"].back();
      a["t_from_s"] = t_first;
      a["t_to_s"] = t;
      a["wall_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      meta["wall_time_s"] = wall_before + a["wall_s"].get<double>();
      meta["particle_steps"] = particle_steps_before + particle_steps;
      meta["model_time_reached_s"] = t;
      brash::run::write_meta(run_dir, meta);
    };
    EngineResult res;
    EarlyStop early{c.speedups.early_stop_rel_ci, c.run.window_s[0], c.run.window_s[1],
                    c.speedups.early_stop_trend_check};
    if (!resume) {
      res = run_engine(run_dir, ranks, run_duration, "in.lmp", &early, restart_every_model_s, on_progress);
    } else {
      for (const auto& restart : restarts) {
        // Keep what the earlier engine wrote (a killed attempt, or the one before this retry: each engine
        // opens hull_force.raw anew); the resumed run re-emits rows from its restart step on.
        if (fs::exists(run_dir / "hull_force.raw"))
          fs::rename(run_dir / "hull_force.raw",
                     run_dir / fmt::format("hull_force.part{}.raw", hull_force_raws(run_dir).size()));
        opt.restart_file = restart;
        brash::run::write_atomic(run_dir / "in_resume.lmp", brash::liggghts::input_script(c, box, opt));
        std::cerr << "[brash-liggghts] resuming " << run_dir.string() << " from " << restart << "\n";
        meta["resumed_from"] = restart;
        res = run_engine(run_dir, ranks, run_duration, "in_resume.lmp", &early, restart_every_model_s,
                         on_progress);
        if (early.stopped || g_signal != 0 || (res.exit_code == 0 && res.error.empty())) break;
        std::cerr << "[brash-liggghts] resume from " << restart << " failed: " << res.error << "\n";
        // An older restart file helps when this one could not be read; a run that began and then stopped (a
        // guard, bad dynamics) would only stop again the same way from an earlier point.
        if (res.run_started) break;
      }
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const auto raws = hull_force_raws(run_dir);
    // after an early stop the record ends at the stop (rows the engine wrote before the signal landed, and a
    // killed earlier attempt's rows beyond it, are not part of the run)
    const auto rows = raws.empty() ? 0
                                   : convert_hull_force(raws, run_dir / "hull_force.csv",
                                                        early.stopped ? early.t_stop
                                                                      : std::numeric_limits<double>::infinity());
    convert_dumps(run_dir, c);
    meta["wall_time_s"] = wall_before + wall;
    meta["attempts"].back()["wall_s"] = wall;
    if (res.t_last_s >= 0) {
      meta["attempts"].back()["t_from_s"] = res.t_first_s;
      meta["attempts"].back()["t_to_s"] = res.t_last_s;
      meta["model_time_reached_s"] = res.t_last_s;
    }
    meta["loop_time_s"] = res.loop_time_s;  // this attempt's engine loop
    if (res.exits >= 0) meta["exits"] = res.exits;
    meta["particle_steps"] = particle_steps_before +
                             (res.steps > 0 ? static_cast<double>(res.atoms) * static_cast<double>(res.steps)
                                            : res.particle_steps);
    meta["hull_force_rows"] = rows;
    if (early.stopped) {
      // The run ends at the stop: the resolved case says so, the window ends there, meta records why.
      brash::Case stopped = c;
      stopped.run.duration_s = early.t_stop;
      stopped.run.window_s[1] = early.t_stop;
      brash::run::write_atomic(run_dir / "case.yaml", brash::dump_case_yaml(stopped));
      meta["early_stop"] = {{"t_s", early.t_stop},          {"requested_duration_s", run_duration},
                            {"rel_ci_threshold", early.rel_ci}, {"mean_N", early.mean},
                            {"ci95_N", early.ci95}};
      res.exit_code = 0;
      res.error.clear();
      if (!resume)  // (a resumed run keeps the sum over its attempts)
        meta["particle_steps"] =
            static_cast<double>(spheres.size()) * std::round(early.t_stop / c.run.timestep_s);
    }
    if (g_signal != 0 && !early.stopped) {
      meta["status"] = "interrupted";
      // a signal before the first periodic restart file leaves nothing to resume from: say so, not "--resume"
      meta["reason"] =
          restart_candidates(run_dir).empty()
              ? fmt::format(
                    "signal {} ({}): the engine was stopped before its first restart file was written; "
                    "nothing to resume, run the case again",
                    static_cast<int>(g_signal), strsignal(g_signal))
              : fmt::format(
                    "signal {} ({}): the engine was stopped; continue with brash-liggghts-run --resume {}",
                    static_cast<int>(g_signal), strsignal(g_signal), run_dir.string());
      brash::run::write_meta(run_dir, meta);
      std::cerr << "[brash-liggghts] interrupted: " << meta["reason"].get<std::string>() << "\n";
      return 128 + g_signal;
    }
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
  return no_post ? 0 : brash::run::run_postprocessor(run_dir, "[brash-liggghts]");
}
