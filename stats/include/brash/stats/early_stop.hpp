// The early-stop rule of `speedups.early_stop_rel_ci`, in one place: the LIGGGHTS and ODE runners stop the engine
// when it holds, and `brash-post early-stop` replays it on a finished run's record to measure what it would have
// saved (model time not simulated) and what it costs (the estimate at the stop vs the full window's mean).
//
// Rule, checked at model time t with the averaging window [t0, t1] and the resistance samples since t0 (equally
// spaced over [t0, t]): no check before t0 + 0.4 (t1 - t0) or with fewer than 64 samples. Then (the default,
// trend test `slope`, speedups.early_stop_trend_check: true) the run stops when
//  1. block averaging (blocking.hpp) of the samples finds a plateau and the 95 % CI of their mean is below
//     rel_ci |mean| (the precision asked for), and
//  2. the record shows no drift: a straight line is fitted to the samples and its residuals are block averaged,
//     which gives the standard error of the noise's mean, SE_mean, with its autocorrelation counted (a plateau is
//     needed here too). The slope's standard error follows as for uncorrelated samples of the same effective
//     number: SE_slope = SE_mean sqrt(n / S_tt), S_tt the sum of (t_i - mean t)^2. The drift over the whole window,
//     slope (t1 - t0), must lie within its 95 % CI, t_{0.975, k - 2} SE_slope (t1 - t0) (k blocks of the level
//     block averaging chose). While it does not, the run goes on.
// At the stop the rule estimates the full window's mean along the fitted line, mean + slope (t1 - t) / 2, with
// CI95 = t_{0.975, k - 1} sqrt(SE_mean^2 + SE_slope^2 (t1 - t)^2 / 4): a drift too small to be significant yet
// still moves the rest of the window, and its uncertainty is in this CI (at the first check about 2.8 times the
// window mean's). The runners record it in meta.json (early_stop) and brash-post's report shows it.
// Why: the CI of the window mean alone assumes a stationary record. On AR(1) records matched to the paper run
// (tests/stats/test_early_stop.cpp) a drift of -0.7 % over the window put the full window's mean outside the
// stopped mean's CI in 18 % of records and -2 % in 81 % with the halves test (the rule before); the slope test with
// the extrapolated estimate covers it in 96-97 %, and a stationary record still stops at the first check in
// 98.5 % (docs/performance.md "Early stop").
// The previous trend test (`halves`: the two halves' means agree within their combined CI and within rel_ci) is
// kept for replays; `none` is the CI of the window mean alone (speedups.early_stop_trend_check: false).
#pragma once
#include <cstddef>
#include <span>
#include <string>

#include "brash/stats/blocking.hpp"

namespace brash::stats {

inline constexpr double kEarlyStopFirstCheckFraction = 0.4;  // of the window, before the first check
inline constexpr std::size_t kEarlyStopMinSamples = 64;

enum class EarlyStopTrend {
  none,    // the CI of the window mean alone
  halves,  // the rule before the slope test: the halves' means agree (replays only)
  slope,   // the fitted drift within its CI; the full window's mean extrapolated (the runners' rule)
};
const char* to_string(EarlyStopTrend t);
EarlyStopTrend early_stop_trend_from_string(const std::string& s);  // std::invalid_argument for an unknown name

// Why a check stopped the run or let it go on.
enum class EarlyStopReason {
  not_checked,   // before 40 % of the window, < 64 samples, or rel_ci <= 0
  no_plateau,    // block averaging found no plateau: the CI is a lower bound
  drift,         // slope: the drift over the window exceeds its CI
  halves_differ, // halves: the halves' means differ by more than their CI or rel_ci
  ci_too_wide,   // the CI of the estimate is not below rel_ci |estimate|
  stop,          // every condition holds
};

struct EarlyStopVerdict {
  bool checked = false;     // t and the sample count allow a check
  bool stop = false;
  EarlyStopReason reason = EarlyStopReason::not_checked;
  EarlyStopTrend trend_test = EarlyStopTrend::slope;
  double rel_ci = 0;
  BlockingResult blocking;  // of the samples since t0 (when checked): the window's mean so far
  // The full window's mean [t0, t1] as the check estimates it, with its 95 % CI: the blocking mean and CI for
  // `none` and `halves`, the mean extrapolated along the fitted drift for `slope`.
  double estimate = 0;
  double estimate_ci95 = 0;
  // slope: drift over the whole window (slope (t1 - t0), N) and its 95 % CI; halves: the second half's mean - the
  // first's and their combined CI (when the CI test passed); none: 0.
  double trend = 0;
  double trend_ci95 = 0;
  // "drift -1.2 %/window > CI 0.9 %" and the like: the reason in words with its numbers.
  std::string explain() const;
};

// trend_check = false drops the trend test (speedups.early_stop_trend_check: false); true is `slope`.
EarlyStopVerdict early_stop_verdict(std::span<const double> resistance_since_t0, double t_s, double t0_s,
                                    double t1_s, double rel_ci, bool trend_check = true);
EarlyStopVerdict early_stop_verdict(std::span<const double> resistance_since_t0, double t_s, double t0_s,
                                    double t1_s, double rel_ci, EarlyStopTrend trend);

struct EarlyStopReplay {
  bool stopped = false;
  double t_stop_s = 0;      // time of the check at which the rule held (t1 when it never did)
  BlockingResult at_stop;   // window mean and CI at the stop (of [t0, t1] when it never held)
  // The rule's estimate of the full window's mean and its CI at the stop (when it never held: the full window's
  // blocking mean and CI, as a run that went on reports it).
  double estimate = 0;
  double estimate_ci95 = 0;
  EarlyStopVerdict last;    // the verdict of the stop, or of the last check (why the run went on)
};

// Replays the rule on a record (t ascending) with a check every check_every_s of model time (the runner checks
// on each thermo line: every 1/200 of the run). A record that ends before t1 is replayed to its end (stopped false,
// t_stop_s its last check, at_stop and the estimate of the samples in the window). Throws std::invalid_argument on
// bad arguments.
EarlyStopReplay replay_early_stop(std::span<const double> t_s, std::span<const double> resistance_N, double t0_s,
                                  double t1_s, double rel_ci, double check_every_s, bool trend_check = true);
EarlyStopReplay replay_early_stop(std::span<const double> t_s, std::span<const double> resistance_N, double t0_s,
                                  double t1_s, double rel_ci, double check_every_s, EarlyStopTrend trend);

}  // namespace brash::stats
