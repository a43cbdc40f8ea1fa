// fix icefluid in multi-sphere scenes and its input errors: a settled floating bed reaches the mean
// draft of hydrostatic equilibrium; bad fix arguments and a wrong fix order stop with clear messages.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "liggghts_runner.h"

using brash::test::fresh_dir;
using brash::test::read_table;
using brash::test::read_text;
using brash::test::run_liggghts;

namespace {
constexpr double d = 0.017578;

std::string header(double dt) {
  return fmt::format(R"(atom_style granular
atom_modify map array sort 0 0.0
boundary p p f
newton off
communicate single vel yes
units si
region reg block 0 {L} 0 {L} -0.1 0.1 units box
create_box 1 reg
neighbor 0.002 bin
neigh_modify delay 0
{contacts}
timestep {dt}
)",
                     fmt::arg("contacts", brash::test::ice_contact_model("1.35")),
                     fmt::arg("L", 10 * d), fmt::arg("dt", dt));
}
}  // namespace

TEST(LiggghtsBed, TwoLayerBedSettlesAtHydrostaticMeanDraft) {
  // 2 x 100 spheres on two square layers offset by half a cell (the upper layer rests in the pockets).
  std::string in = header(5e-5);
  in += fmt::format(R"(lattice sc {d}
region l1 block 0 {L} 0 {L} -0.001 0.001 units box
create_atoms 1 region l1
lattice sc {d} origin 0.5 0.5 0.7071
region l2 block 0 {L} 0 {L} 0.0122 0.0127 units box
create_atoms 1 region l2
set group all diameter {d} density 900
fix integr all nve/sphere
fix grav all gravity 9.81 vector 0 0 -1
fix damp all viscous 0.01
fix fl all icefluid model both drag_law schiller_naumann
compute frac all reduce ave f_fl[1]
compute vmax all reduce max vz
compute vmin all reduce min vz
variable t equal step*dt
variable n equal count(all)
variable frac equal c_frac
fix out all print 2000 "${{t}} ${{n}} ${{frac}}" file out.txt screen no
thermo_style custom step atoms c_frac c_vmax c_vmin
thermo 20000
run 100000
)",
                    fmt::arg("d", d), fmt::arg("L", 10 * d));
  auto dir = fresh_dir("bed");
  ASSERT_EQ(run_liggghts(dir, in), 0) << dir;
  const auto rows = read_table(dir / "out.txt");
  ASSERT_FALSE(rows.empty());
  EXPECT_EQ(rows.back()[1], 200);
  // (fix viscous adds linear damping, ~1.5 1/s, so the bed's heave dies out within the 5 s run.)
  // Contact forces are internal: at rest the buoyancy of all caps equals the total weight, so the mean
  // submerged fraction of equal spheres is rho_i / rho_w = 0.9 whatever the stacking.
  EXPECT_NEAR(rows.back()[2], 0.9, 0.9 * 5e-3);
}

TEST(LiggghtsFixErrors, MustBeLastPostForceFix) {
  auto dir = fresh_dir("order");
  const std::string in = header(1e-4) + R"(create_atoms 1 single 0.05 0.05 0 units box
set group all diameter 0.017578 density 900
fix integr all nve/sphere
fix fl all icefluid
fix grav all gravity 9.81 vector 0 0 -1
run 10
)";
  EXPECT_NE(run_liggghts(dir, in), 0);
  const std::string out = read_text(dir / "screen_in.lmp.txt");
  EXPECT_NE(out.find("fix icefluid must be the last post_force fix, but fix grav (gravity) comes after it"),
            std::string::npos)
      << out;
}

struct BadArgs {
  std::string args, message;
};

class LiggghtsFixBadArgs : public ::testing::TestWithParam<BadArgs> {};

TEST_P(LiggghtsFixBadArgs, ClearError) {
  auto dir = fresh_dir("badargs");
  const std::string in = header(1e-4) + "create_atoms 1 single 0.05 0.05 0 units box\nfix fl all icefluid " +
                         GetParam().args + "\nrun 1\n";
  EXPECT_NE(run_liggghts(dir, in), 0);
  const std::string out = read_text(dir / "screen_in.lmp.txt");
  EXPECT_NE(out.find(GetParam().message), std::string::npos) << out;
}

INSTANTIATE_TEST_SUITE_P(
    Catalogue, LiggghtsFixBadArgs,
    ::testing::Values(BadArgs{"colour red", "unknown keyword 'colour'"},
                      BadArgs{"model viscous", "unknown fluid model 'viscous'"},
                      BadArgs{"treatment semi", "unknown acceleration treatment 'semi'"},
                      BadArgs{"water_density -1000", "water_density = -1000: must be a positive number"},
                      BadArgs{"cd abc", "keyword 'cd' expects a number, got 'abc'"},
                      BadArgs{"ca uniform -2", "added-mass coefficients must be finite and >= 0"},
                      BadArgs{"flow 1 2", "keyword 'flow' needs 3 value(s)"},
                      BadArgs{"gravity maybe", "keyword 'gravity' expects yes or no"},
                      BadArgs{"model drag hull_flow nohull.stl 0 0 -0.4 0.5",
                              "fix icefluid: nohull.stl: cannot open the file"},
                      BadArgs{"model added_mass hull_flow nohull.stl 0 0 -0.4 0.5",
                              "fix icefluid: 'hull_flow' acts through the drag, and model added_mass has none"},
                      BadArgs{"water_density -1000", "ERROR: fix icefluid: invalid fluid parameters"},
                      BadArgs{"hull_flow nohull.stl 0 0", "keyword 'hull_flow' needs 5 value(s)"},
                      BadArgs{"flow 0.1 0 0 hull_flow nohull.stl 0 0 -0.4 0.5",
                              "'flow' and 'hull_flow' exclude each other"}));
