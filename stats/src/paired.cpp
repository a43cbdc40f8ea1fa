// Mean with its Student-t CI and the paired-ensemble relative difference (paired.hpp).
#include <brash/stats/paired.hpp>
#include <brash/stats/student_t.hpp>

#include <algorithm>
#include <stdexcept>

namespace brash::stats {
namespace {

// Left to right, as the ensemble summaries archived before this library were summed.
double sum_of(std::span<const double> x) {
  double s = 0;
  for (const double v : x) s += v;
  return s;
}

}  // namespace

MeanCi mean_ci95(std::span<const double> x) {
  if (x.size() < 2) throw std::invalid_argument("mean_ci95: needs at least 2 values");
  MeanCi m;
  m.n = x.size();
  const auto k = static_cast<double>(x.size());
  m.mean = sum_of(x) / k;
  double ss = 0;
  for (const double v : x) ss += std::pow(v - m.mean, 2.0);
  m.sd = std::sqrt(ss / (k - 1));
  m.ci95 = student_t975(x.size() - 1) * m.sd / std::sqrt(k);
  return m;
}

double relative_difference(double a, double b) { return (b - a) / (0.5 * (a + b)); }

IndependentDifference independent_relative_difference(double reference, double reference_ci95, double mean,
                                                      double ci95) {
  if (reference == 0 || !std::isfinite(reference))
    throw std::invalid_argument("independent_relative_difference: the reference must be finite and non-zero");
  return {(mean - reference) / reference, std::hypot(reference_ci95, ci95) / std::abs(reference)};
}

PairedDifference paired_relative_difference(std::span<const double> a, std::span<const double> b) {
  if (a.size() != b.size()) throw std::invalid_argument("paired_relative_difference: sides differ in length");
  if (a.size() < 2) throw std::invalid_argument("paired_relative_difference: needs at least 2 pairs");
  PairedDifference p;
  const auto k = static_cast<double>(a.size());
  p.mean_a = sum_of(a) / k;
  p.mean_b = sum_of(b) / k;
  for (std::size_t i = 0; i < a.size(); ++i) p.relative.push_back(relative_difference(a[i], b[i]));
  p.difference = mean_ci95(p.relative);
  return p;
}

bool within(const MeanCi& m, double tol) { return -tol < m.lo() && m.hi() < tol; }

std::optional<std::size_t> pairs_to_resolve(const MeanCi& m, double tol) {
  if (!(std::abs(m.mean) < tol)) return std::nullopt;
  constexpr double kZ975 = 1.96;
  return static_cast<std::size_t>(std::ceil(std::pow(kZ975 * m.sd / std::max(1e-9, tol - std::abs(m.mean)), 2.0)));
}

}  // namespace brash::stats
