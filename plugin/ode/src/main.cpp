// brash-ode: the standalone ODE simulator.
//   brash-ode CASE_DIR [--out RUN_DIR] [--duration S] [...]   run a case into the common run layout (run driver)
//   brash-ode --resume RUN_DIR                               continue a killed or stopped run from its restart files
//   brash-ode --single rise|float|heave|all [--dt S]         single-sphere scenes vs the reference integrator
// SIGINT / SIGTERM stop a run after the step in progress, resumable there (exit 130 / 143).
#include <fmt/format.h>

#include <iostream>

#include "brash/error.hpp"
#include "brash/ode/single.hpp"
#include "brash/run/driver.hpp"
#include "cli.hpp"

namespace {

int run_single(const std::string& scene, const brash::ode::RunOptions& o) {
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

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"brash-ode: standalone ODE simulator of a ship in a channel of brash ice", "brash-ode"};
  brash::ode::RunOptions o;
  std::string scene, implicit_mode = "effective_mass";
  bool no_post = false;
  app.add_option("case_dir", o.case_dir, "case folder holding case.yaml");
  app.add_option("--single", scene, "single-sphere scene vs reference: rise | float | heave | all")
      ->check(CLI::IsMember({"rise", "float", "heave", "all"}));
  std::filesystem::path resume_dir;
  app.add_option("--resume", resume_dir,
                 "continue the killed run in RUN_DIR from its newest intact restart file (all other run options "
                 "come from RUN_DIR/meta.json)");
  app.add_flag("--no-post", no_post, "do not run brash-post afterwards");
  brash::ode::add_run_options(app, o, implicit_mode);
  CLI11_PARSE(app, argc, argv);
  o.implicit_mode = brash::ode::parse_implicit_mode(implicit_mode);
  try {
    brash::ode::OdeLibrary ode;
    if (!scene.empty()) return run_single(scene, o);
    if (resume_dir.empty() && o.case_dir.empty()) {
      fmt::print(stderr, "brash-ode: error: give a CASE_DIR (or --single SCENE)\n{}", app.help());
      return 2;
    }
    if (!resume_dir.empty()) o = brash::ode::options_from_meta(resume_dir, o);
    brash::run::DriverOptions d;
    d.case_path = o.case_dir;
    d.resume_dir = resume_dir;
    d.out_dir = resume_dir.empty() ? o.out_dir : std::filesystem::path();
    d.runs_root = o.runs_root;
    if (resume_dir.empty()) d.overrides = {o.model, o.treatment, o.duration_s, o.end_walls ? "walls" : ""};  // a resume: the run's own
    d.restart_every_s = o.restart_every_s;
    d.post = !no_post;
    d.progress = o.progress;
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
