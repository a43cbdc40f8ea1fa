// brash-liggghts-run with the moving window (speedups.moving_window, fix brash/window) on a small case: the JBC
// scaled to 1 m (brash-hull jbc --lpp 1 --grid-factor 3: on the finer default grid a piece touches more triangles
// than LIGGGHTS' mesh neighbour list holds) at 1 m/s through a 0.6 m channel of 35 mm ice on its settled bed, so
// that in 1.5 s the bow enters the held-out bed and the stern passes the channel. Every snapshot in particles/
// holds every piece of the scene's packing (packing.data): the held-out ones where the packing has them, the
// removed ones where they were last in the scene, both at rest, with the state column (docs/case_format.md,
// particles/); each piece's force on the hull (hull_fx_N) adds up to hull_force.csv's fx.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "runner_case.h"

namespace fs = std::filesystem;

namespace {

struct Row {
  double x, y, z, vx, vy, vz;
  int state;
  double hull_fx_N;  // the piece's force on the hull, x
};

// id -> row of a particles_<step>.csv with the state column
std::map<long, Row> read_snapshot(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "id,x,y,z,radius,vx,vy,vz,submerged_fraction,ca_x,ca_y,ca_z,active,state,hull_fx_N,hull_fy_N,hull_fz_N")
      << file;
  std::map<long, Row> rows;
  while (std::getline(in, line)) {
    std::vector<double> f;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) f.push_back(std::stod(cell));
    EXPECT_EQ(f.size(), 17u) << line;
    if (f.size() != 17) continue;
    rows[std::lround(f[0])] = Row{f[1], f[2], f[3], f[5], f[6], f[7], static_cast<int>(f[13]), f[14]};
  }
  return rows;
}

// id -> position of packing.data's atoms ("id type diameter density x y z")
std::map<long, std::array<double, 3>> read_packing(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line) && line.rfind("Atoms", 0) != 0) {
  }
  std::map<long, std::array<double, 3>> atoms;
  while (std::getline(in, line)) {
    std::istringstream ss(line);
    long id, type;
    double d, rho, x, y, z;
    if (ss >> id >> type >> d >> rho >> x >> y >> z) atoms[id] = {x, y, z};
  }
  return atoms;
}

bool near9(double a, double b) { return std::abs(a - b) <= 1e-8 * std::max(1.0, std::abs(b)); }  // 9 digits written

}  // namespace

