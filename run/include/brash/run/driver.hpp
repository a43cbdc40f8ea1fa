// The run driver: everything a run does around its engine, the same for LIGGGHTS, ODE and YADE
// (docs/case_format.md "Run directory"): the run directory and its lock, case.yaml and meta.json, the attempts
// of a resumed run, stop signals (forwarded to an engine process), progress with ETA, the early stop
// (speedups.early_stop_rel_ci), hull_force.csv and the postprocessor at the end.
#pragma once
#include <filesystem>
#include <string>

#include "brash/run/engine.hpp"
#include "brash/run/runner_setup.hpp"

namespace brash::run {

struct DriverOptions {
  std::filesystem::path case_path;       // case folder or its case.yaml (a new run)
  std::filesystem::path resume_dir;      // a run directory to continue (instead of case_path)
  std::filesystem::path out_dir;         // run directory of a new run; empty: <runs_root>/<case>-<engine>-<model>-<stamp>
  std::filesystem::path runs_root = "runs";
  CaseOverrides overrides;               // --model, --treatment, --duration (new runs only)
  double restart_every_s = -1;           // model time between restart files; <= 0: a tenth of the run
  bool prepare_only = false;             // write the run directory's inputs and stop
  bool post = true;                      // run brash-post on a complete run
  bool progress = true;                  // the progress line with ETA on stderr
};

// The case a run uses: the case file of options (new run) or the run directory's (resume), with the overrides.
// Throws InputError.
Case load_run_case(const DriverOptions& options, const std::string& tag);

// Runs (or resumes) one case with `engine`. Returns the process exit status: 0 complete (and brash-post's status
// when it runs), 1 failed, 2 bad input, 128 + signal when a signal stopped it (resumable).
int drive(Engine& engine, const DriverOptions& options);

// Model time between restart files: options.restart_every_s, else a tenth of the run, on the time-step grid.
double restart_interval_s(const Case& c, double restart_every_s);

}  // namespace brash::run
