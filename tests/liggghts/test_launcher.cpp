// brash-liggghts-run's MPI launcher (mpi_launcher.h, docs/clusters.md): the command line it builds from the
// launcher, the rank count and the facts about the machine (pure), and a 2-rank run under a custom launcher.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "brash/error.hpp"
#include "mpi_launcher.h"
#include "runner_case.h"

namespace fs = std::filesystem;
using brash::liggghts::launch_prefix;
using brash::liggghts::LaunchSpec;
using brash::liggghts::resolve_launcher;

namespace {

LaunchSpec spec(const std::string& launcher, int ranks, bool open_mpi = false, bool as_root = false,
                unsigned cpus = 2, bool oversubscribe = false) {
  return {.launcher = launcher, .ranks = ranks, .oversubscribe = oversubscribe, .as_root = as_root,
          .open_mpi = open_mpi, .cpus = cpus};
}

// The narrowed quick case, 0.1 s.
void write_short_case(const fs::path& case_dir) {
  brash::test::SmallCase k;
  k.duration_s = "0.1";
  k.window_s = "[0.0, 0.1]";
  brash::test::write_small_quick_case(case_dir, k);
}

}  // namespace

TEST(LiggghtsLauncher, OneRankRunsTheEngineWithoutALauncher) {
  EXPECT_EQ(launch_prefix(spec("mpirun", 1, true, true)), "");
  EXPECT_EQ(launch_prefix(spec("srun -n {np}", 1)), "");
}

TEST(LiggghtsLauncher, RankCountIsAppendedOrPlacedAtNp) {
  EXPECT_EQ(launch_prefix(spec("mpirun", 2)), "mpirun -np 2 ");
  EXPECT_EQ(launch_prefix(spec("srun", 4)), "srun -n 4 ");
  EXPECT_EQ(launch_prefix(spec("/usr/bin/srun --cpu-bind=cores", 4)), "/usr/bin/srun --cpu-bind=cores -n 4 ");
  EXPECT_EQ(launch_prefix(spec("mpiexec -n {np} --bind-to core", 3)), "mpiexec -n 3 --bind-to core ");
  EXPECT_EQ(launch_prefix(spec("  my_launcher.sh  ", 2)), "my_launcher.sh -np 2 ");
}

TEST(LiggghtsLauncher, OpenMpiGetsAllowRunAsRootOnlyAsRoot) {
  EXPECT_EQ(launch_prefix(spec("mpirun", 2, true, true)), "mpirun --allow-run-as-root -np 2 ");
  EXPECT_EQ(launch_prefix(spec("mpirun", 2, true, false)), "mpirun -np 2 ");
  EXPECT_EQ(launch_prefix(spec("srun", 2, false, true)), "srun -n 2 ") << "not Open MPI's mpirun";
  EXPECT_EQ(launch_prefix(spec("mpiexec -n {np}", 2, true, true)), "mpiexec --allow-run-as-root -n 2 ");
  EXPECT_EQ(launch_prefix(spec("mpirun --allow-run-as-root", 2, true, true)), "mpirun --allow-run-as-root -np 2 ")
      << "given once, not twice";
}

TEST(LiggghtsLauncher, OversubscribeOnlyWhenAskedOrWhenRanksExceedTheCpus) {
  EXPECT_EQ(launch_prefix(spec("mpirun", 2, true, false, 2)), "mpirun -np 2 ") << "2 ranks on 2 CPUs";
  EXPECT_EQ(launch_prefix(spec("mpirun", 3, true, false, 2)), "mpirun --oversubscribe -np 3 ");
  EXPECT_EQ(launch_prefix(spec("mpirun", 2, true, false, 2, true)), "mpirun --oversubscribe -np 2 ");
  EXPECT_EQ(launch_prefix(spec("mpirun", 8, true, true, 0)), "mpirun --allow-run-as-root -np 8 ") << "CPUs unknown";
  EXPECT_EQ(launch_prefix(spec("mpirun", 3, false, false, 2, true)), "mpirun -np 3 ")
      << "an mpirun that is not Open MPI's does not know the flag";
}

