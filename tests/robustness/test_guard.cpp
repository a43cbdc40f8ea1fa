// fix brash/guard (plugin/liggghts/fix_brash_guard.h): tiny LIGGGHTS scenes that trip each guard, and
// the guard's argument errors. Each stop must name the step, the atom id and the cause.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <regex>
#include <sstream>

#include "../hull_meshes/simple_hulls.hpp"
#include "../liggghts/liggghts_runner.h"
#include "brash/hull/mesh.hpp"
#include "guard_args.h"

namespace fs = std::filesystem;
using brash::test::fresh_dir;
using brash::test::read_text;
using brash::test::run_liggghts;

namespace {

constexpr double kD = 0.017578;

// A 0.2 m box of water (surface z = 0), one ice sphere at (x, y, z) with velocity (vx, vy, vz).
std::string scene(double dt, const std::string& atom_setup, const std::string& fixes, long steps,
                  const std::string& boundary = "f f f") {
  return fmt::format(R"(atom_style granular
atom_modify map array sort 0 0.0
boundary {boundary}
newton off
communicate single vel yes
units si
region reg block -0.1 0.1 -0.1 0.1 -0.1 0.1 units box
create_box 1 reg
neighbor 0.002 bin
neigh_modify delay 0
{contacts}
timestep {dt}
{atoms}
set group all diameter {d} density 900
fix integr all nve/sphere
{fixes}
thermo 100
run {steps}
)",
                     fmt::arg("contacts", brash::test::ice_contact_model("1.35")),
                     fmt::arg("boundary", boundary), fmt::arg("dt", dt), fmt::arg("atoms", atom_setup),
                     fmt::arg("d", kD), fmt::arg("fixes", fixes), fmt::arg("steps", steps));
}

struct Run {
  int status;
  std::string screen;
};

Run run(const std::string& name, const std::string& input, int ranks = 1) {
  const auto dir = fresh_dir("guard_" + name);
  const int st = run_liggghts(dir, input, ranks);
  return {st, read_text(dir / "screen_in.lmp.txt")};
}

const std::string kOneAtom = "create_atoms 1 single 0 0 -0.02 units box";
const std::string kFluid = "fix grav all gravity 9.81 vector 0 0 -1\nfix fl all icefluid";

// "ERROR: fix brash/guard: step N: atom ID: <cause>" with N > 0 (a stop during the run) or N >= 0.
void expect_stop(const Run& r, const std::string& cause, bool during_run = true) {
  EXPECT_NE(r.status, 0) << r.screen;
  const std::regex re(std::string("ERROR: fix brash/guard: step ([0-9]+): atom 1: ") + cause);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.screen, m, re)) << "expected '" << cause << "' in:\n" << r.screen;
  if (during_run) {
    EXPECT_GT(std::stol(m[1]), 0);
  }
}

// Same, for any atom id.
void expect_stop_any(const Run& r, const std::string& atom, const std::string& cause) {
  EXPECT_NE(r.status, 0) << r.screen;
  const std::regex re("ERROR: fix brash/guard: step ([0-9]+): atom " + atom + ": " + cause);
  EXPECT_TRUE(std::regex_search(r.screen, re)) << "expected '" << cause << "' in:\n" << r.screen;
}

}  // namespace

TEST(Guard, SphereShotOutOfTheBox) {
  const auto r = run("box", scene(1e-4, kOneAtom + "\nvelocity all set 5 0 0", "fix g all brash/guard every 1 box "
                                                                                "-0.09 0.09 -0.09 0.09 -0.09 0.09",
                                  1000));
  expect_stop(r, R"(left the box: x = 0\.09[0-9]* > xhi = 0\.09 \(m\))");
  // 0.09 m at 5 m/s and dt 1e-4: the guard stops at step 180 or 181 (x > 0.09 m).
  EXPECT_TRUE(r.screen.find("step 180:") != std::string::npos || r.screen.find("step 181:") != std::string::npos)
      << r.screen;
}

