// brash-post paired-ensemble on synthetic run directories (report.json and meta.json of each seed and side): the
// table, the statement and the summary JSON that brash-study-report and bench/pareto_plot.sh read, on a hand-computed
// ensemble. Pairs (9.5, 10.5), (17, 23), (36, 44), means 62.5 / 3 and 77.5 / 3: B's effect on A is 15 / 62.5 = 0.24
// (over the pairs' means it was 0.2); the delta method's b_i - 1.24 a_i are -1.28, 1.92, -0.64, so
// sd = sqrt(5.7344 / 2) / (62.5 / 3) = 0.08128 and CI95 = t_{0.975, 2} sd / sqrt(3) = 4.303 x 0.04693 = 0.2019;
// seed 4 has only side A complete.
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

#include "synthetic_run.hpp"

namespace fs = std::filesystem;
using brash::post::testing::read_text;
using nlohmann::json;

namespace {

fs::path fresh_dir(const std::string& name) { return brash::post::testing::fresh_dir("ensemble", name); }

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
  return read_text(d / "out.txt");
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
  expect_line(out, "| seed | A: 1 rank [N] | B: 2 ranks, run.timestep_s=2e-4 [N] | (B - A) / A |");
  expect_line(out, "| 1 | 9.500 | 10.500 | +10.53 % |");
  expect_line(out, "| 2 | 17.000 | 23.000 | +35.29 % |");
  expect_line(out, "| 3 | 36.000 | 44.000 | +22.22 % |");
  expect_line(out, "| 4 | 20.25 | - | (incomplete) |");
  expect_line(out, "pairs: 3; ensemble mean A (1 rank) 20.833 N, B (2 ranks, run.timestep_s=2e-4) 25.833 N");
  expect_line(out, "effect (B - A) / A of the means: +24.00 % +- 20.19 % (95 % CI, delta method), sd of one pair "
                   "8.13 %");
  expect_line(out, "wall time: A 330 s, B 180 s in all; speed-up of B over A 1.83x");
  expect_line(out, "WITHIN 50 %: the 95 % CI [+3.81, +44.19] % lies inside [-50, +50] %");

  const auto file = d / "ensemble-np1-vs-np2-dt.json";
  ASSERT_TRUE(fs::exists(file)) << out;
  const std::string text = read_text(file);
  EXPECT_EQ(text.back(), '}');  // as the archived summaries: no newline after the object
  const json s = json::parse(text);
  EXPECT_EQ(s["case"], "synth");
  EXPECT_EQ(s["side_a"], "1");
  EXPECT_EQ(s["side_b"], "2:run.timestep_s=2e-4");
  EXPECT_EQ(s["pairs"], 3);
  EXPECT_NEAR(s["mean_a_N"].get<double>(), 62.5 / 3, 1e-12);
  EXPECT_NEAR(s["mean_b_N"].get<double>(), 77.5 / 3, 1e-12);
  const double sd = std::sqrt(5.7344 / 2) / (62.5 / 3);
  EXPECT_NEAR(s["effect_rel"].get<double>(), 0.24, 1e-15);
  EXPECT_NEAR(s["effect_sd_rel"].get<double>(), sd, 1e-14);
  EXPECT_NEAR(s["effect_ci95_rel"].get<double>(), 4.303 * sd / std::sqrt(3.0), 1e-14);
  EXPECT_EQ(s["a_N"], json({9.5, 17.0, 36.0}));  // the complete pairs only
  EXPECT_EQ(s["b_N"], json({10.5, 23.0, 44.0}));
  EXPECT_EQ(s["wall_a_s"].get<double>(), 330.0);  // seed 4 is not a pair: its wall times are not counted
  EXPECT_EQ(s["wall_b_s"].get<double>(), 180.0);
  EXPECT_NEAR(s["speedup"].get<double>(), 330.0 / 180.0, 1e-15);
}

