// Flyvbjerg-Petersen block averaging with a documented plateau rule (see blocking.hpp).
#include <brash/stats/blocking.hpp>
#include <brash/stats/student_t.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace brash::stats {
namespace {

constexpr double kAgreeSigmas = 2.0;  // plateau: later levels within 2 combined standard errors
// Block means of a plateau level are nearly independent; a larger lag-1 correlation means the
// blocks are still short of the correlation time (and the 1 + 2 rho1 correction is unreliable).
constexpr double kMaxPlateauLag1 = 0.5;

double mean_of(std::span<const double> x) {
  return std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
}

BlockLevel level_of(std::span<const double> x, std::size_t block_size) {
  const double m = mean_of(x);
  double c0 = 0;
  for (const double v : x) c0 += (v - m) * (v - m);
  const auto n = static_cast<double>(x.size());
  c0 /= n;
  double c1 = 0;
  for (std::size_t i = 1; i < x.size(); ++i) c1 += (x[i - 1] - m) * (x[i] - m);
  c1 /= n;
  const double var_of_mean = c0 / (n - 1);
  return {block_size, x.size(), var_of_mean, var_of_mean * std::sqrt(2.0 / (n - 1)), c0 > 0 ? c1 / c0 : 0.0};
}

std::vector<double> halve(std::span<const double> x) {
  std::vector<double> y(x.size() / 2);
  for (std::size_t i = 0; i < y.size(); ++i) y[i] = 0.5 * (x[2 * i] + x[2 * i + 1]);
  return y;
}

}  // namespace

BlockingResult block_average(std::span<const double> x, std::size_t min_blocks) {
  if (x.size() < 2) throw std::invalid_argument("block_average: need at least 2 samples");
  BlockingResult r;
  r.n_samples = x.size();
  r.mean = mean_of(x);
  std::vector<double> cur(x.begin(), x.end());
  for (std::size_t bs = 1; cur.size() >= 2; bs *= 2) {
    r.levels.push_back(level_of(cur, bs));
    cur = halve(cur);
  }
  // Eligible levels: enough blocks for a meaningful variance (level 0 always, for tiny records).
  std::size_t n_eligible = 0;
  while (n_eligible < r.levels.size() && r.levels[n_eligible].n_blocks >= min_blocks) ++n_eligible;
  n_eligible = std::max<std::size_t>(n_eligible, 1);

  const auto agrees_with_later = [&](std::size_t k) {
    if (r.levels[k].lag1_corr > kMaxPlateauLag1) return false;
    for (std::size_t j = k + 1; j < n_eligible; ++j) {
      const double tol = kAgreeSigmas * std::hypot(r.levels[k].var_error, r.levels[j].var_error);
      if (std::abs(r.levels[j].var_of_mean - r.levels[k].var_of_mean) > tol) return false;
    }
    return true;
  };
  // The last eligible level agrees trivially; a plateau needs at least one later level to confirm.
  r.level = n_eligible;
  for (std::size_t k = 0; k + 1 < n_eligible; ++k)
    if (agrees_with_later(k)) { r.level = k; break; }
  r.plateau_found = r.level < n_eligible;
  if (!r.plateau_found) {
    const auto it = std::max_element(r.levels.begin(), r.levels.begin() + static_cast<std::ptrdiff_t>(n_eligible),
                                     [](const BlockLevel& a, const BlockLevel& b) { return a.var_of_mean < b.var_of_mean; });
    r.level = static_cast<std::size_t>(it - r.levels.begin());
  }
  const auto& L = r.levels[r.level];
  // Adjacent block means stay correlated (~tau/b); correct with their lag-1 autocorrelation,
  // whose sample estimate is biased by -1/n_blocks. Never shrink the plain estimate.
  r.correction = std::max(1.0, 1.0 + 2.0 * (L.lag1_corr + 1.0 / static_cast<double>(L.n_blocks)));
  r.sem = std::sqrt(L.var_of_mean * r.correction);
  r.ci95 = student_t975(L.n_blocks - 1) * r.sem;
  return r;
}

HalvesTrend halves_trend(std::span<const double> x) {
  if (x.size() < 4) throw std::invalid_argument("halves_trend: needs at least 4 samples");
  HalvesTrend t;
  const std::size_t h = x.size() / 2;
  t.first = block_average(x.first(h));
  t.second = block_average(x.subspan(h));
  t.difference = t.second.mean - t.first.mean;
  t.ci95 = std::hypot(t.first.ci95, t.second.ci95);
  return t;
}

}  // namespace brash::stats
