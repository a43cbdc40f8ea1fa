// Early-stop rule and its replay (early_stop.hpp).
#include "brash/stats/early_stop.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace brash::stats {

EarlyStopVerdict early_stop_verdict(std::span<const double> r, double t, double t0, double t1, double rel_ci,
                                    bool trend_check) {
  EarlyStopVerdict v;
  if (!(rel_ci > 0) || t < t0 + kEarlyStopFirstCheckFraction * (t1 - t0) || r.size() < kEarlyStopMinSamples) return v;
  v.checked = true;
  v.blocking = block_average(r);
  v.stop = v.blocking.plateau_found && v.blocking.ci95 < rel_ci * std::abs(v.blocking.mean);
  if (v.stop && trend_check) {
    // The CI assumes a stationary record; a resistance still rising (or falling) would be stopped with a biased
    // mean. Stationarity check: the two halves' means agree within their combined 95 % CI and within the
    // precision asked for (the first alone let a ramp through on the quick case: docs/performance.md).
    const auto halves = halves_trend(r);
    v.trend = halves.difference;
    v.trend_ci95 = halves.ci95;
    v.stop = std::abs(v.trend) <= std::min(v.trend_ci95, rel_ci * std::abs(v.blocking.mean));
  }
  return v;
}

EarlyStopReplay replay_early_stop(std::span<const double> t_s, std::span<const double> r, double t0, double t1,
                                  double rel_ci, double check_every_s, bool trend_check) {
  if (t_s.size() != r.size()) throw std::invalid_argument("replay_early_stop: t and resistance differ in length");
  if (!(check_every_s > 0) || !(t1 > t0)) throw std::invalid_argument("replay_early_stop: bad window or check interval");
  std::vector<double> since;  // samples with t0 <= t <= the check time
  std::size_t i = 0;
  while (i < t_s.size() && t_s[i] < t0) ++i;
  EarlyStopReplay out;
  const double eps = 1e-9 * check_every_s;
  for (long k = 1;; ++k) {
    const double tc = static_cast<double>(k) * check_every_s;
    if (tc > t1 + eps) break;
    while (i < t_s.size() && t_s[i] <= tc + eps) since.push_back(r[i++]);
    const auto v = early_stop_verdict(since, tc, t0, t1, rel_ci, trend_check);
    if (v.stop) {
      out.stopped = true;
      out.t_stop_s = tc;
      out.at_stop = v.blocking;
      return out;
    }
  }
  std::vector<double> window;
  for (std::size_t j = 0; j < t_s.size(); ++j)
    if (t_s[j] >= t0 && t_s[j] <= t1 + eps) window.push_back(r[j]);
  out.t_stop_s = t1;
  if (window.size() >= 2) out.at_stop = block_average(window);
  return out;
}

}  // namespace brash::stats
