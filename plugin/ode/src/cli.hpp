// Command-line options shared by brash-ode and bench-ode.
#pragma once
#include <CLI/CLI.hpp>

#include <map>
#include <string>

#include "brash/ode/run_case.hpp"

namespace brash::ode {

inline void add_run_options(CLI::App& app, RunOptions& o, std::string& implicit_mode) {
  app.add_option("--out", o.out_dir, "run directory (default: <runs-root>/<case>-ode-<model>-<stamp>)");
  app.add_option("--runs-root", o.runs_root, "where run directories are created")->capture_default_str();
  app.add_option("--duration", o.duration_s, "simulated time [s] (default: the case's run.duration_s)");
  app.add_option("--model", o.model, "override fluid.model: drag | added_mass | both");
  app.add_option("--treatment", o.treatment, "override fluid.treatment: implicit | explicit");
  app.add_option("--dt", o.stepper.dt_s, "ODE time step [s] (the case's run.timestep_s is the DEM step)")->capture_default_str();
  app.add_option("--iterations", o.stepper.iterations, "dWorldQuickStep iterations")->capture_default_str();
  app.add_option("--erp", o.stepper.erp, "world ERP")->capture_default_str();
  app.add_option("--cfm", o.stepper.cfm, "world CFM")->capture_default_str();
  app.add_option("--surface-layer", o.stepper.contact_surface_layer, "contact surface layer [m]")->capture_default_str();
  app.add_option("--angular-damping", o.stepper.angular_damping, "ODE angular damping per step (fluid torque is neglected)")
      ->capture_default_str();
  app.add_option("--implicit", implicit_mode, "implicit added mass in ODE: effective_mass | scale_forces")
      ->check(CLI::IsMember({"effective_mass", "scale_forces"}))
      ->capture_default_str();
  app.add_option("--broad-phase", o.stepper.broad_phase,
                 "broad phase: grid (ours, follows the active spheres) | sap (ODE's sweep and prune); same contacts")
      ->transform(CLI::CheckedTransformer(std::map<std::string, BroadPhase>{{to_string(BroadPhase::Grid), BroadPhase::Grid},
                                                                            {to_string(BroadPhase::Sap), BroadPhase::Sap}}))
      ->option_text("TEXT:{grid,sap}=grid");
  app.add_option("--sphere-order", o.sphere_order,
                 "order of the ODE bodies: spatial (cells of two mean diameters) | packing (the packing "
                 "file's; slower)")
      ->transform(CLI::CheckedTransformer(
          std::map<std::string, SphereOrder>{{to_string(SphereOrder::Spatial), SphereOrder::Spatial},
                                             {to_string(SphereOrder::Packing), SphereOrder::Packing}}))
      ->option_text("TEXT:{spatial,packing}=spatial");
  app.add_flag("--auto-disable", o.skips.auto_disable, "ODE auto-disable of resting spheres far from the hull (a speed-up)");
  app.add_option("--disable-linear", o.skips.disable_linear_m_s, "auto-disable linear speed threshold [m/s]")
      ->capture_default_str();
  app.add_option("--disable-angular", o.skips.disable_angular_rad_s, "auto-disable angular speed threshold [rad/s]")
      ->capture_default_str();
  app.add_flag("--cull", o.skips.cull,
               "freeze spheres outside a window around the hull (static obstacles) until pushed "
               "(the far-field rule of fix brash/farfield; on with the case's speedups.farfield: true)");
  app.add_option("--cull-ahead", o.cull_ahead_m,
                 "cull/auto-disable: active distance ahead of the bow [m] (default: the case's "
                 "speedups.farfield_ahead_m with farfield: true, else 1)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--cull-behind", o.cull_behind_m,
                 "cull/auto-disable: active distance behind the stern [m] (default: the case's "
                 "speedups.farfield_behind_m with farfield: true, else 1)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--cull-side", o.cull_side_m,
                 "cull/auto-disable: active distance beside the hull's half beam [m] (default: the case's "
                 "speedups.farfield_beside_m, else the whole width)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--cull-wake-weight", o.cull_wake_force_weight,
                 "cull: a frozen sphere wakes when the horizontal force on it exceeds this fraction of the weight of "
                 "a piece of the mean diameter; 0 = the window alone (default: the case's "
                 "speedups.farfield_wake_force_weight)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--cull-wake-speed", o.cull_wake_speed_m_s,
                 "cull: behind the stern a sphere is frozen once no faster than this [m/s] (default: the case's "
                 "speedups.farfield_wake_speed_m_s)")
      ->check(CLI::NonNegativeNumber);
  app.add_flag_callback("--cull-keep-geoms", [&o] { o.skips.cull_geoms = false; },
                        "cull: keep every frozen sphere in collision detection (slower, same contacts; for checking)");
  app.add_flag("--end-walls", o.end_walls, "the case with channel.ends: walls (walls at x = 0 and x = length)");
  app.add_option("--settle", o.settle_s, "settle the whole bed this long [s] before t = 0, the hull parked and every piece "
                 "integrated (a far field begins after it)")
      ->capture_default_str();
  app.add_option("--settle-damping", o.settle_damping,
                 "velocity damping per step over the settling's first half (ODE's body damping; its second half "
                 "is free), to bring the bed to rest on ODE's own contacts")
      ->check(CLI::Range(0.0, 0.5))
      ->capture_default_str();
  app.add_flag_callback("--no-progress", [&o] { o.progress = false; }, "no progress line on stderr");
  app.add_option("--restart-every", o.restart_every_s, "simulated time between restart files in RUN_DIR/restart [s] (0 = none)")
      ->capture_default_str();
  // Testing only: exit like a kill -9 (no cleanup, no final outputs) right after this step.
  app.add_option("--crash-after-step", o.crash_after_step)->group("");
  // Testing only: a SIGTERM arriving during this step (the handled stop: resumable at this step).
  app.add_option("--stop-after-step", o.stop_after_step)->group("");
}

inline ImplicitMode parse_implicit_mode(const std::string& s) {
  return s == "scale_forces" ? ImplicitMode::ScaleForces : ImplicitMode::EffectiveMass;
}

}  // namespace brash::ode
