// brash-ode's case runner: case folder -> ODE scene (packing spheres, kinematic hull trimesh, side walls)
// -> run directory in the common layout (docs/case_format.md): case.yaml, meta.json, hull_force.csv,
// particles/, restart/ (restart_<step>.bin every restart_every_s, the last two kept; see restart.hpp), log.txt.
// All files are written atomically. A killed run continues with resume = true (brash-ode --resume RUN_DIR).
#pragma once
#include <filesystem>
#include <string>

#include "brash/ode/bed.hpp"
#include "brash/ode/world.hpp"

namespace brash::ode {

struct RunOptions {
  std::filesystem::path case_dir;      // folder with case.yaml (or the case.yaml itself)
  std::filesystem::path out_dir;       // run directory; empty = <runs_root>/<case>-ode-<model>-<stamp>
  std::filesystem::path runs_root = "runs";
  double duration_s = 0;               // 0 = the case's run.duration_s
  std::string model, treatment;        // overrides of fluid.model / fluid.treatment ("" = case)
  StepperSettings stepper;             // dt default 5e-4 (the case's run.timestep_s is the DEM step)
  Skips skips;
  ImplicitMode implicit_mode = ImplicitMode::EffectiveMass;
  bool end_walls = false;              // walls at x = 0 and x = length (LIGGGHTS has side walls only)
  double settle_s = 0;                 // simulated settling with the hull parked at start_x (not in t)
  bool progress = true;                // progress line with ETA on stderr
  double overlap_tolerance_over_d = 1e-4;  // packing overlaps beyond this fraction of d_mean are errors
  double restart_every_s = 0.1;        // simulated time between restart files (0 = none)
  // Resume the run in out_dir from its newest intact restart file: every other option is taken from the run's
  // meta.json ("ode_options"), except progress, crash_after_step and stop_after_step.
  bool resume = false;
  long stop_after_step = -1;           // testing: raise SIGTERM during this step (a stop request, handled)
  long crash_after_step = -1;          // testing: std::_Exit(137) right after this step (a kill -9: no cleanup)
};

struct RunResult {
  std::filesystem::path run_dir;
  std::size_t particles = 0;
  long steps = 0;
  long particle_steps = 0;
  double wall_time_s = 0, loop_time_s = 0;
  double simulated_s = 0;
  double mean_fx_window_N = 0;         // mean hull fx over the case window (clipped to the run)
  int stopped_by_signal = 0;           // SIGINT / SIGTERM ended the run early (resumable at `steps`), else 0
  Stats stats;
};

// Throws brash::InputError for bad input (naming file and line/key) and std::runtime_error when the run fails
// (NaN, ...); the run directory's meta.json then says status "failed" with the reason.
RunResult run_case(const RunOptions& o);

}  // namespace brash::ode
