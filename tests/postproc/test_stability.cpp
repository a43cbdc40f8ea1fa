// brash-post stability (brash/post/stability.hpp) on synthetic run directories: a closed box "hull", a few
// pieces with known positions and velocities, and meta.json endings of every kind.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <brash/hull/mesh.hpp>
#include <brash/post/stability.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using brash::post::analyze_stability;
using brash::post::StabilityResult;

namespace {

constexpr double kR = 0.0175, kD = 2 * kR;  // piece radius / diameter
constexpr double kU = 0.5;                  // ship speed
constexpr double kDraft = 0.2;              // box hull: x [0, 1], y [-0.2, 0.2], z [0, 0.4] in its frame

struct Piece {
  double x, y, z, vx = 0, vy = 0, vz = 0;
};
struct Dump {
  double t_s, hull_x_m;
  std::vector<Piece> pieces;
  bool nan = false;
};

void write(const fs::path& p, const std::string& s) {
  std::ofstream(p, std::ios::binary) << s;
}

fs::path box_hull(const fs::path& dir) {
  brash::hull::Mesh m;
  for (int k = 0; k < 8; ++k)
    m.vertices.emplace_back(k & 1 ? 1.0 : 0.0, k & 2 ? 0.2 : -0.2, k & 4 ? 0.4 : 0.0);
  // outward-oriented faces of the unit-index cube
  const int q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : q) m.faces.push_back({f[0], f[1], f[2]}), m.faces.push_back({f[0], f[2], f[3]});
  const fs::path p = dir / "box.stl";
  brash::hull::write_stl(p, m);
  return p;
}

// Floating level of the centre of a 900/1000 sphere: submerged height h with V_sub = 0.9 V.
double floating_z() {
  double lo = 0, hi = kD;
  for (int i = 0; i < 100; ++i) {
    const double h = 0.5 * (lo + hi);
    (std::numbers::pi * h * h * (3 * kR - h) / 3 < 0.9 * 4 * std::numbers::pi * kR * kR * kR / 3 ? lo : hi) =
        h;
  }
  return kR - lo;  // z of the centre: bottom at -h
}

// A run directory with the given dumps, meta status/reason and hull force fx (constant, -resistance).
fs::path make_run(const std::string& tag, const std::vector<Dump>& dumps,
                  const std::string& status = "complete", const std::string& reason = "", double fx_N = 0.0) {
  const fs::path dir = fs::temp_directory_path() / fmt::format("brash_test_stability_{}_{}", tag, ::getpid());
  fs::remove_all(dir);
  fs::create_directories(dir / "particles");
  const fs::path hull = box_hull(dir);
  write(dir / "case.yaml", fmt::format(R"(name: stab
hull: {{file: "{}", draft_m: {}, lpp_m: 1.0, beam_m: 0.4, start_x_m: -2.0}}
ship: {{speed_m_s: {}}}
channel: {{length_m: 3.0, width_m: 1.0}}
ice: {{thickness_m: 0.07, diameter_mean_m: {}, diameter_sd_m: 0.0, density_kg_m3: 900}}
water: {{density_kg_m3: 1000, level_m: 0.0}}
run: {{duration_s: 1.0, timestep_s: 1.0e-4, output_interval_s: 0.01, dump_interval_s: 0.5, window_s: [0.5, 1.0]}}
)",
                                       hull.string(), kDraft, kU, kD));
  nlohmann::json meta = {{"engine", "synthetic"},
                         {"treatment", "explicit"},
                         {"dt_s", 1e-4},
                         {"status", status},
                         {"reason", reason}};
  write(dir / "meta.json", meta.dump());
  std::string f = "t_s,fx_N,fy_N,fz_N\n";
  for (int k = 0; k <= 100; ++k) f += fmt::format("{},{},0,0\n", 0.01 * k, fx_N);
  write(dir / "hull_force.csv", f);
  std::string index = "step,t_s,file,hull_x_m\n";
  for (std::size_t k = 0; k < dumps.size(); ++k) {
    const auto& d = dumps[k];
    const auto file = fmt::format("particles_{}.csv", k);
    index += fmt::format("{},{},{},{}\n", k * 5000, d.t_s, file, d.hull_x_m);
    std::string p = "id,x,y,z,radius,vx,vy,vz,submerged_fraction,ca_x,ca_y,ca_z\n";
    for (std::size_t i = 0; i < d.pieces.size(); ++i) {
      const auto& q = d.pieces[i];
      p += fmt::format("{},{},{},{},{},{},{},{},0.9,0,0,0\n", i + 1, d.nan && i == 0 ? std::nan("") : q.x,
                       q.y, q.z, kR, q.vx, q.vy, q.vz);
    }
    write(dir / "particles" / file, p);
  }
  write(dir / "particles" / "index.csv", index);
  return dir;
}

// Three floating pieces in a row, well apart, far from the hull.
std::vector<Piece> calm() {
  const double z = floating_z();
  return {{0.5, 0.0, z}, {0.6, 0.1, z}, {0.7, -0.1, z}};
}

}  // namespace

