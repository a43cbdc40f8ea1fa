#include "mpi_launcher.h"

#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <fmt/format.h>
#include <sched.h>
#include <thread>
#include <unistd.h>

#include "brash/error.hpp"
#include "brash/run/runner_setup.hpp"

namespace brash::liggghts {

namespace {

constexpr const char* kWhitespace = " \t\n";

bool is_blank(const std::string& s) { return s.find_first_not_of(kWhitespace) == std::string::npos; }

std::string base_name(const std::string& program) {
  const auto slash = program.rfind('/');
  return slash == std::string::npos ? program : program.substr(slash + 1);
}

bool mentions(const std::string& launcher, const std::string& flag) {
  return launcher.find(flag) != std::string::npos;
}

// Replaces every {np} by n; whether there was one.
bool replace_np(std::string& s, int n) {
  bool found = false;
  for (auto at = s.find("{np}"); at != std::string::npos; at = s.find("{np}", at)) {
    s.replace(at, 4, std::to_string(n));
    found = true;
  }
  return found;
}

// Open MPI's flags for this launch, each with a leading space.
std::string open_mpi_flags(const LaunchSpec& s) {
  if (!s.open_mpi) return "";
  std::string flags;
  if (s.as_root && !mentions(s.launcher, "--allow-run-as-root")) flags += " --allow-run-as-root";
  const bool more_ranks_than_cpus = s.cpus > 0 && static_cast<unsigned>(s.ranks) > s.cpus;
  if ((s.oversubscribe || more_ranks_than_cpus) && !mentions(s.launcher, "--oversubscribe")) flags += " --oversubscribe";
  return flags;
}

unsigned usable_cpus() {
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0) return static_cast<unsigned>(CPU_COUNT(&set));
  return std::thread::hardware_concurrency();
}

// `PROGRAM --version` names Open MPI ("mpirun (Open MPI) 4.1.4"); false when it cannot be run.
bool reports_open_mpi(const std::string& program) {
  FILE* p = ::popen((run::shell_quote(program) + " --version 2>&1").c_str(), "r");
  if (!p) return false;
  std::string text;
  char buf[512];
  while (std::fgets(buf, sizeof buf, p)) text += buf;
  ::pclose(p);
  return text.find("Open MPI") != std::string::npos || text.find("OpenRTE") != std::string::npos;
}

}  // namespace

std::string launcher_program(const std::string& launcher) {
  const auto from = launcher.find_first_not_of(kWhitespace);
  if (from == std::string::npos) return "";
  return launcher.substr(from, launcher.find_first_of(kWhitespace, from) - from);
}

std::string launch_prefix(const LaunchSpec& s) {
  if (s.ranks <= 1) return "";
  const std::string program = launcher_program(s.launcher);
  std::string rest = s.launcher.substr(s.launcher.find(program) + program.size());
  const bool placed = replace_np(rest, s.ranks);
  std::string cmd = program + open_mpi_flags(s) + rest;
  while (!cmd.empty() && cmd.find_last_of(kWhitespace) == cmd.size() - 1) cmd.pop_back();
  if (!placed) cmd += fmt::format(" {} {}", base_name(program) == "srun" ? "-n" : "-np", s.ranks);
  return cmd + " ";
}

std::string resolve_launcher(const std::string& option, const char* env) {
  if (!option.empty()) {
    if (is_blank(option)) throw InputError("--launcher: empty; give a command such as \"srun\" or \"mpirun -np {np}\"");
    return option;
  }
  if (env && *env) {
    if (is_blank(env)) throw InputError("BRASH_MPI_LAUNCHER: blank; unset it or give a command such as \"srun\"");
    return env;
  }
  return "mpirun";
}

namespace {

bool executable(const std::string& file) { return ::access(file.c_str(), X_OK) == 0; }

// As the shell finds a command: a name with a slash as it is, any other along PATH.
bool program_found(const std::string& program) {
  if (program.find('/') != std::string::npos) return executable(program);
  const char* path = std::getenv("PATH");
  for (std::string_view dirs = path ? path : ""; !dirs.empty();) {
    const auto colon = dirs.find(':');
    const std::string_view dir = dirs.substr(0, colon);
    if (executable((dir.empty() ? std::string(".") : std::string(dir)) + "/" + program)) return true;
    dirs = colon == std::string_view::npos ? std::string_view() : dirs.substr(colon + 1);
  }
  return false;
}

}  // namespace

void require_launcher_program(const std::string& launcher, const std::string& option, const char* env) {
  const std::string program = launcher_program(launcher);
  if (program_found(program)) return;
  const std::string from = !option.empty()       ? "--launcher"
                           : (env && *env)       ? "BRASH_MPI_LAUNCHER"
                                                 : "the default launcher (install openmpi-bin, or give --launcher)";
  throw InputError(fmt::format("{}: MPI launcher '{}' not found ({})", from, program,
                               program.find('/') != std::string::npos ? "no executable file there" : "not on PATH"));
}

LaunchSpec detect_launch(const std::string& launcher, int ranks, bool oversubscribe) {
  LaunchSpec s;
  s.launcher = launcher;
  s.ranks = ranks;
  s.oversubscribe = oversubscribe;
  s.as_root = ::geteuid() == 0;
  s.cpus = usable_cpus();
  const std::string name = base_name(launcher_program(launcher));
  if (ranks > 1 && (name == "mpirun" || name == "mpiexec" || name == "orterun"))
    s.open_mpi = reports_open_mpi(launcher_program(launcher));
  return s;
}

}  // namespace brash::liggghts
