// The command-line options every engine runner shares (brash-liggghts-run, brash-yade-run, brash-ode): CASE_DIR
// or --resume RUN_DIR, --out, --runs-root, --duration, --model, --treatment, --set, --restart-every, --no-post,
// --prepare-only, into brash::run::DriverOptions. drive() checks their combination. Every option that changes a
// case key changes the case the run uses, so the run directory's case.yaml records it.
#pragma once
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "brash/case_derive.hpp"

#include "brash/run/driver.hpp"

namespace brash::run {

struct DriverCli {
  CLI::Option* case_dir = nullptr;  // a runner's own modes may exclude these
  CLI::Option* resume = nullptr;
};

// An engine whose --restart-every 0 means no restart files, and its default interval in words (a resume too).
struct RestartOff {
  std::string default_text;
};

// `engine`: the run directory's engine name ("liggghts"); `inputs`: what --prepare-only writes, for its help.
inline DriverCli add_driver_options(CLI::App& app, DriverOptions& o, const std::string& engine,
                                    const std::string& inputs, const std::optional<RestartOff>& restart_off = {}) {
  DriverCli cli;
  cli.case_dir = app.add_option("case_dir", o.case_path, "case folder holding case.yaml");
  cli.resume = app.add_option("--resume", o.resume_dir, "continue an interrupted run directory from its newest restart point");
  cli.case_dir->excludes(cli.resume);
  app.add_option("--out", o.out_dir, "run directory (default: runs/<case>-" + engine + "-<model>-<stamp>)");
  app.add_option("--runs-root", o.runs_root, "where run directories are created");
  app.add_option("--duration", o.overrides.duration_s, "simulated time [s] (default: the case's run.duration_s)");
  app.add_option("--model", o.overrides.model, "override fluid.model: drag | added_mass | both");
  app.add_option("--treatment", o.overrides.treatment, "override fluid.treatment: implicit | explicit");
  app.add_option_function<std::vector<std::string>>(
         "--set",
         [&o](const std::vector<std::string>& sets) {
           for (const auto& s : sets) o.overrides.sets.push_back(parse_case_override(s));
         },
         "KEY=VALUE: set a case key for this run, as brash-case derive --set (e.g. ode.timestep_s=1e-3); "
         "repeatable")
      ->type_name("KEY=VALUE")
      ->check([](const std::string& s) {
        return s.find('=') == std::string::npos || s.front() == '='
                   ? "'" + s + "': expected KEY=VALUE (like fluid.model=drag)"
                   : std::string();
      });
  if (restart_off) {
    app.add_option("--restart-every", o.restart_every_s,
                   "model time [s] between restart files (0 = none; default " + restart_off->default_text + ")")
        ->check(CLI::NonNegativeNumber);
  } else {
    app.add_option("--restart-every", o.restart_every_s,
                   "model time [s] between restart points (default: a tenth of the run; also on --resume)")
        ->check(CLI::PositiveNumber);
  }
  app.add_flag_callback("--no-post", [&o] { o.post = false; }, "do not run brash-post afterwards");
  app.add_flag("--prepare-only", o.prepare_only, "write the run directory's inputs (" + inputs + ") and stop");
  return cli;
}

}  // namespace brash::run
