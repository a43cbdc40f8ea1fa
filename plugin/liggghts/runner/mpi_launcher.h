// How brash-liggghts-run starts the engine on N ranks: the MPI launcher's words before `brash-liggghts`
// (docs/clusters.md). --launcher, else $BRASH_MPI_LAUNCHER, else mpirun; {np} in it is the rank count, otherwise
// `-n N` (srun) or `-np N` (any other launcher) is appended. Open MPI's mpirun gets --allow-run-as-root only when
// run as root, and --oversubscribe only when asked or when the ranks exceed the CPUs this process may use.
#pragma once
#include <string>

namespace brash::liggghts {

struct LaunchSpec {
  std::string launcher = "mpirun";  // passed to /bin/sh as written
  int ranks = 1;
  bool oversubscribe = false;  // --oversubscribe
  bool as_root = false;        // the runner's effective user is root
  bool open_mpi = false;       // the launcher's program is Open MPI's mpirun / mpiexec
  unsigned cpus = 0;           // CPUs this process may run on (0: unknown)
};

// The launcher's program: its first word, as written ("srun", "/opt/openmpi/bin/mpirun").
std::string launcher_program(const std::string& launcher);

// The command words before the engine's executable, ending in a space; "" for one rank (the engine runs
// directly). Pure: every fact about the machine comes in the spec.
std::string launch_prefix(const LaunchSpec& s);

// The launcher from the --launcher option, else the environment's BRASH_MPI_LAUNCHER (env may be null), else
// mpirun. InputError naming the option (or the variable) when it is blank.
std::string resolve_launcher(const std::string& option, const char* env);

// InputError when the launcher's program is neither an executable file (a name with a slash) nor found on PATH,
// naming the program and where the launcher came from (option and env as for resolve_launcher).
void require_launcher_program(const std::string& launcher, const std::string& option, const char* env);

// The spec for this process: as_root from the effective user, cpus from the affinity mask, open_mpi by asking
// an mpirun / mpiexec / orterun for its --version (only when ranks > 1).
LaunchSpec detect_launch(const std::string& launcher, int ranks, bool oversubscribe);

}  // namespace brash::liggghts
