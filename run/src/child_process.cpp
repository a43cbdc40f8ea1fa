// An engine as a child process (see child_process.hpp).
#include "brash/run/child_process.hpp"

#include <csignal>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <sys/wait.h>

#include <fmt/format.h>

#include "brash/run/runner_setup.hpp"

namespace brash::run {
namespace {

long read_pid(const std::filesystem::path& file) {
  std::ifstream in(file);
  long pid = 0;
  return in >> pid && pid > 0 ? pid : 0;
}

// The pipe from the child while it runs. Left by an exception, it stops the child and waits for its end, so that
// no engine outlives the runner's attempt.
class ChildPipe {
 public:
  ChildPipe(const std::string& command, const ChildHandlers& on) : file_(::popen(command.c_str(), "r")), on_(on) {
    if (!file_) throw std::runtime_error("cannot start " + command);
  }
  ~ChildPipe() {
    if (!file_) return;
    stop();
    ::pclose(file_);
    try {
      on_.pid(0);
    } catch (...) {  // leaving by an exception already
    }
  }
  ChildPipe(const ChildPipe&) = delete;
  ChildPipe& operator=(const ChildPipe&) = delete;

  // The next line into `line` (cleared first; its capacity kept, so reading allocates only for a longer line).
  bool read_line(std::string& line) {
    line.clear();
    while (std::fgets(buf_, sizeof buf_, file_)) {
      line += buf_;
      if (line.back() == '\n') break;
    }
    return !line.empty();
  }
  void learn_pid(const std::filesystem::path& pid_file) {
    if (pid_ == 0 && (pid_ = read_pid(pid_file)) > 0) on_.pid(pid_);
  }
  // SIGTERM, once, when the pid is known.
  void stop() {
    if (pid_ > 0 && !stop_sent_) stop_sent_ = ::kill(static_cast<pid_t>(pid_), SIGTERM) == 0;
  }
  int close() {
    const int status = ::pclose(file_);
    file_ = nullptr;
    on_.pid(0);
    return status;
  }

 private:
  FILE* file_;
  const ChildHandlers& on_;
  long pid_ = 0;
  bool stop_sent_ = false;
  char buf_[4096];
};

}  // namespace

std::string child_shell_command(const ChildCommand& c) {
  // exec: the shell's pid becomes the program's, so that a stop can signal it
  return fmt::format("cd {} && echo $$ > {} && {}{}exec {} 2>&1", shell_quote(c.dir), shell_quote(c.pid_file), c.env,
                     c.env.empty() ? "" : " ", c.program);
}

ChildExit run_child(const ChildCommand& command, const ChildHandlers& on) {
  ChildPipe pipe(child_shell_command(command), on);
  std::string line;
  while (pipe.read_line(line)) {
    pipe.learn_pid(command.dir / command.pid_file);
    if (on.line(line)) pipe.stop();
  }
  const int status = pipe.close();
  std::error_code ec;  // the pid file names a process that has ended: it goes (a run folder keeps its results only)
  std::filesystem::remove(command.dir / command.pid_file, ec);
  if (WIFEXITED(status)) return {WEXITSTATUS(status), 0};
  return {128, WIFSIGNALED(status) ? WTERMSIG(status) : 0};
}

}  // namespace brash::run
