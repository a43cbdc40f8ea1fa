// Rolling resistance (contact.rolling_friction) in the LIGGGHTS scene: a sphere rolling on a level wall, with
// the contact lines the runner writes for a case (liggghts_input.h), decelerates at the closed form's
// 5/7 mu_r g (docs/physics.md, "Rolling resistance"); with 0 the decks are those of the model without it.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <iostream>
#include <string>

#include "brash/core/reference.hpp"
#include "liggghts_input.h"
#include "liggghts_runner.h"

using brash::test::fresh_dir;
using brash::test::read_table;
using brash::test::run_liggghts;

namespace {
constexpr double kV0 = 0.5;

brash::Case rolling_case(double mu_r) {
  brash::Case c;
  c.name = "sphere";
  c.contact.rolling_friction = mu_r;
  return c;
}

// One ice piece (type 1, the case's mean diameter and density) launched along x at kV0 on a level wall of the
// walls' material (type 3) at z = 0, in air; the case's contact lines, gravity and time step. Rows: t x vx wy.
std::vector<std::vector<double>> roll(const brash::Case& c, const std::string& name, double t_end_s) {
  const double d = c.ice.diameter_mean_m;
  const std::string deck = fmt::format(
      R"({preamble}region reg block -0.1 1.0 -0.1 0.1 -0.05 0.1 units box
create_box 3 reg
neighbor 0.002 bin
neigh_modify delay 0
{contacts}timestep {dt}
fix floor all wall/gran {model} primitive type 3 zplane 0
create_atoms 1 single 0 0 {z0} units box
set group all diameter {d} density {rho}
velocity all set {v0} 0 0 units box
fix integr all nve/sphere
fix grav all gravity {g} vector 0 0 -1
variable t equal step*dt
variable x equal x[1]
variable vx equal vx[1]
variable wy equal omegay[1]
fix out all print {every} "${{t}} ${{x}} ${{vx}} ${{wy}}" file out.txt screen no title "# t x vx wy"
run {steps}
)",
      fmt::arg("preamble", brash::test::kGranularPreamble),
      fmt::arg("contacts", brash::liggghts::contact_lines(c, false)),
      fmt::arg("model", brash::liggghts::granular_model(c)), fmt::arg("dt", c.run.timestep_s),
      fmt::arg("z0", 0.5 * d), fmt::arg("d", d), fmt::arg("rho", c.ice.density_kg_m3), fmt::arg("v0", kV0),
      fmt::arg("g", c.water.gravity_m_s2), fmt::arg("every", std::lround(0.01 / c.run.timestep_s)),
      fmt::arg("steps", std::lround(t_end_s / c.run.timestep_s)));
  const auto dir = fresh_dir(name);
  EXPECT_EQ(run_liggghts(dir, deck), 0) << dir;
  return read_table(dir / "out.txt");
}

// Least-squares slope of vx(t) over the rows from t0_s on (the rolling phase), negated.
double deceleration(const std::vector<std::vector<double>>& rows, double t0_s) {
  double n = 0, st = 0, sv = 0, stt = 0, stv = 0;
  for (const auto& r : rows) {
    if (r[0] < t0_s) continue;
    n += 1, st += r[0], sv += r[2], stt += r[0] * r[0], stv += r[0] * r[2];
  }
  return -(n * stv - st * sv) / (n * stt - st * st);
}
}  // namespace

TEST(LiggghtsRolling, SphereOnAWallDeceleratesAtFiveSeventhsMuRG) {
  const auto c = rolling_case(0.05);
  const auto rows = roll(c, "rolling", 0.4);
  ASSERT_GE(rows.size(), 30u);
  const double a = deceleration(rows, 0.05);
  const double expect = brash::core::analytic::rolling_deceleration(0.05, c.water.gravity_m_s2);
  std::cout << "LIGGGHTS rolling: a = " << a << " m/s^2, closed form " << expect << " m/s^2\n";
  EXPECT_NEAR(a / expect, 1.0, 1e-2);
  // it rolls (v = w R at the contact) and is still moving at the end
  const auto& last = rows.back();
  EXPECT_NEAR(last[2] / (last[3] * 0.5 * c.ice.diameter_mean_m), 1.0, 1e-2);
  EXPECT_GT(last[2], 0.25 * kV0);
}

// Without rolling resistance the sphere keeps its rolling speed (nothing else acts in air).
TEST(LiggghtsRolling, ZeroLeavesTheSphereRolling) {
  const auto c = rolling_case(0);
  const auto rows = roll(c, "rolling_off", 0.4);
  ASSERT_GE(rows.size(), 30u);
  EXPECT_LT(std::abs(deceleration(rows, 0.05)),
            1e-3 * brash::core::analytic::rolling_deceleration(0.05, c.water.gravity_m_s2));
}

namespace {
// A deck with rolling resistance less its rolling lines: the coefficient's fix, and "rolling_friction cdt" on every
// granular model (counted in `models`).
std::string without_rolling_lines(const std::string& deck, std::size_t& models) {
  const std::string cdt = " rolling_friction cdt";
  std::string out;
  for (std::size_t at = 0, end; at < deck.size(); at = end + 1) {
    end = deck.find('\n', at);
    std::string line = deck.substr(at, end - at);
    if (line.starts_with("fix m5 all property/global coefficientRollingFriction peratomtypepair")) continue;
    for (std::size_t p; (p = line.find(cdt)) != std::string::npos; ++models) line.erase(p, cdt.size());
    out += line + "\n";
  }
  return out;
}
}  // namespace

// contact.rolling_friction 0 writes the decks of the model without it: no rolling line at all, and a deck with
// it differs only by its rolling lines (on the pieces, the hull and the walls), the run's and the settling's, whole
// channel and half.
TEST(LiggghtsRolling, ZeroWritesTheDeckWithoutRollingResistance) {
  const brash::liggghts::Box box{-1, 10, -1, 1, -1, 1};
  brash::liggghts::SceneOptions opt;
  opt.duration_s = 1;
  for (const bool symmetry : {false, true}) {
    auto off = rolling_case(0), on = rolling_case(0.05);
    off.speedups.symmetry_y = on.speedups.symmetry_y = symmetry;
    const std::string run_off = brash::liggghts::input_script(off, box, opt);
    const std::string settle_off = brash::liggghts::settle_script(off, box, 100, 10);
    EXPECT_EQ(run_off.find("olling"), std::string::npos);
    EXPECT_EQ(settle_off.find("olling"), std::string::npos);
    std::size_t models = 0;
    EXPECT_EQ(without_rolling_lines(brash::liggghts::input_script(on, box, opt), models), run_off);
    EXPECT_EQ(models, 4u);  // pair gran, the hull, two side walls
    models = 0;
    EXPECT_EQ(without_rolling_lines(brash::liggghts::settle_script(on, box, 100, 10), models), settle_off);
    EXPECT_EQ(models, 5u);  // pair gran, two side walls, two end walls
  }
}