TEST(Guard, SphereShotOutOfTheBoxOnTwoRanks) {
  // Two atoms; the one with the lower id leaves first on whichever rank owns it.
  const std::string atoms = "create_atoms 1 single -0.05 -0.05 -0.02 units box\ncreate_atoms 1 single 0.05 0.05 -0.02 units box\n"
                            "velocity all set 0 0 0\ngroup one id 1\nvelocity one set 0 -5 0";
  const auto r = run("box2", "processors 1 2 1\n" + scene(1e-4, atoms, "fix g all brash/guard every 5 box -0.09 0.09 "
                                                                        "-0.09 0.09 -0.09 0.09",
                                                          1000),
                     2);
  expect_stop(r, R"(left the box: y = -0\.09[0-9]* < ylo = -0\.09 \(m\))");
}

TEST(Guard, PieceJumpsAboveTheWater) {
  const auto r = run("zmax", scene(1e-4, kOneAtom + "\nvelocity all set 0 0 2",
                                   kFluid.substr(0, kFluid.find('\n')) + "\nfix g all brash/guard every 10 zmax 0.05\n" +
                                       kFluid.substr(kFluid.find('\n') + 1),
                                   2000));
  expect_stop(r, R"(above zmax: z = 0\.05[0-9]* > 0\.05 m \(jumped out of the water\))");
}

TEST(Guard, RunawayKineticEnergy) {
  // 2.5e-3 kg at 3 m/s is 1.1e-2 J; the limit is 1e-3 J.
  const auto r = run("ke", scene(1e-4, kOneAtom + "\nvelocity all set 0 3 0", "fix g all brash/guard every 1 ke_max 1e-3", 10));
  expect_stop(r, R"(runaway kinetic energy: 0\.01[0-9]* J > ke_max = 0\.001 J \(\|v\| = 3 m/s\))", false);
}

TEST(Guard, NonFiniteForceAndVelocity) {
  // An overflowing external force (1e308 * 10 = inf) poisons the velocity in the first step.
  const auto r = run("nan", scene(1e-4, kOneAtom,
                                  "variable huge equal 1e308*10\nfix push all addforce v_huge 0 0\n"
                                  "fix g all brash/guard every 1",
                                  10));
  expect_stop(r, R"(non-finite (velocity: vx|position: x|force: fx) = (inf|nan|-nan))", false);
}

TEST(Guard, ExplicitAddedMassBlowUpIsCaught) {
  // Explicit treatment with Ca = 10 for a submerged ice piece: m_a / m = 11 > 1, the lagged acceleration
  // diverges. Periodic box so the piece cannot leave it: the guard must still stop the run (never silent).
  const auto r = run("explicit", scene(1e-4, kOneAtom + "\nvelocity all set 0 0 0.01",
                                       "fix grav all gravity 9.81 vector 0 0 -1\n"
                                       "fix g all brash/guard every 1 ke_max 1.0\n"
                                       "fix fl all icefluid treatment explicit ca uniform 10",
                                       2000, "p p p"));
  expect_stop(r, R"((runaway kinetic energy|non-finite))");
}

TEST(Guard, TimestepTooLargeForContactStiffness) {
  // E = 5 MPa, r = 8.789 mm, rho 900: T_R = 6.45e-4 s; dt 1e-3 is 155 % of it.
  const auto r = run("dt", scene(1e-3, kOneAtom, "fix g all brash/guard every 100 youngs 5e6 poisson 0.3", 10));
  expect_stop(r, R"(timestep 0\.001 s is too large for the contact stiffness: 155 % of the Rayleigh time 0\.000645[0-9]* s)",
              false);
  EXPECT_NE(r.screen.find("step 0: atom 1: timestep"), std::string::npos) << r.screen;
}

TEST(Guard, QuietOnAFloatingPiece) {
  // Every guard on, a piece bobbing at the surface: the run completes.
  const auto r = run("quiet", scene(5e-5, kOneAtom,
                                    "fix grav all gravity 9.81 vector 0 0 -1\n"
                                    "fix g all brash/guard every 1 box -0.09 0.09 -0.09 0.09 -0.09 0.09 zmax 0.02 "
                                    "ke_max 1e-3 youngs 5e6 poisson 0.3\n"
                                    "fix fl all icefluid",
                                    2000));
  EXPECT_EQ(r.status, 0) << r.screen;
  EXPECT_EQ(r.screen.find("ERROR"), std::string::npos) << r.screen;
}

