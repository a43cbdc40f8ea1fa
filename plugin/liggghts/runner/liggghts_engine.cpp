#include "liggghts_engine.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fmt/format.h>
#include <fstream>
#include <iostream>
#include <sstream>

#include "brash/case_hull_flow.hpp"
#include "brash/run/child_process.hpp"
#include "brash/run/hull_regions.hpp"
#include "brash/error.hpp"
#include "brash/hull/hydrostatics.hpp"
#include "brash/hull/panel_flow.hpp"
#include "brash/run/run_layout.hpp"
#include "brash/run/runner_setup.hpp"

namespace fs = std::filesystem;

namespace brash::liggghts {

std::vector<fs::path> hull_force_raws(const fs::path& run_dir) {
  std::vector<fs::path> parts;
  for (int k = 1; fs::exists(run_dir / fmt::format("hull_force.part{}.raw", k)); ++k)
    parts.push_back(run_dir / fmt::format("hull_force.part{}.raw", k));
  if (fs::exists(run_dir / "hull_force.raw")) parts.push_back(run_dir / "hull_force.raw");
  return parts;
}

// Rows of hull_force*.raw (fix ave/time: "step t fx fy fz", then the hull force split of fix brash/hullsplit
// when the deck records it: kSplitColumns) by step. The raw files of a resumed run are read in order; a later
// file's row for a step replaces an earlier one. While a resumed run goes, an earlier attempt's rows beyond the
// current time are not (yet) this run's: t_max_s leaves them out. The split is kept when every row has it (an
// attempt from an older deck has none: then the record has no split rather than part of one).
run::ForceRecord read_hull_force_raws(const std::vector<fs::path>& raws, double t_max_s) {
  constexpr std::size_t n_split = run::kSplitColumns.size();
  struct Row {
    run::ForceRow r;
    std::array<double, n_split> split{};
    bool has_split = false;
  };
  std::map<long, Row> rows;
  for (const auto& raw : raws) {
    std::ifstream in(raw);
    std::string line;
    long first_step = -1;
    while (std::getline(in, line)) {
      if (line.empty() || line[0] == '#') continue;
      std::istringstream ss(line);
      long step;
      Row row;
      run::ForceRow& r = row.r;
      if (!(ss >> step >> r.t_s >> r.fx_N >> r.fy_N >> r.fz_N)) continue;  // a truncated last line of a killed run
      std::size_t k = 0;
      while (k < n_split && ss >> row.split[k]) ++k;
      if (k != 0 && k != n_split) continue;  // a split cut short: the truncated last line of a killed run
      row.has_split = k == n_split;
      if (first_step < 0) first_step = step;
      // A resumed attempt's first row is its set-up (no contact force summed yet: 0): never a record. The
      // earlier attempt's row for that step is kept; without one the step is missing, which brash-post names
      // as a gap.
      if (step == first_step && &raw != &raws.front()) continue;
      rows[step] = row;
    }
  }
  run::ForceRecord out;
  std::vector<double> split;
  bool every_row_split = true;
  for (const auto& [step, row] : rows) {
    if (row.r.t_s > t_max_s) continue;
    out.rows.push_back(row.r);
    every_row_split = every_row_split && row.has_split;
    split.insert(split.end(), row.split.begin(), row.split.end());
  }
  if (every_row_split && !out.rows.empty()) out.set_split(split);
  return out;
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

nlohmann::json LiggghtsEngine::meta() const {
  return {{"engine_version", "LIGGGHTS 3.8.0 (Debian libliggghts) + fix icefluid"},
          {"ranks", ranks_},
          {"launcher", launch_prefix_.empty() ? "none (one rank)" : launch_prefix_.substr(0, launch_prefix_.size() - 1)},
          {"particles", spheres_.size()},  // the half channel's with speedups.symmetry_y
          {"hull_split", run::hull_split_meta(options_.hull_regions)}};
}

void LiggghtsEngine::load(const Case& c, const fs::path& case_file, const std::vector<Sphere>& spheres) {
  case_ = c;
  spheres_ = c.speedups.symmetry_y ? half_channel_spheres(spheres) : spheres;
  full_mesh_ = hull::read_mesh(c.hull.file);
  hull::require_plausible_units(full_mesh_, c.hull.file, c.hull.draft_m, c.hull.lpp_m);
  // Extents and closedness of the full hull (the guard's hull; the contact mesh may be a band or a half).
  const hull::MeshCheck full = hull::check_mesh(full_mesh_);
  full_closed_ = full.closed;
  const double half_beam = std::max(std::abs(full.min_m.y()), std::abs(full.max_m.y()));
  if (2 * half_beam >= c.channel.width_m)
    throw InputError(fmt::format("{}: channel.width_m = {} m is not wider than the hull ({} m across in {}): the "
                                 "channel walls would cut the hull",
                                 case_file.string(), c.channel.width_m, 2 * half_beam, c.hull.file.string()));
  // the hull force split's regions: the parallel mid-body measured on the full hull (brash/core/hull_split.hpp)
  options_.hull_regions = run::measure_hull_regions(full_mesh_, c, case_file);
  contact_mesh_ = full_mesh_;
  if (c.hull.band_m)
    contact_mesh_ = hull::clip_band(contact_mesh_, c.hull.draft_m - (*c.hull.band_m)[0], c.hull.draft_m + (*c.hull.band_m)[1]);
  if (c.speedups.symmetry_y) contact_mesh_ = half_hull(contact_mesh_);
  box_ = scene_box(c, full.min_m.x(), full.max_m.x(), full.min_m.z(), full.max_m.z(), c.run.duration_s);
  options_.duration_s = c.run.duration_s;
  options_.ranks = ranks_;
  options_.hull_x_min_m = full.min_m.x();
  options_.hull_x_max_m = full.max_m.x();
  options_.hull_half_beam_m = half_beam;
  options_.restart_every_steps = std::max(
      1L, std::lround((restart_every_s_ > 0 ? restart_every_s_ : c.run.duration_s / 10) / c.run.timestep_s));
}

// hull.stl (the contact mesh), packing.data and in.lmp; the full hull as hull_full.stl when the contact mesh is
// reduced (the guard and the hull flow need the whole hull; an older run dir resumed may lack it).
void LiggghtsEngine::write_scene(const fs::path& run_dir, bool resume) {
  const bool reduced = case_.hull.band_m || case_.speedups.symmetry_y;
  const std::string full_file = reduced ? "hull_full.stl" : "hull.stl";
  if (reduced && (!resume || !fs::exists(run_dir / full_file)) &&
      (case_.fluid.hull_flow != HullFlow::None || (full_closed_ && case_.guards.max_hull_penetration_d > 0)))
    hull::write_stl(run_dir / full_file, full_mesh_);
  options_.guard_hull_file = full_closed_ && case_.guards.max_hull_penetration_d > 0 ? full_file : "";
  if (!full_closed_)
    std::cerr << "[brash-liggghts] note: " << case_.hull.file.string()
              << " is not a closed surface: the hull penetration guard is off\n";
  // the flow around the whole hull (not the band or the half), computed once here (brash::hull_flow_table)
  if (case_.fluid.hull_flow != HullFlow::None) {
    options_.flow_hull_file = "hull_flow.bin";
    if (!resume || !fs::exists(run_dir / options_.flow_hull_file))
      hull::write_flow_table(run_dir / options_.flow_hull_file, hull_flow_table(case_, full_mesh_),
                             std::string(to_string(case_.fluid.hull_flow)));
  }
  if (resume) return;
  hull::write_stl(run_dir / "hull.stl", contact_mesh_);
  run::write_atomic(run_dir / "packing.data",
                    data_file(spheres_, box_, case_.ice.density_kg_m3, case_.speedups.symmetry_y ? 4 : 3));
  run::write_atomic(run_dir / "in.lmp", input_script(case_, box_, options_));
}

// Periodic restart files, newest first (LIGGGHTS alternates between a and b; a kill while one is written leaves
// the other intact).
std::vector<std::string> LiggghtsEngine::restarts(const fs::path& run_dir) const {
  std::vector<std::pair<fs::file_time_type, std::string>> found;
  for (const char* name : {"restart/a.restart", "restart/b.restart"})
    if (fs::exists(run_dir / name) && fs::file_size(run_dir / name) > 0)
      found.emplace_back(fs::last_write_time(run_dir / name), name);
  std::sort(found.begin(), found.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  std::vector<std::string> out;
  for (const auto& f : found) out.push_back(f.second);
  return out;
}

run::ForceRecord LiggghtsEngine::force_record(const fs::path& run_dir, double t_max_s) const {
  return read_hull_force_raws(hull_force_raws(run_dir), t_max_s);
}

void LiggghtsEngine::finish(const fs::path& run_dir) { convert_dumps(run_dir, case_); }

namespace {

// What the engine's screen output says, line by line.
struct ScreenState {
  bool started = false;  // the thermo header came: the input (and a restart file) was read, the run began
  bool in_thermo = false;
  long prev_step = -1, steps = 0, atoms = 0;
  double loop_time_s = 0;
  long exits = -1;
  std::string error;
};

// A thermo line "step v_t atoms ..." -> (step, t, atoms); false for any other line.
bool read_thermo(ScreenState& s, const std::string& line, long& step, double& t, long& atoms) {
  if (line.rfind("Step ", 0) == 0 || line.find(" Step ") != std::string::npos) {
    s.in_thermo = s.started = true;
    return false;
  }
  if (line.rfind("ERROR", 0) == 0 && s.error.empty()) s.error = line.substr(0, line.find('\n'));
  if (const long n = exit_total(line); n >= 0) s.exits = n;
  if (line.rfind("Loop time of", 0) == 0) {
    s.in_thermo = false;
    std::sscanf(line.c_str(), "Loop time of %lf on %*d procs for %ld steps with %ld atoms", &s.loop_time_s, &s.steps,
                &s.atoms);
  }
  return s.in_thermo && std::sscanf(line.c_str(), " %ld %lf %ld", &step, &t, &atoms) == 3;
}

}  // namespace

// Runs the engine (under the MPI launcher when ranks > 1) on the input script, copies its screen output to log.txt, reports
// each thermo line to the monitor and stops the engine (SIGTERM) when the monitor asks.
run::Attempt LiggghtsEngine::advance(const fs::path& run_dir, const std::string& restart, run::Monitor& monitor) {
  std::string input = "in.lmp";
  if (!restart.empty()) {
    // Keep what the earlier engine wrote (each engine opens hull_force.raw anew); the resumed run re-emits rows
    // from its restart step on.
    if (fs::exists(run_dir / "hull_force.raw"))
      fs::rename(run_dir / "hull_force.raw",
                 run_dir / fmt::format("hull_force.part{}.raw", hull_force_raws(run_dir).size()));
    options_.restart_file = restart;
    input = "in_resume.lmp";
    run::write_atomic(run_dir / input, input_script(case_, box_, options_));
  }
  const run::ChildCommand command{
      run_dir, "", launch_prefix_ + run::shell_quote(run::executable_dir() / "brash-liggghts") + " -in " + input + " -log none"};
  std::ofstream log(run_dir / "log.txt", std::ios::app);
  run::Attempt a;
  ScreenState screen;
  double t_stop = -1;
  const auto on_line = [&](const std::string& line) {
    log << line << std::flush;  // a runner killed outright (kill -9) loses no line
    long step, atoms;
    double t;
    if (!read_thermo(screen, line, step, t, atoms)) return false;
    if (screen.prev_step >= 0 && step > screen.prev_step) a.particle_steps += double(atoms) * double(step - screen.prev_step);
    screen.prev_step = step;
    a.t_last_s = t;
    if (a.t_first_s < 0) a.t_first_s = t;
    if (!monitor.progress(t, a.particle_steps)) return false;
    if (t_stop < 0) t_stop = t;
    return true;
  };
  const int exit_code = run::run_child(command, {[&](long pid) { monitor.engine_process(pid); }, on_line}).code;
  a.started = screen.started;
  if (screen.steps > 0) a.particle_steps = double(screen.atoms) * double(screen.steps);
  if (monitor.stop_reason() == run::StopReason::EarlyStop && t_stop >= 0)  // the engine ran on until the signal landed
    a.particle_steps = double(spheres_.size()) * std::round((t_stop - std::max(0.0, a.t_first_s)) / case_.run.timestep_s);
  if (exit_code != 0 || !screen.error.empty())
    a.error = screen.error.empty() ? fmt::format("LIGGGHTS exited with code {}", exit_code) : screen.error;
  a.meta["loop_time_s"] = screen.loop_time_s;
  if (screen.exits >= 0) a.meta["exits"] = screen.exits;
  return a;
}

}  // namespace brash::liggghts
