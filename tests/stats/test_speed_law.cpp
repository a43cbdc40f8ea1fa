// The speed law in three forms (brash/stats/speed_law.hpp): each form recovers its own parameters from points made
// with it, within its CI, and AICc picks it among the three; the quick case's sweep (docs/validation.md (b))
// prefers R = a + b U^2 to the power law.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "brash/stats/speed_law.hpp"

using namespace brash::stats;

namespace {

const std::vector<double> kSpeeds = {0.2, 0.3, 0.4, 0.482, 0.6, 0.7, 0.85, 1.0};

// Points of `law` with the noise each form's fit assumes (fixed seed): Gaussian of sd 0.1 N added (least squares
// on R), or a factor exp(N(0, 0.005)) with `relative` (the power law's least squares on ln R).
std::vector<double> points(double (*law)(double), unsigned seed, bool relative = false) {
  std::mt19937_64 g(seed);
  std::normal_distribution<double> noise(0.0, relative ? 0.005 : 0.1);
  std::vector<double> r;
  for (double u : kSpeeds) r.push_back(relative ? law(u) * std::exp(noise(g)) : law(u) + noise(g));
  return r;
}

}  // namespace

// 40 seeds per form: its parameters lie within their 95 % intervals in about 38 (at least 34 asserted: a
// binomial(40, 0.95) count falls below 34 with probability ~0.1 %), and AICc picks the form in most of them.
TEST(SpeedLaw, EachFormRecoversItsOwnParametersAndIsChosen) {
  const auto quadratic = [](double u) { return 6.0 + 46.0 * u * u; };
  const auto power = [](double u) { return 40.0 * std::pow(u, 1.2); };
  const auto offset = [](double u) { return 12.0 + 40.0 * std::pow(u, 3.0); };
  int q_a = 0, q_b = 0, q_best = 0, p_n = 0, p_best = 0, o_n = 0, o_a = 0, o_best = 0;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    const auto q = fit_speed_laws(kSpeeds, points(quadratic, seed));
    ASSERT_EQ(q.size(), 3u);
    EXPECT_EQ(q[1].form, "a + b U^2");
    q_a += std::abs(q[1].a - 6.0) <= q[1].a_ci95;
    q_b += std::abs(q[1].b - 46.0) <= q[1].b_ci95;
    q_best += best_speed_law(q) == 1;
    EXPECT_LT(q[1].aicc, q[0].aicc) << seed;  // the power law cannot bend like a constant plus U^2

    const auto p = fit_speed_laws(kSpeeds, points(power, seed, true));
    p_n += std::abs(p[0].n - 1.2) <= p[0].n_ci95;
    p_best += best_speed_law(p) == 0;

    const auto o = fit_speed_laws(kSpeeds, points(offset, seed));
    o_n += std::abs(o[2].n - 3.0) <= o[2].n_ci95;
    o_a += std::abs(o[2].a - 12.0) <= o[2].a_ci95;
    o_best += best_speed_law(o) == 2;
  }
  EXPECT_GE(q_a, 34);
  EXPECT_GE(q_b, 34);
  EXPECT_GE(p_n, 34);
  EXPECT_GE(o_n, 34);
  EXPECT_GE(o_a, 34);
  // a + b U^n contains the other two, so on their points it fits as well with one parameter more: AICc then
  // prefers the smaller form in most seeds, and on points of a + b U^3 it must prefer the larger one.
  EXPECT_GE(q_best, 30);
  EXPECT_GE(p_best, 30);
  EXPECT_GE(o_best, 36);
}

TEST(SpeedLaw, ResidualsAndSseAreThoseOfTheFit) {
  const std::vector<double> u = {0.2, 0.5, 1.0}, r = {8.0, 17.0, 52.0};
  const auto f = fit_speed_laws(u, r);
  for (const auto& fit : f) {
    if (!std::isfinite(fit.a)) continue;
    double sse = 0;
    for (std::size_t i = 0; i < u.size(); ++i) {
      EXPECT_NEAR(fit.residuals[i], r[i] - fit.at(u[i]), 1e-12);
      sse += fit.residuals[i] * fit.residuals[i];
    }
    EXPECT_NEAR(fit.sse, sse, 1e-12);
  }
  EXPECT_TRUE(std::isnan(f[2].n));     // three points: a + b U^n (k = 3) is not fitted
  EXPECT_TRUE(std::isinf(f[1].aicc));  // and N = k + 1 has no AICc
}

// The quick case's sweep with both (docs/validation.md (b), R3 R5 R7 R9 R11): the power law's residuals run
// +, -, -, -, + (systematic), R = a + b U^2 has the lowest AICc.
TEST(SpeedLaw, QuickCaseSweepPrefersAConstantPlusQuadratic) {
  const std::vector<double> u = {0.2, 0.3, 0.482, 0.7, 1.0}, r = {7.56, 10.29, 17.21, 29.16, 52.05};
  const auto f = fit_speed_laws(u, r);
  EXPECT_EQ(best_speed_law(f), 1u);
  EXPECT_GT(f[0].residuals[0], 0);
  EXPECT_LT(f[0].residuals[2], 0);
  EXPECT_GT(f[0].residuals[4], 0);
  EXPECT_LT(f[1].sse, f[0].sse / 10);
}

TEST(SpeedLaw, RefusesBadInput) {
  const std::vector<double> u = {0.2, 0.5}, r = {1.0};
  EXPECT_THROW(fit_speed_laws(u, r), std::invalid_argument);
  const std::vector<double> neg = {-1.0, 2.0};
  EXPECT_THROW(fit_speed_laws(neg, u), std::invalid_argument);
  EXPECT_EQ(best_speed_law({}), 0u);
}
