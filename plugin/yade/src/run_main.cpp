// brash-yade-run CASE_DIR | --resume RUN_DIR: runs a case with YADE through the run driver (brash/run/driver.hpp:
// the run layout of docs/case_format.md, resume, signals, progress, early stop, brash-post) with the YADE adapter
// (yade_engine.hpp).
#include <CLI/CLI.hpp>

#include "brash/run/driver_cli.hpp"
#include "yade_engine.hpp"

int main(int argc, char** argv) {
  CLI::App app{"brash-yade-run: run a case directory with YADE and write the brash run layout",
               "brash-yade-run"};
  brash::run::DriverOptions o;
  int threads = 1;
  brash::run::add_driver_options(app, o, "yade", "scene.json, hull.stl");
  app.add_option("-j,--threads", threads, "YADE OpenMP threads")->check(CLI::Range(1, 256));
  CLI11_PARSE(app, argc, argv);
  brash::yade::YadeEngine engine(threads, o.restart_every_s);
  return brash::run::drive(engine, o);
}
