#include "run_monitor.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fmt/format.h>
#include <limits>
#include <unistd.h>

#include "brash/run/force_record.hpp"
#include "brash/run/run_layout.hpp"
#include "brash/run/stages.hpp"
#include "brash/stats/early_stop.hpp"

namespace fs = std::filesystem;

namespace brash::run {
RunRecord::RunRecord(fs::path run_dir, nlohmann::json meta) : run_dir_(std::move(run_dir)), meta_(std::move(meta)) {
  wall_before_s_ = meta_.value("wall_time_s", 0.0);
  particle_steps_before_ = meta_.value("particle_steps", 0.0);
  if (!meta_.contains("attempts") || !meta_["attempts"].is_array()) meta_["attempts"] = nlohmann::json::array();
}

void RunRecord::begin_attempt(const std::string& from) {
  attempt_start_ = std::chrono::steady_clock::now();
  meta_["attempts"].push_back({{"from", from}, {"t_from_s", nullptr}, {"t_to_s", nullptr}, {"wall_s", 0.0}});
}

double RunRecord::attempt_wall_s() const { return seconds_since(attempt_start_); }

void RunRecord::attempt_reached(double t_first_s, double t_s, double particle_steps) {
  auto& a = meta_["attempts"].back();
  a["t_from_s"] = t_first_s;
  a["t_to_s"] = t_s;
  a["wall_s"] = attempt_wall_s();
  meta_["wall_time_s"] = wall_before_s_ + a["wall_s"].get<double>();
  meta_["particle_steps"] = particle_steps_before_ + particle_steps;
  meta_["model_time_reached_s"] = t_s;
  write();
}

void RunRecord::end_attempt(const Attempt& attempt) {
  auto& a = meta_["attempts"].back();
  a["wall_s"] = attempt_wall_s();
  meta_["wall_time_s"] = wall_before_s_ + a["wall_s"].get<double>();
  if (attempt.t_last_s >= 0) {
    a["t_from_s"] = attempt.t_first_s;
    a["t_to_s"] = attempt.t_last_s;
    meta_["model_time_reached_s"] = attempt.t_last_s;
  }
  meta_["particle_steps"] = particle_steps_before_ + attempt.particle_steps;
  for (const auto& [key, value] : attempt.meta.items()) meta_[key] = value;
}

void RunRecord::write() const { write_meta(run_dir_, meta_); }

RunMonitor::RunMonitor(const Engine& engine, const Case& c, fs::path run_dir, RunRecord& record, StopSignals& signals,
                       double refresh_every_model_s, std::string tag, bool print_progress)
    : engine_(engine), case_(c), run_dir_(std::move(run_dir)), record_(record), signals_(signals),
      refresh_every_model_s_(refresh_every_model_s), tag_(std::move(tag)), tty_(::isatty(::fileno(stderr)) != 0),
      print_progress_(print_progress) {}

void RunMonitor::start_attempt() {
  start_ = std::chrono::steady_clock::now();
  t_first_s_ = -1, last_print_s_ = -1, last_refresh_s_ = 0;
  next_refresh_t_s_ = refresh_every_model_s_ > 0 ? refresh_every_model_s_ : std::numeric_limits<double>::infinity();
}

StopReason RunMonitor::stop_reason() const {
  if (early_.stopped) return StopReason::EarlyStop;
  return signals_.received() != 0 ? StopReason::Signal : StopReason::None;
}

bool RunMonitor::progress(double t_s, double particle_steps, std::string_view detail) {
  if (t_first_s_ < 0) {  // a resumed attempt starts at its restart time
    t_first_s_ = t_s;
    first_progress_wall_s_ = seconds_since(start_);
  }
  if (stop_reason() == StopReason::None) check_early_stop(t_s);
  const double elapsed = seconds_since(start_);
  // the record so far every 30 s of wall time and at every restart time (meta.json says running; the final
  // record at the end replaces it)
  if (elapsed - last_refresh_s_ >= 30.0 || t_s >= next_refresh_t_s_ - 1e-9) {
    last_refresh_s_ = elapsed;
    while (next_refresh_t_s_ <= t_s + 1e-9) next_refresh_t_s_ += refresh_every_model_s_;
    refresh(t_s, particle_steps);
  }
  print(t_s, detail);
  return stop_reason() != StopReason::None;
}

// speedups.early_stop_rel_ci: the windowed mean resistance is known well enough (brash/stats/early_stop.hpp);
// checked from 40 % of the window on, never at the run's last point.
bool RunMonitor::check_early_stop(double t_s) {
  const double rel_ci = case_.speedups.early_stop_rel_ci, t0 = case_.run.window_s[0], t1 = case_.run.window_s[1];
  if (rel_ci <= 0 || t_s >= case_.run.duration_s - 0.5 * case_.run.timestep_s ||
      t_s < t0 + stats::kEarlyStopFirstCheckFraction * (t1 - t0))
    return false;
  std::vector<double> resistance;
  for (const auto& row : engine_.force_record(run_dir_, t_s).rows)
    if (row.t_s >= t0 - 1e-12) resistance.push_back(-row.fx_N);
  const auto v = stats::early_stop_verdict(resistance, t_s, t0, t1, rel_ci, case_.speedups.early_stop_trend_check);
  if (!v.checked) return false;
  early_ = {v.stop,       true,       t_s,     v.blocking.mean,       v.blocking.ci95,       v.estimate,
            v.estimate_ci95, v.trend, v.trend_ci95, stats::to_string(v.trend_test), v.explain()};
  // the last check is in meta.json (refreshed as the run goes): why the run goes on, or why it stopped
  record_.meta()["early_stop_last_check"] = to_json(early_);
  if (!v.stop) return false;
  std::fprintf(stderr,
               "\n%s early stop at t = %.3f s: %s; window mean %.4g N +- %.3g N, the full window's estimated "
               "%.4g N +- %.3g N (95 %% CI)\n",
               tag_.c_str(), t_s, early_.reason.c_str(), v.blocking.mean, v.blocking.ci95, v.estimate,
               v.estimate_ci95);
  return true;
}

nlohmann::json to_json(const EarlyStopState& e) {
  return {{"t_s", e.t_s},
          {"stop", e.stopped},
          {"reason", e.reason},
          {"trend_test", e.trend_test},
          {"mean_N", e.mean_N},
          {"ci95_N", e.ci95_N},
          {"estimate_N", e.estimate_N},
          {"estimate_ci95_N", e.estimate_ci95_N},
          {"drift_N", e.drift_N},
          {"drift_ci95_N", e.drift_ci95_N}};
}

void RunMonitor::refresh(double t_s, double particle_steps) {
  write_hull_force_csv(run_dir_ / "hull_force.csv", engine_.force_record(run_dir_, t_s));
  record_.attempt_reached(t_first_s_, t_s, particle_steps);
}

// On a terminal the line is rewritten in place every 2 s; into a file (nohup, a study's log) it is a line of
// its own every 30 s, so that the log stays readable.
void RunMonitor::print(double t_s, std::string_view detail) {
  const double elapsed = seconds_since(start_);
  if (!print_progress_ || t_s <= t_first_s_ || (last_print_s_ >= 0 && elapsed - last_print_s_ < (tty_ ? 2.0 : 30.0))) return;
  last_print_s_ = elapsed;
  const double duration = case_.run.duration_s;
  // the stepping rate since the first progress point: the engine's start-up (reading the scene, MPI) is paid once
  const double eta = (elapsed - first_progress_wall_s_) * (duration - t_s) / (t_s - t_first_s_);
  // t to the case's step (at least 2 decimals): a benchmark reads seconds per step off these lines
  const int t_digits = std::clamp(static_cast<int>(std::ceil(-std::log10(case_.run.timestep_s) - 1e-9)), 2, 6);
  std::fprintf(stderr, "%s%s t = %.*f / %.2f s (%3.0f%%)  elapsed %.0f s  ETA %.0f s%s%.*s%s", tty_ ? "\r" : "",
               tag_.c_str(), t_digits, t_s, duration, 100 * t_s / duration, elapsed, eta, detail.empty() ? "" : "  ",
               static_cast<int>(detail.size()), detail.data(), tty_ ? "   " : "\n");
}

void RunMonitor::end_line() const {
  if (tty_ && last_print_s_ >= 0) std::fprintf(stderr, "\n");
}

}  // namespace brash::run
