// An engine as a child process (brash/run/child_process.hpp), with `sh -c` children standing in for the engine.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>

#include "brash/run/child_process.hpp"
#include "brash/run/runner_setup.hpp"

namespace fs = std::filesystem;
using brash::run::ChildCommand;
using brash::run::ChildExit;

namespace {

class Child : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("brash child " + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());  // a space: the folder is quoted
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Runs `sh -c script` in dir_; records its lines and the pids it was given.
  ChildExit run(const std::string& script, const std::function<bool(const std::string&)>& stop_on = nullptr) {
    const ChildCommand command{dir_, "BRASH_TEST_WORD=word", "sh -c " + brash::run::shell_quote(script)};
    return brash::run::run_child(command, {[&](long pid) { pids_.push_back(pid); },
                                           [&](const std::string& line) {
                                             lines_.push_back(line);
                                             return stop_on && stop_on(line);
                                           }});
  }

  fs::path dir_;
  std::vector<std::string> lines_;
  std::vector<long> pids_;
};

}  // namespace

TEST_F(Child, LinesInOrderAndExitStatus) {
  const ChildExit e = run("echo one; echo two >&2; printf 'three %s' \"$BRASH_TEST_WORD\"; exit 3");
  EXPECT_EQ(lines_, (std::vector<std::string>{"one\n", "two\n", "three word"}));
  EXPECT_EQ(e.code, 3);
  EXPECT_EQ(e.signal, 0);
}

// ... and its pid file while it runs, gone once it has ended.
TEST_F(Child, RunsInItsFolderAndWritesItsPid) {
  const ChildExit e = run("pwd; echo $$; cat engine.pid");
  ASSERT_EQ(lines_.size(), 3u);
  EXPECT_TRUE(fs::equivalent(lines_[0].substr(0, lines_[0].size() - 1), dir_)) << lines_[0];
  const long pid = std::stol(lines_[1]);  // exec: the program runs in the shell's process
  EXPECT_EQ(std::stol(lines_[2]), pid);
  EXPECT_FALSE(fs::exists(dir_ / "engine.pid"));
  ASSERT_EQ(pids_.size(), 2u);
  EXPECT_EQ(pids_.front(), pid);
  EXPECT_EQ(pids_.back(), 0);  // ended
  EXPECT_EQ(e.code, 0);
}

TEST_F(Child, LongLinesArriveWhole) {
  run("head -c 10000 /dev/zero | tr '\\0' x; echo; echo end");
  ASSERT_EQ(lines_.size(), 2u);
  EXPECT_EQ(lines_[0], std::string(10000, 'x') + "\n");
}

// A stop asked by the line handler is a SIGTERM: the child ends on it, long before its own end.
TEST_F(Child, StopSendsSigterm) {
  const auto t0 = std::chrono::steady_clock::now();
  const ChildExit e = run("echo ready; exec sleep 30", [](const std::string& line) { return line == "ready\n"; });
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(20));
  EXPECT_EQ(e.code, 128);
  EXPECT_EQ(e.signal, SIGTERM);
}

// The pid handed out is where the run driver forwards a stop signal it receives (SIGTERM, SIGINT, SIGHUP: each
// forwarded as a SIGTERM): one sent there ends the child.
TEST_F(Child, ForwardedSignalEndsIt) {
  const auto t0 = std::chrono::steady_clock::now();
  const ChildExit e = run("echo ready; exec sleep 30", [&](const std::string&) {
    ::kill(static_cast<pid_t>(pids_.at(0)), SIGTERM);
    return false;
  });
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(20));
  EXPECT_EQ(e.code, 128);
  EXPECT_EQ(e.signal, SIGTERM);
}

TEST_F(Child, HandlerExceptionEndsTheChild) {
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_THROW(run("echo ready; exec sleep 30", [](const std::string&) -> bool { throw std::runtime_error("x"); }),
               std::runtime_error);
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(20));
  ASSERT_FALSE(pids_.empty());
  EXPECT_EQ(pids_.back(), 0);
}