// ------------------------------------------------------------------ hull penetration (keyword hull)
// A 4 cm x 4 cm x 10 cm box hull (STL frame: x 0..0.04, y -0.02..0.02, z 0..0.1) whose frame origin starts at
// (-0.09, 0, -0.05) and moves at 1 m/s in +x: its front face is at x = -0.05 + t. The guard only reads the
// hull (no mesh contact in these scenes): the atom at rest at x = 0 gets its centre inside the hull once
// -0.05 + t > 0, i.e. after step 500 at dt 1e-4 (500 or 501 with rounding).
fs::path write_box_hull(const fs::path& dir) {
  const auto file = dir / "box_hull.stl";
  brash::hull::write_stl(file, brash::hull::test::box(0.04, 0.04, 0.1));
  return file;
}
const std::string kHull = "hull box_hull.stl -0.09 0 -0.05 1 0 0";

Run run_in(const fs::path& dir, const std::string& input, int ranks = 1, const std::string& name = "in.lmp") {
  const int st = run_liggghts(dir, input, ranks, name);
  return {st, read_text(dir / ("screen_" + name + ".txt"))};
}

void expect_hull_stop_at_500(const Run& r, const std::string& atom = "1") {
  expect_stop_any(r, atom,
                  R"(hull penetration: 0\.0(08|09)[0-9]* m = 5[0-9] % of its diameter 0\.01758 m > )"
                  R"(max_hull_penetration_d 0\.5 \(centre inside the hull)");
  EXPECT_TRUE(r.screen.find("step 500:") != std::string::npos ||
              r.screen.find("step 501:") != std::string::npos)
      << r.screen;
}

TEST(Guard, SphereInsideTheMovingHull) {
  const auto dir = fresh_dir("guard_hull");
  write_box_hull(dir);
  const auto r = run_in(dir, scene(1e-4, kOneAtom, "fix g all brash/guard every 1 " + kHull, 1000));
  expect_hull_stop_at_500(r);
}

TEST(Guard, SphereInsideTheMovingHullOnTwoRanks) {
  // Atom 1 at y = -0.01 (x = 0.05, rank 0) and atom 2 at y = +0.01 (x = 0, rank 1): the hull reaches atom 2
  // first; rank 1 finds it and sends the cause to rank 0, which prints the error.
  const auto dir = fresh_dir("guard_hull2");
  write_box_hull(dir);
  const std::string atoms =
      "create_atoms 1 single 0.05 -0.01 -0.02 units box\ncreate_atoms 1 single 0 0.01 -0.02 "
      "units box";
  const auto r = run_in(
      dir, "processors 1 2 1\n" + scene(1e-4, atoms, "fix g all brash/guard every 1 " + kHull, 1000), 2);
  expect_hull_stop_at_500(r, "2");
}

TEST(Guard, OverlapFromOutsideAboveTheThreshold) {
  // max_penetration 0.1: stop once the front face is 0.1 d = 1.76 mm past the sphere's leading point, i.e. at
  // -0.05 + t = -r + 0.1 d (t = 0.04297: step 430), with the centre still outside (0.047 m from the hull
  // frame's origin, the front face being at x = 0.04 in that frame).
  const auto dir = fresh_dir("guard_hull_out");
  write_box_hull(dir);
  const auto r = run_in(
      dir, scene(1e-4, kOneAtom, "fix g all brash/guard every 1 " + kHull + " max_penetration 0.1", 1000));
  expect_stop_any(r, "1",
                  R"(hull penetration: 0\.0017[0-9]* m = 10 % of its diameter 0\.01758 m > )"
                  R"(max_hull_penetration_d 0\.1 \(centre outside the hull; hull frame x = 0\.0470)");
  EXPECT_TRUE(r.screen.find("step 430:") != std::string::npos ||
              r.screen.find("step 431:") != std::string::npos)
      << r.screen;
}

