// fix icefluid's hull_flow: the force on pieces near a moving hull is the core's drag and the water's
// acceleration (flow_acceleration.hpp) in the thin-ship flow
// (brash::hull::thin_ship_flow of the same STL, at the hull's position at that step), on 1 and 2 ranks; the
// water pushes pieces ahead of the bow forward and draws pieces alongside aft.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <brash/hull/flow.hpp>
#include <brash/hull/mesh.hpp>
#include <cmath>
#include <map>

#include "brash/core/fluid.hpp"
#include "brash/core/immersion.hpp"
#include "brash/core/reference.hpp"
#include "liggghts_runner.h"

using namespace brash::core;
using brash::test::fresh_dir;
using brash::test::read_table;
using brash::test::run_liggghts;

namespace {
constexpr double d = 0.017578, r = d / 2, rho_i = 900, draft = 0.4125, speed = 0.482, x0 = -3.5, dt = 1e-4;
const std::string kHull = std::string(BRASH_HULL_DIR) + "/jbc_panamax_model.stl";

// Floating pieces (at their equilibrium draft) around the hull, which starts at x0 and moves at `speed`;
// no contacts between them (far apart). Dumps id, x, v and the total force (= the fluid force in x, y) at
// the last step with full precision.
std::string scene(long steps, const std::string& flow_args) {
  const double z = r - analytic::height_for_fraction(r, rho_i / 1000.0);
  std::string atoms;
  // stem at x ~ x0 + 7.2: ahead of it, beside the bow shoulder, alongside the middle, off the side, far ahead
  for (const auto& [x, y] : std::vector<std::pair<double, double>>{{3.8, 0.0},
                                                                   {3.9, 0.05},
                                                                   {3.2, 0.6},
                                                                   {2.6, -0.62},
                                                                   {0.0, 0.6},
                                                                   {0.0, -0.7},
                                                                   {1.0, 1.5},
                                                                   {6.0, 0.0}})
    atoms += fmt::format("create_atoms 1 single {} {} {} units box\n", x, y, z);
  return fmt::format(R"({preamble}processors * 1 1
region reg block -5 8 -2 2 -1 0.5 units box
create_box 1 reg
neighbor 0.002 bin
neigh_modify delay 0
{contacts}
timestep {dt}
{atoms}set group all diameter {d} density {rho}
fix integr all nve/sphere
fix grav all gravity 9.81 vector 0 0 -1
fix fl all icefluid model drag {flow}
dump out all custom {steps} dump.*.txt id x y z vx vy vz fx fy fz
dump_modify out format "%d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g"
run {steps}
)",
                     fmt::arg("preamble", brash::test::kGranularPreamble),
                     fmt::arg("contacts", brash::test::ice_contact_model("0.3")), fmt::arg("dt", dt),
                     fmt::arg("atoms", atoms), fmt::arg("d", d), fmt::arg("rho", rho_i),
                     fmt::arg("flow", flow_args), fmt::arg("steps", steps));
}

std::string hull_flow_args() {
  return fmt::format("hull_flow {} {} 0 {} {}", kHull, x0, -draft, speed);
}

// id -> row (id x y z vx vy vz fx fy fz)
std::map<int, std::vector<double>> last_dump(const std::filesystem::path& dir, long steps) {
  std::map<int, std::vector<double>> out;
  for (const auto& row : read_table(dir / fmt::format("dump.{}.txt", steps)))
    if (row.size() == 10) out[static_cast<int>(row[0])] = row;
  return out;
}
}  // namespace

TEST(LiggghtsHullFlow, DragIsTheCoresInTheHullsFlowOnOneAndTwoRanks) {
  const long steps = 200;
  const FlowTable table = brash::hull::thin_ship_flow(brash::hull::read_mesh(kHull), draft, speed);
  std::map<int, std::vector<double>> by_ranks[2];
  for (int ranks : {1, 2}) {
    auto dir = fresh_dir(fmt::format("hullflow{}", ranks));
    ASSERT_EQ(run_liggghts(dir, scene(steps, hull_flow_args()), ranks), 0)
        << brash::test::read_text(dir / "screen_in.lmp.txt");
    const std::string screen = brash::test::read_text(dir / "screen_in.lmp.txt");
    EXPECT_NE(screen.find("fix icefluid: hull flow from"), std::string::npos) << screen;
    by_ranks[ranks - 1] = last_dump(dir, steps);
    ASSERT_EQ(by_ranks[ranks - 1].size(), 8u);
    int moved = 0;
    for (const auto& [id, row] : by_ranks[ranks - 1]) {
      // The fix saw this step's position and the half-step velocity (velocity Verlet: the dump's velocity has
      // the second half kick v += dt / 2 f / m on top)
      const Vec3 x(row[1], row[2], row[3]), f(row[7], row[8], row[9]);
      const Vec3 v = Vec3(row[4], row[5], row[6]) - 0.5 * dt * f / (rho_i * analytic::sphere_volume(r));
      FluidParams p;
      p.model = FluidModel::Drag;
      const Vec3 frame(x0 + speed * steps * dt, 0, 0);  // water level at z = 0
      Vec3 du_dt;
      table.at(x - frame, p.flow_velocity_m_s, du_dt);
      // the drag on the relative velocity and the water's acceleration, rho V_s Du/Dt (model drag: C_a = 0)
      const Immersion im = immersion(r, x.z(), 0.0);
      const Vec3 drag = drag_force(p, r, im, v) + p.water_density_kg_m3 * im.volume_m3 * du_dt;
      EXPECT_NEAR(row[7], drag.x(), 1e-9 * (1 + std::abs(drag.x())) + 1e-12) << "atom " << id;
      EXPECT_NEAR(row[8], drag.y(), 1e-9 * (1 + std::abs(drag.y())) + 1e-12) << "atom " << id;
      moved += p.flow_velocity_m_s.norm() > 1e-3;
    }
    EXPECT_GE(moved, 5);  // most pieces are inside the flow
  }
  // rank-independent to round-off
  for (const auto& [id, row] : by_ranks[0])
    for (int k = 1; k < 10; ++k)
      EXPECT_NEAR(by_ranks[1][id][k], row[k], 1e-12 * (1 + std::abs(row[k]))) << id;
  // pushed ahead of the stem, drawn aft alongside the middle, untouched far ahead
  EXPECT_GT(by_ranks[0][1][4], 0);
  EXPECT_LT(by_ranks[0][5][4], 0);
  EXPECT_EQ(by_ranks[0][8][4], 0.0);
}

TEST(LiggghtsHullFlow, WithoutItPiecesAtRestStayAtRest) {
  const long steps = 50;
  auto dir = fresh_dir("hullflow_off");
  ASSERT_EQ(run_liggghts(dir, scene(steps, "")), 0) << brash::test::read_text(dir / "screen_in.lmp.txt");
  for (const auto& [id, row] : last_dump(dir, steps)) {
    EXPECT_EQ(row[4], 0.0) << id;
    EXPECT_EQ(row[5], 0.0) << id;
  }
}
