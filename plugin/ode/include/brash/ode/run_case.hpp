// brash-ode's case runner: the ODE adapter of the run driver (brash/run/engine.hpp). Case -> ODE scene (packing
// spheres, kinematic hull trimesh, side walls) advanced in this process; restart/restart_<step>.bin every
// restart_every_s (the last two kept; restart.hpp), and one at the very step a stop signal arrives, so that
// `brash-ode --resume RUN_DIR` continues a killed or stopped run as its case.yaml says. The driver writes the rest
// of the run layout.
#pragma once
#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "brash/ode/bed.hpp"
#include "brash/ode/world.hpp"
#include "brash/run/engine.hpp"

namespace brash::run {
struct DriverOptions;
}

namespace brash::ode {

// What a run takes besides its case (the case's ode: section and speedups.farfield_* set the engine: see
// settings below): how often it writes restart files, its own progress lines, and testing hooks.
struct RunOptions {
  double restart_every_s = 0.1;        // simulated time between restart files (0 = none)
  bool progress = true;                // the engine's own lines on stderr (the driver prints progress)
  // --scene-from: the pieces of another run's particle dump (id,x,y,z,radius[,vx,vy,vz][,omegax,omegay,omegaz]
  // [,state]: any engine's particles/ file of the same case) instead of the packing, with the hull where it was
  // scene_time_s into that run: the run goes on from there, its record's times from scene_time_s
  // (take_scene_from); meta.json keeps both, and a resume reads them back.
  std::filesystem::path scene_from;
  double scene_time_s = 0;
  std::optional<std::array<double, 2>> requested_window_s;  // the case's window, when it began before scene_time_s
  long stop_after_step = -1;           // testing: raise SIGTERM during this step (a stop request, handled)
  long crash_after_step = -1;          // testing: std::_Exit(137) right after this step (a kill -9: no cleanup)
};

// The engine's settings from the case, each computed in this one place: the stepper of the ode: section, the
// implicit realisation, and the far field (speedups.farfield_*: the window, the membership period of
// farfield_every_steps DEM steps in ODE steps, the wake rule in SI units; brash/core/far_field.hpp) with ODE's
// auto-disable (ode.auto_disable*, which keeps the pieces inside that window awake).
StepperSettings stepper_settings(const Case& c);
ImplicitMode implicit_mode(const Case& c);
Skips far_field_skips(const Case& c);

// A run directory of brash-ode from before the ode: case keys keeps its settings in meta.json ("ode_options"), not
// in its case.yaml. Before such a run is resumed they move into its case.yaml as the case keys that give the same
// run (the ode: section; a far field set on the command line as speedups.farfield_*), and "ode_options" leaves
// meta.json; true when they did. Settings the keys cannot give are an InputError naming meta.json, the run
// directory left as it was.
bool move_ode_options_into_case(const std::filesystem::path& run_dir);

// The interval between restart files a run directory was started with (meta.json "restart_every_s", or its
// "ode_options"), -1 when it names none: a resume keeps it unless given another, so that it writes its restart
// files, and normalises its quaternions there (World::reset_orientations), at the same steps as the uninterrupted
// run, which it then reproduces bit for bit.
double restart_every_of_run(const std::filesystem::path& run_dir);

// A run from another run's particle dump (--scene-from FILE --scene-time T): a new run goes on from T to the
// case's run.duration_s (--duration), refused unless that is after T; a window that begins before T is clipped to
// begin at T (the run's case.yaml says so, meta.json keeps the requested one in "window_requested_s"), one that
// ends before it refused. The snapshot's own time, where its folder's index.csv lists it, must be T. A resume
// (--resume RUN_DIR) takes the scene its meta.json names ("scene_from", "scene_time_s"). InputError naming the
// options.
void take_scene_from(run::DriverOptions& d, RunOptions& o);

// What the last attempt did (bench-ode's numbers).
struct RunSummary {
  long steps = 0;                      // last step done
  double dt_s = 0;                     // the ODE step (ode.timestep_s)
  double simulated_s = 0;              // the model time it advanced (from its start or restart point)
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
  // speedups.farfield: the far-field rule with the case's window, period and wake (far_field_skips).
  bool idles_far_field() const override { return true; }
  WakeRefusal wake_refusal(WakeBy by) const override;
  void load(const Case& c, const std::filesystem::path& case_file, const std::vector<Sphere>& spheres) override;
  void write_scene(const std::filesystem::path&, bool) override {}  // the scene lives in this process
  std::vector<std::string> restarts(const std::filesystem::path& run_dir) const override;
  run::Attempt advance(const std::filesystem::path& run_dir, const std::string& restart, run::Monitor& m) override;
  run::ForceRecord force_record(const std::filesystem::path& run_dir, double t_max_s) const override;
  const RunSummary& summary() const { return summary_; }

  struct Scene;  // what load() reads: the case, spheres, hull mesh, guards, hull flow

 private:
  RunOptions options_;
  std::unique_ptr<Scene> scene_;
  run::ForceRecord record_;  // the record so far (as written: the early stop reads what a replay reads)
  RunSummary summary_;
};

}  // namespace brash::ode
