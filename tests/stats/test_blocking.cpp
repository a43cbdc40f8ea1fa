// Block averaging: CI of the mean on AR(1) signals with known variance of the mean.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <brash/stats/blocking.hpp>

using namespace brash::stats;

namespace {

// x_t = phi x_{t-1} + e_t, e ~ N(0, 1), started in the stationary distribution.
std::vector<double> ar1(double phi, std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> e(0, 1);
  std::vector<double> x(n);
  x[0] = e(rng) / std::sqrt(1 - phi * phi);
  for (std::size_t i = 1; i < n; ++i) x[i] = phi * x[i - 1] + e(rng);
  return x;
}

// Exact Var(mean) of n stationary AR(1) samples: sigma^2/n [1 + 2 sum_k (1 - k/n) phi^k].
double ar1_var_of_mean(double phi, std::size_t n) {
  const double s2 = 1 / (1 - phi * phi);
  double sum = 0, pk = 1;
  for (std::size_t k = 1; k < n; ++k) {
    pk *= phi;
    sum += (1 - static_cast<double>(k) / n) * pk;
  }
  return s2 / n * (1 + 2 * sum);
}

}  // namespace

TEST(Blocking, ConstantAndWhiteNoise) {
  const std::vector<double> c(100, 3.5);
  const auto rc = block_average(c);
  EXPECT_DOUBLE_EQ(rc.mean, 3.5);
  EXPECT_EQ(rc.ci95, 0);
  const auto w = ar1(0.0, 4096, 7);
  const auto rw = block_average(w);
  EXPECT_TRUE(rw.plateau_found);
  EXPECT_NEAR(rw.sem, 1 / std::sqrt(4096.0), 0.25 / std::sqrt(4096.0));
}

// The block-averaging acceptance test: for each phi the estimated Var(mean), averaged over 40 seeds,
// is within 10 % of the exact value. N = 2500 is the paper window (25 s at 0.01 s), N = 16384 a longer one.
TEST(Blocking, AR1VarianceOfMeanWithin10Percent) {
  for (const std::size_t n : {std::size_t{2500}, std::size_t{16384}}) {
    for (const double phi : {0.0, 0.5, 0.8, 0.9}) {
      constexpr int kSeeds = 40;
      double sum_ratio = 0;
      int covered = 0;
      const double exact = ar1_var_of_mean(phi, n);
      for (int s = 0; s < kSeeds; ++s) {
        const auto x = ar1(phi, n, 1000u * static_cast<unsigned>(phi * 100) + static_cast<unsigned>(s) + n);
        const auto r = block_average(x);
        sum_ratio += r.sem * r.sem / exact;
        covered += std::abs(r.mean) <= r.ci95;  // true mean is 0
      }
      const double mean_ratio = sum_ratio / kSeeds;
      EXPECT_NEAR(mean_ratio, 1.0, 0.10) << "n " << n << " phi " << phi;
      EXPECT_GE(covered, 32) << "95 % CI coverage too low, n " << n << " phi " << phi;  // >= 80 % of 40
      std::printf("n %5zu phi %.2f  <est/exact Var(mean)> = %.3f  coverage %d/%d\n", n, phi, mean_ratio, covered, kSeeds);
    }
  }
}

TEST(Blocking, ShortCorrelatedRecordFlagsNoPlateau) {
  // phi 0.999: correlation time ~2000 samples >> record/16: no plateau, flagged.
  const auto r = block_average(ar1(0.999, 2048, 3));
  EXPECT_FALSE(r.plateau_found);
  EXPECT_GT(r.ci95, 0);
}