TEST(StabilityAnalysis, SubmergedVolumeIntegralIsTheBuoyancyPotential) {
  using brash::post::submerged_volume_integral_m4;
  const double r = kR, pi = std::numbers::pi;
  EXPECT_EQ(submerged_volume_integral_m4(r, -0.01), 0.0);
  EXPECT_NEAR(submerged_volume_integral_m4(r, 2 * r), 4 * pi * std::pow(r, 4) / 3, 1e-18);
  for (const double h : {0.2 * r, r, 1.7 * r, 2.5 * r}) {  // d I / d h = V_sub(h)
    const double eps = 1e-7, hh = std::min(h, 2 * r);
    const double v_sub = pi * hh * hh * (3 * r - hh) / 3;
    const double dI =
        (submerged_volume_integral_m4(r, h + eps) - submerged_volume_integral_m4(r, h - eps)) / (2 * eps);
    EXPECT_NEAR(dI, v_sub, 1e-6 * v_sub) << h;
  }
}

TEST(StabilityAnalysis, CalmCompleteRunIsStable) {
  const auto dir = make_run("calm", {{0.0, -2.0, calm()}, {0.5, -1.75, calm()}, {1.0, -1.5, calm()}});
  const StabilityResult r = analyze_stability(dir);
  EXPECT_EQ(r.status, "complete");
  EXPECT_EQ(r.verdict, "stable") << (r.silent_reasons.empty() ? "" : r.silent_reasons[0]);
  EXPECT_EQ(r.snapshots, 3u);
  EXPECT_EQ(r.pieces, 3u);
  ASSERT_TRUE(r.max_hull_penetration_d);
  EXPECT_EQ(*r.max_hull_penetration_d, 0.0);
  EXPECT_EQ(r.max_overlap_d, 0.0);
  EXPECT_EQ(r.escaped_max, 0u);
  EXPECT_EQ(r.above_water_max, 0u);
  EXPECT_NEAR(r.above_water_m, 0.14, 1e-12);  // 2 ice thicknesses
  ASSERT_TRUE(r.energy_excess);
  EXPECT_NEAR(*r.energy_excess, 0.0, 1e-12);
  EXPECT_NEAR(r.energy_ref_J, 3 * 0.5 * 900 * 4 * std::numbers::pi * kR * kR * kR / 3 * kU * kU, 1e-12);
  EXPECT_EQ(r.energy_first_J, r.energy_last_J);
  // floating is the minimum of gravity + buoyancy potential: a piece pushed 3 mm down or lifted 3 mm has more
  // energy
  for (const double dz : {-0.003, 0.003}) {
    auto moved = calm();
    moved[0].z += dz;
    EXPECT_GT(analyze_stability(make_run("calm_dz", {{0.0, -2.0, moved}})).energy_first_J, r.energy_first_J)
        << dz;
  }
}

TEST(StabilityAnalysis, PieceInsideTheHullIsASilentPenetration) {
  auto inside = calm();
  // hull at x = -1.5 + [0, 1] in the scene at t = 1 s, keel at z = -0.2: a centre 5 cm inside its top side
  // wall
  inside[1] = {-1.0, 0.15, -0.05};
  const auto dir = make_run("pen", {{0.0, -2.0, calm()}, {1.0, -1.5, inside}});
  const StabilityResult r = analyze_stability(dir);
  ASSERT_TRUE(r.max_hull_penetration_d);
  EXPECT_NEAR(*r.max_hull_penetration_d, (kR + 0.05) / kD,
              1e-5);  // float32 STL; centre inside: r + distance to the surface
  EXPECT_EQ(r.max_penetration_piece, 2);
  EXPECT_EQ(r.max_penetration_t_s, 1.0);
  EXPECT_EQ(r.verdict, "silent");
  ASSERT_EQ(r.silent_reasons.size(), 1u);
  EXPECT_NE(r.silent_reasons[0].find("hull penetration"), std::string::npos) << r.silent_reasons[0];
  // the same piece outside the hull, touching it by a quarter of its diameter: measured, not silent
  inside[1] = {-1.0, 0.2 + kR - 0.25 * kD, -0.05};
  const StabilityResult ok =
      analyze_stability(make_run("pen_ok", {{0.0, -2.0, calm()}, {1.0, -1.5, inside}}));
  EXPECT_NEAR(*ok.max_hull_penetration_d, 0.25, 1e-5);
  EXPECT_EQ(ok.verdict, "stable");
}

TEST(StabilityAnalysis, SphereOverlapIsTheLargestPairOverlapOverDiameter) {
  auto p = calm();
  p[1] = {p[0].x + 0.6 * kD, p[0].y, p[0].z};  // overlap 0.4 d
  StabilityResult r = analyze_stability(make_run("ov", {{0.0, -2.0, p}}));
  EXPECT_NEAR(r.max_overlap_d, 0.4, 1e-9);
  EXPECT_EQ(r.max_overlap_pieces[0], 1);
  EXPECT_EQ(r.max_overlap_pieces[1], 2);
  EXPECT_EQ(r.verdict, "stable");
  p[2] = {p[0].x, p[0].y - 0.3 * kD, p[0].z};  // overlap 0.7 d: silent
  r = analyze_stability(make_run("ov2", {{0.0, -2.0, p}}));
  EXPECT_NEAR(r.max_overlap_d, 0.7, 1e-9);
  EXPECT_EQ(r.verdict, "silent");
}

