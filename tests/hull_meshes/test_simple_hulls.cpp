// Hull tool on hulls with known answers: box barge (hydrostatics exact) and wedge bow (FSICR angles).
#include <brash/hull/hydrostatics.hpp>
#include <brash/hull/mesh.hpp>
#include <gtest/gtest.h>

#include "simple_hulls.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <numbers>

namespace brash::hull {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

TEST(BoxBarge, HydrostaticsExact) {
  const double L = 10, B = 2, D = 1.5, T = 0.6;
  const Mesh m = test::box(L, B, D);
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.ok());
  EXPECT_EQ(c.boundary_edges, 0);
  EXPECT_EQ(c.euler_characteristic, 2);
  EXPECT_NEAR(c.signed_volume_m3, L * B * D, 1e-12);
  const Hydrostatics h = hydrostatics(m, T, L);
  EXPECT_NEAR(h.volume_m3, L * B * T, 1e-12);
  EXPECT_NEAR(h.cb, 1.0, 1e-12);
  EXPECT_NEAR(h.lcb_x_m, L / 2, 1e-12);
  EXPECT_NEAR(h.kb_m, T / 2, 1e-12);
  EXPECT_NEAR(h.waterplane_area_m2, L * B, 1e-12);
  EXPECT_NEAR(h.lcf_x_m, L / 2, 1e-12);
  EXPECT_NEAR(h.wetted_surface_m2, L * B + 2 * (L + B) * T, 1e-12);
  EXPECT_NEAR(h.lwl_m, L, 1e-12);
  EXPECT_NEAR(h.bwl_m, B, 1e-12);
}

TEST(BoxBarge, StlRoundTripAndBand) {
  const Mesh m = test::box(7.0, 1.125, 0.625);
  const auto file = std::filesystem::temp_directory_path() / ("brash_test_box_" + std::to_string(::getpid()) + ".stl");
  write_stl(file, m);
  EXPECT_EQ(std::filesystem::file_size(file), 84u + 50u * m.faces.size());
  {  // the header's text ends with a line end (LIGGGHTS reads the first line as text, quotes paired)
    std::ifstream in(file, std::ios::binary);
    std::string first_line;
    std::getline(in, first_line);
    EXPECT_EQ(first_line, "brash binary STL, metres, 12 triangles");
  }
  const Mesh r = read_mesh(file);
  EXPECT_EQ(r.vertices.size(), 8u);
  EXPECT_EQ(r.faces.size(), 12u);
  EXPECT_TRUE(check_mesh(r).ok());
  EXPECT_NEAR(hydrostatics(r, 0.4125, 7.0).volume_m3, 7.0 * 1.125 * 0.4125, 1e-6);
  std::filesystem::remove(file);
  // Bottom and lid lie outside the band [0.3, 0.5]; the 8 side triangles cross it.
  const Mesh band = clip_band(m, 0.3, 0.5);
  EXPECT_EQ(band.faces.size(), 8u);
  EXPECT_FALSE(check_mesh(band).closed);
  EXPECT_EQ(check_mesh(band).boundary_edges, 8);
}

