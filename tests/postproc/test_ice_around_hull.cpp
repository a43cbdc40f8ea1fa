// The ice around the hull (brash/post/ice_around_hull.hpp) on a box hull with square arrays of spheres of known
// thickness ahead of its bow and beside it, and brash-post's report on run folders with and without what the section
// needs.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <brash/hull/mesh.hpp>
#include <brash/post/ice_around_hull.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "synthetic_run.hpp"

#ifdef BRASH_POST_HAVE_VTK
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#endif

namespace fs = std::filesystem;
using brash::post::IceAroundHull;

namespace {

constexpr double kPi = std::numbers::pi;
// box hull: x [0, 1], y [-0.2, 0.2], z [0, 0.4] in its frame, draft 0.2; the water at z = 0 in the channel
constexpr double kDraft = 0.2, kBeam = 0.4;
// a square array of equal spheres holds pi/6 of its volume: with this porosity one layer of diameter d reads d
const double kPorosity = 1 - kPi / 6;
constexpr double kRa = 0.01;   // the pieces ahead (d = 0.02: five columns per band of a quarter beam)
constexpr double kRs = 0.005;  // the pieces beside (d = 0.01: five columns per band of Lwl / 20, ten rows per strip)

struct Piece {
  double x, y, z, r, fx = 0, fy = 0, fz = 0;
};

brash::hull::Mesh box_mesh() {
  brash::hull::Mesh m;
  for (int k = 0; k < 8; ++k) m.vertices.emplace_back(k & 1 ? 1.0 : 0.0, k & 2 ? 0.2 : -0.2, k & 4 ? 0.4 : 0.0);
  const int q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : q) m.faces.push_back({f[0], f[1], f[2]}), m.faces.push_back({f[0], f[2], f[3]});
  return m;
}

// Ahead of the bow: three layers in the first band (piled at the stem), two in the next three, none beyond; each
// piece of the first column pushes the hull with 1 N along -x. Beside: one layer over the whole length, both sides.
// Under the hull: one piece touching the bottom (0.02 m below the keel with its bottom) and one 0.06 m below the
// keel, clear of it.
std::vector<Piece> layered_ice() {
  std::vector<Piece> p;
  for (int i = 0; i < 20; ++i)      // columns ahead: centres 1.01 .. 1.39
    for (int j = 0; j < 20; ++j) {  // across the beam: -0.19 .. 0.19
      const int layers = i < 5 ? 3 : 2;
      for (int l = 0; l < layers; ++l)
        p.push_back({1.0 + kRa + 2 * kRa * i, -0.19 + 2 * kRa * j, -kRa - 2 * kRa * l, kRa, i == 0 ? -1.0 : 0.0});
    }
  for (int i = 0; i < 100; ++i)
    for (int j = 0; j < 10; ++j)
      for (const double side : {-1.0, 1.0})
        p.push_back({kRs + 2 * kRs * i, side * (0.2 + kRs + 2 * kRs * j), -kRs, kRs});
  p.push_back({0.5, 0.1, -kDraft - kRa, kRa, 0, 0, 2.0});  // on the bottom, pushing it up with 2 N
  p.push_back({0.5, 0.0, -0.25, kRa});                       // below the keel, not touching
  return p;
}

std::string snapshot_csv(const std::vector<Piece>& pieces, bool forces) {
  std::string s = "id,x,y,z,radius,vx,vy,vz,submerged_fraction,ca_x,ca_y,ca_z,active";
  s += forces ? ",hull_fx_N,hull_fy_N,hull_fz_N\n" : "\n";
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const auto& q = pieces[i];
    s += fmt::format("{},{},{},{},{},0,0,0,1,0.5,0.5,0.5,1", i + 1, q.x, q.y, q.z, q.r);
    s += forces ? fmt::format(",{},{},{}\n", q.fx, q.fy, q.fz) : "\n";
  }
  return s;
}

void write(const fs::path& p, const std::string& s) { std::ofstream(p, std::ios::binary) << s; }

