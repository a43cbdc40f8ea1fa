// The run driver's progress line (run/src/run_monitor.cpp): its ETA is the stepping rate since the attempt's first
// progress point, so an engine's start-up (reading the scene, starting MPI: seconds before the first point) does
// not count as stepping time.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <regex>
#include <string>
#include <thread>
#include <unistd.h>

#include "run_monitor.hpp"
#include "stop_signals.hpp"

namespace fs = std::filesystem;

namespace {

// An engine that is never run: the monitor only asks it for its force record (the early stop, off here).
class IdleEngine final : public brash::run::Engine {
 public:
  std::string name() const override { return "idle"; }
  std::string runner() const override { return "idle-run"; }
  nlohmann::json meta() const override { return nlohmann::json::object(); }
  void load(const brash::Case&, const fs::path&, const std::vector<brash::Sphere>&) override {}
  void write_scene(const fs::path&, bool) override {}
  std::vector<std::string> restarts(const fs::path&) const override { return {}; }
  brash::run::Attempt advance(const fs::path&, const std::string&, brash::run::Monitor&) override { return {}; }
  brash::run::ForceRecord force_record(const fs::path&, double) const override { return {}; }
};

}  // namespace

// A start-up of 2 s, then 10 of 100 model seconds in 0.1 s of wall time: 90 s left at that rate is an ETA of
// about 1 s (the start-up counted as stepping time, as before, it would be about 19 s).
TEST(RunMonitor, EtaIsTheSteppingRateSinceTheFirstProgressPoint) {
  const fs::path dir = fs::temp_directory_path() / ("brash_run_monitor_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  brash::Case c;
  c.run.duration_s = 100.0;
  c.run.timestep_s = 0.01;
  c.speedups.early_stop_rel_ci = 0;
  IdleEngine engine;
  brash::run::RunRecord record(dir, nlohmann::json::object());
  brash::run::StopSignals signals;
  brash::run::RunMonitor monitor(engine, c, dir, record, signals, 0.0, "[test]", true);
  record.begin_attempt("start");
  testing::internal::CaptureStderr();
  monitor.start_attempt();
  std::this_thread::sleep_for(std::chrono::seconds(2));  // the engine's start-up
  monitor.progress(0.0, 0, "");
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  monitor.progress(10.0, 1e6, "");
  std::fflush(stderr);
  const std::string out = testing::internal::GetCapturedStderr();
  std::smatch m;
  ASSERT_TRUE(std::regex_search(out, m, std::regex(R"(\[test\] t = 10\.00 / 100\.00 s \( *10%\)  elapsed [0-9]+ s  ETA ([0-9]+) s)")))
      << out;
  // the stepping rate, 0.1 s per 10 model seconds, gives 0.9 s; up to 0.5 s per 10 model seconds on a busy machine
  EXPECT_LE(std::stoi(m[1].str()), 5) << out;
  fs::remove_all(dir);
}
