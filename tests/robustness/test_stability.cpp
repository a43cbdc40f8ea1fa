// Stability of the core integrator (stability_core.hpp): the implicit treatment is stable for every Ca
// and contains the paper's settings with a wide time-step margin; the explicit treatment fails where the
// theory says (m_a / m = Ca rho_w s / rho_i ~ 1), and that failure is never silent (detected).
#include <gtest/gtest.h>

#include "stability_core.hpp"

using namespace brash;
using stability::Cell;
using stability::run_cell;

TEST(StabilityCore, PaperSettingsStableWithMargin) {
  for (double k : {0.25, 1.0, 4.0}) {
    Cell c{.dt_s = 5e-5, .ca = -1, .table = core::CaTable::table1(), .treatment = core::Treatment::Implicit,
           .density_ratio = 0.9, .impact_m_s = k * 0.482, .duration_s = 1.0};
    EXPECT_TRUE(run_cell(c).stable) << k;
    c.dt_s = 5e-3;  // 100 x the paper's step
    EXPECT_TRUE(run_cell(c).stable) << k;
  }
}

TEST(StabilityCore, ImplicitStableForEveryCa) {
  for (double ca : {0.0, 0.5, 2.0, 10.0})
    for (double ratio : {0.5, 0.9, 0.99}) {
      Cell c{.dt_s = 5e-5, .ca = ca, .treatment = core::Treatment::Implicit, .density_ratio = ratio,
             .impact_m_s = 1.928, .duration_s = 0.5};
      const auto r = run_cell(c);
      EXPECT_TRUE(r.stable) << "Ca " << ca << " ratio " << ratio << ": " << r.cause;
    }
}

TEST(StabilityCore, ExplicitFailsAboveTheoryAndIsDetected) {
  Cell c{.dt_s = 5e-5, .ca = 0.5, .treatment = core::Treatment::Explicit, .density_ratio = 0.9, .impact_m_s = 0.482,
         .duration_s = 0.5};
  EXPECT_TRUE(run_cell(c).stable);
  c.ca = 2.0;
  const auto r = run_cell(c);
  EXPECT_FALSE(r.stable);
  EXPECT_FALSE(r.cause.empty());
  EXPECT_GT(r.max_added_mass_ratio, 1.0);
}

TEST(StabilityCore, ExplicitBoundaryMatchesTheory) {
  for (double ratio : {0.5, 0.9}) {
    Cell c{.dt_s = 5e-5, .density_ratio = ratio, .impact_m_s = 0.482, .duration_s = 0.5};
    const double ca_crit = stability::explicit_critical_ca(c, 0.0, 10.0, 1e-2);
    c.ca = ca_crit, c.treatment = core::Treatment::Explicit;
    const auto r = run_cell(c);
    const double theory = ratio / r.max_submerged_fraction;
    EXPECT_NEAR(ca_crit / theory, 1.0, 0.1) << "ratio " << ratio << " Ca_crit " << ca_crit << " theory " << theory;
  }
}