// A run folder: the box hull at hull_x_m = 0 in the channel (start_x_m 0, the ship at rest), two snapshots of the
// layered ice in the window [0.5, 1.0] s and one before it holding one piece alone (which must not count).
fs::path make_run(const std::string& tag, bool forces, bool snapshots = true) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("brash_test_ice_around_{}_{}", tag, ::getpid());
  fs::remove_all(dir);
  fs::create_directories(dir / "particles");
  brash::hull::write_stl(dir / "box.stl", box_mesh());
  write(dir / "case.yaml", fmt::format(R"(name: ice_around
hull: {{file: box.stl, draft_m: {}, lpp_m: 1.0, beam_m: {}, start_x_m: 0.0}}
ship: {{speed_m_s: 0.0001, scale_lambda: 25.0, ice_class: IA}}
channel: {{length_m: 3.0, width_m: 1.0}}
ice: {{thickness_m: 0.04, diameter_mean_m: 0.02, diameter_sd_m: 0.0, porosity: {:.17g}}}
water: {{level_m: 0.0}}
run: {{duration_s: 1.0, timestep_s: 1.0e-4, output_interval_s: 0.01, dump_interval_s: 0.5, window_s: [0.5, 1.0]}}
)",
                                       kDraft, kBeam, kPorosity));
  write(dir / "meta.json",
        R"({"engine": "synthetic", "status": "complete", "reason": "", "hull_split": {"x_par_aft_m": 0.2, "x_par_fwd_m": 0.8}})");
  std::string f = "t_s,fx_N,fy_N,fz_N\n";
  for (int k = 0; k <= 100; ++k) f += fmt::format("{},-1.5,0,0\n", 0.01 * k);
  write(dir / "hull_force.csv", f);
  std::string index = "step,t_s,file,hull_x_m\n";
  if (snapshots) {
    const double times[] = {0.0, 0.5, 1.0};
    for (int k = 0; k < 3; ++k) {
      const auto file = fmt::format("particles_{}.csv", k * 5000);
      index += fmt::format("{},{},{},0\n", k * 5000, times[k], file);
      write(dir / "particles" / file,
            snapshot_csv(k == 0 ? std::vector<Piece>{{2.5, 0.0, -kRa, kRa}} : layered_ice(), forces));
    }
  }
  write(dir / "particles" / "index.csv", index);
  return dir;
}

std::vector<brash::post::SnapshotEntry> entries_of(const fs::path& dir) {
  return brash::post::read_snapshot_index(dir / "particles", false);
}

IceAroundHull analyze(const fs::path& dir, std::optional<brash::post::FsicrBrash> fsicr = std::nullopt) {
  const auto c = brash::post::read_post_case(dir / "case.yaml");
  return brash::post::analyze_ice_around_hull(entries_of(dir), {0.5, 1.0}, c, box_mesh(), {0.2, 0.8}, fsicr, false);
}

std::string run_post(const fs::path& dir) {
  const std::string cmd = fmt::format("'{}' '{}' --no-plots > '{}' 2>&1", BRASH_POST_EXE, dir.string(),
                                      (dir / "post.log").string());
  const int st = std::system(cmd.c_str());
  std::ifstream in(dir / "post.log");
  std::stringstream ss;
  ss << in.rdbuf();
  EXPECT_EQ(st, 0) << ss.str();
  return ss.str();
}

nlohmann::json report_of(const fs::path& dir) { return nlohmann::json::parse(std::ifstream(dir / "report.json")); }

