// Single-sphere analytic scenes run through brash-liggghts (LIGGGHTS integrates, fix icefluid adds the
// fluid forces) against the reference integrator of plugin/core and the closed forms; 1 vs 2 ranks;
// restart = uninterrupted run.
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>

#include "brash/core/reference.hpp"
#include "liggghts_runner.h"

using namespace brash::core;
using brash::test::fresh_dir;
using brash::test::read_table;
using brash::test::run_liggghts;

namespace {
constexpr double d = 0.017578, r = d / 2, rho_i = 900, rho_w = 1000, g = 9.81;

// One sphere in a closed box whose z-range is split between ranks (so the sphere migrates).
std::string scene(double z0, double dt, const std::string& fix_args, int print_every, long steps,
                  const std::string& extra_before_run = "") {
  return fmt::format(R"({preamble}processors 1 1 *
region reg block -0.05 0.05 -0.05 0.05 -2.0 0.1 units box
create_box 1 reg
neighbor 0.002 bin
neigh_modify delay 0
{contacts}
timestep {dt}
create_atoms 1 single 0 0 {z0} units box
set group all diameter {d} density {rho}
fix integr all nve/sphere
fix grav all gravity 9.81 vector 0 0 -1
fix fl all icefluid {fix_args}
variable t equal step*dt
variable z equal z[1]
variable vz equal vz[1]
fix out all print {every} "${{t}} ${{z}} ${{vz}}" file out.txt screen no title "# t z vz"
{extra}
run {steps}
)",
                     fmt::arg("preamble", brash::test::kGranularPreamble),
                     fmt::arg("contacts", brash::test::ice_contact_model("0.3")),
                     fmt::arg("dt", dt), fmt::arg("z0", z0), fmt::arg("d", d), fmt::arg("rho", rho_i),
                     fmt::arg("fix_args", fix_args), fmt::arg("every", print_every), fmt::arg("extra", extra_before_run),
                     fmt::arg("steps", steps));
}

ReferenceSphere reference(double z0, double dt, FluidModel model) {
  ReferenceSphere s;
  s.params.model = model;
  s.radius_m = r;
  s.density_kg_m3 = rho_i;
  s.dt_s = dt;
  s.x_m = Vec3(0, 0, z0);
  s.setup();
  return s;
}
}  // namespace

TEST(LiggghtsSingleSphere, RiseMatchesReferenceAndAnalytic) {
  const double dt = 1e-5;
  auto dir = fresh_dir("rise");
  ASSERT_EQ(run_liggghts(dir, scene(-1.0, dt, "model both", 10000, 100000)), 0) << dir;
  const auto rows = read_table(dir / "out.txt");
  ASSERT_GE(rows.size(), 10u);
  auto ref = reference(-1.0, dt, FluidModel::Both);
  const auto rise = analytic::rise(r, rho_i, rho_w, g, 0.44, 0.5);
  long done = 0;
  for (const auto& row : rows) {
    const long step = std::lround(row[0] / dt);
    ref.run(step - done);
    done = step;
    if (step == 0) continue;
    EXPECT_NEAR(row[2] / ref.v_m_s.z(), 1.0, 5e-3) << "t " << row[0];
    EXPECT_NEAR(row[2] / (rise.terminal_velocity_m_s * std::tanh(row[0] / rise.time_constant_s)), 1.0, 5e-3);
  }
}

// `fix icefluid` without `model`: the default is both (drag plus added mass). The rise follows the both
// reference and not the added_mass one (no drag: it would keep accelerating).
TEST(LiggghtsSingleSphere, DefaultModelIsDragPlusAddedMass) {
  const double dt = 1e-5;
  auto dir = fresh_dir("rise_default");
  ASSERT_EQ(run_liggghts(dir, scene(-1.0, dt, "", 5000, 30000)), 0) << dir;
  const auto rows = read_table(dir / "out.txt");
  ASSERT_GE(rows.size(), 5u);
  auto both = reference(-1.0, dt, FluidModel::Both), am = reference(-1.0, dt, FluidModel::AddedMass);
  both.run(30000);
  am.run(30000);
  EXPECT_NEAR(rows.back()[2] / both.v_m_s.z(), 1.0, 5e-3);
  EXPECT_GT(am.v_m_s.z() / both.v_m_s.z(), 1.05);  // the two references differ by more than the tolerance
}

