// Bad-input catalogue helpers: every entry builds one bad input in a fresh folder, feeds it to the
// reader or command that owns it, and reports how it was rejected (exception text or exit code +
// output). The tests then check that the rejection names the file (and line/key) and the problem.
#pragma once
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace brash::robust {

namespace fs = std::filesystem;

// How an input was rejected. `exit_code` is -1 for a library call that threw brash::InputError,
// -2 when nothing rejected the input (a catalogue failure), else the process exit status.
struct Outcome {
  int exit_code = -2;
  std::string message;
};

struct Entry {
  std::string name;                                 // test name (letters, digits, underscores)
  std::function<Outcome(const fs::path& dir)> run;  // build the input in `dir`, feed it, report
  std::vector<std::string> expect;                  // substrings of the message; "{dir}" = the folder
  int exit_code = -1;                               // expected: -1 InputError, 0..255 exit status, 256 any nonzero
};

// gtest prints parameters with this (instead of a byte dump).
inline void PrintTo(const Entry& e, std::ostream* os) { *os << e.name; }

inline fs::path fresh_dir(const std::string& name) {
  auto dir = fs::temp_directory_path() / ("brash_robust_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

inline void write_file(const fs::path& file, const std::string& content) {
  fs::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << content;
}

inline std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// Runs a shell command line in `dir`, stdout+stderr to dir/output.txt; returns exit status + output.
inline Outcome run_command(const fs::path& dir, const std::string& command) {
  const std::string cmd = "cd '" + dir.string() + "' && " + command + " > output.txt 2>&1";
  const int status = std::system(cmd.c_str());
  Outcome o;
  o.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  o.message = read_text(dir / "output.txt");
  return o;
}

inline std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (auto pos = s.find(from); pos != std::string::npos; pos = s.find(from, pos + to.size())) s.replace(pos, from.size(), to);
  return s;
}

// The entry's expected exit code (256 = any non-zero) and every expected fragment ({dir} = the entry's
// folder) in the message.
inline void expect_clear_error(const Entry& e, const Outcome& o, const fs::path& dir) {
  if (e.exit_code == 256)
    EXPECT_NE(o.exit_code, 0) << o.message;
  else
    EXPECT_EQ(o.exit_code, e.exit_code) << o.message;
  for (const auto& want : e.expect) {
    const std::string w = replace_all(want, "{dir}", dir.string());
    EXPECT_NE(o.message.find(w), std::string::npos) << "expected '" << w << "' in:\n" << o.message;
  }
}

}  // namespace brash::robust
