// brash-liggghts-run CASE_DIR: runs a case with LIGGGHTS end to end through the run driver
// (brash/run/driver.hpp: the run layout of docs/case_format.md, resume, progress, early stop, brash-post) with
// the LIGGGHTS adapter (liggghts_engine.h). --rebuild-record rewrites a run's record from its raw files.
#include <CLI/CLI.hpp>
#include <cstdlib>
#include <fmt/format.h>
#include <fstream>
#include <iostream>

#include "brash/case.hpp"
#include "brash/error.hpp"
#include "brash/run/force_record.hpp"
#include "brash/run/driver.hpp"
#include "brash/run/driver_cli.hpp"
#include "brash/run/run_layout.hpp"
#include "liggghts_engine.h"
#include "mpi_launcher.h"

namespace fs = std::filesystem;

namespace {

// hull_force.csv and particles/index.csv of a run directory from its raw files (all attempts), and the count of
// pieces gone through the channel's ends from its log.
int rebuild_record(const fs::path& run_dir) {
  using namespace brash::liggghts;
  const auto raws = hull_force_raws(run_dir);
  if (raws.empty())
    throw brash::InputError(run_dir.string() + ": no hull_force.raw or hull_force.part*.raw to rebuild the record from");
  const brash::run::RunDirLock lock(run_dir);  // not while a runner writes it
  const std::size_t rows = brash::run::write_hull_force_csv(
      run_dir / "hull_force.csv", read_hull_force_raws(raws, std::numeric_limits<double>::infinity()));
  std::cerr << "[brash-liggghts] " << (run_dir / "hull_force.csv").string() << ": " << rows << " rows from "
            << raws.size() << " raw file(s)\n";
  if (fs::is_directory(run_dir / "particles")) {
    const std::size_t converted = convert_dumps(run_dir, brash::load_case(run_dir / "case.yaml"));
    std::cerr << "[brash-liggghts] " << (run_dir / "particles" / "index.csv").string()
              << ": every particles_<step>.csv"
              << (converted ? fmt::format(" ({} dump(s) converted)", converted) : "") << "\n";
  }
  long exits = -1;
  std::ifstream log(run_dir / "log.txt");
  for (std::string line; std::getline(log, line);)
    if (const long n = exit_total(line); n >= 0) exits = n;
  auto meta = nlohmann::json::parse(std::ifstream(run_dir / "meta.json"), nullptr, false);
  if (exits >= 0 && meta.is_object()) {
    meta["exits"] = exits;
    brash::run::write_meta(run_dir, meta);
    std::cerr << "[brash-liggghts] " << exits << " piece(s) gone through the channel's ends (log.txt)\n";
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"brash-liggghts-run: run a case directory with LIGGGHTS and write the brash run layout",
               "brash-liggghts-run"};
  brash::run::DriverOptions o;
  int ranks = 1;
  fs::path rebuild_dir;
  const auto cli = brash::run::add_driver_options(app, o, "liggghts", "in.lmp, packing.data, hull.stl");
  app.add_option("--np", ranks, "MPI ranks")->check(CLI::Range(1, 1024));
  std::string launcher;
  bool oversubscribe = false;
  app.add_option("--launcher", launcher,
                 "MPI launcher for --np > 1 (default: $BRASH_MPI_LAUNCHER, else mpirun); {np} in it is the rank "
                 "count, else -n N (srun) or -np N is appended (docs/clusters.md)");
  app.add_flag("--oversubscribe", oversubscribe,
               "let Open MPI's mpirun start more ranks than it counts cores (added by itself when --np exceeds the "
               "CPUs this process may use)");
  auto* rebuild_opt = app.add_option("--rebuild-record", rebuild_dir,
                                     "rewrite a run directory's hull_force.csv from its raw force files (all "
                                     "attempts) with this runner's rules, then run brash-post");
  rebuild_opt->excludes(cli.case_dir)->excludes(cli.resume);
  CLI11_PARSE(app, argc, argv);
  if (!rebuild_dir.empty()) {
    try {
      rebuild_record(rebuild_dir);
    } catch (const std::exception& e) {
      std::cerr << "brash-liggghts-run: error: " << e.what() << "\n";
      return 1;
    }
    return o.post ? brash::run::run_postprocessor(rebuild_dir, "[brash-liggghts]") : 0;
  }
  std::string prefix;
  try {
    const char* env_launcher = std::getenv("BRASH_MPI_LAUNCHER");
    const std::string resolved = brash::liggghts::resolve_launcher(launcher, env_launcher);
    if (ranks > 1) brash::liggghts::require_launcher_program(resolved, launcher, env_launcher);
    const auto spec = brash::liggghts::detect_launch(resolved, ranks, oversubscribe);
    prefix = brash::liggghts::launch_prefix(spec);
  } catch (const brash::InputError& e) {
    std::cerr << "brash-liggghts-run: error: " << e.what() << "\n";
    return 2;
  }
  brash::liggghts::LiggghtsEngine engine(ranks, o.restart_every_s, prefix);
  return brash::run::drive(engine, o);
}
