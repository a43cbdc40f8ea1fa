// The resistance's speed law R(U) in three forms, fitted by least squares on R itself (residuals in N, so the forms
// compare on the same footing):
//   a U^n        the pure power law (its log-log line: power_law.hpp);
//   a + b U^2    a speed-independent part plus a quadratic one (linear least squares, n = 2 fixed);
//   a + b U^n    both free (n by a one-dimensional search; a and b linear for each n).
// Each with its parameters' 95 % intervals (Student t with points - k degrees of freedom; the Gauss-Newton
// covariance s^2 (J^T J)^-1 for a + b U^n) and the small-sample Akaike criterion
//   AICc = N ln(SSE / N) + 2k + 2k (k + 1) / (N - k - 1)   (+inf where N <= k + 1),
// which weighs the fit against its number of parameters k: the lowest AICc is the form the points support.
#pragma once
#include <cmath>
#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

namespace brash::stats {

struct SpeedLawFit {
  std::string_view form;                        // "a U^n" | "a + b U^2" | "a + b U^n"
  std::size_t points = 0, params = 0;           // N, k
  double a = NAN, b = NAN, n = NAN;             // b NaN for a U^n; n = 2 for a + b U^2
  double a_ci95 = NAN, b_ci95 = NAN, n_ci95 = NAN;  // NaN where not estimable (a of the power law, n fixed)
  double sse = NAN, aicc = NAN;                 // sum of squared residuals [N^2]; AICc
  std::vector<double> residuals;                // R - fit, per point
  double at(double u) const { return std::isfinite(b) ? a + b * std::pow(u, n) : a * std::pow(u, n); }
};

// The three forms in the order above (a form needs more points than parameters; with fewer its values are NaN).
// u and r of equal length, every value > 0 (std::invalid_argument otherwise).
std::vector<SpeedLawFit> fit_speed_laws(std::span<const double> u, std::span<const double> r);

// Index of the form with the lowest finite AICc, or fits.size() when none has one.
std::size_t best_speed_law(const std::vector<SpeedLawFit>& fits);

}  // namespace brash::stats
