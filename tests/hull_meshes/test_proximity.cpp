// brash::hull::Proximity (the hull penetration guard's query): exact values on the box barge and the wedge
// against closed forms, inside/outside (also on projected edges and vertices of the triangulation), far
// points, random points against a brute-force/analytic oracle, and the JBC.
#include <gtest/gtest.h>

#include <algorithm>
#include <brash/hull/jbc.hpp>
#include <brash/hull/mesh.hpp>
#include <brash/hull/proximity.hpp>
#include <cmath>
#include <numbers>
#include <random>

#include "simple_hulls.hpp"

namespace brash::hull {
namespace {

using Eigen::Vector3d;

constexpr double kTol = 1e-12;

// Box barge L x B x D: x in [0, L], y in [-B/2, B/2], z in [0, D].
constexpr double kL = 2.0, kB = 1.0, kD = 0.5;

// Signed distance to the box (negative inside).
double box_signed_distance(const Vector3d& p) {
  const Vector3d lo(0, -kB / 2, 0), hi(kL, kB / 2, kD);
  const Vector3d out = (lo - p).cwiseMax(p - hi).cwiseMax(0.0);
  if (out.squaredNorm() > 0) return out.norm();
  return -std::min(
      {p.x() - lo.x(), hi.x() - p.x(), p.y() - lo.y(), hi.y() - p.y(), p.z() - lo.z(), hi.z() - p.z()});
}

double expected_penetration(double signed_d, double r) {
  if (signed_d <= 0) return r - signed_d;
  return signed_d < r ? r - signed_d : 0.0;
}

TEST(ClosestPointOnTriangle, RegionsOfTheTriangle) {
  const Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_TRUE(closest_point_on_triangle({0.2, 0.3, 2}, a, b, c).isApprox(Vector3d(0.2, 0.3, 0)));  // face
  EXPECT_TRUE(closest_point_on_triangle({-1, -1, 1}, a, b, c).isApprox(a));                        // vertex a
  EXPECT_TRUE(closest_point_on_triangle({3, -1, 0}, a, b, c).isApprox(b));                         // vertex b
  EXPECT_TRUE(closest_point_on_triangle({0.5, -2, 0}, a, b, c).isApprox(Vector3d(0.5, 0, 0)));     // edge ab
  EXPECT_TRUE(closest_point_on_triangle({1, 1, 0.5}, a, b, c).isApprox(Vector3d(0.5, 0.5, 0)));    // edge bc
  EXPECT_TRUE(closest_point_on_triangle({-3, 0.25, 0}, a, b, c).isApprox(Vector3d(0, 0.25, 0)));   // edge ca
  // Degenerate (collinear) triangle: closest point of the segment.
  EXPECT_TRUE(closest_point_on_triangle({0.5, 1, 0}, a, b, Vector3d(2, 0, 0)).isApprox(Vector3d(0.5, 0, 0)));
}

TEST(ClosestPointOnTriangle, NeverFartherThanDenseSampling) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int n = 0; n < 200; ++n) {
    const Vector3d a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng)), c(u(rng), u(rng), u(rng));
    const Vector3d p(2 * u(rng), 2 * u(rng), 2 * u(rng));
    const double d = (closest_point_on_triangle(p, a, b, c) - p).norm();
    double sampled = 1e300;
    const int m = 200;
    for (int i = 0; i <= m; ++i)
      for (int j = 0; i + j <= m; ++j) {
        const double s = double(i) / m, t = double(j) / m;
        sampled = std::min(sampled, (a + s * (b - a) + t * (c - a) - p).norm());
      }
    EXPECT_LE(d, sampled + 1e-12);
    EXPECT_GE(d, sampled - 0.02 * ((b - a).norm() + (c - a).norm()));
  }
}