// The box hull as a real LIGGGHTS mesh moved by fix move/mesh (as brash-liggghts-run's scene does) and the
// guard's hull on the same path. The atom is not integrated, so the mesh passes through it: first contact
// force when the front face reaches x = -r (step 413), guard stop when it passes the centre (step 500/501).
std::string moving_mesh_scene(bool restart, long steps) {
  std::string s =
      "atom_style granular\natom_modify map array sort 0 0.0\nnewton off\ncommunicate single vel yes\nunits "
      "si\n";
  s += restart ? "read_restart r.restart\n"
               : "boundary f f f\nregion reg block -0.1 0.1 -0.1 0.1 -0.1 0.1 units box\ncreate_box 1 reg\n";
  s += "neighbor 0.002 bin\nneigh_modify delay 0\n" + brash::test::ice_contact_model("1.35") +
       "\ntimestep 1e-4\n";
  if (!restart) s += kOneAtom + fmt::format("\nset group all diameter {} density 900\n", kD);
  s += "fix hull all mesh/surface/stress file box_hull.stl type 1 move -0.09 0 -0.05\n"
       "fix hullwall all wall/gran model hertz tangential history mesh n_meshes 1 meshes hull\n"
       "fix mv all move/mesh mesh hull linear 1 0 0\n"
       "fix g all brash/guard every 1 " +
       kHull +
       "\n"
       "thermo_style custom step f_hull[1]\nthermo 1\nthermo_modify norm no\n";
  s += fmt::format("run {}{}\n", steps, restart ? " upto" : "");
  if (!restart) s += "write_restart r.restart\n";
  return s;
}

// First step whose thermo line shows a non-zero hull force (-1 if none).
long first_contact_step(const std::string& screen) {
  std::istringstream in(screen);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    long step;
    double fx;
    if ((ls >> step >> fx) && (ls >> std::ws).eof() && fx != 0) return step;
  }
  return -1;
}

TEST(Guard, HullPositionAgreesWithMoveMeshAlsoAfterReadRestart) {
  // Uninterrupted: the mesh touches the atom at step 413, the guard stops at 500/501.
  const auto dir = fresh_dir("guard_hull_restart");
  write_box_hull(dir);
  const auto whole = run_in(dir, moving_mesh_scene(false, 1000), 1, "whole.lmp");
  expect_hull_stop_at_500(whole);
  const long contact = first_contact_step(whole.screen);
  EXPECT_GE(contact, 412);
  EXPECT_LE(contact, 413);
  // 200 steps, write_restart, a new LIGGGHTS process reads it and continues to step 1000 (the runner's
  // --resume): fix move/mesh restores its mesh and time, the guard uses the restored step counter; both must
  // agree with the uninterrupted run.
  ASSERT_EQ(run_in(dir, moving_mesh_scene(false, 200), 1, "a.lmp").status, 0);
  const auto resumed = run_in(dir, moving_mesh_scene(true, 1000), 1, "b.lmp");
  expect_hull_stop_at_500(resumed);
  EXPECT_EQ(first_contact_step(resumed.screen), contact) << resumed.screen;
}

TEST(Guard, QuietWhenTheHullPassesBeside) {
  // The hull passes 3 cm beside the atom (y offset 0.04 - 0.02 = 0.02 m > r): the run completes.
  const auto dir = fresh_dir("guard_hull_quiet");
  write_box_hull(dir);
  const auto r = run_in(
      dir,
      scene(1e-4, kOneAtom, "fix g all brash/guard every 1 hull box_hull.stl -0.09 0.04 -0.05 1 0 0", 1500));
  EXPECT_EQ(r.status, 0) << r.screen;
  EXPECT_EQ(r.screen.find("ERROR"), std::string::npos) << r.screen;
}

