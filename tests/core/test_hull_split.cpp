// The hull force split of one contact (brash/core/hull_split.hpp): region by the contact's x, mechanism along the
// contact normal; each set adds up to the contact force's x.
#include <gtest/gtest.h>

#include <cmath>

#include "brash/core/hull_split.hpp"

using namespace brash::core;

namespace {
const HullRegions kRegions{2.0, 5.0};  // parallel mid-body from x = 2 m to x = 5 m
}

TEST(HullSplit, RegionByTheContactPointAgainstTheParallelMidBody) {
  EXPECT_EQ(hull_region(kRegions, 5.01), kSplitBow);
  EXPECT_EQ(hull_region(kRegions, 5.0), kSplitMid);
  EXPECT_EQ(hull_region(kRegions, 3.0), kSplitMid);
  EXPECT_EQ(hull_region(kRegions, 2.0), kSplitMid);
  EXPECT_EQ(hull_region(kRegions, 1.99), kSplitStern);
  const double f[3] = {-3.0, 1.0, 2.0}, n[3] = {1, 0, 0};
  HullSplit s{};
  add_contact_x(s, kRegions, 6.0, f, n);
  add_contact_x(s, kRegions, 0.5, f, n);
  add_contact_x(s, kRegions, 0.5, f, n);
  EXPECT_EQ(s[kSplitBow], -3.0);
  EXPECT_EQ(s[kSplitMid], 0.0);
  EXPECT_EQ(s[kSplitStern], -6.0);
}

// A contact on a face inclined by 30 degrees (normal (-sin, 0, cos), any length) whose force is a push of 10 N
// along the normal plus a friction of 3 N along the face: the normal part's x is the push's, the tangential part's
// the friction's, and they add up to the force's x.
TEST(HullSplit, MechanismAlongTheContactNormal) {
  const double th = M_PI / 6, push = 10, friction = 3;
  const double unit_n[3] = {-std::sin(th), 0, std::cos(th)}, along[3] = {std::cos(th), 0, std::sin(th)};
  const double f[3] = {-push * unit_n[0] + friction * along[0], 0, -push * unit_n[2] + friction * along[2]};
  const double n[3] = {2.5 * unit_n[0], 2.5 * unit_n[1], 2.5 * unit_n[2]};  // not a unit vector
  HullSplit s{};
  add_contact_x(s, kRegions, 3.0, f, n);
  EXPECT_NEAR(s[kSplitNormal], push * std::sin(th), 1e-12);
  EXPECT_NEAR(s[kSplitTangential], friction * std::cos(th), 1e-12);
  EXPECT_NEAR(s[kSplitNormal] + s[kSplitTangential], f[0], 1e-12);
  EXPECT_EQ(s[kSplitMid], f[0]);
  // the normal's sign does not matter
  const double minus_n[3] = {-n[0], -n[1], -n[2]};
  HullSplit t{};
  add_contact_x(t, kRegions, 3.0, f, minus_n);
  EXPECT_NEAR(t[kSplitNormal], s[kSplitNormal], 1e-12);
}