TEST(LiggghtsSingleSphere, FloatingDraftAndHeavePeriod) {
  const double dt = 2e-5;
  const double h = analytic::height_for_fraction(r, rho_i / rho_w);
  const double z_eq = r - h;
  auto dir = fresh_dir("heave");
  const long steps = 150000;  // 3 s, ~15 periods, undamped (added_mass model)
  ASSERT_EQ(run_liggghts(dir, scene(z_eq + 1e-3 * r, dt, "model added_mass", 1, steps)), 0) << dir;
  const auto rows = read_table(dir / "out.txt");
  ASSERT_GE(rows.size(), size_t(steps));
  std::vector<double> up;  // upward zero crossings of z - z_eq
  double zmin = 1, zmax = -1;
  for (size_t i = 1; i < rows.size(); ++i) {
    const double a = rows[i - 1][1] - z_eq, b = rows[i][1] - z_eq;
    if (a < 0 && b >= 0) up.push_back(rows[i - 1][0] + dt * (-a) / (b - a));
    zmin = std::min(zmin, rows[i][1]);
    zmax = std::max(zmax, rows[i][1]);
  }
  ASSERT_GE(up.size(), 5u);
  const double period = (up.back() - up.front()) / double(up.size() - 1);
  const double expect = analytic::heave_period(r, rho_i, rho_w, g, 0.5 * h / (2 * r));
  EXPECT_NEAR(period / expect, 1.0, 5e-3) << period << " vs " << expect;
  // the oscillation is centred on the floating draft (mean of extremes)
  EXPECT_NEAR(0.5 * (zmin + zmax), z_eq, 1e-4 * d);
}

TEST(LiggghtsSingleSphere, DampedSphereSettlesAtFloatingDraft) {
  const double dt = 1e-4;
  auto dir = fresh_dir("draft");
  ASSERT_EQ(run_liggghts(dir, scene(0.5 * r, dt, "model both drag_law schiller_naumann", 250000, 2500000)), 0);
  const auto rows = read_table(dir / "out.txt");
  ASSERT_FALSE(rows.empty());
  const double z_eq = r - analytic::height_for_fraction(r, rho_i / rho_w);
  EXPECT_LT(std::abs(rows.back()[1] - z_eq), 1e-4 * d);
}

TEST(LiggghtsSingleSphere, OneAndTwoRanksIdentical) {
  const double dt = 1e-5;
  auto d1 = fresh_dir("np1"), d2 = fresh_dir("np2");
  // 1.5 s: the sphere rises from z=-1.0 through the rank boundary at z=-0.95.
  const std::string in = scene(-1.0, dt, "model both", 5000, 150000);
  ASSERT_EQ(run_liggghts(d1, in, 1), 0);
  ASSERT_EQ(run_liggghts(d2, in, 2), 0) << d2;
  const auto a = read_table(d1 / "out.txt"), b = read_table(d2 / "out.txt");
  ASSERT_EQ(a.size(), b.size());
  EXPECT_LT(a.front()[1], -0.95);
  EXPECT_GT(a.back()[1], -0.95) << "the sphere must have crossed the rank boundary (box midpoint)";
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t k = 0; k < 3; ++k) EXPECT_NEAR(a[i][k], b[i][k], 1e-12 * (1 + std::abs(a[i][k])));
}

TEST(LiggghtsSingleSphere, RestartContinuesLikeUninterruptedRun) {
  const double dt = 2e-5;
  for (const char* args : {"model both", "model both treatment explicit"}) {
    auto full = fresh_dir("full"), split = fresh_dir("split");
    const double z0 = 0.3 * r;  // crosses the surface and oscillates: reversal and partial immersion
    ASSERT_EQ(run_liggghts(full, scene(z0, dt, args, 100, 20000)), 0);
    ASSERT_EQ(run_liggghts(split, scene(z0, dt, args, 100, 10000, "") + "write_restart state.restart\n", 1), 0);
    // second process: read the restart, redefine the same fixes with the same IDs, continue
    const std::string second = fmt::format(R"(atom_modify map array sort 0 0.0
newton off
communicate single vel yes
read_restart state.restart
neighbor 0.002 bin
neigh_modify delay 0
{contacts}
timestep {dt}
fix integr all nve/sphere
fix grav all gravity 9.81 vector 0 0 -1
fix fl all icefluid {args}
variable t equal step*dt
variable z equal z[1]
variable vz equal vz[1]
fix out all print 100 "${{t}} ${{z}} ${{vz}}" file out2.txt screen no title "# t z vz"
run 10000
)",
                     fmt::arg("contacts", brash::test::ice_contact_model("0.3")),
                                           fmt::arg("dt", dt), fmt::arg("args", args));
    ASSERT_EQ(run_liggghts(split, second, 1, "in2.lmp"), 0) << split;
    const auto a = read_table(full / "out.txt"), b = read_table(split / "out2.txt");
    ASSERT_FALSE(b.empty());
    // compare at equal times
    for (const auto& rb : b) {
      const auto it = std::find_if(a.begin(), a.end(), [&](const auto& ra) { return std::abs(ra[0] - rb[0]) < dt / 2; });
      ASSERT_NE(it, a.end());
      EXPECT_NEAR((*it)[1], rb[1], 1e-12) << args << " t " << rb[0];
      EXPECT_NEAR((*it)[2], rb[2], 1e-12) << args << " t " << rb[0];
    }
  }
}
