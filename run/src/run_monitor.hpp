// The driver's side of brash::run::Monitor: progress with ETA on the terminal, meta.json and hull_force.csv
// refreshed while the engine runs (so that brash-post can look at a long run as it goes), the early stop.
#pragma once
#include <chrono>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "brash/run/engine.hpp"
#include "stop_signals.hpp"

namespace brash::run {

// meta.json of a run and its attempts: wall time and particle-steps are totals over the attempts (a resume adds
// to what the run directory's meta.json recorded; a killed attempt counts up to its last refresh).
class RunRecord {
 public:
  RunRecord(std::filesystem::path run_dir, nlohmann::json meta);
  void begin_attempt(const std::string& from);          // "start" or "restart"
  void attempt_reached(double t_first_s, double t_s, double particle_steps);  // and writes meta.json
  void end_attempt(const Attempt& a);                     // totals, engine keys; does not write
  void write() const;
  nlohmann::json& meta() { return meta_; }
  double attempt_wall_s() const;

 private:
  std::filesystem::path run_dir_;
  nlohmann::json meta_;
  double wall_before_s_ = 0, particle_steps_before_ = 0;
  std::chrono::steady_clock::time_point attempt_start_;
};

// The early stop's last check (brash/stats/early_stop.hpp): whether it stopped the run, and why it did or why the
// run went on.
struct EarlyStopState {
  bool stopped = false;
  bool checked = false;                  // at least one check
  double t_s = 0, mean_N = 0, ci95_N = 0;  // the check's time, the window mean so far and its CI95
  double estimate_N = 0, estimate_ci95_N = 0;  // the full window's mean as the rule estimates it, with its CI95
  double drift_N = 0, drift_ci95_N = 0;  // the fitted drift over the whole window and its CI95
  std::string trend_test;                // slope | none
  std::string reason;                    // e.g. "drift -1.20 %/window > CI 0.90 %"
};
nlohmann::json to_json(const EarlyStopState& e);  // the meta.json object of a stop or a last check

class RunMonitor final : public Monitor {
 public:
  RunMonitor(const Engine& engine, const Case& c, std::filesystem::path run_dir, RunRecord& record,
             StopSignals& signals, double refresh_every_model_s, std::string tag, bool print_progress);
  void engine_process(long pid) override { signals_.engine_process(pid); }
  bool progress(double t_s, double particle_steps, std::string_view detail) override;
  StopReason stop_reason() const override;
  void start_attempt();    // before each advance
  void end_line() const;   // after an attempt: ends a progress line rewritten in place
  const EarlyStopState& early_stop() const { return early_; }

 private:
  bool check_early_stop(double t_s);
  void refresh(double t_s, double particle_steps);
  void print(double t_s, std::string_view detail);

  const Engine& engine_;
  const Case& case_;
  std::filesystem::path run_dir_;
  RunRecord& record_;
  StopSignals& signals_;
  double refresh_every_model_s_;
  std::string tag_;
  bool tty_;
  bool print_progress_;
  EarlyStopState early_;
  std::chrono::steady_clock::time_point start_;
  double t_first_s_ = -1, last_print_s_ = -1, last_refresh_s_ = 0, next_refresh_t_s_ = 0;
  double first_progress_wall_s_ = 0;  // wall time of the attempt's first progress point (the engine set up)
};

}  // namespace brash::run
