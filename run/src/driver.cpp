#include "brash/run/driver.hpp"

#include <chrono>
#include <cmath>
#include <cstring>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <fstream>
#include <iostream>
#include <limits>
#include <optional>

#include "brash/error.hpp"
#include "brash/run/force_record.hpp"
#include "brash/run/run_layout.hpp"
#include "brash/run/settle.hpp"
#include "brash/run/stages.hpp"
#include "run_monitor.hpp"
#include "stop_signals.hpp"

namespace fs = std::filesystem;

namespace brash::run {
namespace {

fs::path case_file_of(const DriverOptions& o) {
  if (!o.resume_dir.empty()) return o.resume_dir / "case.yaml";
  return fs::is_directory(o.case_path) ? o.case_path / "case.yaml" : o.case_path;
}

nlohmann::json read_meta(const fs::path& run_dir) {
  return nlohmann::json::parse(std::ifstream(run_dir / "meta.json"), nullptr, false);
}

bool is_complete(const fs::path& run_dir) {
  const auto meta = read_meta(run_dir);
  return !meta.is_discarded() && meta.value("status", "") == "complete";
}

// A run directory to resume (locked by the caller): one with a restart point.
fs::path open_resumed_run(const Engine& engine, const fs::path& run_dir) {
  if (engine.restarts(run_dir).empty())
    throw InputError(run_dir.string() +
                     ": no restart file to resume from: the run stopped before its first one was written; run the "
                     "case again");
  return run_dir;
}

fs::path open_new_run(const Engine& engine, const Case& c, const DriverOptions& o, std::optional<RunDirLock>& lock) {
  const fs::path dir = o.out_dir.empty()
                           ? make_run_dir(o.runs_root, c.name, engine.name(), std::string(to_string(c.fluid.model)))
                           : o.out_dir;
  fs::create_directories(dir / "particles");
  fs::create_directories(dir / "restart");
  lock.emplace(dir);  // --out into a run still going is refused
  write_atomic(dir / "case.yaml", dump_case_yaml(c));
  return dir;
}

nlohmann::json initial_meta(const Engine& engine, const Case& c, std::size_t particles) {
  nlohmann::json meta = {{"engine", engine.name()},
                         {"fluid_model", to_string(c.fluid.model)},
                         {"treatment", to_string(c.fluid.treatment)},
                         {"dt_s", c.run.timestep_s},
                         {"particles", particles},
                         {"wall_time_s", 0.0},
                         {"particle_steps", 0.0},
                         {"git_commit", git_commit()},
                         {"status", "running"},
                         {"reason", ""}};
  const nlohmann::json engine_meta = engine.meta();
  for (const auto& [key, value] : engine_meta.items()) meta[key] = value;
  return meta;
}

// meta.json "stages" of a new run (brash/run/stages.hpp): what the packing and the settled bed cost, made now or
// before, and the set-up of the scene; run_s and post_s follow when the run and its report are done.
nlohmann::json initial_stages(const Case& c, bool packing_made_now, bool bed_made_now, const fs::path& start_file,
                              double setup_s) {
  nlohmann::json s = {{"packing", made_input(packing_wall_s(c.ice.packing_file), packing_made_now)}};
  if (c.ice.settle) s["settling"] = made_input(settled_bed_wall_s(start_file), bed_made_now);
  s["setup_s"] = setup_s;
  return s;
}

// The attempt of a run: from the start, or from the newest restart point that can be read (a restart file that
// cannot be read is no attempt of its own: the next older one is tried, within the same attempt).
Attempt run_attempt(Engine& engine, const fs::path& run_dir, bool resume, RunRecord& record, RunMonitor& monitor,
                    const std::string& tag) {
  const std::vector<std::string> restarts = resume ? engine.restarts(run_dir) : std::vector<std::string>{""};
  record.begin_attempt(resume ? "restart" : "start");
  Attempt attempt;
  for (const auto& restart : restarts) {
    if (resume) {
      std::cerr << tag << " resuming " << run_dir.string() << " from " << restart << "\n";
      record.meta()["resumed_from"] = restart;
    }
    monitor.start_attempt();
    attempt = engine.advance(run_dir, restart, monitor);
    monitor.end_line();
    if (monitor.stop_reason() != StopReason::None || attempt.error.empty() || !resume) break;
    std::cerr << tag << " resume from " << restart << " failed: " << attempt.error << "\n";
    // An older restart point helps when this one could not be read; a run that began and then stopped (a guard,
    // bad dynamics) would only stop again the same way from an earlier point.
    if (attempt.started) break;
  }
  record.end_attempt(attempt);
  return attempt;
}

// The run ends at the early stop: the resolved case says so, the window ends there, meta.json records why.
void record_early_stop(const Case& c, const fs::path& run_dir, const EarlyStopState& early, nlohmann::json& meta) {
  Case stopped = c;
  stopped.run.duration_s = early.t_s;
  stopped.run.window_s[1] = std::min(stopped.run.window_s[1], early.t_s);
  write_atomic(run_dir / "case.yaml", dump_case_yaml(stopped));
  auto e = to_json(early);
  e["requested_duration_s"] = c.run.duration_s;
  e["requested_window_s"] = {c.run.window_s[0], c.run.window_s[1]};
  e["rel_ci_threshold"] = c.speedups.early_stop_rel_ci;
  meta["early_stop"] = e;
  meta.erase("early_stop_last_check");  // the stop is the last check
}

// status, reason and the exit status of a run whose last attempt ended.
int conclude(const Engine& engine, const fs::path& run_dir, const Attempt& attempt, int signal, bool early_stopped,
             nlohmann::json& meta, const std::string& tag) {
  if (signal != 0 && !early_stopped) {
    meta["status"] = "interrupted";
    // a signal before the first restart point leaves nothing to resume from: say so, not "--resume"
    meta["reason"] = engine.restarts(run_dir).empty()
                         ? fmt::format("signal {} ({}): the engine was stopped before its first restart file was "
                                       "written; nothing to resume, run the case again",
                                       signal, strsignal(signal))
                         : fmt::format("signal {} ({}): the engine was stopped; continue with {} --resume {}", signal,
                                       strsignal(signal), engine.runner(), run_dir.string());
    std::cerr << tag << " interrupted: " << meta["reason"].get<std::string>() << "\n";
    return 128 + signal;
  }
  if (!attempt.error.empty() && !early_stopped) {
    meta["status"] = "failed";
    meta["reason"] = attempt.error;
    std::cerr << tag << " run failed: " << attempt.error << " (see " << (run_dir / "log.txt").string() << ")\n";
    return 1;
  }
  meta["status"] = "complete";
  return 0;
}

}  // namespace

double restart_interval_s(const Case& c, double restart_every_s) {
  const double every = restart_every_s > 0 ? restart_every_s : c.run.duration_s / 10;
  return static_cast<double>(std::max(1L, std::lround(every / c.run.timestep_s))) * c.run.timestep_s;
}

Case load_run_case(const DriverOptions& o, const std::string& tag) {
  const bool resume = !o.resume_dir.empty();
  if (resume && !fs::exists(o.resume_dir / "case.yaml"))
    throw InputError(o.resume_dir.string() + ": not a run directory (no case.yaml)");
  return load_case_with_overrides(case_file_of(o), resume ? CaseOverrides{} : o.overrides, tag);
}

namespace {

// A run is a case or a resume; a resume continues the run as it was set up. Empty: fine, else the complaint.
std::string options_problem(const DriverOptions& o) {
  if (o.case_path.empty() && o.resume_dir.empty()) return "case_dir (a folder with case.yaml) or --resume RUN_DIR is required";
  const auto& v = o.overrides;
  if (!o.resume_dir.empty() &&
      (!v.model.empty() || !v.treatment.empty() || v.duration_s > 0 || !v.sets.empty() || !o.out_dir.empty()))
    return "--resume continues a run as it was set up (its case.yaml); it takes no "
           "--model/--treatment/--duration/--set/--out";
  return {};
}

// Case keys that only some engines carry out: refused by name on the others, before any output; one message names
// every such key and the copy of the case that this engine runs.
void refuse_what_the_engine_cannot_run(const Case& c, const fs::path& case_file, const Engine& engine) {
  std::vector<std::string> reasons, sets;
  const auto refuse = [&](const std::string& key, const std::string& what, const std::string& instead) {
    reasons.push_back(fmt::format("{}: true: {} is made on LIGGGHTS (brash-liggghts-run); {} {}", key, what,
                                  engine.runner(), instead));
    sets.push_back(fmt::format(" --set {}=false", key));
  };
  if (c.ice.settle && !engine.starts_from_settled_bed())
    refuse("ice.settle", "the settled bed", "starts from the packing (ice.settle: false)");
  if (c.speedups.symmetry_y && !engine.runs_half_channel())
    refuse("speedups.symmetry_y", "the half channel", "runs the whole channel (speedups.symmetry_y: false)");
  if (c.speedups.farfield && !engine.idles_far_field())
    refuse("speedups.farfield", "the idle far field", "integrates every piece (speedups.farfield: false)");
  if (c.speedups.moving_window && !engine.moves_window())
    refuse("speedups.moving_window", "the moving window", "runs the whole channel (speedups.moving_window: false)");
  if (const Engine::WakeRefusal no = engine.wake_refusal(c.speedups.farfield_wake_by);
      c.speedups.farfield && engine.idles_far_field() && !no.why.empty()) {
    reasons.push_back(fmt::format("speedups.farfield_wake_by: {}: {}", to_string(c.speedups.farfield_wake_by), no.why));
    sets.push_back(fmt::format(" --set speedups.farfield_wake_by={}", to_string(no.instead)));
  }
  if (reasons.empty()) return;
  throw InputError(fmt::format("{}: {}. Run a copy made with `brash-case derive {}{} --out DIR`", case_file.string(),
                               fmt::join(reasons, "; "), case_file.parent_path().string(), fmt::join(sets, "")));
}

}  // namespace

int drive(Engine& engine, const DriverOptions& o) {
  if (const std::string problem = options_problem(o); !problem.empty()) {
    std::cerr << engine.runner() << ": error: " << problem << "\n";
    return 2;
  }
  const std::string tag = "[brash-" + engine.name() + "]";
  const bool resume = !o.resume_dir.empty();
  fs::path run_dir;
  std::optional<RunDirLock> lock;  // held for the whole run (and by an engine process it starts)
  std::optional<RunRecord> record;
  try {
    const fs::path case_file = case_file_of(o);
    const Case c = load_run_case(o, tag);
    const bool packing_made_now = !fs::exists(c.ice.packing_file);
    prepare_case_inputs(c, case_file, tag);
    refuse_what_the_engine_cannot_run(c, case_file, engine);
    Case start = c;  // the packing, or its settled bed (ice.settle, brash/run/settle.hpp)
    const StartingPacking starting = starting_packing(c, tag);
    start.ice.packing_file = starting.file;
    const auto setup_start = std::chrono::steady_clock::now();
    const auto spheres = read_case_packing(  // checked against the case before any output
        start, c.ice.settle ? kSettledBedMaxOverlapOverD : kPackingMaxOverlapOverD);
    engine.load(c, case_file, spheres);
    if (resume) {
      lock.emplace(o.resume_dir);  // a run still going is refused before anything is touched
      if (is_complete(o.resume_dir)) {
        std::cerr << tag << " " << o.resume_dir.string() << ": the run is complete; nothing to resume\n";
        return 0;
      }
    }
    run_dir = resume ? open_resumed_run(engine, o.resume_dir) : open_new_run(engine, c, o, lock);
    engine.write_scene(run_dir, resume);
    if (o.prepare_only) {
      std::cout << run_dir.string() << "\n";
      return 0;
    }
    const auto old_meta = resume ? read_meta(run_dir) : nlohmann::json();
    record.emplace(run_dir, old_meta.is_object() ? old_meta : initial_meta(engine, c, spheres.size()));
    if (!resume)  // a resume continues the run its stages describe
      record->meta()["stages"] = initial_stages(c, packing_made_now, starting.made_now, starting.file,
                                                seconds_since(setup_start));
    record->meta()["status"] = "running";
    record->meta()["reason"] = "";
    record->write();
    std::cerr << tag << " " << spheres.size() << " spheres -> " << run_dir.string() << "\n";

    StopSignals signals;  // from here on a signal is forwarded to the engine
    RunMonitor monitor(engine, c, run_dir, *record, signals, restart_interval_s(c, o.restart_every_s), tag,
                       o.progress);
    const Attempt attempt = run_attempt(engine, run_dir, resume, *record, monitor, tag);
    const auto& early = monitor.early_stop();
    auto& meta = record->meta();
    meta["hull_force_rows"] = write_hull_force_csv(
        run_dir / "hull_force.csv",
        engine.force_record(run_dir, early.stopped ? early.t_s : std::numeric_limits<double>::infinity()));
    engine.finish(run_dir);
    if (early.stopped) record_early_stop(c, run_dir, early, meta);
    const int status = conclude(engine, run_dir, attempt, signals.received(), early.stopped, meta, tag);
    if (meta.contains("stages")) meta["stages"]["run_s"] = meta["wall_time_s"];
    record->write();
    if (status != 0) return status;
    std::cerr << fmt::format("{} done in {:.1f} s ({:.3g} particle-steps/s)\n", tag, record->attempt_wall_s(),
                             attempt.particle_steps / std::max(1e-9, record->attempt_wall_s()));
  } catch (const std::exception& e) {
    std::cerr << engine.runner() << ": error: " << e.what() << "\n";
    if (record) {
      record->meta()["status"] = "failed";
      record->meta()["reason"] = e.what();
      record->write();
    }
    return dynamic_cast<const InputError*>(&e) ? 2 : 1;
  }
  std::cout << run_dir.string() << "\n";
  if (!o.post) return 0;
  const auto post_start = std::chrono::steady_clock::now();
  const int post = run_postprocessor(run_dir, tag);
  if (record->meta().contains("stages")) {
    record->meta()["stages"]["post_s"] = seconds_since(post_start);
    record->write();
  }
  return post;
}

}  // namespace brash::run
