// brash::ode::World's hull flow (fluid.hull_flow on brash-ode): the drag of floating pieces near the moving
// JBC hull is the core's drag in the thin-ship flow (brash::hull::thin_ship_flow of the same STL) at the
// hull's position at the start of each step, as fix icefluid's hull_flow (tests/liggghts/test_hull_flow.cpp);
// the water pushes pieces ahead of the bow forward and draws pieces alongside aft. set_hull_flow needs a hull
// and drag.
#include <gtest/gtest.h>

#include <brash/hull/flow.hpp>
#include <brash/hull/mesh.hpp>
#include <stdexcept>
#include <utility>
#include <vector>

#include "brash/core/immersion.hpp"
#include "brash/core/reference.hpp"
#include "brash/ode/world.hpp"

using namespace brash::ode;
using namespace brash::core;

namespace {
constexpr double d = 0.017578, r = d / 2, rho_i = 900, draft = 0.4125, speed = 0.482, x0 = -3.5, dt = 1e-4;
const std::string kHull = std::string(BRASH_HULL_DIR) + "/jbc_panamax_model.stl";

FluidParams drag_params() {
  FluidParams p;
  p.model = FluidModel::Drag;
  return p;
}

// The JBC hull as brash-ode sets it: the STL's vertices with the waterline at the body's z = 0, the body at
// (x0, 0, 0) moving at `speed`.
void set_jbc_hull(World& w, const brash::hull::Mesh& mesh) {
  std::vector<double> verts;
  std::vector<dTriIndex> tris;
  for (const auto& v : mesh.vertices) verts.insert(verts.end(), {v.x(), v.y(), v.z() - draft});
  for (const auto& f : mesh.faces)
    for (int k = 0; k < 3; ++k) tris.push_back(static_cast<dTriIndex>(f[k]));
  w.set_hull(std::move(verts), std::move(tris), Vec3(x0, 0, 0), Vec3(speed, 0, 0));
}
}  // namespace

TEST(OdeHullFlow, DragIsTheCoresInTheHullsFlowAtTheHullsPosition) {
  static OdeLibrary lib;
  const brash::hull::Mesh mesh = brash::hull::read_mesh(kHull);
  const FlowTable table = brash::hull::thin_ship_flow(mesh, draft, speed);
  const FluidParams p = drag_params();
  StepperSettings st;
  st.dt_s = dt;
  World w(p, st, Frictions{1.35, 0.1, 1.35});
  set_jbc_hull(w, mesh);
  w.set_hull_flow(table);
  ASSERT_TRUE(w.has_hull_flow());
  // floating pieces (at their equilibrium draft), far apart and clear of the hull: stem at x ~ x0 + 7.2
  const double z = r - analytic::height_for_fraction(r, rho_i / 1000.0);
  const std::vector<std::pair<double, double>> xy{{3.8, 0.0}, {3.9, 0.05}, {3.2, 0.6}, {2.6, -0.62},
                                                  {0.0, 0.6}, {0.0, -0.7}, {1.0, 1.5}, {6.0, 0.0}};
  for (const auto& [x, y] : xy) w.add_sphere(Vec3(x, y, z), r, rho_i);

  const long steps = 200;
  std::vector<Vec3> x_before(w.size()), v_before(w.size());
  Vec3 hull_before = Vec3::Zero();
  for (long k = 0; k < steps; ++k) {
    if (k == steps - 1) {
      hull_before = w.hull_position();
      for (std::size_t i = 0; i < w.size(); ++i) x_before[i] = w.position(i), v_before[i] = w.velocity(i);
    }
    w.step();
  }
  // the hull has moved: the flow's frame follows it
  EXPECT_NEAR(hull_before.x(), x0 + speed * dt * double(steps - 1), 1e-9);
  const Vec3 frame(hull_before.x(), hull_before.y(), p.water_level_m);
  int nonzero = 0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    Vec3 u, du_dt;
    table.at(x_before[i] - frame, u, du_dt);
    if (u.norm() > 1e-4) ++nonzero;
    FluidParams pi = p;
    pi.flow_velocity_m_s = u, pi.flow_acceleration_m_s2 = du_dt;  // the drag and the water's acceleration
    const FluidOutput expect = evaluate(pi, Sphere{r, w.mass(i), x_before[i], v_before[i]}, FluidState{}, dt);
    const FluidOutput& got = w.fluid_output(i);
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(got.force_N[a], expect.force_N[a], 1e-12 + 1e-9 * expect.force_N.norm())
          << "piece " << i << " axis " << a;
  }
  EXPECT_GE(nonzero, 6);  // all but the pieces off the side and far ahead feel the flow

  // the water moves the pieces (from rest, in 0.02 s): ahead of the stem forward, alongside the middle aft
  // (a slower flow there: ~1e-5 m/s gained, against ~1e-4 ahead of the stem)
  EXPECT_GT(w.velocity(0).x(), 1e-4);
  EXPECT_LT(w.velocity(4).x(), -5e-6);
  EXPECT_LT(w.velocity(5).x(), -5e-6);
  // far ahead of the bow the water is at rest
  EXPECT_LT(std::abs(w.velocity(7).x()), 0.1 * w.velocity(0).x());
}

TEST(OdeHullFlow, StillWaterWithoutIt) {
  static OdeLibrary lib;
  const brash::hull::Mesh mesh = brash::hull::read_mesh(kHull);
  StepperSettings st;
  st.dt_s = dt;
  World w(drag_params(), st, Frictions{1.35, 0.1, 1.35});
  set_jbc_hull(w, mesh);
  const double z = r - analytic::height_for_fraction(r, rho_i / 1000.0);
  w.add_sphere(Vec3(3.8, 0, z), r, rho_i);
  for (int k = 0; k < 200; ++k) w.step();
  EXPECT_FALSE(w.has_hull_flow());
  EXPECT_LT(std::abs(w.velocity(0).x()), 1e-9);  // a floating piece at rest stays at rest
}

TEST(OdeHullFlow, NeedsAHullAndADragModel) {
  static OdeLibrary lib;
  const brash::hull::Mesh mesh = brash::hull::read_mesh(kHull);
  const FlowTable table = brash::hull::thin_ship_flow(mesh, draft, speed);
  StepperSettings st;
  World no_hull(drag_params(), st, Frictions{1.35, 0.1, 1.35});
  EXPECT_THROW(no_hull.set_hull_flow(table), std::invalid_argument);
  FluidParams am;
  am.model = FluidModel::AddedMass;
  World added_mass(am, st, Frictions{1.35, 0.1, 1.35});
  set_jbc_hull(added_mass, mesh);
  EXPECT_THROW(added_mass.set_hull_flow(table), std::invalid_argument);
  FluidParams both;
  both.model = FluidModel::Both;
  World with_both(both, st, Frictions{1.35, 0.1, 1.35});
  set_jbc_hull(with_both, mesh);
  EXPECT_NO_THROW(with_both.set_hull_flow(table));
}
