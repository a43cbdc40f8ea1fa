// Runner behaviours on a small case: kill -9 and resume; early stop on the confidence interval.
//
// kill -9 and resume: a small case is run uninterrupted, and again killed (the whole process group,
// engine included) after its second periodic restart, then continued with `brash-liggghts-run --resume`.
// Before the restart point the hull force is identical; after it the DEM trajectory is not bit-exact
// (LIGGGHTS recomputes contact forces at set-up from full-step velocities, and granular flow is chaotic),
// so the resumed run must give the same mean resistance within the noise of the signal.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <thread>
#include <vector>

#include "brash/stats/early_stop.hpp"
#include "runner_case.h"

namespace fs = std::filesystem;

namespace {
struct Row {
  double t, fx;
};
std::vector<Row> read_force(const fs::path& csv) {
  std::vector<Row> rows;
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    Row r;
    char comma;
    std::istringstream ss(line);
    ss >> r.t >> comma >> r.fx;
    rows.push_back(r);
  }
  return rows;
}
double mean_resistance(const std::vector<Row>& rows, double t0) {
  double s = 0;
  int n = 0;
  for (const auto& r : rows)
    if (r.t >= t0) s -= r.fx, ++n;
  return n ? s / n : 0;
}
}  // namespace

namespace {
// Waits up to 60 s until a run started in the background has a complete periodic restart file to resume from.
// LIGGGHTS writes a.restart, then b.restart one interval later: a exists from the moment it is opened (a
// signal then can leave it empty or partial), so only once b exists is a known complete.
bool wait_for_complete_restart_file(const fs::path& run) {
  for (int i = 0; i < 600; ++i) {
    if (fs::exists(run / "restart/b.restart")) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return false;
}
std::string first_line(const fs::path& file) {
  const std::string text = brash::test::read_text(file);
  return text.substr(0, text.find('\n'));
}
// `brash-liggghts-run --resume RUN --no-post`, its output into log; returns std::system's status.
int resume_runner(const fs::path& run, const fs::path& log) {
  return std::system((std::string("'") + BRASH_BIN_DIR + "/brash-liggghts-run' --resume '" + run.string() +
                      "' --no-post > '" + log.string() + "' 2>&1")
                         .c_str());
}
// Starts the runner in the background (a new session), its pid into dir/pid and its exit code into dir/rc.
void start_runner_recording_exit(const fs::path& dir, const fs::path& run, const std::string& extra_args) {
  const std::string start = "setsid bash -c '" + brash::test::runner_command(dir / "case", run) + extra_args +
                            " & echo $! > \"" + (dir / "pid").string() + "\"; wait $!; echo $? > \"" +
                            (dir / "rc").string() + "\"' > '" + (dir / "run.log").string() + "' 2>&1 &";
  ASSERT_EQ(std::system(start.c_str()), 0);
}
// Waits up to 30 s for dir/rc written by start_runner_recording_exit.
bool wait_for_exit_code(const fs::path& dir) {
  for (int i = 0; i < 300; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    if (fs::exists(dir / "rc") && !brash::test::read_text(dir / "rc").empty()) return true;
  }
  return false;
}
// The quick case, narrowed and shortened (liggghts_runner.h): 0.6 s.
void write_small_case(const fs::path& case_dir, const std::string& window, const std::string& output_interval,
                      const std::string& extra, const std::string& fluid_model = "") {
  brash::test::write_small_quick_case(case_dir, {.duration_s = "0.6",
                                                 .window_s = window,
                                                 .output_interval_s = output_interval,
                                                 .dump_interval_s = "0.1",
                                                 .fluid_model = fluid_model,
                                                 .extra = extra});
}
}  // namespace

TEST(LiggghtsRunner, EarlyStopWhenTheConfidenceIntervalIsSmallEnough) {
  const fs::path dir = brash::test::fresh_dir("earlystop");
  // A loose threshold (50 % of the mean) so that the short run meets it: checked from 0.1 + 0.4 * 0.5 s on. The
  // bow is still entering the ice (a ramp), so the default trend check would (rightly) never stop it: this test
  // is about the runner stopping the engine, the rule itself is tested in tests/stats/test_early_stop.cpp.
  // added_mass: its record over the bow's first 0.6 s meets the 50 % threshold before the end (with both the
  // drag's rise keeps the CI above it)
  write_small_case(dir / "case", "[0.1, 0.6]", "0.002",
                   "speedups:\n  early_stop_rel_ci: 0.5\n  early_stop_trend_check: false\n", "added_mass");
  ASSERT_EQ(brash::test::run_runner(dir / "case", dir / "run", dir / "run.log"), 0);
  const std::string meta = brash::test::read_text(dir / "run/meta.json");
  EXPECT_NE(meta.find("\"complete\""), std::string::npos);
  ASSERT_NE(meta.find("\"early_stop\""), std::string::npos) << meta;
  const auto rows = read_force(dir / "run/hull_force.csv");
  ASSERT_FALSE(rows.empty());
  EXPECT_GE(rows.back().t, 0.3 - 1e-9);  // not before the check starts
  EXPECT_LT(rows.back().t, 0.55);        // well before the requested end
  // the runner stopped where the rule, replayed on its record at its check times (0.6 / 200 s), says
  std::vector<double> t, r;
  for (const auto& row : rows) t.push_back(row.t), r.push_back(-row.fx);
  const auto replay = brash::stats::replay_early_stop(t, r, 0.1, 0.6, 0.5, 0.6 / 200, false);
  EXPECT_TRUE(replay.stopped);
  // the record ends with the last output row (every 0.002 s) at or before the stop
  EXPECT_LE(rows.back().t, replay.t_stop_s + 1e-9);
  EXPECT_GT(rows.back().t, replay.t_stop_s - 0.002 - 1e-9);
  // the run's resolved case ends at the stop, so the report's window does too
  const std::string yaml = brash::test::read_text(dir / "run/case.yaml");
  EXPECT_EQ(yaml.find("duration_s: 0.6\n"), std::string::npos) << yaml;
  fs::remove_all(dir);
}

// A run killed before its early-stop checks start, then resumed: the resumed process applies the rule too, on the
// record of both attempts. Whether this (chaotic) trajectory meets the rule is not known in advance, so the test
// replays the rule on the final record at the runner's check times (every 0.6 / 200 s) and asks the runner to
// have done exactly that: stopped at the replay's time with the record ending there, or run to the end.
TEST(LiggghtsRunner, EarlyStopInAResumedRunFollowsTheRule) {
  const fs::path dir = brash::test::fresh_dir("earlystop_resume");
  write_small_case(dir / "case", "[0.1, 0.6]", "0.002",
                   "speedups:\n  early_stop_rel_ci: 0.5\n  early_stop_trend_check: false\n");
  const fs::path run = dir / "run";
  const std::string start = "setsid bash -c 'echo $$ > \"" + (dir / "pid").string() + "\"; exec " +
                            brash::test::runner_command(dir / "case", run) + "' > '" + (dir / "killed.log").string() +
                            "' 2>&1 &";
  ASSERT_EQ(std::system(start.c_str()), 0);
  ASSERT_TRUE(wait_for_complete_restart_file(run)) << "no complete restart file";
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  const std::string pid = brash::test::read_text(dir / "pid");
  ASSERT_EQ(std::system(("kill -9 -" + pid.substr(0, pid.find('\n')) + " 2>/dev/null; sleep 0.5").c_str()), 0);
  ASSERT_EQ(brash::test::read_text(run / "meta.json").find("\"early_stop\""), std::string::npos)
      << "stopped before the kill: the test needs a kill before the checks start";
  ASSERT_EQ(resume_runner(run, dir / "resume.log"), 0) << brash::test::read_text(dir / "resume.log");
  const std::string meta = brash::test::read_text(run / "meta.json");
  EXPECT_NE(meta.find("\"complete\""), std::string::npos) << meta;
  const auto rows = read_force(run / "hull_force.csv");
  ASSERT_GT(rows.size(), 100u);
  std::vector<double> t, r;
  for (const auto& row : rows) t.push_back(row.t), r.push_back(-row.fx);
  const auto replay = brash::stats::replay_early_stop(t, r, 0.1, 0.6, 0.5, 0.6 / 200, false);
  const bool stopped = meta.find("\"early_stop\"") != std::string::npos;
  std::printf("[early stop, resumed run] runner: %s; replay: %s at %.3f s\n", stopped ? "stopped" : "ran to the end",
              replay.stopped ? "stops" : "never stops", replay.t_stop_s);
  EXPECT_EQ(stopped, replay.stopped);
  if (replay.stopped) {  // the record ends with the last output row (every 0.002 s) at or before the stop
    EXPECT_LE(rows.back().t, replay.t_stop_s + 1e-9);
    EXPECT_GT(rows.back().t, replay.t_stop_s - 0.002 - 1e-9);
  } else {
    EXPECT_NEAR(rows.back().t, 0.6, 1e-9);
  }
  fs::remove_all(dir);
}

// SIGTERM to the runner alone (a batch system, `kill PID`): the engine must not run on orphaned. The runner
// forwards the signal, ends the run as `interrupted` (exit 128 + 15) with the resume command, and --resume finishes it.
TEST(LiggghtsRunner, TermSignalToTheRunnerStopsTheEngineAndTheRunResumes) {
  const fs::path dir = brash::test::fresh_dir("sigterm");
  write_small_case(dir / "case", "[0.3, 0.6]", "0.01", "");
  const fs::path run = dir / "run";
  start_runner_recording_exit(dir, run, "");
  ASSERT_TRUE(wait_for_complete_restart_file(run)) << "no complete restart file";
  const std::string runner_pid = first_line(dir / "pid"), engine_pid = first_line(run / "engine.pid");
  ASSERT_FALSE(engine_pid.empty());
  ASSERT_EQ(std::system(("kill -TERM " + runner_pid).c_str()), 0);  // the runner only, not its process group
  ASSERT_TRUE(wait_for_exit_code(dir)) << "the runner did not exit within 30 s of SIGTERM";
  EXPECT_EQ(std::stoi(brash::test::read_text(dir / "rc")), 128 + 15) << brash::test::read_text(dir / "run.log");
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  EXPECT_NE(std::system(("kill -0 " + engine_pid + " 2>/dev/null").c_str()), 0) << "the engine runs on orphaned";
  const std::string meta = brash::test::read_text(run / "meta.json");
  EXPECT_NE(meta.find("\"interrupted\""), std::string::npos) << meta;
  EXPECT_NE(meta.find("--resume " + run.string()), std::string::npos) << meta;
  EXPECT_FALSE(fs::exists(run / "restart/final.restart")) << "signalled too late: the run had finished";
  ASSERT_EQ(resume_runner(run, dir / "resume.log"), 0) << brash::test::read_text(dir / "resume.log");
  EXPECT_NE(brash::test::read_text(run / "meta.json").find("\"complete\""), std::string::npos);
  EXPECT_NEAR(read_force(run / "hull_force.csv").back().t, 0.6, 1e-9);
  fs::remove_all(dir);
}

// SIGTERM before the first restart file: nothing can be resumed, and the run says so instead of offering
// --resume.
TEST(LiggghtsRunner, TermSignalBeforeTheFirstRestartFileSaysRunAgain) {
  const fs::path dir = brash::test::fresh_dir("sigterm_early");
  write_small_case(dir / "case", "[0.3, 0.6]", "0.01", "");
  const fs::path run = dir / "run";
  // first restart file at 0.5 s of the 0.6 s run: seconds of wall time after the engine starts
  start_runner_recording_exit(dir, run, " --restart-every 0.5");
  bool engine_up = false;
  for (int i = 0; i < 600 && !engine_up; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    engine_up = fs::exists(run / "engine.pid") && !first_line(run / "engine.pid").empty();
  }
  ASSERT_TRUE(engine_up) << "the engine did not start within 60 s";
  ASSERT_EQ(std::system(("kill -TERM " + first_line(dir / "pid")).c_str()), 0);
  ASSERT_TRUE(wait_for_exit_code(dir)) << "the runner did not exit within 30 s of SIGTERM";
  ASSERT_FALSE(fs::exists(run / "restart/a.restart") && fs::file_size(run / "restart/a.restart") > 0)
      << "signalled too late: the test needs no restart file yet";
  EXPECT_EQ(std::stoi(brash::test::read_text(dir / "rc")), 128 + 15)
      << brash::test::read_text(dir / "run.log");
  const std::string meta = brash::test::read_text(run / "meta.json");
  EXPECT_NE(meta.find("\"interrupted\""), std::string::npos) << meta;
  EXPECT_NE(meta.find("nothing to resume, run the case again"), std::string::npos) << meta;
  EXPECT_EQ(meta.find("--resume"), std::string::npos) << meta;
  const int rc = resume_runner(run, dir / "resume.log");
  EXPECT_NE(WEXITSTATUS(rc), 0);
  EXPECT_NE(
      brash::test::read_text(dir / "resume.log").find("before its first one was written; run the case again"),
      std::string::npos)
      << brash::test::read_text(dir / "resume.log");
  fs::remove_all(dir);
}

TEST(LiggghtsRunner, RestartIntervalDefaultsToATenthOfTheRunAndCanBeSet) {
  const fs::path dir = brash::test::fresh_dir("restart_every");
  write_small_case(dir / "case", "[0.0, 0.6]", "0.01", "");
  const std::string cmd = brash::test::runner_command(dir / "case", dir / "run_default") + " --prepare-only > /dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  // dt = 1e-4 s: a tenth of 0.6 s is 600 steps
  EXPECT_NE(brash::test::read_text(dir / "run_default/in.lmp").find("\nrestart 600 "), std::string::npos);
  const std::string cmd_set = brash::test::runner_command(dir / "case", dir / "run_set") +
                              " --prepare-only --restart-every 0.02 > /dev/null";
  ASSERT_EQ(std::system(cmd_set.c_str()), 0);
  EXPECT_NE(brash::test::read_text(dir / "run_set/in.lmp").find("\nrestart 200 "), std::string::npos);
  const std::string cmd_bad = brash::test::runner_command(dir / "case", dir / "run_bad") +
                              " --prepare-only --restart-every -1 > /dev/null 2>&1";
  EXPECT_NE(std::system(cmd_bad.c_str()), 0);
  fs::remove_all(dir);
}

TEST(LiggghtsResume, KilledRunResumesToTheSameResult) {
  const fs::path dir = brash::test::fresh_dir("resume");
  write_small_case(dir / "case", "[0.2, 0.6]", "0.01", "");

  ASSERT_EQ(brash::test::run_runner(dir / "case", dir / "full", dir / "full.log"), 0);
  // Into a file (not a terminal) the progress is plain lines, never rewritten in place with '\r'.
  EXPECT_EQ(brash::test::read_text(dir / "full.log").find('\r'), std::string::npos);

  // Start in a new session (process group = its pid), kill -9 the whole group after the 2nd restart file.
  const fs::path killed = dir / "killed";
  const std::string start = "setsid bash -c 'echo $$ > \"" + (dir / "pid").string() + "\"; exec " +
                            brash::test::runner_command(dir / "case", killed) + "' > '" +
                            (dir / "killed.log").string() + "' 2>&1 &";
  ASSERT_EQ(std::system(start.c_str()), 0);
  ASSERT_TRUE(wait_for_complete_restart_file(killed)) << "no second restart file";
  // while it runs, a resume of the same directory is refused (it would write the same files)
  const fs::path busy = dir / "busy.log";
  const int busy_rc = resume_runner(killed, busy);
  EXPECT_NE(WEXITSTATUS(busy_rc), 0);
  EXPECT_NE(brash::test::read_text(busy).find("another process is running in this run directory"), std::string::npos)
      << brash::test::read_text(busy);
  EXPECT_NE(brash::test::read_text(killed / "meta.json").find("\"running\""), std::string::npos);  // left alone
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  const std::string pid = brash::test::read_text(dir / "pid");
  ASSERT_EQ(std::system(("kill -9 -" + pid.substr(0, pid.find('\n')) + " 2>/dev/null; sleep 0.5").c_str()),
            0);
  EXPECT_FALSE(fs::exists(killed / "restart/final.restart")) << "killed too late: the run had finished";
  EXPECT_NE(brash::test::read_text(killed / "meta.json").find("\"running\""), std::string::npos);
  // meta.json was refreshed while the engine ran: the killed attempt's wall time and model time count
  const auto meta_killed = nlohmann::json::parse(brash::test::read_text(killed / "meta.json"));
  ASSERT_EQ(meta_killed["attempts"].size(), 1u) << meta_killed.dump();
  EXPECT_EQ(meta_killed["attempts"][0]["from"], "start");
  EXPECT_GT(meta_killed["wall_time_s"].get<double>(), 0.0);
  EXPECT_GE(meta_killed["model_time_reached_s"].get<double>(), 0.06 - 1e-9);
  EXPECT_GT(meta_killed["particle_steps"].get<double>(), 0.0);
  // log.txt has every engine line the runner read before the kill (written through, not buffered): at least
  // the thermo line of the model time meta.json records
  {
    std::istringstream log(brash::test::read_text(killed / "log.txt"));
    const std::regex thermo(R"(^\s+[0-9]+\s+([0-9.eE+-]+)\s+[0-9]+\s)");
    double t_max = -1;
    std::smatch m;
    for (std::string line; std::getline(log, line);)
      if (std::regex_search(line, m, thermo)) t_max = std::max(t_max, std::stod(m[1]));
    EXPECT_GE(t_max, meta_killed["model_time_reached_s"].get<double>() - 1e-9);
  }
  // the record so far was written with the restart files (brash-post can look at a run while it goes)
  const auto so_far = read_force(killed / "hull_force.csv");
  ASSERT_FALSE(so_far.empty());
  EXPECT_GE(so_far.back().t, 0.06 - 1e-9);  // at least up to the first restart time (a tenth of 0.6 s)

  // the killed attempt's snapshots converted now (as when an attempt ends by itself), so the resumed attempt
  // finds them as particles_<step>.csv beside its own dumps
  const std::string rebuild = std::string("'") + BRASH_BIN_DIR + "/brash-liggghts-run' --rebuild-record '" +
                              killed.string() + "' --no-post > '" + (dir / "rebuild.log").string() + "' 2>&1";
  ASSERT_EQ(std::system(rebuild.c_str()), 0) << brash::test::read_text(dir / "rebuild.log");
  EXPECT_NE(brash::test::read_text(dir / "rebuild.log").find("dump(s) converted"), std::string::npos)
      << brash::test::read_text(dir / "rebuild.log");

  // the newest restart file cut short (a kill while it was written): the resume cannot read it and takes the
  // other
  const fs::path a_file = killed / "restart/a.restart", b_file = killed / "restart/b.restart";
  const fs::path newest = fs::last_write_time(a_file) > fs::last_write_time(b_file) ? a_file : b_file;
  const fs::path other = newest == a_file ? b_file : a_file;
  fs::resize_file(newest, 100);
  ASSERT_EQ(resume_runner(killed, dir / "resume.log"), 0) << brash::test::read_text(dir / "resume.log");
  const std::string resume_log = brash::test::read_text(dir / "resume.log");
  EXPECT_NE(resume_log.find("resume from restart/" + newest.filename().string() + " failed"),
            std::string::npos)
      << resume_log;
  EXPECT_NE(resume_log.find("from restart/" + other.filename().string()), std::string::npos) << resume_log;
  EXPECT_NE(brash::test::read_text(killed / "meta.json").find("\"complete\""), std::string::npos);
  // wall time and particle-steps are totals over both attempts; the resumed one redid the steps between the
  // restart it took and where the killed attempt had got to (none when the kill came while the restart file
  // after that point was being written: the one truncated above), so the work is the uninterrupted run's plus
  // those
  const auto meta_full = nlohmann::json::parse(brash::test::read_text(dir / "full/meta.json"));
  const auto meta_resumed = nlohmann::json::parse(brash::test::read_text(killed / "meta.json"));
  const auto& attempts = meta_resumed["attempts"];
  ASSERT_EQ(attempts.size(), 2u) << meta_resumed.dump();
  EXPECT_EQ(attempts[1]["from"], "restart");
  const double t_from = attempts[1]["t_from_s"].get<double>(),
               t_killed = meta_killed["model_time_reached_s"].get<double>();
  EXPECT_LE(t_from, t_killed + 1e-9);
  EXPECT_NEAR(meta_resumed["wall_time_s"].get<double>(),
              attempts[0]["wall_s"].get<double>() + attempts[1]["wall_s"].get<double>(), 1e-6);
  EXPECT_GE(attempts[0]["wall_s"].get<double>(), meta_killed["wall_time_s"].get<double>() - 1e-9);
  const double pieces = meta_full["particles"].get<double>(), dt = meta_full["dt_s"].get<double>();
  EXPECT_NEAR(meta_resumed["particle_steps"].get<double>(),
              meta_full["particle_steps"].get<double>() + pieces * std::round((t_killed - t_from) / dt),
              0.5 * pieces)
      << "killed at t = " << t_killed << " s, resumed from " << t_from << " s";
  EXPECT_EQ(meta_full["attempts"].size(), 1u);

  // the snapshot index lists the snapshots of both attempts, as the uninterrupted run's does (it used to list
  // only the resumed attempt's, so brash-post's band check and ParaView files missed the first attempt's)
  const std::string index_full = brash::test::read_text(dir / "full/particles/index.csv");
  EXPECT_EQ(std::count(index_full.begin(), index_full.end(), '\n'), 8)
      << index_full;  // header + t = 0, 0.1 .. 0.6
  EXPECT_EQ(brash::test::read_text(killed / "particles/index.csv"), index_full);

  const auto a = read_force(dir / "full/hull_force.csv"), b = read_force(killed / "hull_force.csv");
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GT(a.size(), 50u);
  // identical up to and including the first restart's step (10 % of the run = 0.06 s)
  for (std::size_t i = 0; i < a.size() && a[i].t <= 0.06 + 1e-9; ++i) {
    EXPECT_EQ(a[i].t, b[i].t);
    EXPECT_EQ(a[i].fx, b[i].fx) << "t " << a[i].t;
  }
  const double ra = mean_resistance(a, 0.2), rb = mean_resistance(b, 0.2);
  EXPECT_GT(ra, 2.0);
  EXPECT_NEAR(rb / ra, 1.0, 0.10) << ra << " vs " << rb;

  // --rebuild-record: the record from the raw files again, as the runner wrote it
  const std::string record = brash::test::read_text(killed / "hull_force.csv");
  fs::remove(killed / "particles/index.csv");
  ASSERT_EQ(std::system(rebuild.c_str()), 0) << brash::test::read_text(dir / "rebuild.log");
  EXPECT_EQ(brash::test::read_text(killed / "hull_force.csv"), record);
  EXPECT_EQ(brash::test::read_text(killed / "particles/index.csv"), index_full);  // rebuilt too
  EXPECT_FALSE(nlohmann::json::parse(brash::test::read_text(killed / "meta.json")).contains("exits"));
  // ... and the count of pieces gone through the channel's ends from the last "N in all" of fix brash/exit
  std::ofstream(killed / "log.txt", std::ios::app)
      << "fix brash/exit: step 100: 2 piece(s) left the scene through the channel's ends (x < -1 or x > 2 "
         "m); 2 in all\n"
      << "fix brash/exit: step 200: 1 piece(s) left the scene through the channel's ends (x < -1 or x > 2 "
         "m); 3 in all\n";
  ASSERT_EQ(std::system(rebuild.c_str()), 0) << brash::test::read_text(dir / "rebuild.log");
  EXPECT_EQ(nlohmann::json::parse(brash::test::read_text(killed / "meta.json"))["exits"], 3);
  // without the killed attempt's rows from t = 0.03 s on (as when they were lost) the resumed attempt's
  // set-up row at its restart time (no contact force summed yet) is not taken for a record: the record jumps
  // from 0.02 s to one output interval after the restart (a gap brash-post names)
  {
    std::istringstream part(brash::test::read_text(killed / "hull_force.part1.raw"));
    std::string kept;
    for (std::string line; std::getline(part, line);) {
      std::istringstream ss(line);
      long step;
      double t;
      if (line.empty() || line[0] == '#' || !(ss >> step >> t) || t < 0.03 - 1e-9) kept += line + "\n";
    }
    std::ofstream(killed / "hull_force.part1.raw") << kept;
  }
  ASSERT_EQ(std::system(rebuild.c_str()), 0) << brash::test::read_text(dir / "rebuild.log");
  const auto rebuilt = read_force(killed / "hull_force.csv");
  const double t_restart = attempts[1]["t_from_s"].get<double>();
  std::size_t k = 0;
  while (k < rebuilt.size() && rebuilt[k].t < 0.03 - 1e-9) ++k;
  ASSERT_LT(k, rebuilt.size());
  EXPECT_NEAR(rebuilt[k - 1].t, 0.02, 1e-9);
  EXPECT_NEAR(rebuilt[k].t, t_restart + 0.01, 1e-9);
  // and a run still going is not rebuilt under its runner
  EXPECT_NE(std::system((std::string("'") + BRASH_BIN_DIR + "/brash-liggghts-run' --rebuild-record '" +
                         (dir / "no_such_run").string() + "' --no-post > /dev/null 2>&1")
                            .c_str()),
            0);
  fs::remove_all(dir);
}

TEST(LiggghtsRunner, FarfieldSceneWakesPushedIceByTheCasesRuleUnlessTheWindowAloneIsAsked) {
  const fs::path dir = brash::test::fresh_dir("farfield_scene");
  const auto prepare = [&](const std::string& speedups, const std::string& name) {
    write_small_case(dir / name, "[0.0, 0.6]", "0.01", speedups);
    const std::string cmd = brash::test::runner_command(dir / name, dir / (name + "_run")) + " --prepare-only > /dev/null";
    EXPECT_EQ(std::system(cmd.c_str()), 0);
    return brash::test::read_text(dir / (name + "_run/in.lmp"));
  };
  // default wake force: 1e-3 of the mean piece's weight (d 0.035 m, 900 kg/m3: 0.19820 N)
  const std::string wake = prepare("speedups:\n  farfield: true\n  farfield_ahead_m: 0.3\n", "wake");
  const auto pos = wake.find(" wake_force ");
  ASSERT_NE(pos, std::string::npos) << wake;
  EXPECT_NEAR(std::stod(wake.substr(pos + 12)), 1e-3 * 900 * M_PI / 6 * std::pow(0.035, 3) * 9.81, 1e-12);
  EXPECT_NE(wake.find(" wake_speed 0.005 "), std::string::npos);
  EXPECT_NE(wake.find("cpu f_farfield[1]\n"), std::string::npos) << "the idle count is in the log";
  const std::string window =
      prepare("speedups:\n  farfield: true\n  farfield_ahead_m: 0.3\n  farfield_wake_force_weight: 0\n", "window");
  EXPECT_NE(window.find("fix farfield all brash/farfield"), std::string::npos);
  EXPECT_EQ(window.find("wake_force"), std::string::npos);
  const std::string neighbour = prepare(
      "speedups:\n  farfield: true\n  farfield_ahead_m: 0.3\n  farfield_wake_by: neighbour_speed\n", "neighbour");
  EXPECT_NE(neighbour.find(" wake_neighbour_speed 0.005 active active"), std::string::npos) << neighbour;
  EXPECT_EQ(neighbour.find("wake_force"), std::string::npos);
  EXPECT_EQ(neighbour.find(" beside "), std::string::npos);  // the whole width unless farfield_beside_m
  // farfield_beside_m: the half width beyond which ice idles is the hull's half beam (the JBC model's 0.5625 m) + it
  const std::string beside = prepare("speedups:\n  farfield: true\n  farfield_ahead_m: 0.3\n  farfield_beside_m: 0.1\n",
                                     "beside");
  const auto at = beside.find(" beside ");
  ASSERT_NE(at, std::string::npos) << beside;
  EXPECT_NEAR(std::stod(beside.substr(at + 8)), 0.5625 + 0.1, 2e-3);
  // the push front is brash-ode's: refused by name before any output, with the copy to run
  write_small_case(dir / "front", "[0.0, 0.6]", "0.01",
                   "speedups:\n  farfield: true\n  farfield_ahead_m: 0.3\n  farfield_wake_by: push_front\n");
  const fs::path err = dir / "front_stderr.txt";
  const std::string cmd = brash::test::runner_command(dir / "front", dir / "front_run") + " --prepare-only > /dev/null 2> '" +
                          err.string() + "'";
  const int st = std::system(cmd.c_str());
  EXPECT_TRUE(WIFEXITED(st) && WEXITSTATUS(st) == 2) << st;
  const std::string why = brash::test::read_text(err);
  EXPECT_NE(why.find("speedups.farfield_wake_by: push_front"), std::string::npos) << why;
  EXPECT_NE(why.find("--set speedups.farfield_wake_by=neighbour_speed --out DIR"), std::string::npos) << why;
  EXPECT_FALSE(fs::exists(dir / "front_run" / "in.lmp"));
  fs::remove_all(dir);
}
