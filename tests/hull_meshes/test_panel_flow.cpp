// The hull side of the panel flow (panel_flow.hpp): the waterline cut, the panels grouped from a fine mesh,
// the double body of a half-submerged sphere against the whole sphere's closed form, the table file, and on
// the JBC the stagnation at the stem that the thin-ship sheet cannot give.
#include <gtest/gtest.h>

#include <brash/hull/flow.hpp>
#include <brash/hull/panel_flow.hpp>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "../core/panel_meshes.hpp"
#include "brash/error.hpp"

#ifndef BRASH_JBC_MODEL_STL
#error "BRASH_JBC_MODEL_STL must be defined by the build"
#endif

namespace {

using brash::core::Triangle;
using brash::core::Vec3;
namespace core = brash::core;
namespace hull = brash::hull;

constexpr double kU = 0.482;

hull::Mesh mesh_of(const std::vector<Triangle>& tris, const Vec3& shift) {
  hull::Mesh m;
  for (const Triangle& t : tris) {
    const int k = static_cast<int>(m.vertices.size());
    for (const Vec3& v : t.v) m.vertices.push_back(v + shift);
    m.faces.push_back({k, k + 1, k + 2});
  }
  return m;
}

// a sphere of radius a moving at U e_x (Lamb §92): the still-water flow
Vec3 sphere_exact(const Vec3& p, double a) {
  const double r = p.norm();
  return kU * a * a * a / 2 * (3 * p.x() * p / std::pow(r, 5) - Vec3::UnitX() / std::pow(r, 3));
}

// the largest |u - exact| / U at 1.1 and 2 radii over directions below the water
double sphere_error(const core::PanelSolution& s, double a) {
  double e = 0;
  for (const Triangle& t : brash::test::icosphere(2)) {
    const Vec3 d = core::triangle_centroid(t).normalized();
    if (d.z() > -0.05) continue;
    for (double f : {1.1, 2.0})
      e = std::max(e, (core::panel_velocity(s, f * a * d) - sphere_exact(f * a * d, a)).norm() / kU);
  }
  return e;
}

TEST(PanelFlowHull, CutAtTheWaterlineKeepsHalfTheSphere) {
  const double a = 0.3, water = 0.5;
  const std::vector<Triangle> sphere = brash::test::scaled(brash::test::icosphere(3), Vec3::Constant(a));
  double whole = 0, wetted = 0;
  for (const Triangle& t : sphere) whole += core::triangle_area(t);
  const std::vector<Triangle> w = hull::wetted_triangles(mesh_of(sphere, Vec3(0, 0, water)), water);
  for (const Triangle& t : w) {
    wetted += core::triangle_area(t);
    for (const Vec3& v : t.v) ASSERT_LE(v.z(), 1e-12);
    EXPECT_GT(core::triangle_normal(t).dot(core::triangle_centroid(t)), 0.0);  // still outward
  }
  EXPECT_NEAR(wetted, whole / 2, 1e-3 * whole);
  EXPECT_GT(w.size(), sphere.size() / 2);  // the triangles across the waterline were cut, not dropped
}

TEST(PanelFlowHull, HalfSubmergedSphereWithItsMirrorIsTheWholeSphere) {
  const double a = 0.3, water = 0.5;
  const hull::Mesh m =
      mesh_of(brash::test::scaled(brash::test::icosphere(3), Vec3::Constant(a)), Vec3(0, 0, water));
  const core::PanelSolution s = hull::panel_solution(m, water, kU, {.max_panels = 2000});
  EXPECT_TRUE(s.body.mirror_z);
  const double e = sphere_error(s, a);
  RecordProperty("error", std::to_string(e));
  EXPECT_LT(e, 0.01);
  EXPECT_NEAR(core::panel_velocity(s, Vec3(0.4, 0.1, 0.0)).z(), 0.0, 1e-12);  // a rigid lid
}

TEST(PanelFlowHull, GroupedPanelsOfAFineMeshMatchTheClosedForm) {
  // 2560 wetted triangles in 640 panels: the grouping keeps the exact geometry with a quarter of the unknowns
  const double a = 0.3;
  const hull::Mesh m =
      mesh_of(brash::test::scaled(brash::test::icosphere(4), Vec3::Constant(a)), Vec3::Zero());
  const core::PanelSolution s = hull::panel_solution(m, 0.0, kU, {.max_panels = 640});
  EXPECT_EQ(s.body.panels(), 640u);
  const double e = sphere_error(s, a);
  RecordProperty("error", std::to_string(e));
  EXPECT_LT(e, 0.01);
}

TEST(PanelFlowHull, TableFileRoundTripAndKey) {
  const hull::Mesh m =
      mesh_of(brash::test::scaled(brash::test::icosphere(2), Vec3::Constant(0.3)), Vec3::Zero());
  const core::FlowTable t = hull::panel_flow(m, 0.0, kU, {.table_spacing_fraction_of_draft = 0.5});
  const auto file = std::filesystem::temp_directory_path() / "brash_test_panel_flow.bin";
  hull::write_flow_table(file, t, "key 1");
  const auto back = hull::read_flow_table(file, "key 1");
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->values(), t.values());
  EXPECT_EQ(back->nodes(), t.nodes());
  EXPECT_EQ(back->at(Vec3(0.35, -0.1, -0.1)), t.at(Vec3(0.35, -0.1, -0.1)));
  EXPECT_FALSE(hull::read_flow_table(file, "key 2").has_value());
  EXPECT_FALSE(hull::read_flow_table(file.string() + ".missing", "key 1").has_value());
  std::filesystem::remove(file);
}

