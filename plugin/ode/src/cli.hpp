// The command line of brash-ode and bench-ode: the run driver's options (brash/run/driver_cli.hpp: CASE_DIR or
// --resume RUN_DIR, --out, --duration, --model, --treatment, --set KEY=VALUE, --restart-every, ...), another run's
// snapshot as the start (--scene-from, --scene-time), short forms of the case's ode: keys (--dt S is --set ode.timestep_s=S: a change of the case, which the run directory's case.yaml
// records), and what a run takes besides its case (RunOptions).
#pragma once
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "brash/case.hpp"
#include "brash/ode/run_case.hpp"
#include "brash/run/driver_cli.hpp"

namespace brash::ode {

// An option that is a short form of `--set KEY=VALUE`.
struct KeyOption {
  const char* option;
  const char* key;
  const char* help;
};
inline constexpr KeyOption kKeyOptions[] = {
    {"--dt", "ode.timestep_s", "ODE time step [s] (the case's run.timestep_s is the soft-contact step)"},
    {"--iterations", "ode.iterations", "dWorldQuickStep iterations"},
    {"--implicit", "ode.implicit", "implicit added mass in ODE: effective_mass | scale_forces"},
    {"--broad-phase", "ode.broad_phase", "broad phase: grid (ours) | sap (ODE's sweep and prune); same contacts"},
    {"--sphere-order", "ode.sphere_order",
     "order of the ODE bodies: spatial (cells of two mean diameters) | packing (the packing file's; slower)"},
    {"--settle", "ode.settle_s",
     "settle the whole bed this long [s] before t = 0, the hull parked (a far field begins after it)"},
    {"--settle-damping", "ode.settle_damping", "velocity damping per step over the settling's first half"},
};

// The driver's options, the short forms of the ode: keys, --no-progress and the hidden testing options.
inline run::DriverCli add_ode_options(CLI::App& app, run::DriverOptions& d, RunOptions& o) {
  const run::DriverCli cli =
      run::add_driver_options(app, d, "ode", "case.yaml; the scene is built in brash-ode",
                              run::RestartOff{fmt::format("{} s; on --resume the run's own", RunOptions{}.restart_every_s)});
  for (const KeyOption& k : kKeyOptions)
    app.add_option_function<std::string>(
           k.option, [&d, key = k.key](const std::string& v) { d.overrides.sets.emplace_back(key, v); },
           fmt::format("{} (--set {}=VALUE; default: the case's)", k.help, k.key))
        ->type_name("VALUE");
  CLI::Option* scene_from = app.add_option("--scene-from", o.scene_from,
                 "start from another run's particle snapshot of this case (RUN_DIR/particles/particles_<step>.csv: "
                 "id,x,y,z,radius[,vx,vy,vz][,omegax,omegay,omegaz][,state]) instead of the packing; the run goes on "
                 "from --scene-time to --duration")
      ->check(CLI::ExistingFile)
      ->excludes(cli.resume);
  CLI::Option* scene_time =
      app.add_option("--scene-time", o.scene_time_s,
                     "with --scene-from: the snapshot's model time [s]; the hull starts where it was then, the "
                     "record's times from there")
          ->check(CLI::NonNegativeNumber)
          ->excludes(cli.resume)
          ->needs(scene_from);
  scene_from->needs(scene_time);
  app.add_flag_callback("--no-progress", [&o, &d] { o.progress = d.progress = false; }, "no progress line on stderr");
  // Testing only: exit like a kill -9 (no cleanup, no final outputs) right after this step.
  app.add_option("--crash-after-step", o.crash_after_step)->group("");
  // Testing only: a SIGTERM arriving during this step (the handled stop: resumable at this step).
  app.add_option("--stop-after-step", o.stop_after_step)->group("");
  return cli;
}

// The run options with the driver's --restart-every (not given: RunOptions' default), and the driver's interval
// between its own records set to the same.
inline void take_restart_every(run::DriverOptions& d, RunOptions& o) {
  if (d.restart_every_s >= 0) o.restart_every_s = d.restart_every_s;
  d.restart_every_s = o.restart_every_s;
}

// The settings of a scene without a case file (brash-ode --single, bench-ode --bed): the default case with the
// command line's case keys, validated as a case file's. Throws InputError naming the key.
inline Case case_of_command_line(const run::CaseOverrides& overrides) {
  std::map<std::string, std::vector<std::pair<std::string, std::string>>> sections;
  auto sets = overrides.sets;
  if (!overrides.treatment.empty()) sets.emplace_back("fluid.treatment", overrides.treatment);
  if (!overrides.model.empty()) sets.emplace_back("fluid.model", overrides.model);
  std::string yaml = "name: command line\n";
  for (const auto& [key, value] : sets) {
    const auto dot = key.find('.');
    if (dot == std::string::npos)
      yaml += key + ": " + value + "\n";  // (a top-level key: the loader names it)
    else
      sections[key.substr(0, dot)].emplace_back(key.substr(dot + 1), value);
  }
  for (const auto& [section, keys] : sections) {
    yaml += section + ":\n";
    for (const auto& [key, value] : keys) yaml += "  " + key + ": " + value + "\n";
  }
  return parse_case(yaml, std::filesystem::current_path(), "the command line's case keys");
}

}  // namespace brash::ode
