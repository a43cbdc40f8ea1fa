// The decks of examples/ run as a user runs them: `brash-liggghts -in DECK` in a folder holding the example's
// files, then `brash-post` on that folder. Physics (the floating draft against its closed form) and outputs (the
// hull force record, brash-post's report from a run without meta.json) are checked.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fmt/format.h>
#include <fstream>
#include <nlohmann/json.hpp>

#include "brash/core/reference.hpp"
#include "liggghts_runner.h"

namespace fs = std::filesystem;
using brash::test::fresh_dir;
using brash::test::read_table;

namespace {

const fs::path kExamples = BRASH_EXAMPLES_DIR;

// A fresh folder with every file of examples/<name>.
fs::path copy_example(const std::string& name) {
  const auto dir = fresh_dir("example_" + name);
  for (const auto& e : fs::directory_iterator(kExamples / name)) fs::copy(e.path(), dir / e.path().filename());
  return dir;
}

// `brash-liggghts -in DECK VARS` in dir; the exit status (screen output in dir/screen.txt).
int run_deck(const fs::path& dir, const std::string& deck, const std::string& vars = "") {
  const auto cmd = fmt::format("cd '{}' && '{}' -in {} {} -log log.txt > screen.txt 2>&1", dir.string(),
                               BRASH_LIGGGHTS_EXE, deck, vars);
  return std::system(cmd.c_str());
}

int run_post(const fs::path& dir) {
  const auto cmd = fmt::format("'{}' --no-paraview '{}' > '{}' 2>&1", BRASH_POST_EXE, dir.string(),
                               (dir / "post.txt").string());
  const int rc = std::system(cmd.c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

}  // namespace

// Dropped onto the water, the sphere settles; its mean draft over the last 10 s is the closed form's (the cap
// volume V_cap(h) = pi h^2 (3r - h) / 3 holding rho_i / rho_w of the sphere's volume) within 1 %.
TEST(Examples, FloatingSphereSettlesAtTheClosedFormDraft) {
  struct Sphere {
    double d, rho;
  };
  for (const Sphere s : {Sphere{0.05, 900}, Sphere{0.1, 850}}) {
    const auto dir = copy_example("floating_sphere");
    ASSERT_EQ(run_deck(dir, "in.floating_sphere", fmt::format("-var d {} -var rho {}", s.d, s.rho)), 0) << dir;
    const auto rows = read_table(dir / "draft.txt");
    ASSERT_EQ(rows.size(), 1u) << dir;
    ASSERT_EQ(rows[0].size(), 3u);
    const double fraction = s.rho / 1000.0;
    const double draft = brash::core::analytic::height_for_fraction(0.5 * s.d, fraction);
    EXPECT_NEAR(rows[0][1] / draft, 1.0, 0.01) << "d " << s.d << ": draft " << rows[0][1] << " m vs " << draft;
    EXPECT_NEAR(rows[0][2] / fraction, 1.0, 0.01) << "submerged fraction";
    EXPECT_NE(brash::test::read_text(dir / "screen.txt").find("floating draft"), std::string::npos);
  }
}

// The channel deck runs to its end; its hull force record has a row every 5 ms and the ice resists the hull
// (mean -fx > 0 over the window, beyond its scatter); brash-post reports the same mean from the raw record with
// case.yaml alone, with the fluid model the deck ran (fix icefluid's line in its log, not case.yaml's 'both') and
// the folder's name as title, then marks the run complete once a meta.json says so.
TEST(Examples, ChannelRunsAndBrashPostReportsItsResistance) {
  const auto dir = copy_example("channel");
  ASSERT_EQ(run_deck(dir, "in.channel", "-var model drag"), 0) << dir;
  const auto rows = read_table(dir / "hull_force.raw");
  ASSERT_EQ(rows.size(), 501u) << "one row every 100 steps of 50,000, and step 0";
  double sum = 0;
  int n = 0;
  for (const auto& r : rows) {
    ASSERT_EQ(r.size(), 5u);
    if (r[1] >= 1.0 - 1e-9) sum -= r[2], ++n;
  }
  const double resistance = sum / n;
  EXPECT_GT(resistance, 0.05) << "mean -fx over [1, 2.5] s: the ice must resist the hull";

  ASSERT_EQ(run_post(dir), 0) << brash::test::read_text(dir / "post.txt");
  auto report = read_json(dir / "report.json");
  const auto& r = report["resistance_model_N"];
  EXPECT_NEAR(r["mean"].get<double>(), resistance, 1e-6 * resistance);
  EXPECT_GT(r["mean"].get<double>() - r["ci95"].get<double>(), 0) << "resisting beyond the 95 % CI";
  EXPECT_EQ(report["engine"], "unknown");
  EXPECT_EQ(report["fluid_model"], "drag");
  EXPECT_EQ(report["treatment"], "implicit");
  EXPECT_NE(brash::test::read_text(dir / "report.md").find("# brash run report: " + dir.filename().string() + "\n"),
            std::string::npos);
  EXPECT_FALSE(report["complete"].get<bool>()) << "nothing says the run finished";
  EXPECT_NE(brash::test::read_text(dir / "report.md").find("no meta.json"), std::string::npos);
  // the deck's own dump custom files (every 0.5 s) give the ice views, without brash's particles/ layout
  EXPECT_TRUE(fs::exists(dir / "ice_views_001.00s.png") || fs::exists(dir / "ice_views_001.50s.png"))
      << brash::test::read_text(dir / "post.txt");
  EXPECT_TRUE(fs::exists(dir / "ice_views_002.50s.png")) << brash::test::read_text(dir / "post.txt");
  EXPECT_NE(brash::test::read_text(dir / "post/ice_views_50000.gp").find("polygon"), std::string::npos)
      << "the hull's waterline from hull_barge.stl";
  EXPECT_NE(brash::test::read_text(dir / "report.md").find("LIGGGHTS dump custom file(s)"), std::string::npos);

  std::ofstream(dir / "meta.json") << R"({"engine": "liggghts", "status": "complete"})";
  ASSERT_EQ(run_post(dir), 0) << brash::test::read_text(dir / "post.txt");
  report = read_json(dir / "report.json");
  EXPECT_EQ(report["engine"], "liggghts");
  EXPECT_TRUE(report["complete"].get<bool>());
  EXPECT_NEAR(report["resistance_model_N"]["mean"].get<double>(), resistance, 1e-6 * resistance);
}

// The example's hull is closed and its guard watches it: a hull started across the ice (pieces inside it) is
// stopped by fix brash/guard with its message, not run silently.
TEST(Examples, ChannelGuardStopsAHullStartedInsideTheIce) {
  const auto dir = copy_example("channel");
  EXPECT_NE(run_deck(dir, "in.channel", "-var x0 0.1 -var steps 200"), 0);
  EXPECT_NE(brash::test::read_text(dir / "screen.txt").find("hull penetration"), std::string::npos)
      << brash::test::read_text(dir / "screen.txt");
}