TEST(PanelFlowHull, RefusesAHullOutOfTheWater) {
  const hull::Mesh m = mesh_of(brash::test::icosphere(1), Vec3::Zero());
  EXPECT_THROW(hull::panel_solution(m, 2.0, kU), brash::InputError);
  EXPECT_THROW(hull::panel_solution(m, -2.0, kU), brash::InputError);
}

// The JBC's double-body solution at the paper case's speed, solved once for the tests below (~30 s).
const core::PanelSolution& jbc_solution() {
  static const core::PanelSolution s = hull::panel_solution(hull::read_mesh(BRASH_JBC_MODEL_STL), 0.4125, kU);
  return s;
}

// A place on the JBC's wetted surface: a triangle's centroid and its outward normal.
struct Site {
  std::string name;
  Vec3 centre, normal;
};

// the triangle of the solution with the highest score
template <class Score>
Site site(const std::string& name, Score score) {
  const core::PanelSolution& s = jbc_solution();
  double best = -1e300;
  Site out{name, Vec3::Zero(), Vec3::Zero()};
  for (const Triangle& t : s.body.triangles) {
    const Vec3 c = core::triangle_centroid(t), n = core::triangle_normal(t);
    const double v = score(c, n);
    if (v > best) best = v, out.centre = c, out.normal = n;
  }
  return out;
}

// The stem (the foremost point a little under the water), the bow shoulder (0.93 L, the side turning into the
// bow), the side of the parallel midbody and the bilge of the forebody (x = 0.9 L, normal half down).
std::vector<Site> jbc_sites() {
  return {site("stem", [](const Vec3& c, const Vec3&) { return c.z() < -0.02 && c.z() > -0.06 ? c.x() : -1e9; }),
          site("shoulder", [](const Vec3& c, const Vec3& n) {
            return n.y() > 0.7 ? -(c - Vec3(0.93 * 7.0, 0.4, -0.2)).norm() : -1e9;
          }),
          site("side", [](const Vec3& c, const Vec3& n) { return n.y() > 0.95 ? -(c - Vec3(3.5, 0.6, -0.2)).norm() : -1e9; }),
          site("bilge", [](const Vec3& c, const Vec3& n) {
            return c.x() > 6.2 && c.x() < 6.4 && c.y() > 0 ? n.dot(Vec3(0, 1, -1).normalized()) : -1e9;
          })};
}

