// fluid.hull_flow: panel through the case (brash/case_hull_flow.hpp): the key is read and written back, the
// table is the hull side's panel flow, cached beside the packing and computed again when its key changes.
#include <gtest/gtest.h>

#include <brash/case.hpp>
#include <brash/case_hull_flow.hpp>
#include <brash/error.hpp>
#include <brash/hull/flow.hpp>
#include <brash/hull/panel_flow.hpp>
#include <cmath>
#include <filesystem>
#include <numbers>

namespace {

namespace fs = std::filesystem;

// a half-submerged closed spheroid 1.2 x 0.4 x 0.4 m, keel at z = 0 (a crude hull)
brash::hull::Mesh spheroid(int nu, int nv) {
  brash::hull::Mesh m;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double th = std::numbers::pi * j / nv, ph = 2 * std::numbers::pi * i / nu;
      m.vertices.emplace_back(0.6 * std::cos(th), 0.2 * std::sin(th) * std::cos(ph),
                              0.2 + 0.2 * std::sin(th) * std::sin(ph));
    }
  auto id = [&](int i, int j) { return j * nu + i % nu; };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

brash::Case panel_case(const fs::path& dir, double speed) {
  brash::Case c = brash::parse_case("name: p\nfluid: {model: drag, hull_flow: panel}\n", dir, "test");
  c.hull.draft_m = 0.2;
  c.water.level_m = 0.0;
  c.ship.speed_m_s = speed;
  return c;
}

TEST(CaseHullFlow, PanelIsACaseKey) {
  const brash::Case c = panel_case(fs::temp_directory_path(), 0.5);
  EXPECT_EQ(c.fluid.hull_flow, brash::HullFlow::Panel);
  EXPECT_NE(brash::dump_case_yaml(c).find("  hull_flow: panel\n"), std::string::npos);
  EXPECT_THROW(brash::parse_case("name: p\nfluid: {model: drag, hull_flow: panels}\n",
                                 fs::temp_directory_path(), "test"),
               brash::InputError);
}

TEST(CaseHullFlow, PanelFlowIsCachedBesideThePackingAndKeyed) {
  const fs::path dir = fs::temp_directory_path() / "brash_test_case_hull_flow";
  fs::remove_all(dir);
  const brash::hull::Mesh m = spheroid(24, 12);
  // the cache does not depend on the table's kind: the cheapest (CouplingChoosesTheTable checks the choice)
  brash::Case c = panel_case(dir, 0.5);
  c.fluid.hull_flow_coupling = brash::HullFlowCoupling::DragRegularTable;
  const fs::path cache = brash::panel_flow_cache_file(c);
  EXPECT_EQ(cache, dir / "generated/panel_flow.bin");
  const brash::core::FlowTable first = brash::hull_flow_table(c, m);
  ASSERT_TRUE(fs::exists(cache));
  const brash::hull::PanelFlowSettings settings{.near_hull = brash::hull_flow_near_hull(c)};
  EXPECT_EQ(first.values(), brash::hull::panel_flow(m, 0.2, 0.5, settings).values());  // the hull side's table
  // ahead of the nose the water is pushed forward
  EXPECT_GT(first.at(brash::core::Vec3(0.65, 0.0, -0.02)).x(), 0.1);
  // read back, not computed: a marked cache file under the same key comes back as it is
  brash::hull::write_flow_table(
      cache,
      brash::core::FlowTable::from_values(first.lo(), first.hi(), first.nodes(), true,
                                          std::vector<double>(first.values().size(), 7.0)),
      brash::panel_flow_key(c, m));
  EXPECT_EQ(brash::hull_flow_table(c, m).values().front(), 7.0);
  // another speed: another key, computed again (and the flow scales with the speed)
  brash::Case faster = panel_case(dir, 1.0);
  faster.fluid.hull_flow_coupling = c.fluid.hull_flow_coupling;
  EXPECT_NE(brash::panel_flow_key(faster, m), brash::panel_flow_key(c, m));
  const brash::core::FlowTable second = brash::hull_flow_table(faster, m);
  const brash::core::Vec3 p(0.7, 0.1, -0.05);
  EXPECT_NEAR(second.at(p).x(), 2.0 * first.at(p).x(), 1e-9);
  // another hull: another key
  brash::hull::Mesh moved = m;
  moved.vertices[0].x() += 1e-3;
  EXPECT_NE(brash::panel_flow_key(c, moved), brash::panel_flow_key(c, m));
  // thin_ship and none are not cached
  brash::Case thin = c;
  thin.fluid.hull_flow = brash::HullFlow::ThinShip;
  EXPECT_EQ(brash::hull_flow_table(thin, m).values(),
            brash::hull::thin_ship_flow(m, 0.2, 0.5, {.near_hull = brash::hull_flow_near_hull(thin)}).values());
  thin.fluid.hull_flow = brash::HullFlow::None;
  EXPECT_TRUE(brash::hull_flow_table(thin, m).empty());
  fs::remove_all(dir);
}

// fluid.hull_flow_coupling: full holds Du/Dt and the bricks along the hull; drag the same bricks without Du/Dt;
// drag_regular_table neither (the table of earlier versions, which samples the field inside the hull). Each its own cache key.
TEST(CaseHullFlow, CouplingChoosesTheTable) {
  const fs::path dir = fs::temp_directory_path() / "brash_test_case_hull_flow_coupling";
  fs::remove_all(dir);
  const brash::hull::Mesh m = spheroid(24, 12);
  brash::Case c = panel_case(dir, 0.5);  // the panel flow's cache keys
  const std::string full_key = brash::panel_flow_key(c, m);
  c.fluid.hull_flow_coupling = brash::HullFlowCoupling::Drag;
  const std::string drag_key = brash::panel_flow_key(c, m);
  c.fluid.hull_flow_coupling = brash::HullFlowCoupling::DragRegularTable;
  EXPECT_NE(full_key, drag_key);
  EXPECT_NE(drag_key, brash::panel_flow_key(c, m));
  c.fluid.hull_flow = brash::HullFlow::ThinShip;  // the tables (the thin-ship sheet's: the same choice, cheaper)
  const brash::core::FlowTable regular = brash::hull_flow_table(c, m);
  c.fluid.hull_flow_coupling = brash::HullFlowCoupling::Drag;
  const brash::core::FlowTable drag = brash::hull_flow_table(c, m);
  c.fluid.hull_flow_coupling = brash::HullFlowCoupling::Full;
  const brash::core::FlowTable full = brash::hull_flow_table(c, m);
  EXPECT_TRUE(full.has_acceleration());
  EXPECT_FALSE(drag.has_acceleration());
  EXPECT_FALSE(regular.has_acceleration());
  EXPECT_FALSE(full.bricks().empty());
  EXPECT_EQ(drag.bricks().size(), full.bricks().size());
  EXPECT_EQ(drag.brick_values().size(), full.brick_values().size());
  EXPECT_TRUE(regular.bricks().empty());
  fs::remove_all(dir);
}

}  // namespace
