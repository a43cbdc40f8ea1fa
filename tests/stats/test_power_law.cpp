// Power-law fit: exact on a power law; on a perturbed one the exponent, prefactor, SE and CI95 of a hand-worked case.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include <brash/stats/power_law.hpp>

using namespace brash::stats;

TEST(PowerLaw, ExactOnAPowerLaw) {
  const std::vector<double> x{0.2, 0.5, 1.0, 2.0, 4.0};
  std::vector<double> y;
  for (const double v : x) y.push_back(3.0 * std::pow(v, 1.5));
  const auto f = fit_power_law(x, y);
  EXPECT_EQ(f.points, 5u);
  EXPECT_NEAR(f.n, 1.5, 1e-12);
  EXPECT_NEAR(f.a, 3.0, 1e-12);
  EXPECT_NEAR(f.n_se, 0.0, 1e-9);
  EXPECT_NEAR(f.n_ci95, 0.0, 1e-8);
}

// x = 1, 2, 4, 8, 16 (ln x = L {0, 1, 2, 3, 4}, L = ln 2), y = 2 x^1.2 exp(e), e = {0.1, -0.1, 0, 0.1, -0.1}.
// Slope: 1.2 + sum(dx e) / sxx = 1.2 + L (-0.2) / (10 L^2) = 1.2 - 0.02 / L. Residuals of e about its fitted line
// -0.02 {-2, -1, 0, 1, 2}: {0.06, -0.12, 0, 0.12, -0.06}, sum of squares 0.036, so SE = sqrt(0.036 / 3 / (10 L^2))
// and CI95 = t_{0.975, 3} SE = 3.182 SE. Prefactor: exp(mean ln y - n mean ln x) = 2 exp(2 L (1.2 - n)) = 2 e^0.04.
TEST(PowerLaw, SeAndCiOnAPerturbedPowerLaw) {
  const std::vector<double> x{1, 2, 4, 8, 16}, e{0.1, -0.1, 0, 0.1, -0.1};
  std::vector<double> y;
  for (std::size_t i = 0; i < x.size(); ++i) y.push_back(2.0 * std::pow(x[i], 1.2) * std::exp(e[i]));
  const auto f = fit_power_law(x, y);
  const double L = std::log(2.0), se = std::sqrt(0.036 / 3 / (10 * L * L));
  EXPECT_NEAR(f.n, 1.2 - 0.02 / L, 1e-12);
  EXPECT_NEAR(f.a, 2 * std::exp(0.04), 1e-12);
  EXPECT_NEAR(f.n_se, se, 1e-12);
  EXPECT_NEAR(f.n_ci95, 3.182 * se, 1e-12);
  EXPECT_NEAR(f.n_ci95, 0.1590, 1e-4);
}

TEST(PowerLaw, TooFewPointsLeaveNaN) {
  const std::vector<double> one{1.0}, two_x{1.0, 2.0}, two_y{3.0, 6.0}, same_x{2.0, 2.0};
  const auto f1 = fit_power_law(one, one);
  EXPECT_EQ(f1.points, 1u);
  EXPECT_TRUE(std::isnan(f1.n));
  const auto f2 = fit_power_law(two_x, two_y);  // a line through two points: exponent, no SE
  EXPECT_NEAR(f2.n, 1.0, 1e-12);
  EXPECT_NEAR(f2.a, 3.0, 1e-12);
  EXPECT_TRUE(std::isnan(f2.n_se));
  EXPECT_TRUE(std::isnan(f2.n_ci95));
  EXPECT_TRUE(std::isnan(fit_power_law(same_x, two_y).n));
}

TEST(PowerLaw, RejectsNonPositiveOrUnmatchedInput) {
  const std::vector<double> x{1.0, 2.0, 3.0}, y{1.0, 0.0, 3.0}, short_y{1.0, 2.0};
  EXPECT_THROW(fit_power_law(x, y), std::invalid_argument);
  EXPECT_THROW(fit_power_law(x, short_y), std::invalid_argument);
}