constexpr double kPieceDiameter = 0.0176;  // the paper case's ice pieces (m)
// the paper case's clearance (brash::hull_flow_table): half its smallest piece's radius, (d - 3 sd) / 4
constexpr double kClearance = (0.017578 - 3 * 0.0008789) / 4;

// At 0.25, 0.5, 1 and 2 piece diameters off the stem, the bow shoulder, the side and the bilge, the engine's
// table (the cells of hull::panel_flow's grid around each place, built as the whole table builds them) gives the
// panel sum within 2 % of U. The regular table, which samples the panels' field inside the hull and interpolates
// across its surface, misses by far more at the stem.
TEST(PanelFlowHull, JbcTableMatchesThePanelSumUpToTheHull) {
  const core::PanelSolution& s = jbc_solution();
  const hull::Mesh jbc = hull::read_mesh(BRASH_JBC_MODEL_STL);
  double worst_regular_stem = 0;
  for (const Site& place : jbc_sites()) {
    hull::PanelFlowSettings st;
    st.window = std::make_pair(place.centre - Vec3::Constant(0.05), place.centre + Vec3::Constant(0.05));
    st.near_hull.clearance_m = kClearance;
    const core::FlowTable table = hull::panel_flow(s, jbc, 0.4125, st);
    core::FlowField plain;
    plain.velocity = [&](const Vec3& p) { return core::panel_velocity(s, p); };
    const core::FlowTable regular(plain, table.lo(), table.hi(), table.nodes(), table.mirror_y());
    for (double d : {0.25, 0.5, 1.0, 2.0}) {
      const Vec3 p = place.centre + d * kPieceDiameter * place.normal;
      const Vec3 direct = core::panel_velocity(s, p);
      const double e = (table.at(p) - direct).norm() / kU, e_regular = (regular.at(p) - direct).norm() / kU;
      RecordProperty(place.name + "_" + std::to_string(d), std::to_string(e) + " (regular " + std::to_string(e_regular) + ")");
      EXPECT_LT(e, 0.02) << place.name << " at " << d << " diameters";
      if (place.name == "stem") worst_regular_stem = std::max(worst_regular_stem, e_regular);
    }
  }
  EXPECT_GT(worst_regular_stem, 0.2);  // the table as it was fails this check
}

// The same for the thin-ship flow against its own sheet (the sources' regularised sum).
TEST(PanelFlowHull, JbcThinShipTableMatchesTheSheetUpToTheHull) {
  const hull::Mesh jbc = hull::read_mesh(BRASH_JBC_MODEL_STL);
  const hull::ThinShipSheet sheet = hull::thin_ship_sheet(jbc, 0.4125, kU);
  for (const Site& place : jbc_sites()) {
    hull::ThinShipSettings st;
    st.window = std::make_pair(place.centre - Vec3::Constant(0.05), place.centre + Vec3::Constant(0.05));
    const core::FlowTable table = hull::thin_ship_flow(jbc, 0.4125, kU, st);
    for (double d : {0.25, 0.5, 1.0, 2.0}) {
      const Vec3 p = place.centre + d * kPieceDiameter * place.normal;
      const Vec3 direct = core::induced_velocity(sheet.sources, p, sheet.core_radius_m);
      EXPECT_LT((table.at(p) - direct).norm() / kU, 0.02) << place.name << " at " << d << " diameters";
    }
  }
}