TEST(Proximity, BoxBargeExactValues) {
  const Proximity px(test::box(kL, kB, kD));
  EXPECT_TRUE(px.closed());
  // Centre: inside (its xy lies on the diagonal of the top and bottom triangulation: counted once),
  // 0.25 m from the top and bottom.
  EXPECT_TRUE(px.inside({1, 0, 0.25}));
  EXPECT_NEAR(px.distance({1, 0, 0.25}), 0.25, kTol);
  EXPECT_NEAR(px.penetration({1, 0, 0.25}, 0.1), 0.35, kTol);
  // Just below the deck: inside, 0.05 from it.
  EXPECT_NEAR(px.penetration({1, 0.2, 0.45}, 0.02), 0.07, kTol);
  // Outside the side at 0.1 m: overlaps a sphere of radius 0.15 by 0.05; touches r = 0.1; misses r = 0.05.
  EXPECT_FALSE(px.inside({1, 0.6, 0.25}));
  EXPECT_NEAR(px.penetration({1, 0.6, 0.25}, 0.15), 0.05, kTol);
  EXPECT_NEAR(px.penetration({1, 0.6, 0.25}, 0.1), 0.0, kTol);
  EXPECT_EQ(px.penetration({1, 0.6, 0.25}, 0.05), 0.0);
  // Off the bow-side vertical edge: distance to the edge sqrt(0.1^2 + 0.1^2).
  EXPECT_NEAR(px.penetration({2.1, 0.6, 0.25}, 0.2), 0.2 - std::sqrt(0.02), kTol);
  // Below the keel and above the deck.
  EXPECT_NEAR(px.penetration({0.5, -0.3, -0.01}, 0.03), 0.02, kTol);
  EXPECT_NEAR(px.penetration({0.5, -0.3, 0.52}, 0.03), 0.01, kTol);
  // Inside, right on a projected corner vertex column (x = 0 is the stern wall: distance 0).
  EXPECT_NEAR(px.penetration({0, 0.5, 0.25}, 0.01), 0.01, kTol);
  // Far points.
  EXPECT_FALSE(px.inside({10, 10, 10}));
  EXPECT_EQ(px.penetration({10, 10, 10}, 0.5), 0.0);
  EXPECT_EQ(px.penetration({1, 0, -3}, 0.5), 0.0);
  EXPECT_EQ(px.penetration({1, 0, 3}, 0.5), 0.0);  // above, inside the xy footprint
  EXPECT_TRUE(std::isinf(px.distance({10, 10, 10}, 1.0)));
  EXPECT_NEAR(px.distance({1, 0, 3}), 2.5, kTol);
}

TEST(Proximity, BoxBargeRandomPointsMatchTheClosedForm) {
  const Proximity px(test::box(kL, kB, kD));
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> ux(-0.3, kL + 0.3), uy(-kB / 2 - 0.3, kB / 2 + 0.3),
      uz(-0.3, kD + 0.3), ur(0.005, 0.2);
  int inside = 0;
  for (int n = 0; n < 20000; ++n) {
    // Every 4th point on a grid of exact binary fractions: on faces, edges and diagonals of the
    // triangulation.
    Vector3d p(ux(rng), uy(rng), uz(rng));
    if (n % 4 == 0) p = (p * 8).array().round().matrix() / 8;
    const double r = ur(rng), sd = box_signed_distance(p);
    if (sd != 0) {
      EXPECT_EQ(px.inside(p), sd < 0) << p.transpose();
    }
    inside += sd < 0;
    EXPECT_NEAR(px.penetration(p, r), expected_penetration(sd, r), 1e-12) << p.transpose() << " r " << r;
  }
  EXPECT_GT(inside, 3000);
}

TEST(Proximity, WedgeMatchesHalfSpacesAndBruteForce) {
  // The wedge is a convex polyhedron: inside = behind every face plane; distance inside = nearest plane;
  // distance outside = brute force over all triangles.
  const test::Wedge w{2.0, 1.0, 0.4, 0.6, 30.0, 60.0};
  const Mesh m = w.mesh();
  ASSERT_TRUE(check_mesh(m).ok());
  const Proximity px(m);
  auto oracle = [&](const Vector3d& p) {
    double inner = 1e300, brute = 1e300;
    bool in = true;
    for (const auto& f : m.faces) {
      const Vector3d &a = m.vertices[f[0]], &b = m.vertices[f[1]], &c = m.vertices[f[2]];
      const Vector3d n = (b - a).cross(c - a).normalized();
      const double s = n.dot(p - a);
      if (s >= 0) in = false;
      inner = std::min(inner, -s);
      brute = std::min(brute, (closest_point_on_triangle(p, a, b, c) - p).norm());
    }
    return in ? -inner : brute;
  };
  // Exact values: mid parallel body on the centreline at half draft (0.2 from keel, 0.5 from the sides,
  // 0.4 from the deck) and off the stem at the waterline.
  EXPECT_TRUE(px.inside({1.0, 0, 0.2}));
  EXPECT_NEAR(px.penetration({1.0, 0, 0.2}, 0.01), 0.21, kTol);
  const double xs = w.x_stem(0.4);
  EXPECT_FALSE(px.inside({xs + 0.05, 0, 0.4}));
  // Ahead of the stem edge (raked at phi = 60 deg): distance 0.05 sin(phi).
  EXPECT_NEAR(px.penetration({xs + 0.05, 0, 0.4}, 0.1), 0.1 - 0.05 * std::sin(std::numbers::pi / 3), 1e-12);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> ux(-0.2, xs + 0.6), uy(-0.7, 0.7), uz(-0.2, 0.8), ur(0.01, 0.15);
  for (int n = 0; n < 5000; ++n) {
    const Vector3d p(ux(rng), uy(rng), uz(rng));
    const double r = ur(rng), sd = oracle(p);
    EXPECT_EQ(px.inside(p), sd < 0) << p.transpose();
    EXPECT_NEAR(px.penetration(p, r), expected_penetration(sd, r), 1e-12) << p.transpose();
  }
}

