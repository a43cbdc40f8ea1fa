// Mean with its Student-t CI and the paired-ensemble effect on side A (paired.hpp).
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

double relative_effect(double a, double b) {
  if (a == 0 || !std::isfinite(a)) throw std::invalid_argument("relative_effect: side A must be finite and non-zero");
  return (b - a) / a;
}

IndependentDifference independent_relative_difference(double reference, double reference_ci95, double mean,
                                                      double ci95) {
  if (reference == 0 || !std::isfinite(reference))
    throw std::invalid_argument("independent_relative_difference: the reference must be finite and non-zero");
  return {relative_effect(reference, mean), std::hypot(reference_ci95, ci95) / std::abs(reference)};
}

PairedEffect paired_effect(std::span<const double> a, std::span<const double> b) {
  if (a.size() != b.size()) throw std::invalid_argument("paired_effect: sides differ in length");
  if (a.size() < 2) throw std::invalid_argument("paired_effect: needs at least 2 pairs");
  PairedEffect p;
  const auto k = static_cast<double>(a.size());
  p.mean_a = sum_of(a) / k;
  p.mean_b = sum_of(b) / k;
  if (p.mean_a == 0 || !std::isfinite(p.mean_a))
    throw std::invalid_argument("paired_effect: side A's mean must be finite and non-zero");
  for (std::size_t i = 0; i < a.size(); ++i) p.relative.push_back(relative_effect(a[i], b[i]));
  const double ratio = p.mean_b / p.mean_a;
  // the delta method: E's first-order error is the mean of z_i (b_i - ratio a_i) / mean a
  std::vector<double> z;
  for (std::size_t i = 0; i < a.size(); ++i) z.push_back((b[i] - ratio * a[i]) / p.mean_a);
  p.effect = mean_ci95(z);
  p.effect.mean = relative_effect(p.mean_a, p.mean_b);
  return p;
}

bool within(const MeanCi& m, double tol) { return -tol < m.lo() && m.hi() < tol; }

std::optional<std::size_t> pairs_to_resolve(const MeanCi& m, double tol) {
  if (!(std::abs(m.mean) < tol)) return std::nullopt;
  constexpr double kZ975 = 1.96;
  return static_cast<std::size_t>(std::ceil(std::pow(kZ975 * m.sd / std::max(1e-9, tol - std::abs(m.mean)), 2.0)));
}

}  // namespace brash::stats
