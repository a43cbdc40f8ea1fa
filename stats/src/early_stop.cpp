// Early-stop rule and its replay (early_stop.hpp).
#include "brash/stats/early_stop.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "brash/stats/student_t.hpp"

namespace brash::stats {
namespace {

// The slope test of early_stop.hpp on samples equally spaced over [t0, t].
void slope_test(std::span<const double> r, double t, double t0, double t1, double rel_ci, EarlyStopVerdict& v) {
  const std::size_t n = r.size();
  const double nd = static_cast<double>(n);
  const double dt = (t - t0) / (nd - 1.0);  // sample spacing
  // least squares on the sample index i (mean index (n - 1) / 2), S_ii = n (n^2 - 1) / 12
  const double i_mean = 0.5 * (nd - 1.0);
  const double s_ii = nd * (nd * nd - 1.0) / 12.0;
  double s_ir = 0;
  for (std::size_t i = 0; i < n; ++i) s_ir += (static_cast<double>(i) - i_mean) * (r[i] - v.blocking.mean);
  const double slope_per_sample = s_ir / s_ii;
  std::vector<double> residual(n);
  for (std::size_t i = 0; i < n; ++i)
    residual[i] = r[i] - v.blocking.mean - slope_per_sample * (static_cast<double>(i) - i_mean);
  const auto noise = block_average(residual);
  // Var(slope) = Var(mean) n / S_ii for noise whose correlation time is short against the record (block averaging
  // gives Var(mean) with the correlation counted)
  const double se_slope_per_sample = noise.sem * std::sqrt(nd / s_ii);
  const auto k = noise.levels[noise.level].n_blocks;
  const double window_samples = (t1 - t0) / dt;
  v.trend = slope_per_sample * window_samples;
  v.trend_ci95 = student_t975(k > 2 ? k - 2 : 0) * se_slope_per_sample * window_samples;
  // the full window's mean along the line: its centre (t0 + t1) / 2 lies (t1 - t) / 2 after the samples' mean time
  const double ahead_samples = 0.5 * (t1 - t) / dt;
  v.estimate = v.blocking.mean + slope_per_sample * ahead_samples;
  v.estimate_ci95 = student_t975(k - 1) * std::hypot(noise.sem, se_slope_per_sample * ahead_samples);
  if (!v.blocking.plateau_found || !noise.plateau_found)
    v.reason = EarlyStopReason::no_plateau;
  else if (!(v.blocking.ci95 < rel_ci * std::abs(v.blocking.mean)))
    v.reason = EarlyStopReason::ci_too_wide;
  else if (std::abs(v.trend) > v.trend_ci95)
    v.reason = EarlyStopReason::drift;
  else
    v.reason = EarlyStopReason::stop;
}

std::string percent(double x, double of, bool sign) {
  char buf[32];
  std::snprintf(buf, sizeof buf, sign ? "%+.2f %%" : "%.2f %%", of != 0 ? 100.0 * x / std::abs(of) : 0.0);
  return buf;
}

}  // namespace

const char* to_string(EarlyStopTrend t) {
  switch (t) {
    case EarlyStopTrend::none: return "none";
    case EarlyStopTrend::halves: return "halves";
    case EarlyStopTrend::slope: return "slope";
  }
  return "?";
}

EarlyStopTrend early_stop_trend_from_string(const std::string& s) {
  for (const auto t : {EarlyStopTrend::none, EarlyStopTrend::halves, EarlyStopTrend::slope})
    if (s == to_string(t)) return t;
  throw std::invalid_argument("early-stop trend test '" + s + "': expected none, halves or slope");
}

std::string EarlyStopVerdict::explain() const {
  const double m = blocking.mean;
  switch (reason) {
    case EarlyStopReason::not_checked: return "not checked (before 40 % of the window or 64 samples)";
    case EarlyStopReason::no_plateau: return "no blocking plateau: the CI would be a lower bound";
    case EarlyStopReason::drift:
      return "drift " + percent(trend, m, true) + "/window > CI " + percent(trend_ci95, m, false);
    case EarlyStopReason::halves_differ:
      return "halves differ by " + percent(trend, m, true) + " (CI " + percent(trend_ci95, m, false) + ", limit " +
             percent(rel_ci * m, m, false) + ")";
    case EarlyStopReason::ci_too_wide:
      return "CI " + percent(blocking.ci95, m, false) + " >= " + percent(rel_ci * m, m, false);
    case EarlyStopReason::stop:
      return "CI " + percent(blocking.ci95, m, false) + " < " + percent(rel_ci * m, m, false) +
             (trend_test == EarlyStopTrend::slope ? ", drift " + percent(trend, m, true) + "/window within its CI " +
                                                        percent(trend_ci95, m, false) +
                                                        "; the full window's mean +- " +
                                                        percent(estimate_ci95, m, false)
                                                  : std::string());
  }
  return "?";
}

EarlyStopVerdict early_stop_verdict(std::span<const double> r, double t, double t0, double t1, double rel_ci,
                                    bool trend_check) {
  return early_stop_verdict(r, t, t0, t1, rel_ci, trend_check ? EarlyStopTrend::slope : EarlyStopTrend::none);
}

EarlyStopVerdict early_stop_verdict(std::span<const double> r, double t, double t0, double t1, double rel_ci,
                                    EarlyStopTrend trend) {
  EarlyStopVerdict v;
  v.trend_test = trend;
  v.rel_ci = rel_ci;
  if (!(rel_ci > 0) || t < t0 + kEarlyStopFirstCheckFraction * (t1 - t0) || r.size() < kEarlyStopMinSamples) return v;
  v.checked = true;
  v.blocking = block_average(r);
  v.estimate = v.blocking.mean;
  v.estimate_ci95 = v.blocking.ci95;
  if (trend == EarlyStopTrend::slope) {
    slope_test(r, t, t0, t1, rel_ci, v);
  } else if (!v.blocking.plateau_found) {
    v.reason = EarlyStopReason::no_plateau;
  } else if (!(v.blocking.ci95 < rel_ci * std::abs(v.blocking.mean))) {
    v.reason = EarlyStopReason::ci_too_wide;
  } else {
    v.reason = EarlyStopReason::stop;
    if (trend == EarlyStopTrend::halves) {
      // the rule before the slope test: the two halves' means agree within their combined 95 % CI and within the
      // precision asked for
      const auto halves = halves_trend(r);
      v.trend = halves.difference;
      v.trend_ci95 = halves.ci95;
      if (std::abs(v.trend) > std::min(v.trend_ci95, rel_ci * std::abs(v.blocking.mean)))
        v.reason = EarlyStopReason::halves_differ;
    }
  }
  v.stop = v.reason == EarlyStopReason::stop;
  return v;
}

EarlyStopReplay replay_early_stop(std::span<const double> t_s, std::span<const double> r, double t0, double t1,
                                  double rel_ci, double check_every_s, bool trend_check) {
  return replay_early_stop(t_s, r, t0, t1, rel_ci, check_every_s,
                           trend_check ? EarlyStopTrend::slope : EarlyStopTrend::none);
}

EarlyStopReplay replay_early_stop(std::span<const double> t_s, std::span<const double> r, double t0, double t1,
                                  double rel_ci, double check_every_s, EarlyStopTrend trend) {
  if (t_s.size() != r.size()) throw std::invalid_argument("replay_early_stop: t and resistance differ in length");
  if (!(check_every_s > 0) || !(t1 > t0)) throw std::invalid_argument("replay_early_stop: bad window or check interval");
  std::vector<double> since;  // samples with t0 <= t <= the check time
  std::size_t i = 0;
  while (i < t_s.size() && t_s[i] < t0) ++i;
  EarlyStopReplay out;
  const double eps = 1e-9 * check_every_s;
  // checks run up to one check interval past the record's last sample: a run the rule stopped ends its record at
  // or before its stop time, which lies on the check grid
  const double t_end = t_s.empty() ? t0 : std::min(t1, t_s.back() + check_every_s);
  double t_last_check = t0;
  for (long k = 1;; ++k) {
    const double tc = static_cast<double>(k) * check_every_s;
    if (tc > t_end + eps) break;
    while (i < t_s.size() && t_s[i] <= tc + eps) since.push_back(r[i++]);
    const auto v = early_stop_verdict(since, tc, t0, t1, rel_ci, trend);
    if (v.checked) out.last = v, t_last_check = tc;
    if (v.stop) {
      out.stopped = true;
      out.t_stop_s = tc;
      out.at_stop = v.blocking;
      out.estimate = v.estimate;
      out.estimate_ci95 = v.estimate_ci95;
      return out;
    }
  }
  std::vector<double> window;
  for (std::size_t j = 0; j < t_s.size(); ++j)
    if (t_s[j] >= t0 && t_s[j] <= t1 + eps) window.push_back(r[j]);
  out.t_stop_s = t_end >= t1 - eps ? t1 : t_last_check;
  if (window.size() >= 2) {
    out.at_stop = block_average(window);
    out.estimate = out.at_stop.mean;
    out.estimate_ci95 = out.at_stop.ci95;
  }
  return out;
}

}  // namespace brash::stats