TEST(LiggghtsWindowRunner, EverySnapshotHoldsEveryPieceWithItsState) {
  const fs::path dir = brash::test::fresh_dir("window_runner");
  const fs::path case_dir = dir / "case";
  brash::test::write_small_quick_case(
      case_dir, {.duration_s = "1.5", .window_s = "[0.0, 1.5]", .output_interval_s = "0.01",
                 .dump_interval_s = "0.1", .fluid_model = "",
                 .extra = "speedups:\n  moving_window: true\n  moving_window_ahead_m: 0.1\n"
                          "  moving_window_behind_m: 0.05\n"});
  std::string yaml = brash::test::read_text(case_dir / "case.yaml");
  const auto set = [&](const std::string& key, const std::string& value) {
    const std::regex re("\n  " + key + ":[^\n]*");
    ASSERT_TRUE(std::regex_search(yaml, re)) << key;
    yaml = std::regex_replace(yaml, re, value.empty() ? std::string() : "\n  " + key + ": " + value);
  };
  set("file", "jbc_1m.stl");
  set("lpp_m", "1.0");
  set("draft_m", "0.058929");  // 0.4125 m / 7
  set("beam_m", "0.160714");
  set("start_x_m", "-1.07");    // the stem 5 cm before the ice
  set("band_m", "");            // the whole hull
  set("speed_m_s", "1.0");
  set("length_m", "0.6");
  set("width_m", "0.6");
  set("packing_file", "generated/packing.csv\n  settle: true");
  std::ofstream(case_dir / "case.yaml") << yaml;
  ASSERT_EQ(std::system((std::string("'") + BRASH_BIN_DIR + "/brash-hull' jbc --lpp 1.0 --grid-factor 3 --out '" +
                         (case_dir / "jbc_1m.stl").string() + "' > /dev/null")
                            .c_str()),
            0);
  ASSERT_EQ(brash::test::run_runner(case_dir, dir / "run", dir / "run.log"), 0) << brash::test::read_text(dir / "run.log");
  ASSERT_NE(brash::test::read_text(dir / "run/in.lmp").find("fix window all brash/window"), std::string::npos);

  const auto packing = read_packing(dir / "run/packing.data");
  ASSERT_GT(packing.size(), 100u);
  std::vector<std::string> files;
  {
    std::ifstream index(dir / "run/particles/index.csv");
    std::string line;
    std::getline(index, line);
    while (std::getline(index, line)) {  // step,t_s,file,hull_x_m
      std::stringstream ss(line);
      std::string cell;
      for (int k = 0; k < 3; ++k) std::getline(ss, cell, ',');
      files.push_back(cell);
    }
  }
  ASSERT_EQ(files.size(), 16u);  // 0, 0.1, ..., 1.5 s
  // hull_force.csv's fx at each time (its rows every 0.01 s: at each snapshot's time too)
  std::map<long, double> fx_at_ms;
  {
    std::ifstream record(dir / "run/hull_force.csv");
    std::string line;
    std::getline(record, line);
    while (std::getline(record, line)) {
      std::stringstream ss(line);
      std::string t, fx;
      std::getline(ss, t, ',');
      std::getline(ss, fx, ',');
      fx_at_ms[std::lround(1000 * std::stod(t))] = std::stod(fx);
    }
  }
  std::map<long, Row> last_in_scene;
  std::map<long, int> state_before;
  std::size_t held_first = 0, removed_last = 0, entered = 0, pushed = 0;
  for (std::size_t k = 0; k < files.size(); ++k) {
    const auto rows = read_snapshot(dir / "run/particles" / files[k]);
    ASSERT_EQ(rows.size(), packing.size()) << files[k];
    // the pieces' forces on the hull add up to the hull's force (the dump's 6 digits per piece)
    double sum = 0, size = 0;
    for (const auto& [id, r] : rows) sum += r.hull_fx_N, size += std::abs(r.hull_fx_N);
    ASSERT_TRUE(fx_at_ms.count(static_cast<long>(100 * k))) << files[k];
    EXPECT_NEAR(sum, fx_at_ms.at(static_cast<long>(100 * k)), 1e-5 * size + 1e-9) << files[k];
    pushed += size > 0;
    for (const auto& [id, r] : rows) {
      ASSERT_TRUE(packing.count(id)) << files[k] << ": id " << id;
      const auto& p = packing.at(id);
      if (r.state == 1) {  // held out: where the packing has it, at rest, and never in the scene before
        EXPECT_TRUE(near9(r.x, p[0]) && near9(r.y, p[1]) && near9(r.z, p[2])) << files[k] << ": id " << id;
        EXPECT_FALSE(last_in_scene.count(id)) << files[k] << ": id " << id << " held out after being in the scene";
        held_first += k == 0;
      } else if (r.state == 2) {  // removed: where it was last in the scene, at rest
        ASSERT_TRUE(last_in_scene.count(id)) << files[k] << ": id " << id << " removed, never seen";
        const Row& seen = last_in_scene.at(id);
        EXPECT_TRUE(r.x == seen.x && r.y == seen.y && r.z == seen.z) << files[k] << ": id " << id;
        EXPECT_TRUE(r.vx == 0 && r.vy == 0 && r.vz == 0 && r.hull_fx_N == 0) << files[k] << ": id " << id;
        removed_last += k + 1 == files.size();
      } else {
        ASSERT_EQ(r.state, 0) << files[k] << ": id " << id;
        EXPECT_NE(state_before[id], 2) << files[k] << ": id " << id << " back after being removed";
        entered += state_before.count(id) && state_before[id] == 1;
        last_in_scene[id] = r;
      }
      state_before[id] = r.state;
    }
  }
  // the bed ahead was held out at the start, some of it entered the scene, and ice behind the stern was removed
  EXPECT_GT(held_first, 0u);
  EXPECT_GT(entered, 0u);
  EXPECT_GT(removed_last, 0u);
  EXPECT_GT(pushed, 3u);  // snapshots with the hull in the ice
  fs::remove_all(dir);
}
