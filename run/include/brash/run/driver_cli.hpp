// The command-line options every engine runner shares (brash-liggghts-run, brash-yade-run): CASE_DIR or
// --resume RUN_DIR, --out, --runs-root, --duration, --model, --treatment, --restart-every, --no-post,
// --prepare-only, into brash::run::DriverOptions. drive() checks their combination.
#pragma once
#include <CLI/CLI.hpp>
#include <string>

#include "brash/run/driver.hpp"

namespace brash::run {

struct DriverCli {
  CLI::Option* case_dir = nullptr;  // a runner's own modes may exclude these
  CLI::Option* resume = nullptr;
};

// `engine`: the run directory's engine name ("liggghts"); `inputs`: what --prepare-only writes, for its help.
inline DriverCli add_driver_options(CLI::App& app, DriverOptions& o, const std::string& engine,
                                    const std::string& inputs) {
  DriverCli cli;
  cli.case_dir = app.add_option("case_dir", o.case_path, "case folder holding case.yaml");
  cli.resume = app.add_option("--resume", o.resume_dir, "continue an interrupted run directory from its newest restart point");
  cli.case_dir->excludes(cli.resume);
  app.add_option("--out", o.out_dir, "run directory (default: runs/<case>-" + engine + "-<model>-<stamp>)");
  app.add_option("--runs-root", o.runs_root, "where run directories are created");
  app.add_option("--duration", o.overrides.duration_s, "simulated time [s] (default: the case's run.duration_s)");
  app.add_option("--model", o.overrides.model, "override fluid.model: drag | added_mass | both");
  app.add_option("--treatment", o.overrides.treatment, "override fluid.treatment: implicit | explicit");
  app.add_option("--restart-every", o.restart_every_s,
                 "model time [s] between restart points (default: a tenth of the run; also on --resume)")
      ->check(CLI::PositiveNumber);
  app.add_flag_callback("--no-post", [&o] { o.post = false; }, "do not run brash-post afterwards");
  app.add_flag("--prepare-only", o.prepare_only, "write the run directory's inputs (" + inputs + ") and stop");
  return cli;
}

}  // namespace brash::run
