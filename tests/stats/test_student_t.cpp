// Student-t 97.5 % quantiles against the exact ones (7 digits, from the t distribution's CDF): the table to its
// 3 decimals, the expansion above 30 degrees of freedom to 1e-4.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include <brash/stats/student_t.hpp>

using brash::stats::student_t975;

TEST(StudentT, TableMatchesExactQuantiles) {
  for (const auto& [dof, t] : {std::pair<std::size_t, double>{1, 12.7062047}, {2, 4.3026527}, {3, 3.1824463},
                              {5, 2.5705818}, {10, 2.2281389}, {15, 2.1314495}, {30, 2.0422725}})
    EXPECT_NEAR(student_t975(dof), t, 6e-4) << "dof " << dof;
}

TEST(StudentT, ExpansionAboveTheTable) {
  for (const auto& [dof, t] : {std::pair<std::size_t, double>{31, 2.0395134}, {40, 2.0210754}, {60, 2.0002978},
                              {120, 1.9799304}, {1000, 1.9623391}})
    EXPECT_NEAR(student_t975(dof), t, 1e-4) << "dof " << dof;
  // toward the normal quantile 1.959964: + (z^3 + z) / (4 dof) = 2.4e-5 at 1e5 dof
  EXPECT_NEAR(student_t975(100000), 1.959988, 2e-6);
}

TEST(StudentT, DecreasesWithDegreesOfFreedom) {
  EXPECT_TRUE(std::isinf(student_t975(0)));
  for (std::size_t dof = 1; dof < 200; ++dof) EXPECT_GT(student_t975(dof), student_t975(dof + 1)) << "dof " << dof;
}