// A sphere hull (half under the water: with its mirror image the whole sphere) against the closed form at 0.02
// to 0.1 radii off its surface, all round its wetted half; the regular table does not hold it. (At 0.01 radii
// these 1,280 panels themselves miss the closed form by 2.6 % of U; the table of the closed-form field holds 0.01
// to 0.1 radii: tests/core/test_flow_acceleration.cpp.)
TEST(PanelFlowHull, SphereHullTableMatchesTheClosedFormUpToTheSurface) {
  const double a = 0.3;
  const hull::Mesh m = mesh_of(brash::test::scaled(brash::test::icosphere(4), Vec3::Constant(a)), Vec3::Zero());
  const core::PanelSolution s = hull::panel_solution(m, 0.0, kU, {.max_panels = 1280});
  hull::PanelFlowSettings st;
  st.window = std::make_pair(Vec3(-1.2 * a, 0.0, -1.2 * a), Vec3(1.2 * a, 1.2 * a, 0.0));
  const core::FlowTable table = hull::panel_flow(s, m, 0.0, st);
  core::FlowField plain;
  plain.velocity = [&](const Vec3& p) { return core::panel_velocity(s, p); };
  const core::FlowTable regular(plain, table.lo(), table.hi(), table.nodes(), table.mirror_y());
  double worst = 0, worst_regular = 0;
  for (double off : {0.02, 0.05, 0.1})
    for (double th = 0.1; th < std::numbers::pi; th += 0.25)
      for (double ph = 0.1; ph < std::numbers::pi; ph += 0.25) {  // y > 0, z < 0
        const Vec3 d(std::cos(th), std::sin(th) * std::cos(ph), -std::sin(th) * std::sin(ph));
        const Vec3 p = (1 + off) * a * d;
        worst = std::max(worst, (table.at(p) - sphere_exact(p, a)).norm() / kU);
        worst_regular = std::max(worst_regular, (regular.at(p) - sphere_exact(p, a)).norm() / kU);
      }
  RecordProperty("error", std::to_string(worst));
  RecordProperty("error_regular_table", std::to_string(worst_regular));
  EXPECT_LT(worst, 0.02);
  EXPECT_GT(worst_regular, 0.02);
}

// The JBC model at its draft: towards the stem along the centre line at the waterline, the water ahead moves
// more and more with the hull (stagnation: the relative speed falls towards 0); the thin-ship sheet, a smoothed
// centre-plane source, keeps about half the relative flow there (its sum itself: 0.65 / 0.51 / 0.43 of U at 20 /
// 10 / 5 cm). (Closer than ~2 cm, a panel's size at the stem,
// the first-order panels' own near field shows.)
TEST(PanelFlowHull, JbcStemIsAStagnationPoint) {
  const double draft = 0.4125;
  const hull::Mesh jbc = hull::read_mesh(BRASH_JBC_MODEL_STL);
  const core::PanelSolution& s = jbc_solution();
  double x_stem = -1e9;  // the stem at the waterline: the foremost wetted point near z = 0 and y = 0
  for (const Triangle& t : s.body.triangles)
    for (const Vec3& v : t.v)
      if (v.z() > -0.005 && std::abs(v.y()) < 0.01) x_stem = std::max(x_stem, v.x());
  const hull::ThinShipSheet sheet = hull::thin_ship_sheet(jbc, draft, kU);
  auto relative = [&](const Vec3& u) { return (u - kU * Vec3::UnitX()).norm() / kU; };
  double previous = 1.0;
  for (double ahead : {0.2, 0.1, 0.05, 0.025}) {
    const Vec3 p(x_stem + ahead, 0.0, -0.01);
    const double panel_rel = relative(core::panel_velocity(s, p));
    const double thin_rel = relative(core::induced_velocity(sheet.sources, p, sheet.core_radius_m));
    RecordProperty("panel_relative_" + std::to_string(ahead), std::to_string(panel_rel));
    RecordProperty("thin_ship_relative_" + std::to_string(ahead), std::to_string(thin_rel));
    EXPECT_LT(panel_rel, previous) << ahead;
    EXPECT_GT(thin_rel, 0.4) << ahead;
    previous = panel_rel;
  }
  EXPECT_LT(previous, 0.3);  // 2.5 cm ahead of the stem
  // and far ahead both fade to still water
  EXPECT_LT(core::panel_velocity(s, Vec3(x_stem + 3.0, 0.0, -0.1)).norm(), 0.02 * kU);
}

}  // namespace