TEST(StabilityAnalysis, EscapedAndJumpingPiecesAreCounted) {
  auto p = calm();
  p[0].y = 0.51;  // beyond the wall at y = 0.5
  p[2].z = 0.2;   // 0.2 m above the water > 2 x 0.07
  const StabilityResult r = analyze_stability(make_run("esc", {{0.0, -2.0, calm()}, {0.5, -1.75, p}}));
  EXPECT_EQ(r.escaped_max, 1u);
  EXPECT_EQ(r.above_water_max, 1u);
  EXPECT_NEAR(r.max_height_above_water_d, 0.2 / kD, 1e-9);
  EXPECT_EQ(r.verdict, "silent");
  EXPECT_EQ(r.silent_reasons.size(), 3u);  // escaped, above water, and the energy of lifting a piece 0.2 m
}

TEST(StabilityAnalysis, EnergyNotPaidByTheHullIsCreated) {
  auto fast = calm();
  for (auto& q : fast) q.vx = 2 * kU;  // every piece at twice the ship's speed: 4 x E_ref of kinetic energy
  const auto dumps = std::vector<Dump>{{0.0, -2.0, calm()}, {1.0, -1.5, fast}};
  StabilityResult r = analyze_stability(make_run("energy", dumps));
  ASSERT_TRUE(r.energy_excess);
  EXPECT_NEAR(*r.energy_excess, 4.0, 1e-9);
  EXPECT_EQ(r.verdict, "silent");
  // a hull that pushed with 1 N over 1 s at 0.5 m/s did 0.5 J of work, more than that energy: physical
  const double e_ref = r.energy_ref_J;
  ASSERT_LT(4 * e_ref, 0.5);
  r = analyze_stability(make_run("energy_paid", dumps, "complete", "", -1.0));
  EXPECT_NEAR(*r.work_hull_J, 0.5, 1e-9);
  EXPECT_NEAR(*r.energy_excess, 0.0, 1e-12);  // max over the snapshots of E - E0 - W: 0 at the first one
  EXPECT_EQ(r.verdict, "stable");
}

TEST(StabilityAnalysis, GuardStopsAndCrashesAreNamed) {
  const std::vector<Dump> d{{0.0, -2.0, calm()}};
  struct Case {
    std::string status, reason, want_status, want_guard;
  };
  for (const auto& c : std::vector<Case>{
           {"failed",
            "guard: step 30 (t = 0.003 s): piece 42: runaway kinetic energy: 4.494 J > ke_max = 1.428 J",
            "guard", "kinetic_energy"},
           {"failed", "ERROR: fix brash/guard: step 1200: atom 17: left the box: x = 2.31 > xhi = 2.2 (m)",
            "guard", "box"},
           {"failed", "guard: step 380 (t = 0.19 s): piece 721: hull penetration: 0.01906 m = 54 %", "guard",
            "hull"},
           {"failed", "guard: step 5: piece 1: above zmax: z = 1 > 0.3 m (jumped out of the water)", "guard",
            "zmax"},
           {"failed", "guard: step 5: piece 1: non-finite velocity: vx = nan", "guard", "nan"},
           {"failed", "LIGGGHTS exited with code 1", "crashed", ""},
           {"running", "", "crashed", ""}}) {
    const StabilityResult r = analyze_stability(make_run("end", d, c.status, c.reason));
    EXPECT_EQ(r.status, c.want_status) << c.reason;
    EXPECT_EQ(r.guard, c.want_guard) << c.reason;
    EXPECT_EQ(r.verdict, c.want_status) << c.reason;
    if (c.status == "failed") {
      EXPECT_EQ(r.message, c.reason);
    }
  }
}

TEST(StabilityAnalysis, NonFiniteSnapshotOfACompleteRunIsSilent) {
  auto d = std::vector<Dump>{{0.0, -2.0, calm()}, {0.5, -1.75, calm(), true}};
  const StabilityResult r = analyze_stability(make_run("nan", d));
  EXPECT_EQ(r.non_finite_snapshots, 1u);
  EXPECT_EQ(r.snapshots, 1u);
  EXPECT_EQ(r.verdict, "silent");
}

#ifdef BRASH_POST_EXE
TEST(StabilityAnalysis, CommandWritesJson) {
  const auto dir = make_run("cli", {{0.0, -2.0, calm()}});
  const std::string cmd = fmt::format("'{}' stability '{}' > '{}' 2>&1", BRASH_POST_EXE, dir.string(),
                                      (dir / "out.txt").string());
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  std::ifstream in(dir / "stability.json");
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["verdict"], "stable");
  EXPECT_EQ(j["status"], "complete");
  EXPECT_EQ(j["max_overlap_d"], 0.0);
}
#endif
