// brash-post paired-ensemble on synthetic run directories (report.json and meta.json of each seed and side): the
// table, the statement and the summary JSON that brash-study-report and bench/pareto_plot.sh read, on a hand-computed
// ensemble. Pairs (9.5, 10.5), (17, 23), (36, 44) differ by 0.1, 0.3, 0.2 of their mean: mean 0.2, sd 0.1, CI95 =
// t_{0.975, 2} 0.1 / sqrt(3) = 4.303 x 0.0577 = 0.2484; seed 4 has only side A complete.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "brash/post/ensemble.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / fmt::format("brash_ensemble_{}_{}", name, ::getpid());
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// One run of the ensemble: report.json as brash-post writes it (the keys read here), meta.json with the wall time
// (none when wall_s < 0).
void write_run(const fs::path& run, double mean_N, const std::string& status = "complete", double wall_s = -1) {
  fs::create_directories(run);
  std::ofstream(run / "report.json") << json{{"status", status},
                                             {"resistance_model_N", {{"mean", mean_N}, {"ci95", 0.1}}}}.dump(2);
  if (wall_s >= 0) std::ofstream(run / "meta.json") << json{{"status", status}, {"wall_time_s", wall_s}}.dump(2);
}

// seeds 1-3 complete (side A np1, side B np2-dt), seed 4 only side A complete (B still running)
void write_hand_set(const fs::path& d) {
  const std::vector<double> a{9.5, 17, 36}, b{10.5, 23, 44}, wa{100, 110, 120}, wb{50, 60, 70};
  for (std::size_t i = 0; i < a.size(); ++i) {
    write_run(d / fmt::format("s{}-np1", i + 1), a[i], "complete", wa[i]);
    write_run(d / fmt::format("s{}-np2-dt", i + 1), b[i], "complete", wb[i]);
  }
  write_run(d / "s4-np1", 20.25, "complete", 90);
  write_run(d / "s4-np2-dt", 11.0, "running", 10);
}

// Runs the subcommand on DIR; returns its stdout (exit status in *rc).
std::string ensemble(const fs::path& d, int seeds, const std::string& tol_pct, int* rc) {
  const auto cmd = fmt::format(
      "'{}' paired-ensemble '{}' --seeds {} --case synth --side-a 1 --side-b '2:run.timestep_s=2e-4' --name-a np1 "
      "--name-b np2-dt --label-a '1 rank' --label-b '2 ranks, run.timestep_s=2e-4' --tol-pct {} > '{}' 2>&1",
      BRASH_POST_EXE, d.string(), seeds, tol_pct, (d / "out.txt").string());
  *rc = WEXITSTATUS(std::system(cmd.c_str()));
  return read(d / "out.txt");
}

void expect_line(const std::string& out, const std::string& line) {
  EXPECT_NE(out.find(line + "\n"), std::string::npos) << "missing line: " << line << "\nin:\n" << out;
}

}  // namespace

TEST(PairedEnsemble, HandComputedTableAndSummary) {
  const auto d = fresh_dir("hand");
  write_hand_set(d);
  int rc = -1;
  const auto out = ensemble(d, 4, "50", &rc);
  ASSERT_EQ(rc, 0) << out;
  expect_line(out, "== synth, one packing seed per pair, mean resistance over its window, model scale");
  expect_line(out, "| seed | A: 1 rank [N] | B: 2 ranks, run.timestep_s=2e-4 [N] | (B - A) / mean |");
  expect_line(out, "| 1 | 9.500 | 10.500 | +10.00 % |");
  expect_line(out, "| 2 | 17.000 | 23.000 | +30.00 % |");
  expect_line(out, "| 3 | 36.000 | 44.000 | +20.00 % |");
  expect_line(out, "| 4 | 20.25 | - | (incomplete) |");
  expect_line(out, "pairs: 3; ensemble mean A (1 rank) 20.833 N, B (2 ranks, run.timestep_s=2e-4) 25.833 N");
  expect_line(out, "paired difference (B - A): +20.00 % +- 24.84 % (95 % CI), sd of one pair 10.00 %");
  expect_line(out, "wall time: A 330 s, B 180 s in all; speed-up of B over A 1.83x");
  expect_line(out, "WITHIN 50 %: the 95 % CI [-4.84, +44.84] % lies inside [-50, +50] %");

  const auto file = d / "ensemble-np1-vs-np2-dt.json";
  ASSERT_TRUE(fs::exists(file)) << out;
  const std::string text = read(file);
  EXPECT_EQ(text.back(), '}');  // as the archived summaries: no newline after the object
  const json s = json::parse(text);
  EXPECT_EQ(s["case"], "synth");
  EXPECT_EQ(s["side_a"], "1");
  EXPECT_EQ(s["side_b"], "2:run.timestep_s=2e-4");
  EXPECT_EQ(s["pairs"], 3);
  EXPECT_NEAR(s["mean_a_N"].get<double>(), 62.5 / 3, 1e-12);
  EXPECT_NEAR(s["mean_b_N"].get<double>(), 77.5 / 3, 1e-12);
  EXPECT_NEAR(s["diff_rel"].get<double>(), 0.2, 1e-15);
  EXPECT_NEAR(s["sd_rel"].get<double>(), 0.1, 1e-15);
  EXPECT_NEAR(s["ci95_rel"].get<double>(), 4.303 * 0.1 / std::sqrt(3.0), 1e-15);
  EXPECT_EQ(s["wall_a_s"].get<double>(), 330.0);  // seed 4 is not a pair: its wall times are not counted
  EXPECT_EQ(s["wall_b_s"].get<double>(), 180.0);
  EXPECT_NEAR(s["speedup"].get<double>(), 330.0 / 180.0, 1e-15);
}

