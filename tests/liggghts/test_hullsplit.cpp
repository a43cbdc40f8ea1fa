// fix brash/hullsplit (the hull force split, brash/core/hull_split.hpp) on a scene with a known split, and the
// split brash-liggghts-run records beside the total.
//
// Known split: a sphere held still (no integrator) overlaps a plate inclined by theta that slides along its own
// face, so the overlap and the normal force Fn stay constant and the contact slides: the force on the plate is
// -Fn n (n the face's normal towards the sphere) plus the friction mu Fn against the plate's motion. Its normal
// part's x is Fn sin(theta), its tangential part's -mu Fn cos(theta).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "liggghts_runner.h"

using namespace brash::test;

namespace {

constexpr double kTheta = 20.0 * M_PI / 180.0, kMu = 0.3, kSpeed = 0.1;

// Two triangles of the plane through the origin with normal (-sin, 0, cos), 0.6 m square.
void write_plate(const std::filesystem::path& stl) {
  const double t[3] = {std::cos(kTheta), 0, std::sin(kTheta)};
  auto p = [&](double a, double b) {
    return fmt::format("{:.12g} {:.12g} {:.12g}", a * t[0], b, a * t[2]);
  };
  std::ofstream out(stl);
  out << "solid plate\n";
  const auto facet = [&](const std::string& a, const std::string& b, const std::string& c) {
    out << fmt::format("facet normal {} 0 {}\nouter loop\nvertex {}\nvertex {}\nvertex {}\nendloop\nendfacet\n",
                       -std::sin(kTheta), std::cos(kTheta), a, b, c);
  };
  facet(p(-0.3, -0.3), p(0.3, -0.3), p(0.3, 0.3));
  facet(p(-0.3, -0.3), p(0.3, 0.3), p(-0.3, 0.3));
  out << "endsolid plate\n";
}

std::string deck() {
  const double r = 0.02, gap = r - 1e-4;  // overlap 0.1 mm
  const double cx = -std::sin(kTheta) * gap, cz = std::cos(kTheta) * gap;
  std::string s = kGranularPreamble;
  s += "region reg block -0.5 0.5 -0.5 0.5 -0.3 0.3 units box\ncreate_box 2 reg\n";
  s += "neighbor 0.005 bin\nneigh_modify delay 0\n";
  s += "fix m1 all property/global youngsModulus peratomtype 5.e6 5.e6\n"
       "fix m2 all property/global poissonsRatio peratomtype 0.3 0.3\n"
       "fix m3 all property/global coefficientRestitution peratomtypepair 2 0.3 0.3 0.3 0.3\n";
  s += fmt::format("fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 {0} {0} 0.5\n", kMu);
  s += "pair_style gran model hertz tangential history\npair_coeff * *\ntimestep 1e-5\n";
  s += fmt::format("create_atoms 1 single {:.12g} 0 {:.12g} units box\nset atom 1 diameter {} density 900\n", cx, cz,
                   2 * r);
  s += "fix plate all mesh/surface/stress file plate.stl type 2 reference_point 0 0 0\n";
  s += "fix platewall all wall/gran model hertz tangential history mesh n_meshes 1 meshes plate "
       "store_force_contact_stress yes\n";
  s += fmt::format("fix mv all move/mesh mesh plate linear {:.12g} 0 {:.12g}\n", kSpeed * std::cos(kTheta),
                   kSpeed * std::sin(kTheta));
  // the plate's frame moves with it at kSpeed cos(theta) along x: the contact lies at x ~ 0.007 m in it
  const std::string track = fmt::format("hull_x0 0 speed {:.12g}", kSpeed * std::cos(kTheta));
  s += "fix mid all brash/hullsplit mesh plate " + track + " par_aft -1 par_fwd 1\n";
  s += "fix astern all brash/hullsplit mesh plate " + track + " par_aft 0.5 par_fwd 0.6 scale 2\n";
  s += "fix ahead all brash/hullsplit mesh plate " + track + " par_aft -0.6 par_fwd -0.5\n";
  s += "fix out all ave/time 100 1 100 f_plate[1] f_plate[2] f_plate[3] f_mid[1] f_mid[2] f_mid[3] f_mid[4] "
       "f_mid[5] f_astern[1] f_astern[2] f_astern[3] f_astern[4] f_astern[5] f_ahead[1] f_ahead[2] f_ahead[3] "
       "file split.txt\n";
  s += "run 3000\n";
  return s;
}

}  // namespace