// nearest(): the triangle it names holds the nearest point (brute force over every face), on the box's faces,
// edges and corners; nothing within a short reach gives no triangle.
TEST(Proximity, NearestNamesTheTriangleOfTheNearestPoint) {
  const Mesh m = test::box(kL, kB, kD);
  const Proximity prox(m);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> ux(-0.5, kL + 0.5), uy(-1, 1), uz(-0.5, kD + 0.5);
  for (int n = 0; n < 500; ++n) {
    const Vector3d p(ux(rng), uy(rng), uz(rng));
    double brute = 1e300;
    for (const auto& f : m.faces)
      brute = std::min(brute, (closest_point_on_triangle(p, m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]) - p).norm());
    const auto near = prox.nearest(p);
    ASSERT_GE(near.triangle, 0);
    const auto& f = m.faces[static_cast<std::size_t>(near.triangle)];
    EXPECT_NEAR(near.distance_m, brute, kTol);
    EXPECT_NEAR((closest_point_on_triangle(p, m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]) - p).norm(), brute,
                kTol);
    EXPECT_NEAR((near.point - p).norm(), brute, kTol);
    EXPECT_EQ(prox.distance(p), near.distance_m);
  }
  // the bottom's centre seen from below: a bottom triangle (outward normal -z)
  const auto below = prox.nearest({0.7, 0.1, -0.2});
  const auto& f = m.faces[static_cast<std::size_t>(below.triangle)];
  const Vector3d nrm = (m.vertices[f[1]] - m.vertices[f[0]]).cross(m.vertices[f[2]] - m.vertices[f[0]]);
  EXPECT_LT(nrm.normalized().z(), -0.999);
  EXPECT_NEAR(below.distance_m, 0.2, kTol);
  const auto far = prox.nearest({0.7, 0.1, -0.2}, 0.1);
  EXPECT_EQ(far.triangle, -1);
  EXPECT_TRUE(std::isinf(far.distance_m));
}

TEST(Proximity, OpenMeshHasNoInside) {
  Mesh band = clip_band(test::box(kL, kB, kD), 0.2, 0.3);  // the four sides only: open
  const Proximity px(band);
  EXPECT_FALSE(px.closed());
  EXPECT_FALSE(px.inside({1, 0, 0.25}));
  EXPECT_NEAR(px.penetration({1, 0.45, 0.25}, 0.1), 0.05, kTol);  // outside-style overlap only
}

TEST(Proximity, RejectsAnEmptyMesh) {
  EXPECT_THROW(Proximity(Mesh{}), std::runtime_error);
}

TEST(Proximity, JbcCentrelineMidshipAtHalfDraftIsInside) {
  const Mesh jbc = make_jbc(load_jbc_data());
  const Proximity px(jbc);
  ASSERT_TRUE(px.closed());
  const double T = 0.4125;
  EXPECT_TRUE(px.inside({3.5, 0, T / 2}));
  // Flat-bottomed, wall-sided midship section: nearest is the keel (T / 2 below) at B / 2 = 0.5625 abeam.
  EXPECT_NEAR(px.distance({3.5, 0, T / 2}), T / 2, 1e-6);
  EXPECT_NEAR(px.penetration({3.5, 0, T / 2}, 0.0175), 0.0175 + T / 2, 1e-6);
  // Alongside at the waterline, 1 cm off the side: a 3.5 cm sphere overlaps by 1.5 cm; below the keel:
  // nothing.
  EXPECT_FALSE(px.inside({3.5, 0.5625 + 0.01, T}));
  EXPECT_NEAR(px.penetration({3.5, 0.5625 + 0.01, T}, 0.0175), 0.0075, 1e-6);
  EXPECT_EQ(px.penetration({3.5, 0, -0.05}, 0.0175), 0.0);
  // Ahead of the bow and behind the transom: outside, far.
  EXPECT_EQ(px.penetration({8.0, 0, T}, 0.0175), 0.0);
  EXPECT_EQ(px.penetration({-1.0, 0, T}, 0.0175), 0.0);
  // A sweep along the centreline at half draft: inside from just aft of the stern to just behind the stem.
  int in = 0;
  for (int i = 0; i < 600; ++i) in += px.inside({0.5 + 0.01 * i, 0, T / 2});
  EXPECT_EQ(in, 600);
}

}  // namespace
}  // namespace brash::hull
