// Speed-law fits in three forms with their AICc (speed_law.hpp).
#include <brash/stats/power_law.hpp>
#include <brash/stats/speed_law.hpp>
#include <brash/stats/student_t.hpp>

#include <array>
#include <limits>
#include <stdexcept>

namespace brash::stats {
namespace {

double aicc(double sse, std::size_t points, std::size_t k) {
  const double n = static_cast<double>(points), kk = static_cast<double>(k);
  if (points <= k + 1 || !(sse >= 0)) return std::numeric_limits<double>::infinity();
  // an exact fit (SSE 0) would give -inf: floor the SSE so that exact fits still order by k
  return n * std::log(std::max(sse, 1e-300) / n) + 2 * kk + 2 * kk * (kk + 1) / (n - kk - 1);
}

void finish(SpeedLawFit& f, std::span<const double> u, std::span<const double> r) {
  f.sse = 0;
  f.residuals.clear();
  for (std::size_t i = 0; i < u.size(); ++i) {
    f.residuals.push_back(r[i] - f.at(u[i]));
    f.sse += f.residuals.back() * f.residuals.back();
  }
  f.aicc = aicc(f.sse, f.points, f.params);
}

// r = a + b u^n for a fixed n: a, b by linear least squares; false when u^n has no spread.
bool linear_in_power(std::span<const double> u, std::span<const double> r, double n, double& a, double& b,
                     double& sff) {
  const double k = static_cast<double>(u.size());
  double mf = 0, mr = 0;
  for (std::size_t i = 0; i < u.size(); ++i) mf += std::pow(u[i], n) / k, mr += r[i] / k;
  double sfr = 0;
  sff = 0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    const double df = std::pow(u[i], n) - mf;
    sff += df * df, sfr += df * (r[i] - mr);
  }
  if (!(sff > 0)) return false;
  b = sfr / sff, a = mr - b * mf;
  return true;
}

SpeedLawFit unfitted(std::string_view form, std::size_t points, std::size_t params) {
  SpeedLawFit f;
  f.form = form, f.points = points, f.params = params;
  return f;
}

SpeedLawFit power_law(std::span<const double> u, std::span<const double> r) {
  const PowerLawFit p = fit_power_law(u, r);
  SpeedLawFit f = unfitted("a U^n", u.size(), 2);
  f.a = p.a, f.n = p.n, f.n_ci95 = p.n_ci95;
  if (std::isfinite(p.n)) finish(f, u, r);
  return f;
}

SpeedLawFit quadratic(std::span<const double> u, std::span<const double> r) {
  SpeedLawFit f = unfitted("a + b U^2", u.size(), 2);
  f.n = 2;
  double sff = 0;
  if (u.size() < 3 || !linear_in_power(u, r, 2.0, f.a, f.b, sff)) return f;
  finish(f, u, r);
  const double k = static_cast<double>(u.size()), s2 = f.sse / (k - 2);
  double mf = 0;
  for (double x : u) mf += x * x / k;
  const double t = student_t975(u.size() - 2);
  f.b_ci95 = t * std::sqrt(s2 / sff);
  f.a_ci95 = t * std::sqrt(s2 * (1 / k + mf * mf / sff));
  return f;
}

// 3 x 3 symmetric inverse (cofactors); false when singular.
bool invert3(const std::array<std::array<double, 3>, 3>& m, std::array<std::array<double, 3>, 3>& inv) {
  const auto c = [&](int i, int j) {
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
    return m[i1][j1] * m[i2][j2] - m[i1][j2] * m[i2][j1];
  };
  const double det = m[0][0] * c(0, 0) + m[0][1] * c(0, 1) + m[0][2] * c(0, 2);
  if (!(std::abs(det) > 0)) return false;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) inv[i][j] = c(j, i) / det;
  return true;
}

SpeedLawFit offset_power(std::span<const double> u, std::span<const double> r) {
  SpeedLawFit f = unfitted("a + b U^n", u.size(), 3);
  if (u.size() < 4) return f;
  // SSE(n) on a grid of 0.01 over [0.1, 6], then a golden-section search in the best cell's neighbours.
  const auto sse_at = [&](double n) {
    double a = 0, b = 0, sff = 0;
    if (!linear_in_power(u, r, n, a, b, sff)) return std::numeric_limits<double>::infinity();
    double s = 0;
    for (std::size_t i = 0; i < u.size(); ++i) {
      const double e = r[i] - a - b * std::pow(u[i], n);
      s += e * e;
    }
    return s;
  };
  double best_n = NAN, best = std::numeric_limits<double>::infinity();
  for (int i = 10; i <= 600; ++i)
    if (const double s = sse_at(0.01 * i); s < best) best = s, best_n = 0.01 * i;
  if (!std::isfinite(best)) return f;
  double lo = best_n - 0.01, hi = best_n + 0.01;
  const double g = (std::sqrt(5.0) - 1) / 2;
  for (int it = 0; it < 60; ++it) {
    const double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    if (sse_at(x1) < sse_at(x2))
      hi = x2;
    else
      lo = x1;
  }
  f.n = 0.5 * (lo + hi);
  double sff = 0;
  linear_in_power(u, r, f.n, f.a, f.b, sff);
  finish(f, u, r);
  // Gauss-Newton covariance: J_i = (1, u^n, b u^n ln u), s^2 = SSE / (N - 3).
  std::array<std::array<double, 3>, 3> jtj{}, cov{};
  for (double x : u) {
    const std::array<double, 3> j{1.0, std::pow(x, f.n), f.b * std::pow(x, f.n) * std::log(x)};
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q) jtj[p][q] += j[p] * j[q];
  }
  if (!invert3(jtj, cov)) return f;
  const double s2 = f.sse / static_cast<double>(u.size() - 3), t = student_t975(u.size() - 3);
  f.a_ci95 = t * std::sqrt(s2 * cov[0][0]);
  f.b_ci95 = t * std::sqrt(s2 * cov[1][1]);
  f.n_ci95 = t * std::sqrt(s2 * cov[2][2]);
  return f;
}

}  // namespace

std::vector<SpeedLawFit> fit_speed_laws(std::span<const double> u, std::span<const double> r) {
  if (u.size() != r.size()) throw std::invalid_argument("fit_speed_laws: u and r differ in length");
  for (std::size_t i = 0; i < u.size(); ++i)
    if (!(u[i] > 0) || !(r[i] > 0)) throw std::invalid_argument("fit_speed_laws: needs u > 0 and r > 0");
  return {power_law(u, r), quadratic(u, r), offset_power(u, r)};
}

std::size_t best_speed_law(const std::vector<SpeedLawFit>& fits) {
  std::size_t best = fits.size();
  for (std::size_t i = 0; i < fits.size(); ++i)
    if (std::isfinite(fits[i].aicc) && (best == fits.size() || fits[i].aicc < fits[best].aicc)) best = i;
  return best;
}

}  // namespace brash::stats
