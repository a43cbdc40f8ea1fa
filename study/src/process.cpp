// fork/exec with the log as stdout and stderr.
#include "brash/study/process.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace fs = std::filesystem;

namespace brash::study {

namespace {

// In the child: never returns.
[[noreturn]] void exec_in_child(const Command& c, const Settings& s, const fs::path& log) {
  const int fd = log.empty() ? -1 : ::open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  if (fd >= 0) {
    ::dup2(fd, STDOUT_FILENO);
    ::dup2(fd, STDERR_FILENO);
    ::close(fd);
  }
  if (!c.cwd.empty() && ::chdir(c.cwd.c_str()) != 0) {
    std::perror(c.cwd.c_str());
    std::_Exit(127);
  }
  for (const auto& [key, value] : c.env) ::setenv(key.c_str(), value.c_str(), 1);
  std::vector<std::string> words;
  if (c.niced) words = {"nice", "-n", std::to_string(s.nice)};
  words.insert(words.end(), c.argv.begin(), c.argv.end());
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  ::execvp(argv[0], argv.data());
  std::perror(argv[0]);
  std::_Exit(127);
}

}  // namespace

int run_process(const Command& c, const Settings& s, const fs::path& log) {
  if (c.argv.empty()) return 127;
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) return 127;
  if (pid == 0) exec_in_child(c, s, log);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return 127;
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return WIFSIGNALED(status) ? 128 + WTERMSIG(status) : 127;
}

int run_steps(const std::vector<Command>& steps, const Settings& s, const fs::path& log) {
  int rc = 0;
  for (const auto& c : steps)
    if ((rc = run_process(c, s, log)) != 0) break;
  return rc;
}

}  // namespace brash::study
