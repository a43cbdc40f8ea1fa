// Paired-ensemble statistics on a hand-computed set: pairs (9.5, 10.5), (17, 23), (36, 44), means 62.5 / 3 and
// 77.5 / 3. The effect on side A is (77.5 - 62.5) / 62.5 = 0.24 (over the pairs' means it would be 0.2); the delta
// method's b_i - 1.24 a_i are -1.28, 1.92, -0.64 (sum 0), so sd = sqrt(5.7344 / 2) / (62.5 / 3) and
// CI95 = t_{0.975, 2} sd / sqrt(3) with t_{0.975, 2} = 4.303.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include <brash/stats/paired.hpp>

using namespace brash::stats;

TEST(Paired, HandComputedEnsemble) {
  const std::vector<double> a{9.5, 17, 36}, b{10.5, 23, 44};
  const auto p = paired_effect(a, b);
  ASSERT_EQ(p.relative.size(), 3u);
  EXPECT_NEAR(p.relative[0], 1.0 / 9.5, 1e-15);  // each pair on its own A
  EXPECT_NEAR(p.relative[1], 6.0 / 17, 1e-15);
  EXPECT_NEAR(p.relative[2], 8.0 / 36, 1e-15);
  EXPECT_NEAR(p.mean_a, 62.5 / 3, 1e-12);
  EXPECT_NEAR(p.mean_b, 77.5 / 3, 1e-12);
  EXPECT_EQ(p.effect.n, 3u);
  EXPECT_NEAR(p.effect.mean, 0.24, 1e-15);
  const double sd = std::sqrt(5.7344 / 2) / (62.5 / 3);  // 0.081277
  EXPECT_NEAR(p.effect.sd, sd, 1e-14);
  EXPECT_NEAR(p.effect.ci95, 4.303 * sd / std::sqrt(3.0), 1e-14);
  EXPECT_NEAR(p.effect.lo(), 0.24 - 0.201921, 1e-6);
  EXPECT_NEAR(p.effect.hi(), 0.24 + 0.201921, 1e-6);
  // [0.038, 0.442]: inside (-0.45, 0.45), not inside (-0.4, 0.4)
  EXPECT_TRUE(within(p.effect, 0.45));
  EXPECT_FALSE(within(p.effect, 0.4));
  // (1.96 sd / (tol - 0.24))^2 pairs: 0.99 -> 1 at tol 0.4, 99.1 -> 100 at tol 0.256; none once tol <= |mean|
  EXPECT_EQ(pairs_to_resolve(p.effect, 0.4), 1u);
  EXPECT_EQ(pairs_to_resolve(p.effect, 0.256), 100u);
  EXPECT_FALSE(pairs_to_resolve(p.effect, 0.2).has_value());
}

// The one definition of a change's size: on side A, never on the mean of the two sides (A 10 -> B 5 is -50 %, not
// -66.7 %).
TEST(Paired, EffectIsOnSideA) {
  EXPECT_DOUBLE_EQ(relative_effect(10.0, 5.0), -0.5);
  EXPECT_DOUBLE_EQ(relative_effect(4.0, 5.0), 0.25);
  const std::vector<double> a{10, 20}, b{5, 10};
  EXPECT_DOUBLE_EQ(paired_effect(a, b).effect.mean, -0.5);
  EXPECT_DOUBLE_EQ(independent_relative_difference(10.0, 0.1, 5.0, 0.1).relative, -0.5);
  EXPECT_THROW(relative_effect(0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(paired_effect(std::vector<double>{1, -1}, std::vector<double>{2, 2}), std::invalid_argument);
}

// Two values: one degree of freedom, t = 12.706.
TEST(Paired, TwoValuesUseOneDegreeOfFreedom) {
  const std::vector<double> x{1.0, 3.0};
  const auto m = mean_ci95(x);
  EXPECT_DOUBLE_EQ(m.mean, 2.0);
  EXPECT_DOUBLE_EQ(m.sd, std::sqrt(2.0));
  EXPECT_NEAR(m.ci95, 12.706 * std::sqrt(2.0) / std::sqrt(2.0), 1e-12);
}

TEST(Paired, EqualSidesGiveZero) {
  const std::vector<double> a{12, 15, 18, 20};
  const auto p = paired_effect(a, a);
  EXPECT_EQ(p.effect.mean, 0.0);
  EXPECT_EQ(p.effect.ci95, 0.0);
  EXPECT_TRUE(within(p.effect, 1e-6));
}

TEST(Paired, RejectsTooFewOrUnmatchedPairs) {
  const std::vector<double> one{1.0}, two{1.0, 2.0}, three{1.0, 2.0, 3.0};
  EXPECT_THROW(mean_ci95(one), std::invalid_argument);
  EXPECT_THROW(paired_effect(one, one), std::invalid_argument);
  EXPECT_THROW(paired_effect(two, three), std::invalid_argument);
}

// Two separate runs: 10 +- 0.3 N against a reference of 12 +- 0.4 N differ by -1/6 with a CI of 0.5 / 12
// (3-4-5: the CIs add in quadrature), resolved; 11.9 +- 0.3 is not.
TEST(IndependentDifference, CisAddInQuadrature) {
  const auto d = brash::stats::independent_relative_difference(12.0, 0.4, 10.0, 0.3);
  EXPECT_NEAR(d.relative, -1.0 / 6.0, 1e-15);
  EXPECT_NEAR(d.ci95_relative, 0.5 / 12.0, 1e-15);
  EXPECT_TRUE(d.resolved());
  EXPECT_FALSE(brash::stats::independent_relative_difference(12.0, 0.4, 11.9, 0.3).resolved());
  EXPECT_THROW(brash::stats::independent_relative_difference(0.0, 0.4, 1.0, 0.3), std::invalid_argument);
}
