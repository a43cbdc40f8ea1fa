// bench-ode: particle-steps/s and wall time per simulated second of brash-ode on a case (not a test).
//   bench-ode CASE_DIR [--duration 0.5] [--scene-from DUMP.csv --scene-time T] [brash-ode options]
// Also runs a synthetic floating lattice bed without hull (--bed N for N x N lower-layer spheres).
#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <iostream>

#include "brash/ode/bed.hpp"
#include "brash/run/driver.hpp"
#include "cli.hpp"

int main(int argc, char** argv) {
  CLI::App app{"bench-ode: speed of the ODE simulator", "bench-ode"};
  brash::ode::RunOptions o;
  o.duration_s = 0.5;
  o.progress = false;
  std::string implicit_mode = "effective_mass";
  int bed = 0;
  double bed_s = 0.5;
  app.add_option("case_dir", o.case_dir, "case folder");
  app.add_option("--bed", bed, "synthetic bed: N x N spheres per layer, two layers, no hull (0 = off)");
  app.add_option("--bed-duration", bed_s, "simulated time of the synthetic bed [s]")->capture_default_str();
  app.add_option("--scene-from", o.scene_from,
                 "start from another run's particle dump (particles/*.csv: id,x,y,z,radius[,vx,vy,vz]) instead of "
                 "the packing, to time a run's late scene")
      ->check(CLI::ExistingFile);
  app.add_option("--scene-time", o.scene_time_s,
                 "with --scene-from: the dump's model time [s]; the hull starts where it was then")
      ->check(CLI::NonNegativeNumber);
  brash::ode::add_run_options(app, o, implicit_mode);
  app.add_flag("--progress", o.progress,
               "progress lines on stderr, as brash-ode writes them (off by default here)");
  CLI11_PARSE(app, argc, argv);
  o.implicit_mode = brash::ode::parse_implicit_mode(implicit_mode);
  try {
    brash::ode::OdeLibrary ode;
    if (bed > 0) {
      brash::core::FluidParams p;
      brash::ode::World w(p, o.stepper, brash::ode::Frictions{}, o.skips, o.implicit_mode);
      brash::ode::LatticeBedSpec spec;
      spec.nx = spec.ny = bed;
      const auto b = brash::ode::make_lattice_bed(spec);
      for (std::size_t i = 0; i < b.position_m.size(); ++i) w.add_sphere(b.position_m[i], b.radius_m[i], 900);
      brash::ode::add_channel_walls(w, 0, b.length_x_m, 0.5 * b.width_y_m, true);
      const long steps = std::lround(bed_s / o.stepper.dt_s);
      const auto t0 = std::chrono::steady_clock::now();
      for (long k = 0; k < steps; ++k) w.step();
      const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const auto& s = w.stats();
      fmt::print("bench-ode bed {} spheres, dt {} s, {} steps: {:.3g} particle-steps/s, {:.2f} s wall per simulated s "
                 "(fluid {:.2f} / collide {:.2f} / quickstep {:.2f} s), {} contacts at the end\n",
                 w.size(), o.stepper.dt_s, steps, double(s.particle_steps) / wall, wall / bed_s, s.wall_fluid_s,
                 s.wall_collide_s, s.wall_step_s, s.contacts_last);
    }
    if (!o.case_dir.empty()) {
      if (o.out_dir.empty()) o.out_dir = std::filesystem::temp_directory_path() / fmt::format("bench-ode-{}", ::getpid());
      brash::run::DriverOptions d;
      d.case_path = o.case_dir;
      d.out_dir = o.out_dir;
      d.overrides = {o.model, o.treatment, o.duration_s, o.end_walls ? "walls" : ""};
      d.restart_every_s = o.restart_every_s;
      d.post = false;
      brash::ode::OdeEngine engine(o);
      if (const int status = brash::run::drive(engine, d); status != 0) return status;
      const auto& r = engine.summary();
      fmt::print("bench-ode case {}, dt {} s, {} s simulated: {:.3g} particle-steps/s, {:.2f} s wall per "
                 "simulated s (fluid {:.2f} / collide {:.2f} / quickstep {:.2f} s), mean Fx {:.4f} N; run dir {}\n",
                 o.case_dir.string(), o.stepper.dt_s, r.simulated_s, double(r.particle_steps) / r.loop_time_s,
                 r.loop_time_s / r.simulated_s, r.stats.wall_fluid_s, r.stats.wall_collide_s, r.stats.wall_step_s,
                 r.mean_fx_window_N, o.out_dir.string());
    }
  } catch (const std::exception& e) {
    fmt::print(stderr, "bench-ode: error: {}\n", e.what());
    return 1;
  }
  return 0;
}