TEST(Guard, HullMustBeClosedAndReadable) {
  const auto dir = fresh_dir("guard_hull_bad");
  brash::hull::write_stl(dir / "band.stl",
                         brash::hull::clip_band(brash::hull::test::box(0.04, 0.04, 0.1), 0.04, 0.06));
  auto r = run_in(dir, scene(1e-4, kOneAtom, "fix g all brash/guard every 1 hull band.stl 0 0 0 1 0 0", 10));
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.screen.find("ERROR: fix brash/guard: hull band.stl is not a closed surface"), std::string::npos)
      << r.screen;
  r = run_in(dir, scene(1e-4, kOneAtom, "fix g all brash/guard every 1 hull none.stl 0 0 0 1 0 0", 10));
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.screen.find("ERROR: fix brash/guard: hull none.stl: "), std::string::npos) << r.screen;
}

// ------------------------------------------------------------------ argument errors (catalogue entries)
struct BadGuardArgs {
  std::string name, args, message;
};
void PrintTo(const BadGuardArgs& b, std::ostream* os) { *os << b.name; }

const std::vector<BadGuardArgs> kBadArgs = {
    {"missing_every", "box 0 1 0 1 0 1", "fix brash/guard: missing 'every N'"},
    {"every_zero", "every 0", "keyword 'every' expects an integer >= 1, got '0'"},
    {"every_fraction", "every 2.5", "keyword 'every' expects an integer >= 1, got '2.5'"},
    {"unknown_keyword", "every 1 colour red", "unknown keyword 'colour'"},
    {"box_too_few_values", "every 1 box 0 1 0 1", "keyword 'box' needs 6 value(s)"},
    {"box_reversed", "every 1 box 1 0 0 1 0 1", "keyword 'box' needs xlo < xhi"},
    {"zmax_not_a_number", "every 1 zmax high", "keyword 'zmax' expects a number, got 'high'"},
    {"ke_max_negative", "every 1 ke_max -1", "keyword 'ke_max' must be > 0, got -1"},
    {"ke_max_nan", "every 1 ke_max nan", "keyword 'ke_max' expects a finite number, got 'nan'"},
    {"poisson_impossible", "every 1 youngs 5e6 poisson 0.7",
     "keyword 'poisson' must be in (-1, 0.5), got 0.7"},
    {"density_without_youngs", "every 1 density 900", "'density' and 'rmin' belong to the time-step check"},
    {"hull_too_few_values", "every 1 hull h.stl 0 0 0", "keyword 'hull' needs 7 value(s)"},
    {"hull_velocity_not_a_number", "every 1 hull h.stl 0 0 0 fast 0 0",
     "keyword 'hull' expects a number, got 'fast'"},
    {"max_penetration_without_hull", "every 1 max_penetration 0.5",
     "'max_penetration' belongs to the hull check"},
    {"max_penetration_zero", "every 1 hull h.stl 0 0 0 1 0 0 max_penetration 0",
     "keyword 'max_penetration' must be > 0"},
};

class GuardArgs : public ::testing::TestWithParam<BadGuardArgs> {};

// The parser alone (fast, also what the fuzz target exercises).
TEST_P(GuardArgs, ParserRejects) {
  std::vector<std::string> words;
  std::istringstream ss(GetParam().args);
  for (std::string w; ss >> w;) words.push_back(w);
  try {
    brash::liggghts::parse_guard_args(words);
    FAIL() << "accepted: " << GetParam().args;
  } catch (const brash::InputError& e) {
    EXPECT_NE(std::string(e.what()).find(GetParam().message), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Catalogue, GuardArgs, ::testing::ValuesIn(kBadArgs),
                         [](const ::testing::TestParamInfo<BadGuardArgs>& i) { return i.param.name; });

// Through LIGGGHTS: the same messages end the run as an ERROR (three representative entries).
TEST(GuardArgsInLiggghts, StopWithTheParserMessage) {
  for (const auto& b : {kBadArgs[0], kBadArgs[3], kBadArgs[5]}) {
    const auto r = run("args_" + b.name, scene(1e-4, kOneAtom, "fix g all brash/guard " + b.args, 1));
    EXPECT_NE(r.status, 0) << r.screen;
    EXPECT_NE(r.screen.find("ERROR: fix brash/guard: "), std::string::npos) << r.screen;
    EXPECT_NE(r.screen.find(b.message), std::string::npos) << r.screen;
  }
}
