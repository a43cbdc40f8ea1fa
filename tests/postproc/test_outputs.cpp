// brash-post outputs on a synthetic run: PNG plots, ParaView files read back with VTK and meshio,
// and the compare command.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fmt/format.h>
#include <fstream>

#include <nlohmann/json.hpp>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <brash/error.hpp>
#include <brash/post/csv.hpp>
#include <brash/post/native_dump.hpp>
#include <brash/post/paraview.hpp>
#include <brash/post/particles.hpp>
#include <brash/post/plots.hpp>

#include "synthetic_run.hpp"

namespace fs = std::filesystem;
using brash::post::testing::SyntheticRun;

namespace {

fs::path scratch(const std::string& name) {
  return fs::temp_directory_path() / fmt::format("brash_post_out_{}_{}", ::getpid(), name);
}

int sh(const std::string& cmd) {
  const int st = std::system(cmd.c_str());
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

bool is_png(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  char sig[8] = {};
  in.read(sig, 8);
  return in && std::string(sig + 1, 3) == "PNG" && fs::file_size(p) > 5000;
}

// Files of a .pvd collection, in order.
std::vector<fs::path> pvd_files(const fs::path& pvd) {
  const auto text = brash::post::read_text_file(pvd);
  std::vector<fs::path> out;
  for (std::size_t pos = 0; (pos = text.find("file=\"", pos)) != std::string::npos;) {
    pos += 6;
    out.push_back(pvd.parent_path() / text.substr(pos, text.find('"', pos) - pos));
  }
  return out;
}

class Outputs : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = scratch("run");
    run_ = SyntheticRun{};
    write_synthetic_run(dir_, run_);
    status_ = sh(fmt::format("{} {} > {} 2>&1", BRASH_POST_EXE, dir_.string(), (dir_.parent_path() / (dir_.filename().string() + ".log")).string()));
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }
  static inline fs::path dir_;
  static inline SyntheticRun run_;
  static inline int status_ = -1;
};

}  // namespace

