// Power-law fit y = a x^n by least squares of ln y = ln a + n ln x (the speed exponent of the resistance,
// R = a U^n). The slope's standard error comes from the residual variance of the log-log line (points - 2 degrees
// of freedom) and its 95 % interval is CI95 = t_{0.975, points - 2} SE (student_t.hpp).
#pragma once
#include <cmath>
#include <cstddef>
#include <span>

namespace brash::stats {

struct PowerLawFit {
  std::size_t points = 0;
  double a = NAN, n = NAN;  // NaN with fewer than 2 points or a single distinct x
  double n_se = NAN;        // NaN with fewer than 3 points
  double n_ci95 = NAN;      // t_{0.975, points - 2} n_se
};

// x and y of equal length, every value > 0 (std::invalid_argument otherwise).
PowerLawFit fit_power_law(std::span<const double> x, std::span<const double> y);

}  // namespace brash::stats