std::string markdown_of(const fs::path& dir) {
  std::ifstream in(dir / "report.md");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

TEST(IceAroundHull, ThicknessProfileOfKnownLayers) {
  const auto dir = make_run("thickness", false);
  const auto r = analyze(dir, brash::post::FsicrBrash{0.26 + std::sqrt(10.0 * 1.0), 1.0});
  EXPECT_EQ(r.snapshots, 2u);  // the one before the window is left out
  EXPECT_DOUBLE_EQ(r.band_m, 0.1);
  ASSERT_EQ(r.ahead.size(), 8u);
  // three layers of 0.02 m in the first band, two in the next three (columns 5 .. 19), none beyond
  const double expected[8] = {0.06, 0.04, 0.04, 0.04, 0, 0, 0, 0};
  for (std::size_t k = 0; k < 8; ++k) {
    EXPECT_NEAR(r.ahead[k].from_m, 0.1 * k, 1e-12);
    EXPECT_NEAR(r.ahead[k].thickness_m, expected[k], 1e-9) << k;
  }
  EXPECT_NEAR(r.H_F_measured_m, 0.06, 1e-9);
  // FSICR at model scale: / lambda (25)
  ASSERT_TRUE(r.H_F_fsicr_model_m && r.H_M_model_m);
  EXPECT_NEAR(*r.H_F_fsicr_model_m, (0.26 + std::sqrt(10.0)) / 25, 1e-12);
  EXPECT_NEAR(*r.H_M_model_m, 1.0 / 25, 1e-12);
  // beside: one layer of 0.01 m over the whole length
  ASSERT_EQ(r.beside.size(), 20u);
  for (const auto& b : r.beside) EXPECT_NEAR(b.thickness_m, 0.01, 1e-9) << b.from_m;
  EXPECT_NEAR(r.beside.front().from_m, 0.0, 1e-12);
  EXPECT_NEAR(r.beside.back().to_m, 1.0, 1e-12);
  fs::remove_all(dir);
}

TEST(IceAroundHull, ContactShareDepthAndPressureOfKnownLayers) {
  const auto dir = make_run("contact", true);
  const auto r = analyze(dir);
  // touching: the first column ahead (20 x 3), the first row beside (2 x 100), the piece on the bottom
  EXPECT_NEAR(r.touching_pieces_mean, 261, 1e-12);
  EXPECT_NEAR(r.on_bottom_share, 1.0 / 261, 1e-12);
  const double covered = kPi * (60 * kRa * kRa + 200 * kRs * kRs + kRa * kRa);
  // the wetted box: bow and stern faces 0.08 m^2 each, sides 0.2 m^2 each, bottom 0.4 m^2
  EXPECT_NEAR(r.wetted_area_all_m2, 0.96, 1e-12);
  EXPECT_NEAR(r.contact_fraction_all, covered / 0.96, 1e-12);
  double regions = 0;
  for (std::size_t k = 0; k < 3; ++k) regions += r.wetted_area_m2[k];
  EXPECT_NEAR(regions, 0.96, 1e-12);
  // the bow face's triangles (centroid x = 1) are bow; every piece ahead touches them
  EXPECT_GT(r.contact_fraction[0], 0.0);
  // depth: the piece on the bottom reaches 0.22 m below the waterline; the one below the keel 0.06 m below it
  EXPECT_NEAR(r.deepest_touching_mean_m, 0.22, 1e-12);
  EXPECT_NEAR(r.deepest_touching_max_m, 0.22, 1e-12);
  EXPECT_NEAR(r.below_keel_pieces_mean, 2.0, 1e-12);
  EXPECT_NEAR(r.below_keel_deepest_m, 0.06, 1e-12);
  // per triangle: the touched cross sections add up; the pressure field adds up to the pushes (60 N on the bow
  // face, 2 N on the bottom) in each snapshot
  const auto mesh = box_mesh();
  ASSERT_EQ(r.triangle_contact_fraction.size(), mesh.faces.size());
  ASSERT_EQ(r.triangle_pressure_Pa.size(), mesh.faces.size());
  EXPECT_TRUE(r.pressure_missing.empty());
  double cover = 0, bow_push = 0, bottom_push = 0;
  for (std::size_t t = 0; t < mesh.faces.size(); ++t) {
    const auto& f = mesh.faces[t];
    const auto& a = mesh.vertices[f[0]];
    const auto n = (mesh.vertices[f[1]] - a).cross(mesh.vertices[f[2]] - a);
    const double area = 0.5 * n.norm();
    cover += r.triangle_contact_fraction[t] * area;
    if (n.normalized().x() > 0.99) bow_push += r.triangle_pressure_Pa[t] * area;
    else if (n.normalized().z() < -0.99) bottom_push += r.triangle_pressure_Pa[t] * area;
    else EXPECT_EQ(r.triangle_pressure_Pa[t], 0.0) << t;
  }
  EXPECT_NEAR(cover, covered, 1e-12);
  EXPECT_NEAR(bow_push, 60.0, 1e-9);
  EXPECT_NEAR(bottom_push, 2.0, 1e-9);
  fs::remove_all(dir);
}

TEST(IceAroundHull, NoHullForcesNoPressureField) {
  const auto dir = make_run("noforce", false);
  const auto r = analyze(dir);
  fs::remove_all(dir);
  EXPECT_TRUE(r.triangle_pressure_Pa.empty());
  EXPECT_NE(r.pressure_missing.find("hull_fx_N"), std::string::npos) << r.pressure_missing;
  EXPECT_FALSE(r.triangle_contact_fraction.empty());
}

TEST(IceAroundHull, ReportSectionJsonAndHullField) {
  const auto dir = make_run("report", true);
  run_post(dir);
  const auto j = report_of(dir)["ice_around_hull"];
  ASSERT_FALSE(j.contains("not_available")) << j.dump();
  EXPECT_NEAR(j["H_F_measured_m"].get<double>(), 0.06, 1e-9);
  // FSICR's H_F for the box's breadth at full scale (0.4 m x 25 = 10 m) and IA's H_M = 1 m, at model scale
  EXPECT_NEAR(j["H_F_fsicr_model_m"].get<double>(), (0.26 + std::sqrt(10.0)) / 25, 1e-9);
  EXPECT_EQ(j["thickness"]["ahead_of_stem"].size(), 8u);
  EXPECT_NEAR(j["contact"]["all"]["touched_fraction"].get<double>(),
              kPi * (60 * kRa * kRa + 200 * kRs * kRs + kRa * kRa) / 0.96, 1e-9);
  EXPECT_TRUE(j["pressure_missing"].is_null());
  const auto md = markdown_of(dir);
  EXPECT_NE(md.find("## The ice around the hull"), std::string::npos) << md;
  EXPECT_NE(md.find("H_F measured | 0.0600 m"), std::string::npos) << md;
#ifdef BRASH_POST_HAVE_VTK
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName((dir / "hull.vtu").string().c_str());
  reader->Update();
  auto* g = reader->GetOutput();
  ASSERT_EQ(g->GetNumberOfCells(), 12);
  auto* p = g->GetCellData()->GetArray("contact_pressure_Pa");
  auto* c = g->GetCellData()->GetArray("contact_fraction");
  ASSERT_TRUE(p && c);
  double max_p = 0;
  for (vtkIdType i = 0; i < 12; ++i) max_p = std::max(max_p, p->GetTuple1(i));
  EXPECT_GT(max_p, 0.0);
#endif
  fs::remove_all(dir);
}

// Old runs: no hull forces in the snapshots, no snapshots at all, no hull mesh: the section says what is missing
// and prints no numbers.
TEST(IceAroundHull, ReportSaysWhatIsMissing) {
  const auto noforce = make_run("report_noforce", false);
  run_post(noforce);
  EXPECT_FALSE(report_of(noforce)["ice_around_hull"]["pressure_missing"].is_null());
  EXPECT_NE(markdown_of(noforce).find("No contact pressure: the particle snapshots carry no force"), std::string::npos);

  const auto none = make_run("report_nosnap", false, false);
  run_post(none);
  const auto j = report_of(none)["ice_around_hull"];
  ASSERT_TRUE(j.contains("not_available")) << j.dump();
  EXPECT_NE(j["not_available"].get<std::string>().find("no particle snapshots"), std::string::npos);
  EXPECT_FALSE(j.contains("H_F_measured_m"));
  const auto md = markdown_of(none);
  const auto at = md.find("## The ice around the hull\n\nNot available: the run has no particle snapshots");
  EXPECT_NE(at, std::string::npos) << md;
  EXPECT_EQ(md.find("H_F measured"), std::string::npos);
  EXPECT_FALSE(fs::exists(none / "hull.vtu"));

  brash::post::testing::SyntheticRun s;  // its case names a hull file that does not exist
  const auto nohull = fs::temp_directory_path() / fmt::format("brash_test_ice_around_nohull_{}", ::getpid());
  brash::post::testing::write_synthetic_run(nohull, s);
  run_post(nohull);
  const auto k = report_of(nohull)["ice_around_hull"];
  ASSERT_TRUE(k.contains("not_available")) << k.dump();
  EXPECT_NE(k["not_available"].get<std::string>().find("hull mesh could not be read"), std::string::npos);
  EXPECT_NE(markdown_of(nohull).find("Not available: the hull mesh could not be read"), std::string::npos);
  for (const auto& d : {noforce, none, nohull}) fs::remove_all(d);
}