TEST(LiggghtsLauncher, OptionBeatsEnvironmentBeatsDefault) {
  EXPECT_EQ(resolve_launcher("srun", "mpiexec"), "srun");
  EXPECT_EQ(resolve_launcher("", "mpiexec -n {np}"), "mpiexec -n {np}");
  EXPECT_EQ(resolve_launcher("", nullptr), "mpirun");
  EXPECT_EQ(resolve_launcher("", ""), "mpirun");
  EXPECT_THROW(
      {
        try {
          resolve_launcher("  ", nullptr);
        } catch (const brash::InputError& e) {
          EXPECT_NE(std::string(e.what()).find("--launcher"), std::string::npos) << e.what();
          throw;
        }
      },
      brash::InputError);
  EXPECT_THROW(
      {
        try {
          resolve_launcher("", " ");
        } catch (const brash::InputError& e) {
          EXPECT_NE(std::string(e.what()).find("BRASH_MPI_LAUNCHER"), std::string::npos) << e.what();
          throw;
        }
      },
      brash::InputError);
}

// A wrapper script as the launcher (BRASH_MPI_LAUNCHER): it logs its arguments and execs mpirun. The run on 2
// ranks completes, the wrapper saw `-np 2 .../brash-liggghts -in in.lmp`, and meta.json names the launcher.
TEST(LiggghtsLauncher, CustomLauncherFromTheEnvironmentRunsTheCase) {
  const fs::path dir = brash::test::fresh_dir("launcher");
  write_short_case(dir / "case");
  const fs::path wrapper = dir / "launch.sh";
  std::ofstream(wrapper) << "#!/bin/sh\necho \"$@\" >> '" << (dir / "launcher_args.txt").string() << "'\n"
                         << "if [ \"$(id -u)\" = 0 ]; then exec mpirun --allow-run-as-root \"$@\"; fi\n"
                         << "exec mpirun \"$@\"\n";
  fs::permissions(wrapper, fs::perms::owner_all);
  const std::string cmd = "env BRASH_MPI_LAUNCHER='" + wrapper.string() + "' " +
                          brash::test::runner_command(dir / "case", dir / "run") + " --np 2 > '" +
                          (dir / "run.log").string() + "' 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << brash::test::read_text(dir / "run.log");
  const std::string args = brash::test::read_text(dir / "launcher_args.txt");
  EXPECT_EQ(args.rfind("-np 2 ", 0), 0u) << args;
  EXPECT_NE(args.find("/brash-liggghts -in in.lmp"), std::string::npos) << args;
  const std::string meta = brash::test::read_text(dir / "run/meta.json");
  EXPECT_NE(meta.find("\"status\": \"complete\""), std::string::npos) << meta;
  EXPECT_NE(meta.find("\"launcher\": \"" + wrapper.string() + " -np 2\""), std::string::npos) << meta;
  EXPECT_NE(meta.find("\"ranks\": 2"), std::string::npos) << meta;
  EXPECT_GT(brash::test::read_table(dir / "run/hull_force.raw").size(), 5u);
  fs::remove_all(dir);
}

// A blank --launcher and a launcher whose program does not exist are bad input (exit 2, nothing written) naming the
// option or the variable and the program.
TEST(LiggghtsLauncher, BadLaunchersAreNamed) {
  const fs::path dir = brash::test::fresh_dir("launcher_bad");
  write_short_case(dir / "case");
  const std::string runner = brash::test::runner_command(dir / "case", dir / "run");
  int rc = std::system((runner + " --np 2 --launcher ' ' > '" + (dir / "blank.log").string() + "' 2>&1").c_str());
  EXPECT_EQ(WEXITSTATUS(rc), 2);
  EXPECT_NE(brash::test::read_text(dir / "blank.log").find("--launcher"), std::string::npos);
  rc = std::system((runner + " --np 2 --launcher /no/such/launcher > '" + (dir / "missing.log").string() + "' 2>&1").c_str());
  EXPECT_EQ(WEXITSTATUS(rc), 2) << brash::test::read_text(dir / "missing.log");
  EXPECT_NE(brash::test::read_text(dir / "missing.log").find("--launcher: MPI launcher '/no/such/launcher' not found"),
            std::string::npos)
      << brash::test::read_text(dir / "missing.log");
  rc = std::system(("env BRASH_MPI_LAUNCHER='no-such-srun -n {np}' " + runner + " --np 2 > '" +
                    (dir / "env.log").string() + "' 2>&1").c_str());
  EXPECT_EQ(WEXITSTATUS(rc), 2) << brash::test::read_text(dir / "env.log");
  EXPECT_NE(brash::test::read_text(dir / "env.log").find("BRASH_MPI_LAUNCHER: MPI launcher 'no-such-srun' not found (not "
                                                         "on PATH)"),
            std::string::npos)
      << brash::test::read_text(dir / "env.log");
  EXPECT_FALSE(fs::exists(dir / "run")) << "a refused launcher writes nothing";
  fs::remove_all(dir);
}
