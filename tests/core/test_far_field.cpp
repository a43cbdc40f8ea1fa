// The far-field rule (far_field.hpp): window, wake by force, by a neighbour's speed or by the push front, membership
// at an update.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "brash/core/far_field.hpp"

using namespace brash::core;

namespace {
// stern at x = 1, bow at x = 3, active 0.5 m behind and 0.25 m ahead: x in [0.5, 3.25]
const FarFieldWindow kWindow = far_field_window(1.0, 3.0, 0.5, 0.25);
const WakeRule kWake{0.02, 0.005};
const Vec3 kRest = Vec3::Zero(), kSlow(0.003, 0.0, -0.0039), kFast(0.003, 0.0, 0.0041);  // |v| 0.0049, 0.0051
}  // namespace

TEST(FarFieldWindow, ZonesAlongTheChannel) {
  EXPECT_EQ(kWindow.lo_x_m, 0.5);
  EXPECT_EQ(kWindow.hi_x_m, 3.25);
  EXPECT_EQ(far_field_zone(kWindow, 3.25, 0.0), FarFieldZone::Inside);  // the edges are inside
  EXPECT_EQ(far_field_zone(kWindow, 0.5, 0.0), FarFieldZone::Inside);
  EXPECT_EQ(far_field_zone(kWindow, 3.26, 0.0), FarFieldZone::Ahead);
  EXPECT_EQ(far_field_zone(kWindow, 0.49, 0.0), FarFieldZone::Behind);
  EXPECT_EQ(far_field_zone(kWindow, 2.0, 1e6), FarFieldZone::Inside);  // no bound across by default
}

TEST(FarFieldWindow, BesideTheHullWhenBoundedAcross) {
  FarFieldWindow w = kWindow;
  w.centre_y_m = 0.1;
  w.half_width_m = 0.3;
  EXPECT_EQ(far_field_zone(w, 2.0, 0.35), FarFieldZone::Inside);
  EXPECT_EQ(far_field_zone(w, 2.0, -0.21), FarFieldZone::Beside);
  EXPECT_EQ(far_field_zone(w, 4.0, -0.21), FarFieldZone::Ahead);  // along x first
}

TEST(WakeRule, WakesOnHorizontalForceAboveTheThreshold) {
  EXPECT_FALSE(wakes(kWake, 0.012, 0.0159));  // |F_h| 0.01993
  EXPECT_TRUE(wakes(kWake, 0.012, 0.0161));    // |F_h| 0.02008
  EXPECT_FALSE(wakes(WakeRule{0.5, 0.0}, 0.5, 0.0));  // at the threshold: not above
  EXPECT_TRUE(wakes(kWake, -0.03, 0.0));
  EXPECT_FALSE(wakes(WakeRule{}, 100.0, 100.0));  // rule off: the window alone
}

TEST(WakeRule, ForceFromTheCasesWeightFraction) {
  // 1e-3 of the weight of a 0.02 m sphere of 900 kg/m^3 under 9.81 m/s^2: 1e-3 * 900 * pi/6 * 8e-6 * 9.81
  const double expected = 1e-3 * 900 * std::numbers::pi / 6 * 8e-6 * 9.81;
  EXPECT_NEAR(wake_force_N(1e-3, 0.02, 900, 9.81), expected, 1e-15 * expected);
  EXPECT_NEAR(wake_force_N(1e-3, 0.02, 900, 9.81), 3.6983e-5, 1e-9);
  EXPECT_EQ(wake_force_N(0.0, 0.02, 900, 9.81), 0.0);
}

TEST(FarFieldMembership, WindowAloneIdlesEverythingOutside) {
  const WakeRule off;
  for (auto zone : {FarFieldZone::Ahead, FarFieldZone::Behind, FarFieldZone::Beside})
    for (bool was_idle : {false, true}) {
      EXPECT_TRUE(idle_after_update(off, zone, was_idle, false, kFast));
      EXPECT_TRUE(idle_after_update(off, zone, was_idle, true, kFast));
    }
  EXPECT_FALSE(idle_after_update(off, FarFieldZone::Inside, true, false, kRest));
}