TEST(LiggghtsHullSplit, SlidingContactOnAnInclinedPlateHasTheKnownSplit) {
  const auto dir = fresh_dir("hullsplit");
  write_plate(dir / "plate.stl");
  ASSERT_EQ(run_liggghts(dir, deck()), 0) << read_text(dir / "screen_in.lmp.txt");
  const auto rows = read_table(dir / "split.txt");
  ASSERT_GE(rows.size(), 20u);
  const double n[3] = {-std::sin(kTheta), 0, std::cos(kTheta)};
  std::size_t checked = 0;
  for (const auto& r : rows) {
    ASSERT_EQ(r.size(), 17u);
    if (r[0] < 500) continue;  // the set-up row and the first steps, while the tangential spring loads
    const double fx = r[1], fz = r[3];
    const double Fn = -(fx * n[0] + fz * n[2]);  // the push of the sphere on the plate, along -n
    ASSERT_GT(Fn, 0.1) << "step " << r[0];
    const double tol = 1e-5 * Fn;  // fix ave/time prints 6 significant digits
    // region: all in the mid-body for `mid`, the stern (doubled) for `astern`, the bow for `ahead`
    EXPECT_NEAR(r[5], fx, tol) << "step " << r[0];
    EXPECT_EQ(r[4], 0.0);
    EXPECT_EQ(r[6], 0.0);
    EXPECT_NEAR(r[11], 2 * fx, 2 * tol);
    EXPECT_EQ(r[9], 0.0);
    EXPECT_EQ(r[10], 0.0);
    EXPECT_NEAR(r[14], fx, tol);
    EXPECT_EQ(r[15], 0.0);
    // mechanism: the push's x and the friction's x, which slides: mu Fn
    EXPECT_NEAR(r[7], Fn * std::sin(kTheta), tol) << "step " << r[0];
    EXPECT_NEAR(r[8], -kMu * Fn * std::cos(kTheta), tol) << "step " << r[0];
    EXPECT_NEAR(r[7] + r[8], fx, tol);
    EXPECT_NEAR(r[12] + r[13], 2 * fx, 2 * tol);
    ++checked;
  }
  EXPECT_GE(checked, 20u);
  std::filesystem::remove_all(dir);
}

// The fix's keywords are checked once, by name.
TEST(LiggghtsHullSplit, BadKeywordsAreNamed) {
  const auto dir = fresh_dir("hullsplit_bad");
  write_plate(dir / "plate.stl");
  std::string s = deck();
  s = s.substr(0, s.find("fix mid"));
  EXPECT_NE(run_liggghts(dir, s + "fix mid all brash/hullsplit mesh plate hull_x0 0 speed 0.1 par_aft 1\nrun 1\n"), 0);
  EXPECT_NE(read_text(dir / "screen_in.lmp.txt").find("fix brash/hullsplit: needs mesh MESH-ID"), std::string::npos);
  EXPECT_NE(run_liggghts(dir, s + "fix mid all brash/hullsplit mesh nothere hull_x0 0 speed 0 par_aft 0 par_fwd 1\n"
                                  "run 1\n"),
            0);
  EXPECT_NE(read_text(dir / "screen_in.lmp.txt").find("mesh nothere is not a fix mesh/surface"), std::string::npos);
  std::filesystem::remove_all(dir);
}
