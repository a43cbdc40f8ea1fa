// brash-yade-run CASE_DIR | --resume RUN_DIR: runs a case with YADE through the run driver (brash/run/driver.hpp:
// the run layout of docs/case_format.md, resume, signals, progress, early stop, brash-post) with the YADE adapter
// (yade_engine.hpp).
#include <CLI/CLI.hpp>

#include <iostream>

#include "brash/run/driver.hpp"
#include "yade_engine.hpp"

int main(int argc, char** argv) {
  CLI::App app{"brash-yade-run: run a case directory with YADE and write the brash run layout"};
  brash::run::DriverOptions o;
  int threads = 1;
  bool no_post = false;
  auto* case_opt = app.add_option("case_dir", o.case_path, "case folder holding case.yaml");
  auto* resume_opt = app.add_option("--resume", o.resume_dir,
                                    "continue an interrupted run directory from its newest restart point");
  case_opt->excludes(resume_opt);
  app.add_option("--out", o.out_dir, "run directory (default: runs/<case>-yade-<model>-<stamp>)");
  app.add_option("--runs-root", o.runs_root, "where run directories are created");
  app.add_option("--duration", o.overrides.duration_s, "simulated time [s] (default: the case's run.duration_s)");
  app.add_option("--model", o.overrides.model, "override fluid.model: drag | added_mass | both");
  app.add_option("--treatment", o.overrides.treatment, "override fluid.treatment: implicit | explicit");
  app.add_option("--restart-every", o.restart_every_s,
                 "model time [s] between restart points (default: a tenth of the run; also on --resume)")
      ->check(CLI::PositiveNumber);
  app.add_option("-j,--threads", threads, "YADE OpenMP threads")->check(CLI::Range(1, 256));
  app.add_flag("--no-post", no_post, "do not run brash-post afterwards");
  app.add_flag("--prepare-only", o.prepare_only, "write the run directory's inputs (scene.json, hull.stl) and stop");
  CLI11_PARSE(app, argc, argv);
  o.post = !no_post;
  if (o.case_path.empty() && o.resume_dir.empty()) {
    std::cerr << "brash-yade-run: error: case_dir (a folder with case.yaml) or --resume RUN_DIR is required\n";
    return 2;
  }
  if (!o.resume_dir.empty() && (!o.overrides.model.empty() || !o.overrides.treatment.empty() ||
                                o.overrides.duration_s > 0 || !o.out_dir.empty())) {
    std::cerr << "brash-yade-run: error: --resume continues a run as it was set up; it takes no "
                 "--model/--treatment/--duration/--out\n";
    return 2;
  }
  brash::yade::YadeEngine engine(threads, o.restart_every_s);
  return brash::run::drive(engine, o);
}