TEST(FarFieldMembership, InsideIsAlwaysActive) {
  for (bool was_idle : {false, true})
    for (bool first : {false, true})
      EXPECT_FALSE(idle_after_update(kWake, FarFieldZone::Inside, was_idle, first, kRest));
}

TEST(FarFieldMembership, AheadKeepsItsStateAfterTheFirstUpdate) {
  // pushed once: stays active, however slow
  EXPECT_FALSE(idle_after_update(kWake, FarFieldZone::Ahead, false, false, kRest));
  EXPECT_TRUE(idle_after_update(kWake, FarFieldZone::Ahead, true, false, kFast));
  EXPECT_TRUE(idle_after_update(kWake, FarFieldZone::Ahead, false, true, kSlow));  // first update: by speed
  EXPECT_FALSE(idle_after_update(kWake, FarFieldZone::Ahead, true, true, kFast));
}

// By push front the bed ahead of the window is held out from the first update on, moving or not (as the
// moving window holds it); afterwards, as by force, a piece ahead keeps its state; behind and beside, by
// speed.
TEST(FarFieldMembership, ByPushFrontTheBedAheadIsIdleFromTheFirstUpdate) {
  const WakeRule rule{0.02, 0.005, brash::WakeBy::PushFront, 0.005};
  EXPECT_TRUE(idle_after_update(rule, FarFieldZone::Ahead, false, true, kFast));
  EXPECT_TRUE(idle_after_update(rule, FarFieldZone::Ahead, false, true, kSlow));
  EXPECT_FALSE(idle_after_update(rule, FarFieldZone::Ahead, false, false, kRest));
  EXPECT_TRUE(idle_after_update(rule, FarFieldZone::Ahead, true, false, kFast));
  EXPECT_FALSE(idle_after_update(rule, FarFieldZone::Beside, false, true, kFast));
  EXPECT_FALSE(idle_after_update(rule, FarFieldZone::Behind, false, true, kFast));
  EXPECT_FALSE(idle_after_update(rule, FarFieldZone::Inside, true, true, kRest));
}

TEST(FarFieldMembership, BehindAndBesideIdleOnceSlow) {
  for (auto zone : {FarFieldZone::Behind, FarFieldZone::Beside})
    for (bool was_idle : {false, true}) {
      EXPECT_TRUE(idle_after_update(kWake, zone, was_idle, false, kSlow));
      EXPECT_FALSE(idle_after_update(kWake, zone, was_idle, false, kFast));
    }
  // at the threshold speed a piece counts as slow
  const Vec3 at_threshold(0.0, -0.25, 0.0);
  EXPECT_TRUE(idle_after_update(WakeRule{0.5, 0.25}, FarFieldZone::Behind, false, false, at_threshold));
}

TEST(WakeRule, ByNeighbourSpeedWakesNextToAFastPieceOnly) {
  const WakeRule by_neighbour{0.0, 0.005, brash::WakeBy::NeighbourSpeed};
  EXPECT_TRUE(by_neighbour.enabled());
  EXPECT_FALSE(wakes_by_neighbour(by_neighbour, kRest));  // a resting (or idle) neighbour: stays idle
  EXPECT_FALSE(wakes_by_neighbour(by_neighbour, kSlow));
  EXPECT_TRUE(wakes_by_neighbour(by_neighbour, kFast));
  EXPECT_FALSE(wakes_by_neighbour(by_neighbour, Vec3(0.0, 0.0, -0.005)));  // at the threshold: not above
  // each rule answers only its own test
  EXPECT_FALSE(wakes(by_neighbour, 100.0, 100.0));
  EXPECT_FALSE(wakes_by_neighbour(kWake, kFast * 1000));
  // off: speed 0 (the window alone), whatever the neighbour does
  const WakeRule off{0.02, 0.0, brash::WakeBy::NeighbourSpeed};
  EXPECT_FALSE(off.enabled());
  EXPECT_FALSE(wakes_by_neighbour(off, kFast));
  EXPECT_TRUE(idle_after_update(off, FarFieldZone::Ahead, false, false, kFast));
}