TEST(WedgeBow, AnglesAndLengthsExact) {
  const test::Wedge w{.L_par_T = 5.0, .B = 1.0, .T = 0.4, .D = 0.8, .alpha_deg = 30.0, .phi_deg = 60.0};
  const Mesh m = w.mesh();
  ASSERT_TRUE(check_mesh(m).ok());
  const FsicrDetail d = measure_fsicr_detail(m, w.T, 6.0);
  const FsicrParams& p = d.params;
  EXPECT_NEAR(p.alpha_deg, 30.0, 1e-9);
  EXPECT_NEAR(p.phi2_deg, 60.0, 1e-9);
  EXPECT_NEAR(d.phi1_geometric_deg, 60.0, 1e-9);
  EXPECT_FALSE(d.bulbous_bow);
  EXPECT_NEAR(p.phi1_deg, 60.0, 1e-9);
  const double psi = std::atan(std::tan(60.0 / kDeg) / std::sin(30.0 / kDeg)) * kDeg;
  EXPECT_NEAR(p.psi_deg, psi, 1e-9);
  EXPECT_NEAR(p.B_m, 1.0, 1e-12);
  EXPECT_NEAR(p.T_m, 0.4, 0);
  EXPECT_NEAR(p.L_m, 6.0, 0);
  // Sampled every L/70000: the flat-side end and the bow area are exact to that resolution.
  const double dx = 6.0 / 70000;
  EXPECT_NEAR(d.x_stem_m, w.x_stem(w.T), 1e-12);
  EXPECT_NEAR(p.L_par_m, w.L_par_T, 2 * dx);
  EXPECT_NEAR(p.L_bow_m, w.l_bow(), 2 * dx);
  EXPECT_NEAR(p.A_wf_m2, w.l_bow() * w.B / 2, 2 * dx * w.B);
  // Hydrostatics of the wedge: prism volume below T = T * area of the mean section (sections vary linearly).
  const Hydrostatics h = hydrostatics(m, w.T, 6.0);
  EXPECT_NEAR(h.waterplane_area_m2, w.L_par_T * w.B + w.l_bow() * w.B / 2, 1e-12);
  const double a0 = (w.x_stem(0) - w.l_bow()) * w.B + w.l_bow() * w.B / 2;
  EXPECT_NEAR(h.volume_m3, w.T * (a0 + h.waterplane_area_m2) / 2, 1e-12);
}

TEST(WedgeBow, OtherAnglesAndBulbRule) {
  const test::Wedge w{.L_par_T = 4.0, .B = 0.8, .T = 0.3, .D = 0.6, .alpha_deg = 22.5, .phi_deg = 45.0};
  const FsicrDetail d = measure_fsicr_detail(w.mesh(), w.T, 5.0);
  EXPECT_NEAR(d.params.alpha_deg, 22.5, 1e-9);
  EXPECT_NEAR(d.params.phi2_deg, 45.0, 1e-9);
  EXPECT_NEAR(d.params.phi1_deg, 45.0, 1e-9);
  // Inverted wedge (phi > 90): the keel is ahead of the stem at T, which the rule reads as a bulb.
  const test::Wedge inv{.L_par_T = 4.0, .B = 0.8, .T = 0.3, .D = 0.6, .alpha_deg = 22.5, .phi_deg = 100.0};
  const FsicrDetail di = measure_fsicr_detail(inv.mesh(), inv.T, 5.0);
  EXPECT_NEAR(di.phi1_geometric_deg, 100.0, 1e-9);
  EXPECT_NEAR(di.params.phi2_deg, 100.0, 1e-9);
}

TEST(RakedStemBow, StemAndButtockAnglesDiffer) {
  const test::RakedStem r{.x_shoulder = 5.0, .l_bow_T = 1.0, .B = 1.0, .T = 0.4, .D = 0.7, .phi1_deg = 70.0, .lpp = 6.0};
  const Mesh m = r.mesh();
  ASSERT_TRUE(check_mesh(m).ok());
  const FsicrDetail d = measure_fsicr_detail(m, r.T, r.lpp);
  const double phi2 = std::atan(2 * std::tan(70.0 / kDeg)) * kDeg;  // 79.7 deg
  EXPECT_NEAR(d.params.alpha_deg, std::atan(0.5 / 1.0) * kDeg, 1e-9);
  EXPECT_NEAR(d.phi1_geometric_deg, 70.0, 1e-9);
  EXPECT_NEAR(d.params.phi1_deg, 70.0, 1e-9);
  EXPECT_NEAR(d.params.phi2_deg, phi2, 1e-9);
  EXPECT_NEAR(d.params.psi_deg, std::atan(std::tan(phi2 / kDeg) / std::sin(d.params.alpha_deg / kDeg)) * kDeg, 1e-9);
  EXPECT_NEAR(d.x_stem_m, 6.0, 1e-12);
  EXPECT_NEAR(d.params.L_par_m, 5.0, 2 * r.lpp / 70000);
  EXPECT_NEAR(d.params.L_bow_m, 1.0, 2 * r.lpp / 70000);
  EXPECT_NEAR(d.params.A_wf_m2, 0.5, 2 * r.lpp / 70000);
}

}  // namespace
}  // namespace brash::hull