// The summary's fields, in order, and read back (brash::post::read_ensemble_summary, as brash-study-report reads
// its `paired` rows): the effect from the per-pair values. An archived summary of before (evidence/ensembles: the
// mean of (B - A) / mean of the pair, no per-pair values) reads as its effect on A from its ensemble means, exactly,
// with no CI on A and its own numbers kept.
TEST(PairedEnsemble, SummaryFieldsAndReadingBack) {
  const auto d = fresh_dir("fields");
  write_hand_set(d);
  int rc = -1;
  ensemble(d, 3, "1", &rc);
  ASSERT_EQ(rc, 0);
  const auto ours = nlohmann::ordered_json::parse(read_text(d / "ensemble-np1-vs-np2-dt.json"));
  std::vector<std::string> keys;
  for (const auto& [k, v] : ours.items()) keys.push_back(k);
  EXPECT_EQ(keys, (std::vector<std::string>{"case", "side_a", "side_b", "pairs", "mean_a_N", "mean_b_N", "effect_rel",
                                            "effect_ci95_rel", "effect_sd_rel", "definition", "a_N", "b_N",
                                            "wall_a_s", "wall_b_s", "speedup"}));
  const auto e = brash::post::read_ensemble_summary(ours);
  EXPECT_EQ(e.pairs, 3);
  EXPECT_NEAR(e.effect_rel, 0.24, 1e-15);
  EXPECT_NEAR(e.ci95_rel, 4.303 * std::sqrt(5.7344 / 2) / (62.5 / 3) / std::sqrt(3.0), 1e-14);
  EXPECT_TRUE(e.has_ci());
  EXPECT_TRUE(e.resolved());  // [0.038, 0.442]
  EXPECT_TRUE(std::isnan(e.pair_mean_diff_rel));

  const fs::path archive = fs::path(BRASH_SOURCE_DIR) / "evidence/ensembles/quick-hull-flow";
  int compared = 0;
  for (const auto& f : fs::directory_iterator(archive)) {
    const auto j = json::parse(read_text(f.path()));
    ASSERT_FALSE(j.contains("a_N")) << f.path();
    const auto old = brash::post::read_ensemble_summary(j);
    const double ma = j["mean_a_N"].get<double>(), mb = j["mean_b_N"].get<double>();
    EXPECT_EQ(old.effect_rel, (mb - ma) / ma) << f.path();
    EXPECT_FALSE(old.has_ci());
    EXPECT_FALSE(old.resolved());
    EXPECT_EQ(old.pair_mean_diff_rel, j["diff_rel"].get<double>());
    EXPECT_EQ(old.pair_mean_ci95_rel, j["ci95_rel"].get<double>());
    ++compared;
  }
  EXPECT_EQ(compared, 2);
}

// The quick case's panel flow on still water: 17.04 -> 8.51 N is -50.1 % on side A, where the mean of the pair
// gave -66.79 %.
TEST(PairedEnsemble, OldSummaryReadsOnSideA) {
  const json j = json::parse(read_text(fs::path(BRASH_SOURCE_DIR) /
                                  "evidence/ensembles/quick-hull-flow/ensemble-np1-vs-np1-fluid.hull_flow_panel.json"));
  const auto e = brash::post::read_ensemble_summary(j);
  EXPECT_NEAR(e.effect_rel, -0.5007, 5e-5);
  EXPECT_NEAR(e.pair_mean_diff_rel, -0.6679, 5e-5);
}

// Not resolved: the statement says how many pairs would resolve it at this scatter ((1.96 x 0.08128 / (0.3 -
// 0.24))^2 = 7.05 -> 8), or nothing when the effect itself is outside the tolerance.
TEST(PairedEnsemble, NotShownWithPairsToResolve) {
  const auto d = fresh_dir("not_shown");
  write_hand_set(d);
  int rc = -1;
  auto out = ensemble(d, 4, "30", &rc);
  ASSERT_EQ(rc, 0) << out;
  expect_line(out, "NOT SHOWN: the 95 % CI [+3.81, +44.19] % is not inside [-30, +30] %; about 8 pairs would "
                   "resolve it at this scatter");
  out = ensemble(d, 4, "21", &rc);
  expect_line(out, "NOT SHOWN: the 95 % CI [+3.81, +44.19] % is not inside [-21, +21] %");
}

// Two pairs: one degree of freedom, CI95 = 12.706 sd / sqrt(2); one pair: no statement and no summary file.
TEST(PairedEnsemble, StudentQuantileOfPairsMinusOne) {
  const auto d = fresh_dir("two");
  write_hand_set(d);
  int rc = -1;
  ensemble(d, 2, "1", &rc);
  ASSERT_EQ(rc, 0);
  const json s = json::parse(read_text(d / "ensemble-np1-vs-np2-dt.json"));
  EXPECT_EQ(s["pairs"], 2);
  // pairs (9.5, 10.5), (17, 23): means 13.25 and 16.75; z_i = (b_i - (16.75 / 13.25) a_i) / 13.25 = -+z
  const double z = (23 - 16.75 / 13.25 * 17) / 13.25, sd = std::sqrt(2 * z * z / 1);
  EXPECT_NEAR(s["effect_rel"].get<double>(), 3.5 / 13.25, 1e-15);
  EXPECT_NEAR(s["effect_sd_rel"].get<double>(), sd, 1e-14);
  EXPECT_NEAR(s["effect_ci95_rel"].get<double>(), 12.706 * sd / std::sqrt(2.0), 1e-13);

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
  const json s = json::parse(read_text(d / "ensemble-np1-vs-np2-dt.json"));
  EXPECT_TRUE(s["wall_a_s"].is_null());
  EXPECT_TRUE(s["speedup"].is_null());
  EXPECT_NEAR(s["effect_rel"].get<double>(), 1.0 / 15, 1e-15);
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