// The summary has the archived summaries' fields in their order (evidence/ensembles: read by
// brash-study-report for its `paired` rows).
TEST(PairedEnsemble, SummaryHasTheArchivedFields) {
  const auto d = fresh_dir("fields");
  write_hand_set(d);
  int rc = -1;
  ensemble(d, 3, "1", &rc);
  ASSERT_EQ(rc, 0);
  const auto ours = nlohmann::ordered_json::parse(read(d / "ensemble-np1-vs-np2-dt.json"));
  std::vector<std::string> keys;
  for (const auto& [k, v] : ours.items()) keys.push_back(k);
  const fs::path archive = fs::path(BRASH_SOURCE_DIR) / "evidence/ensembles/fluid-reading";
  ASSERT_TRUE(fs::is_directory(archive));
  int compared = 0;
  for (const auto& e : fs::directory_iterator(archive)) {
    if (e.path().extension() != ".json") continue;
    const auto j = nlohmann::ordered_json::parse(read(e.path()));
    std::vector<std::string> archived;
    for (const auto& [k, v] : j.items()) archived.push_back(k);
    EXPECT_EQ(keys, archived) << e.path();
    ++compared;
  }
  EXPECT_GT(compared, 0);
}

// Not resolved: the statement says how many pairs would resolve it at this scatter ((1.96 x 0.1 / (0.21 - 0.2))^2 =
// 384.16 -> 385), or nothing when the mean itself is outside the tolerance.
TEST(PairedEnsemble, NotShownWithPairsToResolve) {
  const auto d = fresh_dir("not_shown");
  write_hand_set(d);
  int rc = -1;
  auto out = ensemble(d, 4, "21", &rc);
  ASSERT_EQ(rc, 0) << out;
  expect_line(out, "NOT SHOWN: the 95 % CI [-4.84, +44.84] % is not inside [-21, +21] %; about 385 pairs would "
                   "resolve it at this scatter");
  out = ensemble(d, 4, "10", &rc);
  expect_line(out, "NOT SHOWN: the 95 % CI [-4.84, +44.84] % is not inside [-10, +10] %");
}

// Two pairs: one degree of freedom, CI95 = 12.706 sd / sqrt(2); one pair: no statement and no summary file.
TEST(PairedEnsemble, StudentQuantileOfPairsMinusOne) {
  const auto d = fresh_dir("two");
  write_hand_set(d);
  int rc = -1;
  ensemble(d, 2, "1", &rc);
  ASSERT_EQ(rc, 0);
  const json s = json::parse(read(d / "ensemble-np1-vs-np2-dt.json"));
  EXPECT_EQ(s["pairs"], 2);
  const double sd = std::sqrt(2 * 0.1 * 0.1 / 1);  // differences 0.1 and 0.3 about their mean 0.2
  EXPECT_NEAR(s["sd_rel"].get<double>(), sd, 1e-15);
  EXPECT_NEAR(s["ci95_rel"].get<double>(), 12.706 * sd / std::sqrt(2.0), 1e-14);

  fs::remove(d / "ensemble-np1-vs-np2-dt.json");
  const auto out = ensemble(d, 1, "1", &rc);
  EXPECT_EQ(rc, 0);
  expect_line(out, "fewer than 2 complete pairs: no ensemble statement");
  EXPECT_FALSE(fs::exists(d / "ensemble-np1-vs-np2-dt.json"));
}

// Runs without meta.json: the wall times are null (valid JSON), the statistics unaffected.
TEST(PairedEnsemble, MissingWallTimeIsNull) {
  const auto d = fresh_dir("no_wall");
  write_run(d / "s1-np1", 10.0);
  write_run(d / "s1-np2-dt", 11.0);
  write_run(d / "s2-np1", 20.0);
  write_run(d / "s2-np2-dt", 21.0);
  int rc = -1;
  const auto out = ensemble(d, 2, "1", &rc);
  ASSERT_EQ(rc, 0) << out;
  const json s = json::parse(read(d / "ensemble-np1-vs-np2-dt.json"));
  EXPECT_TRUE(s["wall_a_s"].is_null());
  EXPECT_TRUE(s["speedup"].is_null());
  EXPECT_NEAR(s["diff_rel"].get<double>(), 0.5 * (1 / 10.5 + 1 / 20.5), 1e-15);
}

TEST(PairedEnsemble, LongSideNamesGiveAShortDistinctFileName) {
  using brash::post::ensemble_file_name;
  EXPECT_EQ(ensemble_file_name("np1", "np2"), "ensemble-np1-vs-np2.json");
  const std::string a = "np1-contact.youngs_modulus_pa_3.125e5_run.timestep_s_8.0e-4_ice.settle_true";
  const std::string b = a + "_speedups.farfield_true_speedups.farfield_ahead_m_0.3_speedups.farfield_behind_m_1.0_"
                            "speedups.farfield_every_steps_100_speedups.farfield_wake_force_weight_";
  const std::string one = ensemble_file_name(a, b + "1e-3"), two = ensemble_file_name(a, b + "0");
  EXPECT_EQ(one.size(), 200u);
  EXPECT_NE(one, two);                                       // the hash tells sides apart beyond the cut
  EXPECT_EQ(one, ensemble_file_name(a, b + "1e-3"));         // and names a summary the same way every time
  EXPECT_EQ(one.rfind("ensemble-" + a + "-vs-", 0), 0u);     // bench/pareto_plot.sh globs ensemble-<A>-vs-*.json
  EXPECT_TRUE(one.ends_with(".json"));
}
