// bench-ode: particle-steps/s and wall time per simulated second of brash-ode on a case (not a test).
//   bench-ode CASE_DIR [--duration 0.5] [--scene-from DUMP.csv --scene-time T] [brash-ode options]
// (with --scene-from the run goes from T to --duration, as brash-ode's)
// Also runs a synthetic floating lattice bed without hull (--bed N for N x N lower-layer spheres), with the
// ode: keys given on the command line.
#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <iostream>

#include "brash/error.hpp"
#include "brash/ode/bed.hpp"
#include "brash/run/driver.hpp"
#include "cli.hpp"

int main(int argc, char** argv) {
  CLI::App app{"bench-ode: speed of the ODE simulator", "bench-ode"};
  brash::run::DriverOptions d;
  d.overrides.duration_s = 0.5;
  d.post = false;
  d.progress = false;
  brash::ode::RunOptions o;
  o.progress = false;
  int bed = 0;
  double bed_s = 0.5;
  const auto cli = brash::ode::add_ode_options(app, d, o);
  app.remove_option(cli.resume);  // a bench run is not resumed
  app.add_option("--bed", bed, "synthetic bed: N x N spheres per layer, two layers, no hull (0 = off)");
  app.add_option("--bed-duration", bed_s, "simulated time of the synthetic bed [s]")->capture_default_str();
  app.add_flag_callback("--progress", [&o, &d] { o.progress = d.progress = true; },
                        "progress lines on stderr, as brash-ode writes them (off by default here)");
  CLI11_PARSE(app, argc, argv);
  try {
    brash::ode::OdeLibrary ode;
    if (bed > 0) {
      const brash::Case c = brash::ode::case_of_command_line(d.overrides);
      const brash::ode::StepperSettings stepper = brash::ode::stepper_settings(c);
      brash::core::FluidParams p;
      brash::ode::World w(p, stepper, brash::ode::Frictions{}, brash::ode::far_field_skips(c),
                          brash::ode::implicit_mode(c));
      brash::ode::LatticeBedSpec spec;
      spec.nx = spec.ny = bed;
      const auto b = brash::ode::make_lattice_bed(spec);
      for (std::size_t i = 0; i < b.position_m.size(); ++i) w.add_sphere(b.position_m[i], b.radius_m[i], 900);
      brash::ode::add_channel_walls(w, 0, b.length_x_m, 0.5 * b.width_y_m, true);
      const long steps = std::lround(bed_s / stepper.dt_s);
      const auto t0 = std::chrono::steady_clock::now();
      for (long k = 0; k < steps; ++k) w.step();
      const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const auto& s = w.stats();
      fmt::print("bench-ode bed {} spheres, dt {} s, {} steps: {:.3g} particle-steps/s, {:.2f} s wall per simulated s "
                 "(fluid {:.2f} / collide {:.2f} / quickstep {:.2f} s), {} contacts at the end\n",
                 w.size(), stepper.dt_s, steps, double(s.particle_steps) / wall, wall / bed_s, s.wall_fluid_s,
                 s.wall_collide_s, s.wall_step_s, s.contacts_last);
    }
    if (!d.case_path.empty()) {
      brash::ode::take_scene_from(d, o);
      if (d.out_dir.empty()) d.out_dir = std::filesystem::temp_directory_path() / fmt::format("bench-ode-{}", ::getpid());
      brash::ode::take_restart_every(d, o);
      brash::ode::OdeEngine engine(o);
      if (const int status = brash::run::drive(engine, d); status != 0) return status;
      const auto& r = engine.summary();
      fmt::print("bench-ode case {}, dt {} s, {} s simulated: {:.3g} particle-steps/s, {:.2f} s wall per "
                 "simulated s (fluid {:.2f} / collide {:.2f} / quickstep {:.2f} s), mean Fx {:.4f} N; run dir {}\n",
                 d.case_path.string(), r.dt_s, r.simulated_s,
                 double(r.particle_steps) / r.loop_time_s, r.loop_time_s / r.simulated_s, r.stats.wall_fluid_s,
                 r.stats.wall_collide_s, r.stats.wall_step_s, r.mean_fx_window_N, d.out_dir.string());
    }
  } catch (const brash::InputError& e) {
    fmt::print(stderr, "bench-ode: input error: {}\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "bench-ode: error: {}\n", e.what());
    return 1;
  }
  return 0;
}