TEST(WakeRule, ByNeighbourSpeedKeepsTheMembershipRule) {
  const WakeRule by_neighbour{0.0, 0.005, brash::WakeBy::NeighbourSpeed};
  EXPECT_FALSE(idle_after_update(by_neighbour, FarFieldZone::Ahead, false, false, kRest));  // woken stays
  EXPECT_TRUE(idle_after_update(by_neighbour, FarFieldZone::Ahead, false, true, kSlow));
  EXPECT_TRUE(idle_after_update(by_neighbour, FarFieldZone::Behind, false, false, kSlow));
  EXPECT_FALSE(idle_after_update(by_neighbour, FarFieldZone::Behind, true, false, kFast));
}

TEST(WakeRule, ByPushFrontTheFrontFollowsThePushAndBesideAndBehindWakeByForce) {
  const WakeRule rule{0.02, 0.005, brash::WakeBy::PushFront, 0.005};
  EXPECT_TRUE(rule.enabled());
  EXPECT_TRUE(rule.front_follows_push());
  EXPECT_TRUE(rule.reads_force());
  EXPECT_FALSE(rule.reads_neighbour_speed());
  // ahead of the front no force wakes; beside the hull and behind the stern the force rule's threshold
  EXPECT_FALSE(wakes(rule, 1.0, 1.0, FarFieldZone::Ahead));
  EXPECT_TRUE(wakes(rule, 0.0, 0.021, FarFieldZone::Beside));
  EXPECT_FALSE(wakes(rule, 0.0, 0.019, FarFieldZone::Beside));
  EXPECT_TRUE(wakes(rule, 0.021, 0.0, FarFieldZone::Behind));
  EXPECT_TRUE(wakes(kWake, 0.021, 0.0, FarFieldZone::Ahead));  // the force rule wakes everywhere
  // the front: ahead of the bow and of the foremost moving piece, never receding
  const double none = -std::numeric_limits<double>::infinity();
  EXPECT_DOUBLE_EQ(push_front_x(3.0, none, none, 0.25), 3.25);
  EXPECT_DOUBLE_EQ(push_front_x(3.0, 3.5, 3.25, 0.25), 3.75);
  EXPECT_DOUBLE_EQ(push_front_x(3.1, 2.0, 3.75, 0.25), 3.75);
  // without a front speed there is no rule (the window alone)
  EXPECT_FALSE((WakeRule{0.02, 0.005, brash::WakeBy::PushFront}.enabled()));
  EXPECT_FALSE((WakeRule{0.02, 0.005, brash::WakeBy::PushFront}.front_follows_push()));
  // membership: ahead keeps its state, behind idles once slow
  EXPECT_TRUE(idle_after_update(rule, FarFieldZone::Ahead, true, false, kFast));
  EXPECT_TRUE(idle_after_update(rule, FarFieldZone::Behind, false, false, kSlow));
}

TEST(WakeRule, TouchingIsCentreDistanceBelowTheSumOfTheRadii) {
  EXPECT_TRUE(touching(0.0199, 0.0, 0.0, 0.01, 0.01));
  EXPECT_FALSE(touching(0.02, 0.0, 0.0, 0.01, 0.01));
  EXPECT_TRUE(touching(0.012, -0.012, 0.008, 0.01, 0.0088));   // |d| 0.018762 < 0.0188
  EXPECT_FALSE(touching(0.012, -0.012, 0.008, 0.01, 0.0087));  // |d| 0.018762 > 0.0187
}

TEST(MovingWindow, FrontLeadsTheBowAndThePushAndNeverRecedes) {
  constexpr double kNone = -std::numeric_limits<double>::infinity();
  // stern 1, bow 3, 2 m kept behind the stern, the front 1.5 m ahead
  MovingWindow w = moving_window(1.0, 3.0, kNone, kNone, 2.0, 1.5);
  EXPECT_EQ(w.remove_below_x_m, -1.0);
  EXPECT_EQ(w.insert_below_x_m, 4.5);
  w = moving_window(1.0, 3.0, 3.7, kNone, 2.0, 1.5);  // the push 0.7 m ahead of the bow
  EXPECT_EQ(w.insert_below_x_m, 5.2);
  w = moving_window(1.0, 3.0, 2.0, 5.2, 2.0, 1.5);  // the pushed ice has stopped: the front stays
  EXPECT_EQ(w.insert_below_x_m, 5.2);
}
