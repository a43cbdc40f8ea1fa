// Paired-ensemble statistics on a hand-computed set: pairs (9.5, 10.5), (17, 23), (36, 44) have relative differences
// 0.1, 0.3, 0.2 (b - a over the pair's mean), so mean 0.2, sd 0.1 and CI95 = t_{0.975, 2} 0.1 / sqrt(3) with
// t_{0.975, 2} = 4.303.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include <brash/stats/paired.hpp>

using namespace brash::stats;

TEST(Paired, HandComputedEnsemble) {
  const std::vector<double> a{9.5, 17, 36}, b{10.5, 23, 44};
  const auto p = paired_relative_difference(a, b);
  ASSERT_EQ(p.relative.size(), 3u);
  EXPECT_NEAR(p.relative[0], 0.1, 1e-15);
  EXPECT_NEAR(p.relative[1], 0.3, 1e-15);
  EXPECT_NEAR(p.relative[2], 0.2, 1e-15);
  EXPECT_NEAR(p.mean_a, 62.5 / 3, 1e-12);
  EXPECT_NEAR(p.mean_b, 77.5 / 3, 1e-12);
  EXPECT_EQ(p.difference.n, 3u);
  EXPECT_NEAR(p.difference.mean, 0.2, 1e-15);
  EXPECT_NEAR(p.difference.sd, 0.1, 1e-15);
  EXPECT_NEAR(p.difference.ci95, 4.303 * 0.1 / std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(p.difference.lo(), 0.2 - 0.24843, 1e-5);
  EXPECT_NEAR(p.difference.hi(), 0.2 + 0.24843, 1e-5);
  // [-0.048, 0.448]: inside (-0.5, 0.5), not inside (-0.4, 0.4)
  EXPECT_TRUE(within(p.difference, 0.5));
  EXPECT_FALSE(within(p.difference, 0.4));
  // (1.96 x 0.1 / (tol - 0.2))^2 pairs: 0.43 -> 1 at tol 0.5, 384.16 -> 385 at tol 0.21; none once tol <= |mean|
  EXPECT_EQ(pairs_to_resolve(p.difference, 0.5), 1u);
  EXPECT_EQ(pairs_to_resolve(p.difference, 0.21), 385u);
  EXPECT_FALSE(pairs_to_resolve(p.difference, 0.2).has_value());
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
  const auto p = paired_relative_difference(a, a);
  EXPECT_EQ(p.difference.mean, 0.0);
  EXPECT_EQ(p.difference.ci95, 0.0);
  EXPECT_TRUE(within(p.difference, 1e-6));
}

TEST(Paired, RejectsTooFewOrUnmatchedPairs) {
  const std::vector<double> one{1.0}, two{1.0, 2.0}, three{1.0, 2.0, 3.0};
  EXPECT_THROW(mean_ci95(one), std::invalid_argument);
  EXPECT_THROW(paired_relative_difference(one, one), std::invalid_argument);
  EXPECT_THROW(paired_relative_difference(two, three), std::invalid_argument);
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
