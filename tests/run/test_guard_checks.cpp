// brash::guard (run/include/brash/run/guard.hpp): the per-piece checks every engine calls, their cause texts
// (the engines' stop messages are built from them), the case's limits and the contact time-step check.
#include <gtest/gtest.h>

#include <algorithm>
#include <brash/run/guard.hpp>
#include <cmath>
#include <limits>

#include "simple_hulls.hpp"

namespace {

using brash::guard::check_piece;
using brash::guard::Limits;
using brash::guard::Piece;
using Eigen::Vector3d;

Piece piece(Vector3d x, Vector3d v = Vector3d::Zero()) {
  Piece p;
  p.x_m = x;
  p.v_m_s = v;
  p.radius_m = 0.01;
  p.mass_kg = 900 * 4.0 / 3 * M_PI * 1e-6;
  return p;
}

TEST(GuardChecks, NonFiniteComesFirst) {
  Limits l;
  l.box = brash::guard::Box{-1, 1, -1, 1, -1, 1};
  Piece p = piece({5, 0, 0});
  p.v_m_s.y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(check_piece(p, l).value(), "non-finite velocity: vy = nan");
  p = piece({0, 0, 0});
  p.force_N = Vector3d(0, 0, std::numeric_limits<double>::infinity());
  EXPECT_EQ(check_piece(p, l).value(), "non-finite force: fz = inf");
  p = piece({0, 0, 0});
  p.omega_rad_s.x() = -std::numeric_limits<double>::infinity();
  EXPECT_EQ(check_piece(p, l).value(), "non-finite angular velocity: wx = -inf");
  p = piece({std::numeric_limits<double>::quiet_NaN(), 0, 0});
  EXPECT_EQ(check_piece(p, l).value(), "non-finite position: x = nan");
}

TEST(GuardChecks, BoxZmaxKineticEnergy) {
  Limits l;
  l.box = brash::guard::Box{-1, 1, -1, 1, -1, 1};
  l.z_max_m = 0.5;
  l.ke_max_J = 1e-3;
  EXPECT_FALSE(check_piece(piece({0, 0, 0}), l));
  EXPECT_EQ(check_piece(piece({0, -1.5, 0}), l).value(), "left the box: y = -1.5 < ylo = -1 (m)");
  EXPECT_EQ(check_piece(piece({2, 0, 0}), l).value(), "left the box: x = 2 > xhi = 1 (m)");
  EXPECT_EQ(check_piece(piece({0, 0, 0.75}), l).value(),
            "above zmax: z = 0.75 > 0.5 m (jumped out of the water)");
  // 3.77e-3 kg at 1 m/s: 1.885e-3 J.
  EXPECT_EQ(check_piece(piece({0, 0, 0}, {0, 1, 0}), l).value(),
            "runaway kinetic energy: 0.001885 J > ke_max = 0.001 J (|v| = 1 m/s)");
  // Spin counts too: 1/5 m r^2 w^2 = 1/5 3.77e-3 1e-4 (100)^2 = 7.5e-4 J ... plus translation at 0.5 m/s.
  Piece p = piece({0, 0, 0}, {0.5, 0, 0});
  p.omega_rad_s = Vector3d(0, 0, 100);
  EXPECT_NE(check_piece(p, l).value().find("runaway kinetic energy: 0.001225 J"), std::string::npos);
}

TEST(GuardChecks, HullPenetrationInTheMovingHullFrame) {
  // Box barge 2 x 1 x 0.5, its frame origin now at (10, 0, -0.25): the hull spans x 10..12, z -0.25..0.25.
  const brash::hull::Proximity prox(brash::hull::test::box(2.0, 1.0, 0.5));
  brash::guard::HullNow hull{&prox, Vector3d(10, 0, -0.25)};
  Limits l;
  l.max_hull_penetration_d = 0.5;
  EXPECT_FALSE(check_piece(piece({9.0, 0, 0}), l, &hull));         // far astern
  EXPECT_FALSE(check_piece(piece({10.5, 0.505, 0}), l, &hull));    // touching the side: 0.005 m = 25 % of d
  EXPECT_FALSE(check_piece(piece({10.5, 0, 0}), l, nullptr));      // no hull given: no check
  const auto c = check_piece(piece({10.5, 0.45, 0.0}), l, &hull);  // centre 5 cm inside
  ASSERT_TRUE(c);
  EXPECT_EQ(*c,
            "hull penetration: 0.06 m = 300 % of its diameter 0.02 m > max_hull_penetration_d 0.5 (centre "
            "inside the "
            "hull, 0.05 m from its surface; hull frame x = 0.5000, y = 0.4500, z = 0.2500 m)");
  l.max_hull_penetration_d = 0.2;  // 0.004 m: a 5 mm overlap from outside is too much
  const auto o = check_piece(piece({10.5, 0.505, 0}), l, &hull);
  ASSERT_TRUE(o);
  EXPECT_NE(o->find("hull penetration: 0.005 m = 25 % of its diameter 0.02 m > max_hull_penetration_d 0.2 "
                    "(centre outside the hull; hull frame"),
            std::string::npos)
      << *o;
}

TEST(GuardChecks, TimestepAgainstRayleighTime) {
  // E = 5 MPa, r = 8.789 mm, rho 900: T_R = 6.45e-4 s.
  EXPECT_NEAR(brash::guard::rayleigh_time_s(0.008789, 900, 5e6, 0.3), 6.45e-4, 1e-6);
  EXPECT_FALSE(brash::guard::check_timestep(5e-5, 0.008789, 900, 5e6, 0.3, 0.3));
  const auto c = brash::guard::check_timestep(1e-3, 0.008789, 900, 5e6, 0.3, 0.3);
  ASSERT_TRUE(c);
  EXPECT_EQ(
      c->rfind("timestep 0.001 s is too large for the contact stiffness: 155 % of the Rayleigh time", 0), 0u)
      << *c;
}

TEST(GuardChecks, StopMessageNamesStepTimePieceCause) {
  EXPECT_EQ(brash::guard::stop_message(1200, 0.12, 17, "left the box: x = 2.31 > xhi = 2.2 (m)"),
            "guard: step 1200 (t = 0.12 s): piece 17: left the box: x = 2.31 > xhi = 2.2 (m)");
}

TEST(GuardChecks, LimitsOfTheQuickCase) {
  const brash::Case c = brash::load_case(std::string(BRASH_SOURCE_DIR) + "/cases/jbc_narrow/case.yaml");
  // JBC extents in its STL frame: x -0.125 .. 7.149, z 0 .. 0.625.
  const auto box = brash::guard::domain_box(c, -0.125, 7.149, 0.0, 0.625, c.run.duration_s);
  const double d = c.ice.diameter_mean_m;
  EXPECT_NEAR(box[0], -7.2 - 0.125 - 10 * d, 1e-12);
  EXPECT_NEAR(box[1], std::max(2.5 + 0.482 * 4, -7.2 + 7.149 + 0.482 * 4) + 10 * d, 1e-12);
  EXPECT_NEAR(box[2], -0.8 - 2 * d, 1e-12);
  EXPECT_NEAR(box[4], std::min(-0.4125, -6 * 0.07) - 2 * d, 1e-12);
  const Limits l = brash::guard::limits_for_case(c, box);
  EXPECT_NEAR((*l.box)[0], box[0] + d / 4, 1e-12);
  EXPECT_NEAR(*l.z_max_m, 5 * 0.07, 1e-12);
  const double dmax = 0.035 + 3 * 0.00175, v = 20 * 0.482;
  EXPECT_NEAR(*l.ke_max_J, 0.5 * 900 * M_PI / 6 * dmax * dmax * dmax * v * v, 1e-9);
  EXPECT_DOUBLE_EQ(*l.max_hull_penetration_d, 0.5);
  brash::Case off = c;
  off.guards.max_hull_penetration_d = 0;
  EXPECT_FALSE(brash::guard::limits_for_case(off, box).max_hull_penetration_d);
}

}  // namespace
