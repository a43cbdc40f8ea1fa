// brash-ode: the standalone ODE simulator.
//   brash-ode CASE_DIR [--out RUN_DIR] [--duration S] [--set KEY=VALUE] [--dt S] [...]   run a case (run driver)
//   brash-ode CASE_DIR --scene-from RUN/particles/particles_<n>.csv --scene-time T [--duration D]
//                                               go on from another run's snapshot at T to D (a run like any other)
//   brash-ode --resume RUN_DIR                  continue a killed or stopped run from its restart files and case.yaml
//   brash-ode --single rise|float|heave|all [--dt S] [--implicit M] [--treatment T]   single-sphere scenes vs the
//                                                                                      reference integrator
// The engine's settings are case keys (the ode: section, speedups.farfield_*): --dt and the other short forms
// change the case, and the run directory's case.yaml records them. SIGINT / SIGTERM stop a run after the step in
// progress, resumable there (exit 130 / 143).
#include <fmt/format.h>

#include <iostream>

#include "brash/error.hpp"
#include "brash/ode/single.hpp"
#include "brash/run/driver.hpp"
#include "cli.hpp"

namespace {

int run_single(const std::string& scene, const brash::run::CaseOverrides& overrides) {
  namespace single = brash::ode::single;
  const brash::Case c = brash::ode::case_of_command_line(overrides);
  single::Options so;
  so.dt_s = c.ode.timestep_s;
  so.mode = brash::ode::implicit_mode(c);
  if (!overrides.treatment.empty()) so.treatment = brash::core::parse_treatment(overrides.treatment);
  if (scene == "rise" || scene == "all") fmt::print("{}\n", single::report(single::rise(so)));
  if (scene == "float" || scene == "all") fmt::print("{}\n", single::report(single::floating(so)));
  if (scene == "heave" || scene == "all") fmt::print("{}\n", single::report(single::heave(so)));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"brash-ode: standalone ODE simulator of a ship in a channel of brash ice", "brash-ode"};
  brash::run::DriverOptions d;
  brash::ode::RunOptions o;
  std::string scene;
  const auto cli = brash::ode::add_ode_options(app, d, o);
  app.add_option("--single", scene, "single-sphere scene vs reference: rise | float | heave | all")
      ->check(CLI::IsMember({"rise", "float", "heave", "all"}))
      ->excludes(cli.case_dir)
      ->excludes(cli.resume);
  CLI11_PARSE(app, argc, argv);
  try {
    brash::ode::OdeLibrary ode;
    if (!scene.empty()) return run_single(scene, d.overrides);
    if (!d.resume_dir.empty() && d.restart_every_s < 0)
      d.restart_every_s = brash::ode::restart_every_of_run(d.resume_dir);
    if (!d.resume_dir.empty() && d.overrides.sets.empty() && brash::ode::move_ode_options_into_case(d.resume_dir))
      fmt::print(stderr, "[brash-ode] {}: the settings of \"ode_options\" in meta.json moved into case.yaml\n",
                 d.resume_dir.string());
    brash::ode::take_scene_from(d, o);
    brash::ode::take_restart_every(d, o);
    brash::ode::OdeEngine engine(o);
    return brash::run::drive(engine, d);
  } catch (const brash::InputError& e) {
    fmt::print(stderr, "brash-ode: input error: {}\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "brash-ode: error: {}\n", e.what());
    return 1;
  }
}
