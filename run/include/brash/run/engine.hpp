// The interface between the run driver (brash/run/driver.hpp) and an engine. The driver owns everything a run
// does around the engine (run directory, meta.json, resume, signals, progress, early stop, the postprocessor);
// an engine adapter only translates: it builds its scene from the case, advances it, writes and reads its
// restart files and reads its hull-force record. Adapters: LIGGGHTS (plugin/liggghts/runner), ODE
// (plugin/ode), YADE (plugin/yade).
#pragma once
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "brash/case.hpp"
#include "brash/run/force_record.hpp"  // ForceRecord
#include "brash/packing.hpp"

namespace brash::run {

enum class StopReason { None, EarlyStop, Signal };

// What an engine reports to the driver while it advances, and how the driver asks it to stop.
class Monitor {
 public:
  virtual ~Monitor() = default;
  // The process the engine runs in while it is a child process (0 once it ended): a stop signal the driver
  // receives is forwarded to it at once.
  virtual void engine_process(long pid) = 0;
  // Model time t_s reached, with the particle-steps this attempt has done; called at the engine's check points
  // (every 1/200 of the run). `detail` ends the progress line. True: stop now (the early stop or a signal);
  // the engine ends the attempt where it is, keeping what it wrote.
  virtual bool progress(double t_s, double particle_steps, std::string_view detail = {}) = 0;
  virtual StopReason stop_reason() const = 0;
};

// What one attempt (a start, or a resume from one restart file) did.
struct Attempt {
  bool started = false;      // the engine got past its set-up (a restart file was read): the run began
  double t_first_s = -1;     // model time of the attempt's first and last check point (-1: none)
  double t_last_s = -1;
  double particle_steps = 0; // of this attempt
  std::string error;         // empty: it reached the end or stopped on request
  nlohmann::json meta;       // engine-specific meta.json keys (loop time, exits, phase times, ...)
};

class Engine {
 public:
  virtual ~Engine() = default;
  virtual std::string name() const = 0;     // "liggghts": run directory names, meta.json "engine"
  virtual std::string runner() const = 0;   // the command a user resumes with, e.g. "brash-liggghts-run"
  virtual nlohmann::json meta() const = 0;  // engine_version, ranks, threads, stepper settings ...
  // Whether a run may start from the settled bed (ice.settle): it is made with LIGGGHTS' soft contacts, whose
  // equilibrium overlaps a rigid-contact engine would push apart.
  virtual bool starts_from_settled_bed() const { return false; }
  // Whether the engine runs the half channel of speedups.symmetry_y and idles the far field of speedups.farfield
  // itself. An engine that does not has the key refused by name: it would run the whole channel, every piece
  // awake, while the case says otherwise.
  virtual bool runs_half_channel() const { return false; }
  virtual bool idles_far_field() const { return false; }
  virtual bool moves_window() const { return false; }  // speedups.moving_window
  // Why the far field's wake rule `by` (speedups.farfield_wake_by) would be wrong on this engine or is not built
  // in it, and the rule to use instead; empty: the engine runs it.
  struct WakeRefusal {
    std::string why;
    WakeBy instead = WakeBy::Force;
  };
  virtual WakeRefusal wake_refusal(WakeBy /*by*/) const { return {}; }

  // Checks the case against what this engine can run and reads what the scene needs (hull, packing), before
  // any output is written. Throws InputError naming the case file.
  virtual void load(const Case& c, const std::filesystem::path& case_file, const std::vector<Sphere>& spheres) = 0;
  // Writes the scene's inputs into the run directory (a new run; on resume, what an older run dir lacks).
  virtual void write_scene(const std::filesystem::path& run_dir, bool resume) = 0;
  // Restart points of a run directory, newest first (empty: nothing to resume from).
  virtual std::vector<std::string> restarts(const std::filesystem::path& run_dir) const = 0;
  // Advances the scene from its start (restart empty) or from a restart point to the case's end.
  virtual Attempt advance(const std::filesystem::path& run_dir, const std::string& restart, Monitor& monitor) = 0;
  // The hull-force record so far, rows with t <= t_max_s, in time order (earlier attempts' rows included), with
  // the hull force split (ForceRecord::set_split) when the engine records it for every row.
  virtual ForceRecord force_record(const std::filesystem::path& run_dir, double t_max_s) const = 0;
  // After the last attempt: completes the run layout (snapshot index, ...).
  virtual void finish(const std::filesystem::path& /*run_dir*/) {}
};

}  // namespace brash::run
