// brash-ode's case runner: the ODE adapter of the run driver (brash/run/engine.hpp). Case -> ODE scene (packing
// spheres, kinematic hull trimesh, side walls) advanced in this process; restart/restart_<step>.bin every
// restart_every_s (the last two kept; restart.hpp), and one at the very step a stop signal arrives, so that
// `brash-ode --resume RUN_DIR` continues a killed or stopped run. The driver writes the rest of the run layout.
#pragma once
#include <filesystem>
#include <memory>
#include <string>

#include "brash/ode/bed.hpp"
#include "brash/ode/world.hpp"
#include "brash/run/engine.hpp"

namespace brash::ode {

// The order in which the packing's spheres become ODE bodies: spatial (cells of two mean diameters, the
// default: bodies and contact rows sit in memory as in space) or the packing file's (random in space; kept to
// measure the difference).
enum class SphereOrder { Spatial, Packing };
inline const char* to_string(SphereOrder o) { return o == SphereOrder::Packing ? "packing" : "spatial"; }

struct RunOptions {
  std::filesystem::path case_dir;      // folder with case.yaml (or the case.yaml itself)
  std::filesystem::path out_dir;       // run directory; empty = <runs_root>/<case>-ode-<model>-<stamp>
  std::filesystem::path runs_root = "runs";
  double duration_s = 0;               // 0 = the case's run.duration_s
  std::string model, treatment;        // overrides of fluid.model / fluid.treatment ("" = case)
  StepperSettings stepper;             // dt default 5e-4 (the case's run.timestep_s is the DEM step)
  Skips skips;
  // --cull's wake rule in the case file's terms, negative = the case's speedups.farfield_wake_force_weight /
  // farfield_wake_speed_m_s (as brash-liggghts-run gives fix brash/farfield); the run sets skips' wake from them.
  double cull_wake_force_weight = -1;
  double cull_wake_speed_m_s = -1;
  // --cull-ahead/--cull-behind/--cull-side, negative = the case's speedups.farfield_ahead_m / farfield_behind_m /
  // farfield_beside_m when the case has speedups.farfield: true, else Skips' defaults (the window of cull_skips)
  double cull_ahead_m = -1, cull_behind_m = -1, cull_side_m = -1;
  ImplicitMode implicit_mode = ImplicitMode::EffectiveMass;
  SphereOrder sphere_order = SphereOrder::Spatial;
  bool end_walls = false;              // --end-walls: the case with channel.ends: walls
  double settle_s = 0;                 // simulated settling with the hull parked at start_x (not in t)
  double settle_damping = 0;           // ODE velocity damping per step over the settling's first half
  bool progress = true;                // the engine's own lines on stderr (the driver prints progress)
  double overlap_tolerance_over_d = 1e-4;  // packing overlaps beyond this fraction of d_mean are errors
  double restart_every_s = 0.1;        // simulated time between restart files (0 = none)
  // bench-ode --scene-from: the pieces of another run's particle dump (id,x,y,z,radius,vx,vy,vz: any engine's
  // particles/ file) instead of the packing, and the hull where it was scene_time_s into that run, to time the
  // ODE step on a run's late scene (pieces numbered in the file's order; not for a resistance)
  std::filesystem::path scene_from;
  double scene_time_s = 0;
  long stop_after_step = -1;           // testing: raise SIGTERM during this step (a stop request, handled)
  long crash_after_step = -1;          // testing: std::_Exit(137) right after this step (a kill -9: no cleanup)
};

// The options a run was set up with, from RUN_DIR/meta.json ("ode_options"), for --resume: every option but
// progress, crash_after_step and stop_after_step (those of `cli`). Throws InputError.
RunOptions options_from_meta(const std::filesystem::path& run_dir, const RunOptions& cli);

// What the last attempt did (bench-ode's numbers).
struct RunSummary {
  long steps = 0;                      // last step done
  double simulated_s = 0;              // its model time
  double loop_time_s = 0;              // wall time of the stepping loop
  long particle_steps = 0;             // of the loop
  double mean_fx_window_N = 0;         // mean hull fx over the case window (clipped to the run)
  Stats stats;
};

class OdeEngine final : public run::Engine {
 public:
  explicit OdeEngine(RunOptions options);
  ~OdeEngine() override;
  std::string name() const override { return "ode"; }
  std::string runner() const override { return "brash-ode"; }
  nlohmann::json meta() const override;
  // The settled bed with a contact surface layer as deep as its largest overlap (load()).
  bool starts_from_settled_bed() const override { return true; }
  // speedups.farfield: the far-field rule as --cull, with the case's window, period and wake (cull_skips).
  bool idles_far_field() const override { return true; }
  WakeRefusal wake_refusal(WakeBy by) const override;
  void load(const Case& c, const std::filesystem::path& case_file, const std::vector<Sphere>& spheres) override;
  void write_scene(const std::filesystem::path&, bool) override {}  // the scene lives in this process
  std::vector<std::string> restarts(const std::filesystem::path& run_dir) const override;
  run::Attempt advance(const std::filesystem::path& run_dir, const std::string& restart, run::Monitor& m) override;
  std::vector<run::ForceRow> force_record(const std::filesystem::path& run_dir, double t_max_s) const override;
  const RunSummary& summary() const { return summary_; }

  struct Scene;  // what load() reads: the case, spheres, hull mesh, guards, hull flow

 private:
  RunOptions options_;
  std::unique_ptr<Scene> scene_;
  std::vector<run::ForceRow> rows_;  // the record so far (as written: the early stop reads what a replay reads)
  RunSummary summary_;
};

}  // namespace brash::ode
