// Rolling resistance (contact.rolling_friction, Frictions::rolling) in ODE: a sphere rolling on a level wall in
// air decelerates at the closed form's 5/7 mu_r g (docs/physics.md, "Rolling resistance"); without it, as
// before the option existed.
#include <gtest/gtest.h>

#include <vector>

#include "brash/core/reference.hpp"
#include "brash/ode/world.hpp"

using namespace brash::ode;

namespace {
constexpr double kR = 0.008789, kRho = 900, kG = 9.81, kFloorZ = 1.0, kV0 = 0.5;
constexpr double kDt = 5e-4;  // brash-ode's production step

OdeLibrary& ode_lib() {
  static OdeLibrary lib;
  return lib;
}

struct Sample {
  double t_s, x_m, vx_m_s, wy_rad_s;
};

// One sphere launched along x at kV0 (not spinning: it slides, then rolls) on a fixed wall whose top is at
// kFloorZ, far above the water (z = 0): gravity and the contact only. Samples every sample_s up to t_end_s.
std::vector<Sample> roll(const Frictions& f, double t_end_s, double sample_s = 0.01) {
  ode_lib();
  brash::core::FluidParams p;
  p.gravity_m_s2 = kG;
  World w(p, StepperSettings{.dt_s = kDt}, f);
  w.add_wall_box(Vec3(0.5, 0, kFloorZ - 0.05), Vec3(2.0, 0.2, 0.1));
  w.add_sphere(Vec3(0, 0, kFloorZ + kR), kR, kRho, Vec3(kV0, 0, 0));
  std::vector<Sample> out;
  const long per_sample = std::lround(sample_s / kDt), samples = std::lround(t_end_s / sample_s);
  for (long k = 1; k <= samples; ++k) {
    for (long i = 0; i < per_sample; ++i) w.step();
    out.push_back({w.stats().t_s, w.position(0).x(), w.velocity(0).x(), w.angular_velocity(0).y()});
  }
  return out;
}

// Least-squares slope of vx(t) over the samples from t0_s on (the rolling phase).
double deceleration(const std::vector<Sample>& s, double t0_s) {
  double n = 0, st = 0, sv = 0, stt = 0, stv = 0;
  for (const auto& x : s) {
    if (x.t_s < t0_s) continue;
    n += 1, st += x.t_s, sv += x.vx_m_s, stt += x.t_s * x.t_s, stv += x.t_s * x.vx_m_s;
  }
  return -(n * stv - st * sv) / (n * stt - st * st);
}
}  // namespace

TEST(OdeRolling, SphereOnAWallDeceleratesAtFiveSeventhsMuRG) {
  const double mu_r = 0.05;
  const auto s = roll(Frictions{.ice_wall = 1.35, .rolling = mu_r}, 0.4);
  const double a = deceleration(s, 0.05);
  const double expect = brash::core::analytic::rolling_deceleration(mu_r, kG);
  std::cout << "ODE rolling: a = " << a << " m/s^2, closed form " << expect << " m/s^2\n";
  EXPECT_NEAR(a / expect, 1.0, 1e-2);
  // it rolls (v = w R at the contact) and is still moving at the end
  EXPECT_NEAR(s.back().vx_m_s / (s.back().wy_rad_s * kR), 1.0, 1e-2);
  EXPECT_GT(s.back().vx_m_s, 0.25 * kV0);
}

TEST(OdeRolling, StopsWhereTheClosedFormSaysAndStays) {
  // once rolling (t1, v1), it stops after v1 / a more seconds and v1^2 / (2 a) more metres; then it stays
  // (ODE's rolling rows hold it as static friction holds a block)
  const double mu_r = 0.2;
  const auto s = roll(Frictions{.ice_wall = 1.35, .rolling = mu_r}, 0.6, kDt);
  const double a = brash::core::analytic::rolling_deceleration(mu_r, kG);
  const Sample& s1 = s[std::lround(0.05 / kDt) - 1];  // well after the sliding phase (~11 ms)
  ASSERT_NEAR(s1.vx_m_s / (s1.wy_rad_s * kR), 1.0, 1e-2);
  std::size_t stop = 0;
  while (stop < s.size() && s[stop].vx_m_s > 1e-9) ++stop;
  ASSERT_LT(stop, s.size()) << "still rolling at " << s.back().t_s << " s";
  const double t_expect = s1.t_s + s1.vx_m_s / a;
  std::cout << "ODE rolling: stopped at " << s[stop].t_s << " s, closed form " << t_expect << " s\n";
  EXPECT_NEAR(s[stop].t_s - s1.t_s, t_expect - s1.t_s, 1e-2 * (t_expect - s1.t_s));
  const double d_expect = s1.vx_m_s * s1.vx_m_s / (2 * a);
  EXPECT_NEAR(s[stop].x_m - s1.x_m, d_expect, 1e-2 * d_expect);
  for (std::size_t i = stop; i < s.size(); ++i) EXPECT_LT(std::abs(s[i].vx_m_s), 1e-9);
}

// Without rolling resistance a rolling sphere keeps its speed (nothing else acts in air), and the run is the
// one of contacts without dContactRolling bit for bit (Frictions' default rolling is 0).
TEST(OdeRolling, ZeroIsTheModelWithoutIt) {
  const auto off = roll(Frictions{.ice_wall = 1.35, .rolling = 0}, 0.4);
  const auto dflt = roll(Frictions{.ice_wall = 1.35}, 0.4);
  ASSERT_EQ(off.size(), dflt.size());
  for (std::size_t i = 0; i < off.size(); ++i) {
    EXPECT_EQ(off[i].vx_m_s, dflt[i].vx_m_s);
    EXPECT_EQ(off[i].wy_rad_s, dflt[i].wy_rad_s);
  }
  EXPECT_LT(deceleration(off, 0.05), 1e-3 * brash::core::analytic::rolling_deceleration(0.05, kG));
}
