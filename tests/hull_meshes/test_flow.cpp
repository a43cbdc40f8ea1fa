// Half-breadths measured on hull meshes and the thin-ship flow table built from them (flow.hpp).
#include <gtest/gtest.h>

#include <brash/hull/flow.hpp>
#include <brash/hull/jbc.hpp>
#include <vector>

#include "brash/error.hpp"
#include "simple_hulls.hpp"

using namespace brash::hull;
using brash::core::Vec3;

TEST(HullFlowMesh, HalfBreadthsOfABoxAndAWedgeBow) {
  const Mesh b = test::box(2.0, 0.6, 0.5);
  const std::vector<double> x{-0.1, 0.2, 1.0, 1.9, 2.1}, z{0.1, 0.4};
  const auto y = half_breadths(b, x, z);
  ASSERT_EQ(y.size(), 10u);
  for (int j = 0; j < 2; ++j) {
    EXPECT_EQ(y[j * 5 + 0], 0.0);  // ahead of and behind the hull: no section there
    EXPECT_EQ(y[j * 5 + 4], 0.0);
    for (int i = 1; i < 4; ++i) EXPECT_NEAR(y[j * 5 + i], 0.3, 1e-12);
  }
  // wedge bow: y = tan(alpha) (x_stem(z) - x) on the bow, B / 2 on the parallel body
  const test::Wedge w{1.5, 0.6, 0.3, 0.5, 30.0, 90.0};  // vertical stem
  const double xs = w.x_stem(0.2);
  const std::vector<double> xb{1.0, xs - 0.3, xs - 0.1, xs + 0.05};
  const auto yb = half_breadths(w.mesh(), xb, std::vector<double>{0.2});
  EXPECT_NEAR(yb[0], 0.3, 1e-12);
  EXPECT_NEAR(yb[1], w.tan_a() * 0.3, 1e-9);
  EXPECT_NEAR(yb[2], w.tan_a() * 0.1, 1e-9);
  EXPECT_EQ(yb[3], 0.0);
}

TEST(HullFlowMesh, JbcFlowPushesAheadAndAsideAndStreamsBackAlongside) {
  const Mesh jbc = make_jbc(load_jbc_data());  // 7 m model, keel at z = 0, x = 0 at the aft perpendicular
  const double draft = 0.4125, U = 0.482;
  const brash::core::FlowTable t = thin_ship_flow(jbc, draft, U);
  Eigen::Vector3d lo = jbc.vertices[0], hi = lo;
  for (const auto& v : jbc.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  const double bow = hi.x(), half_b = hi.y();
  // Displacement flow of a full hull (C_B 0.86): a fraction of the ship speed, largest at the bow.
  EXPECT_GT(t.max_speed_m_s(), 0.05 * U);
  EXPECT_LT(t.max_speed_m_s(), U);
  const Vec3 ahead = t.at(Vec3(bow + 0.1, 0, -0.01));  // just ahead of the stem, at the water level
  EXPECT_GT(ahead.x(), 0.05 * U) << ahead.transpose();
  EXPECT_NEAR(ahead.z(), 0, 1e-3 * U);  // the rigid lid
  const Vec3 shoulder = t.at(Vec3(bow - 0.5, half_b + 0.05, -0.01));
  EXPECT_GT(shoulder.y(), 0) << shoulder.transpose();  // pushed aside
  const Vec3 midship = t.at(Vec3(0.5 * (lo.x() + bow), half_b + 0.05, -0.01));
  EXPECT_LT(midship.x(), 0) << midship.transpose();  // the water streams aft alongside
  // it fades away from the hull: a breadth off the side it is a fraction of its value at the side
  const Vec3 far = t.at(Vec3(bow - 0.5, half_b + 1.1, -0.01));
  EXPECT_LT(far.norm(), 0.5 * shoulder.norm());
  // the mirror image to starboard
  EXPECT_NEAR(t.at(Vec3(bow - 0.5, -half_b - 0.05, -0.01)).y(), -shoulder.y(), 1e-15);
}

TEST(HullFlowMesh, WaterLevelOutsideTheHullIsRefused) {
  const Mesh b = test::box(2.0, 0.6, 0.5);
  EXPECT_THROW(thin_ship_flow(b, 0.6, 0.5), brash::InputError);   // above the deck
  EXPECT_THROW(thin_ship_flow(b, -0.1, 0.5), brash::InputError);  // below the keel
  EXPECT_THROW(thin_ship_flow(Mesh{}, 0.2, 0.5), brash::InputError);
  // a box has half-breadth steps only at its ends: it still has sources (bow and stern faces)
  EXPECT_GT(thin_ship_flow(b, 0.3, 0.5).max_speed_m_s(), 0);
}
