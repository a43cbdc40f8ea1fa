// The generated JBC hull against NMRI's published hydrostatics (the Tokyo 2015 workshop's JBC data,
// hull_meshes/data/README.md) and the FSICR bow parameters measured on NMRI's NURBS surfaces.
#include <brash/hull/hydrostatics.hpp>
#include <brash/hull/jbc.hpp>
#include <brash/hull/mesh.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <unistd.h>

namespace brash::hull {
namespace {

constexpr double kT = 0.4125, kLpp = 7.0;

class Jbc : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { mesh_ = new Mesh(make_jbc(load_jbc_data())); }
  static void TearDownTestSuite() { delete mesh_; }
  static const Mesh& mesh() { return *mesh_; }
  static inline Mesh* mesh_ = nullptr;
};

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

TEST_F(Jbc, WatertightOutward) {
  const MeshCheck c = check_mesh(mesh());
  EXPECT_TRUE(c.closed);
  EXPECT_EQ(c.boundary_edges, 0);     // every edge shared by ...
  EXPECT_EQ(c.nonmanifold_edges, 0);  // ... exactly two faces
  EXPECT_TRUE(c.oriented);
  EXPECT_TRUE(c.outward);
  EXPECT_EQ(c.degenerate_faces, 0);
  EXPECT_EQ(c.euler_characteristic, 2);
  EXPECT_EQ(2 * c.edges, 3 * c.faces);
  // Extents of the data: transom x = -0.125, bulb nose x = 7.149, B = 1.125, deck lid z = 0.625.
  EXPECT_NEAR(c.min_m.x(), -0.125, 1e-6);
  EXPECT_NEAR(c.max_m.x(), 7.149, 2e-3);
  EXPECT_NEAR(c.max_m.y(), 0.5625, 1e-6);
  EXPECT_NEAR(c.min_m.y(), -0.5625, 1e-6);
  EXPECT_NEAR(c.min_m.z(), 0.0, 0);
  EXPECT_NEAR(c.max_m.z(), 0.625, 1e-12);
  // Whole closed hull up to the lid: 4.37469 m^3 on the NURBS-derived STL of the README.
  EXPECT_LT(rel(c.signed_volume_m3, 4.37469), 0.01);
}

TEST_F(Jbc, HydrostaticsMatchPublished) {
  const Hydrostatics h = hydrostatics(mesh(), kT, kLpp);
  EXPECT_LT(rel(h.volume_m3, 2.78703), 0.01) << h.volume_m3;  // NMRI 178369.9 m^3 / 40^3
  EXPECT_LT(rel(h.cb, 0.8580), 0.01) << h.cb;                 // NMRI Cb
  EXPECT_NEAR(h.lcb_x_m, 3.5 + 0.025475 * kLpp, 0.005);       // NMRI LCB 2.5475 % Lpp fwd of midship
  EXPECT_NEAR(h.bwl_m, 1.125, 1e-6);
  EXPECT_LT(rel(h.lwl_m, 7.125), 0.001) << h.lwl_m;
  // No published waterplane area: compared with the README's STL/NURBS value.
  EXPECT_LT(rel(h.waterplane_area_m2, 7.286), 0.01) << h.waterplane_area_m2;
  // Wetted surface: compared with 12.42 m^2, the area of the NURBS surfaces below T (README), because
  // this mesh is built from the same geometry. NMRI's published S0 = 12.2226 m^2 is 1.6 % lower for a
  // reason the README could not find (other basis); we stay 1.2-2 % above it, like the NURBS.
  EXPECT_LT(rel(h.wetted_surface_m2, 12.42), 0.01) << h.wetted_surface_m2;
  EXPECT_GT(h.wetted_surface_m2 / 12.2226 - 1, 0.012);
  EXPECT_LT(h.wetted_surface_m2 / 12.2226 - 1, 0.020);
}

TEST_F(Jbc, StlRoundTripKeepsTopologyAndVolume) {
  const auto file = std::filesystem::temp_directory_path() / ("brash_test_jbc_" + std::to_string(::getpid()) + ".stl");
  write_stl(file, mesh());
  const Mesh r = read_mesh(file);
  std::filesystem::remove(file);
  EXPECT_EQ(r.vertices.size(), mesh().vertices.size());  // float32 rounding merged no vertices
  EXPECT_TRUE(check_mesh(r).ok());
  EXPECT_LT(rel(hydrostatics(r, kT, kLpp).volume_m3, hydrostatics(mesh(), kT, kLpp).volume_m3), 1e-6);
}

TEST_F(Jbc, ScalesGeometrically) {
  const double lambda = 40.0;  // full-scale JBC, Lpp 280 m
  const Mesh full = make_jbc(load_jbc_data(), {.lpp_m = kLpp * lambda});
  ASSERT_TRUE(check_mesh(full).ok());
  const Hydrostatics hm = hydrostatics(mesh(), kT, kLpp);
  const Hydrostatics hf = hydrostatics(full, kT * lambda, kLpp * lambda);
  EXPECT_LT(rel(hf.volume_m3, hm.volume_m3 * lambda * lambda * lambda), 1e-9);
  EXPECT_LT(rel(hf.wetted_surface_m2, hm.wetted_surface_m2 * lambda * lambda), 1e-9);
  EXPECT_LT(rel(hf.cb, hm.cb), 1e-9);
  EXPECT_TRUE(unit_problems(full, kT * lambda, kLpp * lambda).empty());
}

TEST_F(Jbc, CoarserGridStaysWithinOnePercent) {
  const Mesh coarse = make_jbc(load_jbc_data(), {.grid_factor = 2.0});
  ASSERT_TRUE(check_mesh(coarse).ok());
  EXPECT_LT(coarse.faces.size(), mesh().faces.size());
  const Hydrostatics h = hydrostatics(coarse, kT, kLpp);
  EXPECT_LT(rel(h.volume_m3, 2.78703), 0.01);
  EXPECT_LT(rel(h.waterplane_area_m2, 7.286), 0.01);
  EXPECT_LT(rel(h.wetted_surface_m2, 12.42), 0.01);
}

TEST_F(Jbc, WaterlineBandForDem) {
  const double lo = kT - 0.1, hi = kT + 0.1;
  const Mesh band = clip_band(mesh(), lo, hi);
  EXPECT_GT(band.faces.size(), 1000u);
  EXPECT_LT(band.faces.size(), mesh().faces.size() / 2);
  for (const auto& f : band.faces) {
    double zmin = 1e9, zmax = -1e9;
    for (int v : f) {
      zmin = std::min(zmin, band.vertices[v].z());
      zmax = std::max(zmax, band.vertices[v].z());
    }
    ASSERT_TRUE(zmax >= lo && zmin <= hi);
  }
  EXPECT_FALSE(check_mesh(band).closed);
  // The band keeps the waterline: same waterline length and breadth as the whole hull.
  const auto segs_full = hydrostatics(mesh(), kT, kLpp), segs_band = hydrostatics(band, kT, kLpp);
  EXPECT_DOUBLE_EQ(segs_band.lwl_m, segs_full.lwl_m);
  EXPECT_DOUBLE_EQ(segs_band.bwl_m, segs_full.bwl_m);
}

// README values (NURBS): alpha 38.0, phi2 79.7, psi 83.6, L_par 4.144, L_bow 1.376, A_wf 1.207, same
// conventions (B/4 point, buttock at T +- 5 mm, flat side within 0.01 mm of B/2). Angles agree within
// 1 deg. L_par, L_bow and A_wf depend on where the tangential flat side is said to end: the offsets have
// a station every 175 mm there and the monotone spline is flat only between two stations at B/2, so
// the flat side may end up to one station (0.175 m) earlier than on the NURBS.
TEST_F(Jbc, FsicrParametersNearNurbsValues) {
  const FsicrDetail d = measure_fsicr_detail(mesh(), kT, kLpp);
  const FsicrParams& p = d.params;
  EXPECT_NEAR(p.alpha_deg, 38.0, 1.0);
  EXPECT_NEAR(p.phi2_deg, 79.7, 1.0);
  EXPECT_NEAR(p.psi_deg, 83.6, 0.5);
  EXPECT_TRUE(d.bulbous_bow);
  EXPECT_EQ(p.phi1_deg, 90.0);
  EXPECT_NEAR(p.L_par_m, 4.144, 0.175);
  EXPECT_NEAR(p.L_bow_m, 1.376, 0.05);
  EXPECT_NEAR(p.A_wf_m2, 1.207, 0.03);
  EXPECT_NEAR(d.x_stem_m, 6.9999, 0.005);
  EXPECT_NEAR(d.x_b4_m, 6.774, 0.005);
  EXPECT_NEAR(p.B_m, 1.125, 1e-6);
  EXPECT_EQ(p.T_m, kT);
  EXPECT_EQ(p.L_m, kLpp);
}

}  // namespace
}  // namespace brash::hull
