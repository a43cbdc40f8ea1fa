// An engine run as a child process of its runner (brash-liggghts-run, brash-yade-run): started by /bin/sh in its
// run directory, its pid written to a file there, its output (stdout and stderr together) read line by line.
// The shell writes its own pid and then execs the engine, so the pid in the file is the engine's (or its MPI
// launcher's): the process a stop signal must reach. The runner forwards its stop signals to that pid (the run
// driver's engine_process); a stop the runner decides itself (the early stop) is a SIGTERM sent here.
#pragma once
#include <filesystem>
#include <functional>
#include <string>

namespace brash::run {

struct ChildCommand {
  std::filesystem::path dir;            // where it runs; the pid file is written there
  std::string env;                      // shell assignments for it, "NAME=value ..." (quoted); may be empty
  std::string program;                  // shell words: the program and its arguments (quoted)
  std::string pid_file = "engine.pid";  // in dir
};

// The /bin/sh command line that runs `c` (its output to a pipe, stderr included).
std::string child_shell_command(const ChildCommand& c);

struct ChildHandlers {  // both set
  // The child's pid, once its pid file names it; 0 once the child ended.
  std::function<void(long pid)> pid;
  // Each line of its output, with its newline (the last one may have none). True: stop the child (a SIGTERM,
  // sent once); its lines are still read until it ends.
  std::function<bool(const std::string& line)> line;
};

struct ChildExit {
  int code = 0;    // its exit status; 128 when a signal ended it
  int signal = 0;  // the signal that ended it; 0 when it exited
};

// Runs the child to its end. Throws std::runtime_error when it cannot be started. A handler that throws ends
// the child (SIGTERM) before the exception leaves.
ChildExit run_child(const ChildCommand& command, const ChildHandlers& on);

}  // namespace brash::run
