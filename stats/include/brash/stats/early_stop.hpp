// The early-stop rule of `speedups.early_stop_rel_ci`, in one place: the LIGGGHTS and ODE runners stop the engine
// when it holds, and `brash-post early-stop` replays it on a finished run's record to measure what it would have
// saved (model time not simulated) and what it costs (window mean at the stop vs the full window's).
//
// Rule, checked at model time t with the averaging window [t0, t1] and the resistance samples since t0:
// stop when t >= t0 + 0.4 (t1 - t0), there are >= 64 samples, block averaging finds a plateau (the CI is not a
// lower bound), the 95 % CI of the mean is below rel_ci |mean|, and the record shows no trend: the means of its
// two halves agree within their combined 95 % CI and within rel_ci |mean| (a resistance still growing would
// otherwise stop with a mean biased low: measured on the quick case, docs/performance.md).
#pragma once
#include <cstddef>
#include <span>

#include "brash/stats/blocking.hpp"

namespace brash::stats {

inline constexpr double kEarlyStopFirstCheckFraction = 0.4;  // of the window, before the first check
inline constexpr std::size_t kEarlyStopMinSamples = 64;

struct EarlyStopVerdict {
  bool checked = false;     // t and the sample count allow a check
  bool stop = false;
  BlockingResult blocking;  // of the samples since t0 (when checked)
  double trend = 0;         // second half's mean - first half's (when the CI test passed)
  double trend_ci95 = 0;    // their combined 95 % CI
};

// trend_check = false drops the trend condition (speedups.early_stop_trend_check: false).
EarlyStopVerdict early_stop_verdict(std::span<const double> resistance_since_t0, double t_s, double t0_s,
                                    double t1_s, double rel_ci, bool trend_check = true);

struct EarlyStopReplay {
  bool stopped = false;
  double t_stop_s = 0;      // time of the check at which the rule held (t1 when it never did)
  BlockingResult at_stop;   // window mean and CI at the stop (of [t0, t1] when it never held)
};

// Replays the rule on a record (t ascending) with a check every check_every_s of model time (the runner checks
// on each thermo line: every 1/200 of the run). Throws std::invalid_argument on bad arguments.
EarlyStopReplay replay_early_stop(std::span<const double> t_s, std::span<const double> resistance_N, double t0_s,
                                  double t1_s, double rel_ci, double check_every_s, bool trend_check = true);

}  // namespace brash::stats
