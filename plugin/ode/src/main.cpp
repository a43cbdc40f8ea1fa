// brash-ode: the standalone ODE simulator.
//   brash-ode CASE_DIR [--out RUN_DIR] [--duration S] [...]   run a case into the common run layout
//   brash-ode --resume RUN_DIR                               continue a killed run from its restart files
//   brash-ode --single rise|float|heave|all [--dt S]         single-sphere scenes vs the reference integrator
// SIGINT / SIGTERM stop a run after the step in progress, resumable there (exit 130 / 143).
#include <fmt/format.h>

#include <iostream>

#include "brash/error.hpp"
#include "brash/ode/single.hpp"
#include "cli.hpp"

int main(int argc, char** argv) {
  CLI::App app{"brash-ode: standalone ODE simulator of a ship in a brash-ice channel"};
  brash::ode::RunOptions o;
  std::string scene, implicit_mode = "effective_mass";
  app.add_option("case_dir", o.case_dir, "case folder holding case.yaml");
  app.add_option("--single", scene, "single-sphere scene vs reference: rise | float | heave | all")
      ->check(CLI::IsMember({"rise", "float", "heave", "all"}));
  std::filesystem::path resume_dir;
  app.add_option("--resume", resume_dir,
                 "continue the killed run in RUN_DIR from its newest intact restart file (all other run options "
                 "come from RUN_DIR/meta.json)");
  brash::ode::add_run_options(app, o, implicit_mode);
  CLI11_PARSE(app, argc, argv);
  o.implicit_mode = brash::ode::parse_implicit_mode(implicit_mode);
  try {
    brash::ode::OdeLibrary ode;
    if (!scene.empty()) {
      namespace single = brash::ode::single;
      single::Options so;
      so.dt_s = o.stepper.dt_s;
      so.mode = o.implicit_mode;
      if (!o.treatment.empty()) so.treatment = brash::core::parse_treatment(o.treatment);
      if (scene == "rise" || scene == "all") fmt::print("{}\n", single::report(single::rise(so)));
      if (scene == "float" || scene == "all") fmt::print("{}\n", single::report(single::floating(so)));
      if (scene == "heave" || scene == "all") fmt::print("{}\n", single::report(single::heave(so)));
      return 0;
    }
    if (!resume_dir.empty()) {
      o.out_dir = resume_dir;
      o.resume = true;
    } else if (o.case_dir.empty()) {
      fmt::print(stderr, "brash-ode: error: give a CASE_DIR (or --single SCENE)\n{}", app.help());
      return 2;
    }
    const auto r = brash::ode::run_case(o);
    std::cout << r.run_dir.string() << "\n";
    // stopped by SIGINT / SIGTERM: resumable, but not complete (the shell's convention for a signal's end)
    if (r.stopped_by_signal) return 128 + r.stopped_by_signal;
  } catch (const brash::InputError& e) {
    fmt::print(stderr, "brash-ode: input error: {}\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "brash-ode: error: {}\n", e.what());
    return 1;
  }
  return 0;
}
