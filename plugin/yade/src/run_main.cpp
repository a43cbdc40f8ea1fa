// brash-yade-run CASE_DIR: runs a case with YADE through the run driver (brash/run/driver.hpp: the run layout of
// docs/case_format.md, progress, early stop, brash-post) with the YADE adapter (yade_engine.hpp). YADE writes no
// restart files yet: an interrupted run is run again.
#include <CLI/CLI.hpp>

#include "brash/run/driver.hpp"
#include "yade_engine.hpp"

int main(int argc, char** argv) {
  CLI::App app{"brash-yade-run: run a case directory with YADE and write the brash run layout"};
  brash::run::DriverOptions o;
  int threads = 1;
  bool no_post = false;
  app.add_option("case_dir", o.case_path, "case folder holding case.yaml")->required();
  app.add_option("--out", o.out_dir, "run directory (default: runs/<case>-yade-<model>-<stamp>)");
  app.add_option("--runs-root", o.runs_root, "where run directories are created");
  app.add_option("--duration", o.overrides.duration_s, "simulated time [s] (default: the case's run.duration_s)");
  app.add_option("--model", o.overrides.model, "override fluid.model: drag | added_mass | both");
  app.add_option("--treatment", o.overrides.treatment, "override fluid.treatment: implicit | explicit");
  app.add_option("-j,--threads", threads, "YADE OpenMP threads")->check(CLI::Range(1, 256));
  app.add_flag("--no-post", no_post, "do not run brash-post afterwards");
  app.add_flag("--prepare-only", o.prepare_only, "write the run directory's inputs (scene.json, hull.stl) and stop");
  CLI11_PARSE(app, argc, argv);
  o.post = !no_post;
  brash::yade::YadeEngine engine(threads);
  return brash::run::drive(engine, o);
}