TEST_F(Outputs, CliSucceedsAndListsOutputs) {
  ASSERT_EQ(status_, 0);
  std::ifstream in(dir_ / "report.json");
  const auto j = nlohmann::json::parse(in);
  for (const auto* f : {"force_history.png", "resistance_full_scale.png", "particles.pvd"}) {
    EXPECT_NE(std::find(j["outputs"].begin(), j["outputs"].end(), f), j["outputs"].end()) << f;
  }
  // No temp files left behind (atomic writes renamed every one).
  for (const auto& e : fs::recursive_directory_iterator(dir_))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

TEST_F(Outputs, PlotsArePngs) {
  EXPECT_TRUE(is_png(dir_ / "force_history.png"));
  EXPECT_TRUE(is_png(dir_ / "resistance_full_scale.png"));
  // Default ice views: snapshots nearest to 15, 27.5, 40 s -> 20 s and 40 s.
  EXPECT_TRUE(is_png(dir_ / "ice_views_020.00s.png"));
  EXPECT_TRUE(is_png(dir_ / "ice_views_040.00s.png"));
  EXPECT_FALSE(fs::exists(dir_ / "ice_views_000.00s.png"));
  EXPECT_TRUE(fs::exists(dir_ / "post" / "force_history.gp"));
  // The mean line is drawn at fx's window mean (the red curve), and its label names it so: fx, and -fx as resistance.
  const std::string gp = brash::post::read_text_file(dir_ / "post" / "force_history.gp");
  EXPECT_NE(gp.find("window mean of fx"), std::string::npos) << gp;
  EXPECT_EQ(gp.find("mean resistance -fx"), std::string::npos) << gp;
}

TEST_F(Outputs, ParticlesReadBackWithVtk) {
  const auto files = pvd_files(dir_ / "particles.pvd");
  ASSERT_EQ(files.size(), run_.snapshot_times_s.size());
  vtkNew<vtkXMLUnstructuredGridReader> r;
  r->SetFileName(files[1].string().c_str());
  r->Update();
  auto* g = r->GetOutput();
  ASSERT_EQ(g->GetNumberOfPoints(), run_.particles);
  auto* pd = g->GetPointData();
  for (const auto* name : {"radius", "velocity", "submerged_fraction", "ca", "id"}) ASSERT_NE(pd->GetArray(name), nullptr) << name;
  EXPECT_EQ(pd->GetArray("velocity")->GetNumberOfComponents(), 3);
  EXPECT_EQ(pd->GetArray("ca")->GetNumberOfComponents(), 3);
  // Particle 7 of the synthetic snapshot at t = 20 s.
  double p[3];
  g->GetPoint(7, p);
  EXPECT_NEAR(p[0], 0.7 + 0.2, 1e-12);
  EXPECT_NEAR(p[1], -1.0 + 0.21, 1e-12);
  EXPECT_NEAR(p[2], -0.005, 1e-12);
  EXPECT_NEAR(pd->GetArray("radius")->GetTuple1(7), 0.0088, 1e-15);
  EXPECT_NEAR(pd->GetArray("velocity")->GetComponent(7, 0), 0.07, 1e-15);
  EXPECT_NEAR(pd->GetArray("velocity")->GetComponent(7, 2), -0.007, 1e-15);
  EXPECT_NEAR(pd->GetArray("submerged_fraction")->GetTuple1(7), 0.907, 1e-15);
  EXPECT_NEAR(pd->GetArray("ca")->GetComponent(7, 2), 0.0, 1e-15);
  EXPECT_NEAR(pd->GetArray("ca")->GetComponent(6, 2), 0.5, 1e-15);
  ASSERT_NE(pd->GetArray("active"), nullptr);  // 1 integrated, 0 idle far-field ice (every 4th synthetic piece)
  EXPECT_EQ(pd->GetArray("active")->GetTuple1(7), 1.0);
  EXPECT_EQ(pd->GetArray("active")->GetTuple1(8), 0.0);
}

// A LIGGGHTS deck's own dump custom files (one per snapshot) are the run's snapshots when it has no particles/:
// found by their first line, ordered by step, timed by the case's step; diameter read as 2 radius; the
// submerged fraction from the sphere's height (half a sphere centred on the water line: 0.5); no velocities
// and no C_a in the dump: NaN, not zero. A second TIMESTEP in a file and a missing column are refused by name.
TEST(Particles, NativeDumpCustomFilesAreSnapshots) {
  const auto dir = scratch("native");
  fs::create_directories(dir / "dump");
  const auto dump = [](long step, const std::string& atoms) {
    return fmt::format("ITEM: TIMESTEP\n{}\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp ff\n-1 1\n-1 1\n-1 1\n"
                       "ITEM: ATOMS {}\n", step, atoms);
  };
  brash::post::testing::write_text(dir / "dump/ice_2000.liggghts", dump(2000, "id type x y z diameter") +
                                                                    "7 1 0.5 0.1 0.0 0.02\n8 1 0.6 0.1 -0.02 0.02\n");
  brash::post::testing::write_text(dir / "ice_1000.liggghts", dump(1000, "id x y z radius vx vy vz") +
                                                               "7 0.4 0.1 0.01 0.01 0.1 0 0\n8 0.6 0.1 0 0.01 0 0 0\n");
  brash::post::testing::write_text(dir / "notes.txt", "ITEM: something else\n");
  const auto entries = brash::post::native_dump_index(dir, {.timestep_s = 1e-4, .hull_start_x_m = -1.0,
                                                            .speed_m_s = 0.5, .water_level_m = 0.0});
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[0].step, 1000);
  EXPECT_DOUBLE_EQ(entries[0].t_s, 0.1);
  EXPECT_DOUBLE_EQ(entries[1].hull_x_m, -1.0 + 0.5 * 0.2);
  const auto first = brash::post::read_snapshot(entries[0], false);
  EXPECT_EQ(first.id, (std::vector<std::int64_t>{7, 8}));
  EXPECT_DOUBLE_EQ(first.vx[0], 0.1);
  EXPECT_NEAR(first.submerged_fraction[1], 0.5, 1e-12);  // centred on the water line
  EXPECT_EQ(first.submerged_fraction[0], 0.0);          // resting on it
  EXPECT_TRUE(std::isnan(first.ca_x[0]));
  const auto second = brash::post::read_snapshot(entries[1], false);
  EXPECT_DOUBLE_EQ(second.radius[0], 0.01);  // diameter / 2
  EXPECT_TRUE(std::isnan(second.vx[0]));      // not in the dump
  EXPECT_NEAR(second.submerged_fraction[1], 1.0, 1e-12);
  const auto refused = [&](const std::string& name, const std::string& text) {
    brash::post::testing::write_text(dir / name, text);
    try {
      (void)brash::post::read_native_dump(dir / name, 0.0);
    } catch (const brash::InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(refused("two.liggghts", dump(1, "id x y z radius") + "1 0 0 0 0.01\n2 0 0 0 0.01\n" +
                                        dump(2, "id x y z radius") + "1 0 0 0 0.01\n2 0 0 0 0.01\n")
                .find("two.liggghts:12: a second TIMESTEP"),
            std::string::npos);
  EXPECT_NE(refused("noradius.liggghts", dump(1, "id x y z") + "1 0 0 0\n2 0 0 0\n").find("neither 'radius' nor"),
            std::string::npos);
  EXPECT_NE(refused("short.liggghts", dump(1, "id x y z radius") + "1 0 0 0 0.01\n").find("1 atoms where NUMBER"),
            std::string::npos);
  fs::remove_all(dir);
}

// The particles files of LIGGGHTS and ODE end with the active column, YADE's (and older runs') at ca_z: both are
// read; an active value other than 0 or 1 is refused naming the file, line and column.
TEST(Particles, ActiveColumnIsReadWhereTheFileHasIt) {
  const auto dir = scratch("active");
  fs::create_directories(dir);
  const std::string header = "id,x,y,z,radius,vx,vy,vz,submerged_fraction,ca_x,ca_y,ca_z";
  brash::post::testing::write_text(dir / "with.csv", header + ",active\n1,0,0,0,0.01,0,0,0,0.9,0.5,0.5,0.5,1\n"
                                                              "2,1,0,-0.002,0.01,0,0,0,0.93,0,0,0,0\n");
  const auto with = brash::post::read_snapshot(dir / "with.csv", false);
  EXPECT_EQ(with.active, (std::vector<std::uint8_t>{1, 0}));
  EXPECT_EQ(with.submerged_fraction[1], 0.93);
  brash::post::testing::write_text(dir / "without.csv", header + "\n1,0,0,0,0.01,0,0,0,0.9,0.5,0.5,0.5\n");
  const auto without = brash::post::read_snapshot(dir / "without.csv", false);
  EXPECT_EQ(without.size(), 1u);
  EXPECT_TRUE(without.active.empty());
  brash::post::testing::write_text(dir / "bad.csv", header + ",active\n1,0,0,0,0.01,0,0,0,0.9,0.5,0.5,0.5,2\n");
  try {
    (void)brash::post::read_snapshot(dir / "bad.csv", false);
    ADD_FAILURE() << "no InputError";
  } catch (const brash::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.csv:2: column 'active'"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

// The moving window's snapshots hold every piece of the channel with a state column (0 in the scene, 1 held out,
// 2 removed): a statistic reads the pieces in the scene only (the band check does not see a held-out piece deep
// below the band), the pictures every piece (the ParaView file with its state field, the ice views drawing those
// outside the scene grey); a state other than 0, 1, 2 is refused naming the file, line and column.
TEST(Particles, StateColumnOfTheMovingWindow) {
  const auto dir = scratch("state");
  fs::create_directories(dir);
  const std::string header = "id,x,y,z,radius,vx,vy,vz,submerged_fraction,ca_x,ca_y,ca_z,active,state\n";
  brash::post::testing::write_text(dir / "particles_10.csv", header +
                                                                 "1,0.5,0.1,-0.2,0.01,0,0,0,1,0,0,0,0,2\n"
                                                                 "2,1.0,0,0,0.01,0.3,0,0,0.5,0.5,0.5,0.5,1,0\n"
                                                                 "3,1.5,-0.1,-0.3,0.01,0,0,0,1,0,0,0,0,1\n");
  brash::post::testing::write_text(dir / "index.csv", "step,t_s,file,hull_x_m\n10,0.5,particles_10.csv,0.2\n");
  const auto entries = brash::post::read_snapshot_index(dir, false);
  ASSERT_EQ(entries.size(), 1u);
  const auto scene = brash::post::read_snapshot(entries[0], false);
  EXPECT_EQ(scene.id, (std::vector<std::int64_t>{2}));
  EXPECT_EQ(scene.active, (std::vector<std::uint8_t>{1}));
  EXPECT_EQ(scene.state, (std::vector<std::uint8_t>{brash::post::kScene}));
  EXPECT_EQ(scene.vx, (std::vector<double>{0.3}));
  const auto all = brash::post::read_snapshot(entries[0], false, brash::post::Pieces::All);
  EXPECT_EQ(all.id, (std::vector<std::int64_t>{1, 2, 3}));
  EXPECT_EQ(all.state, (std::vector<std::uint8_t>{brash::post::kRemoved, brash::post::kScene, brash::post::kHeldOut}));
  EXPECT_EQ(all.z[2], -0.3);
  // the band check: pieces 1 and 3 reach 0.21 m and 0.31 m below the water, piece 2 0.01 m
  const auto band = brash::post::check_contact_band(entries, 0.1, 0.0, false);
  EXPECT_EQ(band.pieces_below_max, 0u);
  EXPECT_NEAR(band.deepest_bottom_m, 0.01, 1e-12);
  // ParaView: every piece, with the state field
  brash::post::PostCase c;
  c.lpp_m = 1.0, c.beam_m = 0.2, c.channel_width_m = 1.0;
  std::vector<std::string> notes;
  const auto pv = brash::post::write_paraview(dir, entries, std::nullopt, c, false, notes);
  ASSERT_EQ(pv.snapshots, 1u);
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName((dir / "paraview/particles_10.vtu").string().c_str());
  reader->Update();
  auto* grid = reader->GetOutput();
  ASSERT_EQ(grid->GetNumberOfPoints(), 3);
  auto* state = grid->GetPointData()->GetArray("state");
  ASSERT_NE(state, nullptr);
  EXPECT_EQ(state->GetTuple1(0), 2.0);
  EXPECT_EQ(state->GetTuple1(2), 1.0);
  // the ice views: the piece in the scene coloured, the two outside it grey (light held out, dark removed)
  const auto png = brash::post::plot_ice_views(all, entries[0], c, dir, dir / "work", {});
  EXPECT_TRUE(is_png(png)) << png;
  const auto script = brash::post::read_text_file(dir / "work/ice_views_10.gp");
  EXPECT_NE(script.find("ice_outside_10.dat' using 1:2:3:4 with circles lc rgb variable"), std::string::npos) << script;
  EXPECT_NE(script.find("1 particles in the scene; grey: 2 outside it"), std::string::npos) << script;
  const auto grey = brash::post::read_text_file(dir / "work/ice_outside_10.dat");
  EXPECT_NE(grey.find(fmt::format("0.5 0.1 0.01 {}\n", 0x8c8c8c)), std::string::npos) << grey;
  EXPECT_NE(grey.find(fmt::format("1.5 -0.1 0.01 {}\n", 0xd9d9d9)), std::string::npos) << grey;
  EXPECT_EQ(brash::post::read_text_file(dir / "work/ice_top_10.dat").find("1.5 "), std::string::npos);
  brash::post::testing::write_text(dir / "bad.csv", header + "1,0,0,0,0.01,0,0,0,0.9,0.5,0.5,0.5,1,3\n");
  try {
    (void)brash::post::read_snapshot(dir / "bad.csv", false);
    ADD_FAILURE() << "no InputError";
  } catch (const brash::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.csv:2: column 'state': '3'"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

TEST_F(Outputs, ParticlesReadBackWithMeshio) {
  const auto files = pvd_files(dir_ / "particles.pvd");
  ASSERT_FALSE(files.empty());
  // /usr/bin/python3: Debian's python3-meshio (the python3 on PATH may be another build).
  const auto py = fmt::format(
      "import meshio, sys\n"
      "m = meshio.read(sys.argv[1])\n"
      "pd = m.point_data\n"
      "assert m.points.shape == ({}, 3), m.points.shape\n"
      "for k in ('radius', 'velocity', 'submerged_fraction', 'ca', 'id', 'active'): assert k in pd, (k, list(pd))\n"
      "assert pd['velocity'].shape == ({}, 3) and pd['ca'].shape == ({}, 3)\n"
      "assert abs(pd['velocity'][7][0] - 0.07) < 1e-15 and abs(pd['submerged_fraction'][7] - 0.907) < 1e-15\n"
      "assert abs(m.points[7][0] - 0.9) < 1e-12\n",
      run_.particles, run_.particles, run_.particles);
  const auto script = dir_ / "check_meshio.py";
  brash::post::testing::write_text(script, py);
  EXPECT_EQ(sh(fmt::format("/usr/bin/python3 {} {}", script.string(), files[1].string())), 0);
}

TEST_F(Outputs, CompareMakesTableCsvAndPlot) {
  const auto second = scratch("run2");
  SyntheticRun r2;
  r2.mean_resistance_N = 3.0;
  write_synthetic_run(second, r2);
  const auto out = scratch("compare");
  ASSERT_EQ(sh(fmt::format("{} compare {} {} --out {} > /dev/null 2>&1", BRASH_POST_EXE, dir_.string(), second.string(), out.string())), 0);
  const auto csv = brash::post::read_text_file(out / "compare.csv");
  EXPECT_NE(csv.find("run,engine,fluid_model,speed_m_s,mean_N"), std::string::npos);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3);
  EXPECT_NE(csv.find(",complete,duration_s,window_start_s,window_end_s\n"), std::string::npos) << csv;
  // each run's length and averaging window beside its resistance (the synthetic runs: 45 s, window [15, 40] s)
  EXPECT_NE(brash::post::read_text_file(out / "compare.md").find("| synthetic | added_mass | 0.482 | 45.000 | 15.000-40.000 |"),
            std::string::npos) << brash::post::read_text_file(out / "compare.md");
  EXPECT_TRUE(is_png(out / "compare.png"));
  fs::remove_all(second);
  fs::remove_all(out);
}

// The contact band check of brash-post: a piece pushed 0.2 m down (bottom 0.2088 m below the waterline) in the
// snapshot at t = 20 s, with the contact hull cut 0.15 m below the waterline, is reported (note, contact_band.ok
// false, the deepest bottom and its time); a band 0.3 m deep passes; a full hull is not checked.
TEST(ContactBand, PieceBelowTheBandIsReported) {
  struct Variant {
    std::string band;
    bool checked, ok;
  };
  for (const auto& v : {Variant{"  band_m: [0.15, 0.1]\n", true, false}, Variant{"  band_m: [0.3, 0.1]\n", true, true},
                        Variant{"", false, true}}) {
    SCOPED_TRACE(v.band);
    const auto dir = scratch("band");
    SyntheticRun r;
    r.hull_extra_yaml = v.band;
    r.deep_piece_z_m = -0.2;
    write_synthetic_run(dir, r);
    ASSERT_EQ(sh(fmt::format("{} {} --no-plots --no-paraview > /dev/null 2>&1", BRASH_POST_EXE, dir.string())), 0);
    const auto j = nlohmann::json::parse(brash::post::read_text_file(dir / "report.json"));
    const std::string notes = j["notes"].dump();
    ASSERT_EQ(j.contains("contact_band"), v.checked);
    EXPECT_EQ(notes.find("contact band:") == std::string::npos, v.ok) << notes;
    if (v.checked) {
      const auto& b = j["contact_band"];
      EXPECT_EQ(b["ok"].get<bool>(), v.ok);
      EXPECT_NEAR(b["deepest_piece_bottom_below_waterline_m"].get<double>(), 0.2 + 0.0088, 1e-9);
      EXPECT_DOUBLE_EQ(b["deepest_t_s"].get<double>(), 20.0);
      EXPECT_EQ(b["snapshots"].get<int>(), 3);
      EXPECT_EQ(b["pieces_below_band_max"].get<int>(), v.ok ? 0 : 1);
    }
    fs::remove_all(dir);
  }
}

TEST(FarFieldNote, WindowAloneRunsAreFlagged) {
  struct Variant {
    std::string case_extra, meta_extra;
    bool flagged;
  };
  for (const auto& v : {Variant{"speedups:\n  farfield: true\n  farfield_wake_force_weight: 0\n", "", true},
                        Variant{"speedups:\n  farfield: true\n", "", false},  // the wake rule (default)
                        Variant{"", R"(, "skips": {"cull": true})", true},    // brash-ode --cull before the wake
                        Variant{"", R"(, "skips": {"cull": true, "cull_wake_force_N": 0})", true},  // window alone
                        Variant{"", R"(, "skips": {"cull": true, "cull_wake_force_N": 0.0123})", false},  // wake rule
                        Variant{"", R"(, "skips": {"cull": false})", false}}) {
    SCOPED_TRACE(v.case_extra + v.meta_extra);
    const auto dir = scratch("farfield_note");
    SyntheticRun r;
    write_synthetic_run(dir, r);
    {
      std::ofstream(dir / "case.yaml", std::ios::app) << v.case_extra;
    }
    if (!v.meta_extra.empty()) {
      std::string meta = brash::post::read_text_file(dir / "meta.json");
      meta.insert(meta.rfind('}'), v.meta_extra);
      brash::post::testing::write_text(dir / "meta.json", meta);
    }
    ASSERT_EQ(sh(fmt::format("{} {} --no-plots --no-paraview > /dev/null 2>&1", BRASH_POST_EXE, dir.string())), 0);
    const auto j = nlohmann::json::parse(brash::post::read_text_file(dir / "report.json"));
    EXPECT_EQ(j["notes"].dump().find("window alone") != std::string::npos, v.flagged) << j["notes"].dump();
    fs::remove_all(dir);
  }
}

namespace {
std::string sh_stdout(const std::string& cmd) {
  std::string out;
  if (FILE* p = ::popen(cmd.c_str(), "r")) {
    char buf[4096];
    while (std::fgets(buf, sizeof buf, p)) out += buf;
    ::pclose(p);
  }
  return out;
}
}  // namespace

// brash-post sample-stats: the statistics library on numbers from a script (bench/thermo_force.py). 1 2 3 4: mean
// 2.5, sd sqrt(5/3), se sd / 2, CI95 = t(0.975, 3) se = 3.182 se (the library's table: 3 decimals).
TEST(SampleStats, MeanSdSeAndStudentCi) {
  const auto j = nlohmann::json::parse(sh_stdout(fmt::format("echo '1 2\n3 4' | {} sample-stats -", BRASH_POST_EXE)));
  EXPECT_EQ(j["n"], 4);
  EXPECT_DOUBLE_EQ(j["mean"].get<double>(), 2.5);
  EXPECT_NEAR(j["sd"].get<double>(), std::sqrt(5.0 / 3.0), 1e-12);
  EXPECT_NEAR(j["se"].get<double>(), std::sqrt(5.0 / 3.0) / 2, 1e-12);
  EXPECT_NEAR(j["ci95"].get<double>(), 3.182 * std::sqrt(5.0 / 3.0) / 2, 1e-12);
  const auto dir = scratch("sample_stats");
  fs::create_directories(dir);
  const std::string bad = fmt::format("echo '1 2 x3' | {} sample-stats - > {}/err.txt 2>&1", BRASH_POST_EXE, dir.string());
  EXPECT_EQ(sh(bad), 2);
  EXPECT_NE(brash::post::read_text_file(dir / "err.txt").find("'x3' (value 3) is not a finite number"), std::string::npos);
  fs::remove_all(dir);
}

// brash-post difference: two separate runs' resistance, relative difference and the CIs added in quadrature.
TEST(Difference, RelativeDifferenceWithCombinedCi) {
  const auto ref = scratch("difference_ref"), other = scratch("difference_other");
  SyntheticRun a, b;
  b.mean_resistance_N = 2.2;
  write_synthetic_run(ref, a);
  write_synthetic_run(other, b);
  for (const auto& d : {ref, other})
    ASSERT_EQ(sh(fmt::format("{} {} --no-plots --no-paraview > /dev/null 2>&1", BRASH_POST_EXE, d.string())), 0);
  const auto report = [](const fs::path& d) {
    return nlohmann::json::parse(brash::post::read_text_file(d / "report.json"))["resistance_model_N"];
  };
  const auto ra = report(ref), rb = report(other);
  const auto j = nlohmann::json::parse(
      sh_stdout(fmt::format("{} difference {} {}", BRASH_POST_EXE, ref.string(), other.string())));
  const double m0 = ra["mean"], c0 = ra["ci95"], m1 = rb["mean"], c1 = rb["ci95"];
  EXPECT_NEAR(j["diff_rel"].get<double>(), (m1 - m0) / m0, 1e-12);
  EXPECT_NEAR(j["ci95_rel"].get<double>(), std::hypot(c0, c1) / m0, 1e-12);
  EXPECT_NEAR(j["diff_rel"].get<double>(), 0.1, 0.03);  // 2.2 vs 2.0 N plateaus
  EXPECT_TRUE(j["resolved"].get<bool>());
  fs::remove_all(ref);
  fs::remove_all(other);
}
