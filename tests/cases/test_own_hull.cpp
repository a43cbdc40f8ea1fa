// brash-case new NAME --hull FILE --draft T (docs/own_hull.md): a hull becomes a case folder with its measured keys,
// and a hull that fails the checks is refused with the reason, leaving no folder. Run as a process, as a user would.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "brash/case.hpp"
#include "brash/hull/hydrostatics.hpp"
#include "brash/hull/mesh.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kBin = BRASH_BIN_DIR;
const fs::path kJbc = BRASH_JBC_MODEL_STL;

fs::path temp_dir(const std::string& tag) {
  const fs::path d = fs::temp_directory_path() / ("brash_test_own_hull_" + tag + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string slurp(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

struct Result {
  int rc;
  std::string out;
};

// brash-case new NAME --cases-dir DIR ARGS; stdout and stderr together.
Result new_case(const fs::path& dir, const std::string& name, const std::string& args) {
  const fs::path log = dir / (name + ".log");
  const std::string cmd = "'" + (kBin / "brash-case").string() + "' new " + name + " --cases-dir '" + dir.string() +
                          "' " + args + " > '" + log.string() + "' 2>&1";
  const int st = std::system(cmd.c_str());
  return {WIFEXITED(st) ? WEXITSTATUS(st) : -1, slurp(log)};
}

// A box hull as OBJ: x 0..length, y -half_beam..half_beam (+ y_shift), z 0..depth, quads, outward unless flipped;
// `drop_face` leaves one side out (an open mesh).
fs::path write_box_obj(const fs::path& file, double scale = 1.0, bool flipped = false, bool drop_face = false,
                       double y_shift = 0.0) {
  const double L = 2.0 * scale, hb = 0.3 * scale, D = 0.5 * scale, dy = y_shift * scale;
  std::ofstream out(file);
  out << "# box hull\n";
  for (const auto& v : std::vector<std::array<double, 3>>{{0, -hb, 0}, {L, -hb, 0}, {L, hb, 0}, {0, hb, 0},
                                                          {0, -hb, D}, {L, -hb, D}, {L, hb, D}, {0, hb, D}})
    out << "v " << v[0] << " " << v[1] + dy << " " << v[2] << "\n";
  std::vector<std::array<int, 4>> faces{{1, 4, 3, 2}, {5, 6, 7, 8}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 4, 8, 7}, {4, 1, 5, 8}};
  if (drop_face) faces.pop_back();
  for (auto f : faces) {
    if (flipped) std::swap(f[1], f[3]);
    out << "f " << f[0] << "/1 " << f[1] << "/1 " << f[2] << "/1 " << f[3] << "/1\n";
  }
  return file;
}

}  // namespace

// The JBC STL the build makes, through --hull on the paper case as template: the paper case's hull keys come back
// from the measurement alone.
TEST(OwnHull, JbcStlBecomesACaseWithItsMeasuredKeys) {
  ASSERT_TRUE(fs::exists(kJbc)) << kJbc;
  const fs::path dir = temp_dir("jbc");
  const Result r = new_case(dir, "my_jbc", "--template jbc_ia_5kn --hull '" + kJbc.string() + "' --draft 0.4125 --lpp 7.0");
  ASSERT_EQ(r.rc, 0) << r.out;
  const fs::path copy = dir / "my_jbc" / kJbc.filename();
  ASSERT_TRUE(fs::exists(copy));
  EXPECT_EQ(slurp(copy), slurp(kJbc));  // an STL is copied as it is
  const brash::Case c = brash::load_case(dir / "my_jbc/case.yaml");
  EXPECT_EQ(c.hull.file, fs::absolute(copy).lexically_normal());  // the case's own copy, not the build's
  EXPECT_DOUBLE_EQ(c.hull.draft_m, 0.4125);
  EXPECT_DOUBLE_EQ(c.hull.lpp_m, 7.0);
  const auto mesh = brash::hull::read_mesh(kJbc);
  const auto hydro = brash::hull::hydrostatics(mesh, 0.4125, 7.0);
  EXPECT_NEAR(c.hull.beam_m, hydro.bwl_m, 1e-6 * hydro.bwl_m);
  EXPECT_NEAR(c.hull.beam_m, 1.125, 1e-3);                        // the paper's beam
  EXPECT_NEAR(c.hull.start_x_m, -7.2, 1e-6);                       // the template's start, bow as far out of the ice
  EXPECT_NEAR(c.channel.width_m, 2.25, 1e-3);                      // two beams, as in the template
  EXPECT_NEAR(c.channel.length_m, 21.0, 1e-9);
  EXPECT_NE(r.out.find("bulbous bow"), std::string::npos) << r.out;  // FSICR parameters measured and printed
  EXPECT_NE(r.out.find("alpha 38.1 deg"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("no bow the FSICR formula"), std::string::npos) << r.out;
  // another hull than the template's: the paper's published values are not this case's
  EXPECT_FALSE(c.references.declared());
  EXPECT_NE(r.out.find("published references"), std::string::npos) << r.out;
}

// The JBC at a lighter draft (0.3 m instead of 0.4125 m): the waterline cuts the bulb, whose top recedes going up.
// The bulb is recognised there too (phi1 = 90 deg, as FSICR says for a bulbous bow), and every FSICR angle the case
// is made with is in (0, 90] deg or named in a warning with its value and that range.
TEST(OwnHull, JbcAtALighterDraftGivesFsicrAnglesOrSaysWhyNot) {
  const fs::path dir = temp_dir("jbc_light");
  const Result r = new_case(dir, "light", "--hull '" + kJbc.string() + "' --draft 0.3 --lpp 7.0");
  ASSERT_EQ(r.rc, 0) << r.out;
  const auto fsicr = brash::hull::measure_fsicr_detail(brash::hull::read_mesh(kJbc), 0.3, 7.0);
  EXPECT_TRUE(fsicr.bulbous_bow);
  EXPECT_EQ(fsicr.params.phi1_deg, 90.0);
  EXPECT_NE(r.out.find("phi1 90.0 deg (bulbous bow)"), std::string::npos) << r.out;
  const auto& p = fsicr.params;
  for (const auto& [name, deg] : {std::pair{"alpha", p.alpha_deg}, std::pair{"phi1", p.phi1_deg},
                                   std::pair{"phi2", p.phi2_deg}, std::pair{"psi", p.psi_deg}}) {
    const std::string warning = fmt::format("warning: FSICR angle {} = {:.1f} deg is outside the valid range (0, 90]",
                                            name, deg);
    if (deg > 0 && deg <= 90)
      EXPECT_EQ(r.out.find(warning), std::string::npos) << r.out;
    else
      EXPECT_NE(r.out.find(warning), std::string::npos) << name << " " << deg << "\n" << r.out;
  }
}

// An OBJ box (quads, texture indices) is read natively and goes into the case folder as an STL; without --lpp the
// waterline length is Lpp; the channel follows the hull.
TEST(OwnHull, BoxObjBecomesAnStlCase) {
  const fs::path dir = temp_dir("box");
  const fs::path obj = write_box_obj(dir / "box.obj");
  const Result r = new_case(dir, "boxy", "--hull '" + obj.string() + "' --draft 0.2 --scale 20 --speed 0.3");
  ASSERT_EQ(r.rc, 0) << r.out;
  const brash::Case c = brash::load_case(dir / "boxy/case.yaml");
  EXPECT_EQ(c.hull.file, fs::absolute(dir / "boxy/box.stl").lexically_normal());
  const auto check = brash::hull::check_mesh(brash::hull::read_mesh(c.hull.file));
  EXPECT_TRUE(check.ok());
  EXPECT_NEAR(check.signed_volume_m3, 2.0 * 0.6 * 0.5, 1e-6);
  EXPECT_DOUBLE_EQ(c.hull.draft_m, 0.2);
  EXPECT_DOUBLE_EQ(c.hull.lpp_m, 2.0);
  EXPECT_DOUBLE_EQ(c.hull.beam_m, 0.6);
  EXPECT_DOUBLE_EQ(c.channel.width_m, 1.2);
  EXPECT_DOUBLE_EQ(c.channel.length_m, 2.0);  // one ship length, as the default template (the quick case)
  EXPECT_LT(c.hull.start_x_m + 2.0, 0.0);  // the bow starts outside the ice
  EXPECT_DOUBLE_EQ(c.ship.scale_lambda, 20.0);
  EXPECT_DOUBLE_EQ(c.ship.speed_m_s, 0.3);
  EXPECT_NE(r.out.find("Cb 1.000"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("no bow the FSICR formula can take"), std::string::npos) << r.out;  // a box has no bow
  // The same case again: refused without --force, accepted with it.
  EXPECT_EQ(new_case(dir, "boxy", "--hull '" + obj.string() + "' --draft 0.2").rc, 2);
  EXPECT_EQ(new_case(dir, "boxy", "--hull '" + obj.string() + "' --draft 0.25 --force").rc, 0);
  EXPECT_DOUBLE_EQ(brash::load_case(dir / "boxy/case.yaml").hull.draft_m, 0.25);
}

// Hulls that fail a check: exit 2, the reason in the message, no case folder left behind.
TEST(OwnHull, BadHullsAreRefusedWithTheReason) {
  const fs::path dir = temp_dir("bad");
  // millimetres: the JBC written with every vertex x1000, as CAD tools often export
  brash::hull::Mesh mm = brash::hull::read_mesh(kJbc);
  for (auto& v : mm.vertices) v *= 1000.0;
  brash::hull::write_stl(dir / "jbc_mm.stl", mm);
  struct Bad {
    std::string name, args, reason;
  };
  const std::vector<Bad> bad{
      {"open", "--hull '" + write_box_obj(dir / "open.obj", 1.0, false, true).string() + "' --draft 0.2",
       "not closed (4 boundary edges"},
      {"mm_stl", "--hull '" + (dir / "jbc_mm.stl").string() + "' --draft 0.4125", "millimetres (scale by 0.001)"},
      {"mm_obj", "--hull '" + write_box_obj(dir / "mm.obj", 1000.0).string() + "' --draft 0.2", "millimetres"},
      {"inward", "--hull '" + write_box_obj(dir / "in.obj", 1.0, true).string() + "' --draft 0.2", "faces point inward"},
      {"offset", "--hull '" + write_box_obj(dir / "off.obj", 1.0, false, false, 0.3).string() + "' --draft 0.2",
       "not centred on y = 0"},
      {"narrow", "--hull '" + write_box_obj(dir / "box.obj").string() + "' --draft 0.2 --width 0.5",
       "not wider than the waterline beam 0.6 m of --hull"},
      {"dry", "--hull '" + (dir / "box.obj").string() + "' --draft 0.6", "below the waterline"},
      {"no_draft", "--hull '" + (dir / "box.obj").string() + "'", "needs --draft"},
      {"missing", "--hull '" + (dir / "nowhere.stl").string() + "' --draft 0.2", "nowhere.stl: no such file"},
  };
  for (const auto& b : bad) {
    const Result r = new_case(dir, b.name, b.args);
    EXPECT_EQ(r.rc, 2) << b.name << ": " << r.out;
    EXPECT_NE(r.out.find(b.reason), std::string::npos) << b.name << ": " << r.out;
    EXPECT_NE(r.out.find("--hull"), std::string::npos) << b.name << ": " << r.out;
    EXPECT_FALSE(fs::exists(dir / b.name)) << b.name;
  }
}

// Other formats go through meshio (/usr/bin/python3): a PLY box becomes an STL case; a file meshio cannot read is
// refused with its message.
TEST(OwnHull, MeshioFormats) {
  const fs::path dir = temp_dir("meshio");
  {
    std::ofstream ply(dir / "box.ply");
    ply << "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
           "element face 6\nproperty list uchar int vertex_indices\nend_header\n"
           "0 -0.3 0\n2 -0.3 0\n2 0.3 0\n0 0.3 0\n0 -0.3 0.5\n2 -0.3 0.5\n2 0.3 0.5\n0 0.3 0.5\n"
           "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";
  }
  const Result ok = new_case(dir, "plybox", "--hull '" + (dir / "box.ply").string() + "' --draft 0.2");
  ASSERT_EQ(ok.rc, 0) << ok.out;
  const brash::Case c = brash::load_case(dir / "plybox/case.yaml");
  EXPECT_EQ(c.hull.file.filename(), "box.stl");
  EXPECT_DOUBLE_EQ(c.hull.beam_m, 0.6);
  EXPECT_TRUE(brash::hull::check_mesh(brash::hull::read_mesh(c.hull.file)).ok());

  std::ofstream(dir / "junk.ply") << "ply\nthis is not a mesh\n";
  const Result r = new_case(dir, "junk", "--hull '" + (dir / "junk.ply").string() + "' --draft 0.2");
  EXPECT_EQ(r.rc, 2) << r.out;
  EXPECT_NE(r.out.find("junk.ply"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("meshio could not read it"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir / "junk"));
}
