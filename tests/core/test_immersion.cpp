// Immersion geometry against closed forms at s = 0, 0.5, 0.9, 1 and continuity across the surface.
#include <gtest/gtest.h>

#include <numbers>

#include "brash/core/immersion.hpp"
#include "brash/core/reference.hpp"

using namespace brash::core;
constexpr double kPi = std::numbers::pi;
constexpr double r = 0.008789;

TEST(Immersion, AboveWaterIsDry) {
  const auto im = immersion(r, 1.5 * r, 0.0);
  EXPECT_EQ(im.height_m, 0.0);
  EXPECT_EQ(im.volume_m3, 0.0);
  EXPECT_EQ(im.fraction, 0.0);
  EXPECT_EQ(projected_area(r, im, 0.3), 0.0);
}

TEST(Immersion, HalfSubmerged) {
  const auto im = immersion(r, 0.0, 0.0);
  EXPECT_DOUBLE_EQ(im.height_m, r);
  EXPECT_NEAR(im.volume_m3, 2.0 / 3.0 * kPi * r * r * r, 1e-18);
  EXPECT_NEAR(im.fraction, 0.5, 1e-15);
  EXPECT_NEAR(im.waterline_radius_sq_m2, r * r, 1e-18);
  EXPECT_NEAR(projected_area_vertical(r, im), kPi * r * r, 1e-15);
  EXPECT_NEAR(projected_area_horizontal(r, im), 0.5 * kPi * r * r, 1e-15);
}

TEST(Immersion, NinetyPercent) {
  const double h = analytic::height_for_fraction(r, 0.9);
  const auto im = immersion(r, -h + r, 0.0);  // water at 0, bottom at -h
  EXPECT_NEAR(im.height_m, h, 1e-15);
  EXPECT_NEAR(im.fraction, 0.9, 1e-12);
  EXPECT_NEAR(im.volume_m3, kPi * h * h * (3 * r - h) / 3, 1e-18);
  // centre below water: projected along z is the full disc
  EXPECT_NEAR(projected_area_vertical(r, im), kPi * r * r, 1e-15);
  // segment of height h seen from the side = full disc minus the dry segment of height 2r - h
  const double hd = 2 * r - h;
  const double dry = r * r * std::acos((r - hd) / r) - (r - hd) * std::sqrt(hd * (2 * r - hd));
  EXPECT_NEAR(projected_area_horizontal(r, im), kPi * r * r - dry, 1e-15);
}

TEST(Immersion, FullySubmerged) {
  const auto im = immersion(r, -1.01 * r, 0.0);
  EXPECT_EQ(im.height_m, 2 * r);
  EXPECT_NEAR(im.fraction, 1.0, 1e-15);
  EXPECT_NEAR(im.volume_m3, analytic::sphere_volume(r), 1e-18);
  for (double c : {0.0, 0.4, 1.0}) EXPECT_NEAR(projected_area(r, im, c), kPi * r * r, 1e-15);
}

TEST(Immersion, ContinuousAcrossTheSurface) {
  // Step the centre through the water surface; no jump larger than the local slope allows.
  const double dz = 1e-7;
  double prev_v = immersion(r, 1.2 * r, 0).volume_m3;
  double prev_a = projected_area(r, immersion(r, 1.2 * r, 0), 0.6);
  for (double zc = 1.2 * r; zc > -1.2 * r; zc -= dz) {
    const auto im = immersion(r, zc, 0.0);
    const double a = projected_area(r, im, 0.6);
    EXPECT_LE(std::abs(im.volume_m3 - prev_v), kPi * r * r * dz * 1.0001);
    EXPECT_LE(std::abs(a - prev_a), 2 * kPi * r * dz * 1.0001 + 1e-15);
    prev_v = im.volume_m3;
    prev_a = a;
  }
}
