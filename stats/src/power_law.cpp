// Least-squares power-law fit with the exponent's standard error and CI (power_law.hpp).
#include <brash/stats/power_law.hpp>
#include <brash/stats/student_t.hpp>

#include <stdexcept>

namespace brash::stats {

PowerLawFit fit_power_law(std::span<const double> x, std::span<const double> y) {
  if (x.size() != y.size()) throw std::invalid_argument("fit_power_law: x and y differ in length");
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!(x[i] > 0) || !(y[i] > 0)) throw std::invalid_argument("fit_power_law: needs x > 0 and y > 0");
  PowerLawFit f;
  f.points = x.size();
  if (x.size() < 2) return f;
  double sx = 0, sy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) sx += std::log(x[i]), sy += std::log(y[i]);
  const double k = static_cast<double>(x.size());
  const double mx = sx / k, my = sy / k;
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double dx = std::log(x[i]) - mx;
    sxx += dx * dx;
    sxy += dx * (std::log(y[i]) - my);
  }
  if (sxx <= 0) return f;
  f.n = sxy / sxx;
  f.a = std::exp(my - f.n * mx);
  if (x.size() >= 3) {
    double ssr = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double e = std::log(y[i]) - (my + f.n * (std::log(x[i]) - mx));
      ssr += e * e;
    }
    f.n_se = std::sqrt(ssr / (k - 2.0) / sxx);
    f.n_ci95 = student_t975(x.size() - 2) * f.n_se;
  }
  return f;
}

}  // namespace brash::stats
