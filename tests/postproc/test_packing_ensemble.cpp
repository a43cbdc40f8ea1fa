// brash-post packing-ensemble on synthetic run folders (case.yaml of the synthetic case with its own ice.seed, and
// report.json with the keys brash-post writes): the ensemble mean with its between-packing CI against a hand
// computation, the table, the JSON summary's keys, each refusal with its message, and two runs post-processed by
// brash-post itself.
//
// Hand set: 4 packings with window means 10, 12, 11, 15 N: mean 12 N, deviations -2, 0, -1, 3, sum of squares 14,
// sd = sqrt(14 / 3) = 2.160247 N, CI95 = t_{0.975,3} sd / sqrt(4) = 3.182446 x 1.080123 = 3.437432 N. Within-run
// CIs 0.5, 0.7, 0.6, 0.8 N: mean 0.65 N, so the between-packing CI is 5.288 times it. Full scale x 28.5^3 / 1000
// (the synthetic case's lambda): 277.790 kN; FSICR R_CH 990 kN, R_CH / R = 3.5638, 2.770 to 4.994 over
// the mean's CI (357.36 and 198.22 kN).
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "synthetic_run.hpp"

namespace fs = std::filesystem;
using brash::post::testing::read_text;
using nlohmann::json;
using brash::post::testing::synthetic_case_yaml;
using brash::post::testing::write_text;

namespace {

constexpr double kLam3_kN = 28.5 * 28.5 * 28.5 / 1000;  // model N -> full-scale kN of the synthetic case

fs::path fresh_dir(const std::string& name) { return brash::post::testing::fresh_dir("packens", name); }

// The synthetic case with ice.seed `seed`, its hull a file "hull.stl" of the run folder (so every run resolves it to
// a path of its own, with the same bytes) and its packing the default generated/packing.csv of the run folder (a
// path of its own too); `old_line`, when given, is replaced by `new_line`.
std::string case_text(std::uint64_t seed, const std::string& old_line = "", const std::string& new_line = "") {
  std::string t = synthetic_case_yaml(40.0);
  const auto at = t.find("file: no_such_hull.stl");
  t.replace(at, std::string("file: no_such_hull.stl").size(), "file: hull.stl");
  if (!old_line.empty()) {
    const auto p = t.find(old_line);
    EXPECT_NE(p, std::string::npos) << old_line;
    t.replace(p, old_line.size(), new_line);
  }
  return t + fmt::format("ice:\n  seed: {}\n", seed);
}

struct RunSpec {
  std::uint64_t seed = 1;
  double mean_N = 10, ci95_N = 0.5;
  std::optional<bool> drifts;  // none: no window_halves in the report
  std::array<double, 2> window_s{15.0, 40.0};
  bool met_no_ice = false;
  std::string hull_bytes = "solid box\nendsolid box\n";
};

RunSpec spec(std::uint64_t seed, double mean_N) {
  RunSpec s;
  s.seed = seed;
  s.mean_N = mean_N;
  return s;
}

// A run folder: case.yaml, hull.stl and report.json with the keys brash-post writes (report.cpp).
void write_run(const fs::path& run, const RunSpec& s, const std::string& case_yaml) {
  fs::create_directories(run);
  write_text(run / "case.yaml", case_yaml);
  write_text(run / "hull.stl", s.hull_bytes);
  json r{{"case", "synthetic"},
         {"status", "complete"},
         {"window_s", {s.window_s[0], s.window_s[1]}},
         {"met_no_ice", s.met_no_ice},
         {"resistance_model_N", {{"mean", s.mean_N}, {"ci95", s.ci95_N}}},
         {"lambda", 28.5},
         {"resistance_full_kN", s.mean_N * kLam3_kN},
         {"resistance_full_ci95_kN", s.ci95_N * kLam3_kN},
         {"fsicr", {{"R_CH_kN", 990.0}}},
         {"ratio_fsicr_to_sim", 990.0 / (s.mean_N * kLam3_kN)}};
  if (s.drifts)
    r["resistance_model_N"]["window_halves"] = {{"first_mean", s.mean_N}, {"second_mean", s.mean_N},
                                                {"difference", 0.0}, {"difference_ci95", 0.1},
                                                {"drifts", *s.drifts}};
  if (s.met_no_ice)
    for (const char* k : {"resistance_model_N", "resistance_full_kN", "resistance_full_ci95_kN"}) r[k] = nullptr;
  write_text(run / "report.json", r.dump(2));
}

void write_run(const fs::path& run, const RunSpec& s) { write_run(run, s, case_text(s.seed)); }

// The hand set: seeds 1-4 in d/s1 .. d/s4.
std::vector<fs::path> write_hand_set(const fs::path& d) {
  const std::vector<double> mean{10, 12, 11, 15}, ci{0.5, 0.7, 0.6, 0.8};
  const std::vector<std::optional<bool>> drift{false, true, false, std::nullopt};
  std::vector<fs::path> runs;
  for (std::size_t i = 0; i < mean.size(); ++i) {
    runs.push_back(d / fmt::format("s{}", i + 1));
    RunSpec s = spec(i + 1, mean[i]);
    s.ci95_N = ci[i];
    s.drifts = drift[i];
    write_run(runs.back(), s);
  }
  return runs;
}

struct Result {
  int rc = -1;
  std::string out;  // stdout and stderr
};

Result packing_ensemble(const std::vector<fs::path>& runs, const std::string& more = "") {
  std::string args;
  for (const auto& r : runs) args += fmt::format(" '{}'", r.string());
  const fs::path log = fs::temp_directory_path() / fmt::format("brash_packens_out_{}.txt", ::getpid());
  const auto cmd = fmt::format("'{}' packing-ensemble{} {} > '{}' 2>&1", BRASH_POST_EXE, args, more, log.string());
  Result r;
  r.rc = WEXITSTATUS(std::system(cmd.c_str()));
  r.out = read_text(log);
  return r;
}

void expect_line(const std::string& out, const std::string& line) {
  EXPECT_NE(out.find(line + "\n"), std::string::npos) << "missing line: " << line << "\nin:\n" << out;
}

void expect_refused(const Result& r, const std::string& message) {
  EXPECT_EQ(r.rc, 2) << r.out;
  EXPECT_NE(r.out.find(message), std::string::npos) << "missing: " << message << "\nin:\n" << r.out;
}

}  // namespace

TEST(PackingEnsemble, HandComputedMeanAndBetweenPackingCi) {
  const auto d = fresh_dir("hand");
  const auto runs = write_hand_set(d);
  const auto r = packing_ensemble(runs);
  ASSERT_EQ(r.rc, 0) << r.out;
  const fs::path file = d / "packing-ensemble-synthetic.json";
  ASSERT_TRUE(fs::exists(file)) << r.out;
  const json s = json::parse(read_text(file));
  const double sd = std::sqrt(14.0 / 3), ci = 3.182446 * sd / 2;
  EXPECT_EQ(s["n"], 4);
  EXPECT_EQ(s["dof"], 3);
  EXPECT_NEAR(s["mean_N"].get<double>(), 12.0, 1e-12);
  EXPECT_NEAR(s["sd_N"].get<double>(), sd, 1e-12);
  EXPECT_NEAR(s["ci95_N"].get<double>(), ci, 2e-4 * ci);  // the project's t table has 3 decimals: 3.182
  EXPECT_NEAR(s["full_kN"].get<double>(), 12.0 * kLam3_kN, 1e-9);
  EXPECT_NEAR(s["full_ci95_kN"].get<double>(), ci * kLam3_kN, 2e-4 * ci * kLam3_kN);
  EXPECT_NEAR(s["sd_full_kN"].get<double>(), sd * kLam3_kN, 1e-9);
  EXPECT_NEAR(s["within_ci95_mean_N"].get<double>(), 0.65, 1e-12);
  EXPECT_NEAR(s["between_over_within_ci95"].get<double>(), ci / 0.65, 2e-4 * ci / 0.65);
  EXPECT_EQ(s["window_halves_drifting"], 1);
  EXPECT_NEAR(s["fsicr_R_CH_kN"].get<double>(), 990.0, 1e-12);
  EXPECT_NEAR(s["ratio_fsicr_to_mean"].get<double>(), 990.0 / (12.0 * kLam3_kN), 1e-12);
  const auto range = s["ratio_fsicr_to_mean_over_ci95"];
  ASSERT_EQ(range.size(), 2u);
  EXPECT_NEAR(range[0].get<double>(), 990.0 / ((12.0 + ci) * kLam3_kN), 1e-3);
  EXPECT_NEAR(range[1].get<double>(), 990.0 / ((12.0 - ci) * kLam3_kN), 1e-3);
  ASSERT_EQ(s["runs"].size(), 4u);
  EXPECT_EQ(s["runs"][1]["run"], "s2");
  EXPECT_EQ(s["runs"][1]["seed"], 2);
  EXPECT_EQ(s["runs"][1]["mean_N"], 12.0);
  EXPECT_EQ(s["runs"][1]["ci95_N"], 0.7);
  EXPECT_EQ(s["runs"][1]["window_halves_drift"], true);
  EXPECT_TRUE(s["runs"][3]["window_halves_drift"].is_null());

  expect_line(r.out, "== synthetic: 4 packings, mean resistance over the window [15, 40] s");
  expect_line(r.out, "| run | ice.seed | window [s] | model [N] | full scale [kN] | window halves |");
  expect_line(r.out, "| s1 | 1 | [15, 40] | 10.000 ± 0.500 | 231.5 ± 11.6 | agree |");
  expect_line(r.out, "| s2 | 2 | [15, 40] | 12.000 ± 0.700 | 277.8 ± 16.2 | drifts |");
  expect_line(r.out, "| s4 | 4 | [15, 40] | 15.000 ± 0.800 | 347.2 ± 18.5 | - |");
  expect_line(r.out,
              "| **ensemble mean** (n = 4) | | [15, 40] | **12.000 ± 3.437** | **277.8 ± 79.6** | 1 of 4 drift |");
  expect_line(r.out, "between packings: sd 2.160 N (50.0 kN full scale), n = 4, 95 % CI = t_{0.975,3} 3.182 x sd / "
                     "sqrt(n)");
  expect_line(r.out, "between-packing CI95 / mean within-run CI95 (0.650 N) = 5.29");
  expect_line(r.out, "FSICR R_CH 990.0 kN; R_CH / R of the mean = 3.56 (2.77 to 4.99 over the mean's 95 % CI)");
  expect_line(r.out, "wrote " + file.string());
}

// The summary's keys, in order; --out puts it where it is asked for.
TEST(PackingEnsemble, SummaryKeysAndOut) {
  const auto d = fresh_dir("keys");
  const auto runs = write_hand_set(d);
  const fs::path out = d / "elsewhere.json";
  const auto r = packing_ensemble(runs, fmt::format("--out '{}'", out.string()));
  ASSERT_EQ(r.rc, 0) << r.out;
  EXPECT_FALSE(fs::exists(d / "packing-ensemble-synthetic.json"));
  const auto s = nlohmann::ordered_json::parse(read_text(out));
  std::vector<std::string> keys;
  for (const auto& [k, v] : s.items()) keys.push_back(k);
  EXPECT_EQ(keys, (std::vector<std::string>{"case", "definition", "window_s", "n", "dof", "t975", "runs", "mean_N",
                                            "ci95_N", "sd_N", "full_kN", "full_ci95_kN", "sd_full_kN",
                                            "within_ci95_mean_N", "between_over_within_ci95",
                                            "window_halves_drifting", "fsicr_R_CH_kN", "ratio_fsicr_to_mean",
                                            "ratio_fsicr_to_mean_over_ci95"}));
  std::vector<std::string> run_keys;
  for (const auto& [k, v] : s["runs"][0].items()) run_keys.push_back(k);
  EXPECT_EQ(run_keys, (std::vector<std::string>{"run", "dir", "seed", "mean_N", "ci95_N", "full_kN", "full_ci95_kN",
                                                "window_halves_drift"}));
  EXPECT_EQ(s["case"], "synthetic");
  EXPECT_EQ(s["window_s"], json({15.0, 40.0}));
}

TEST(PackingEnsemble, RefusesFewerThanTwoRuns) {
  const auto d = fresh_dir("one");
  const auto runs = write_hand_set(d);
  expect_refused(packing_ensemble({runs[0]}), fmt::format("1 run folder(s) given ({}); at least 2 are needed",
                                                          runs[0].string()));
}

TEST(PackingEnsemble, RefusesARunWithoutReport) {
  const auto d = fresh_dir("noreport");
  const auto runs = write_hand_set(d);
  fs::remove(runs[2] / "report.json");
  expect_refused(packing_ensemble(runs),
                 fmt::format("{}: no report.json (run brash-post {} first)", runs[2].string(), runs[2].string()));
}

TEST(PackingEnsemble, RefusesARunThatMetNoIce) {
  const auto d = fresh_dir("noice");
  const auto runs = write_hand_set(d);
  RunSpec s = spec(2, 12);
  s.met_no_ice = true;
  write_run(runs[1], s);
  expect_refused(packing_ensemble(runs), fmt::format("{}: the hull met no ice in the run's window [15, 40] s: it has "
                                                     "no resistance",
                                                     (runs[1] / "report.json").string()));
}

// A case that differs in more than the packing: the differing keys listed; the packing file's and the hull file's
// paths (each run's own folder) are not among them.
TEST(PackingEnsemble, RefusesCasesThatDifferBeyondThePacking) {
  const auto d = fresh_dir("case");
  const auto runs = write_hand_set(d);
  write_run(runs[3], spec(4, 15),
            case_text(4, "speed_m_s: 0.482", "speed_m_s: 0.5") + "  porosity: 0.3\n");
  expect_refused(packing_ensemble(runs),
                 fmt::format("{}/case.yaml differs from {}/case.yaml in ice.porosity, ship.speed_m_s: the runs of a "
                             "packing ensemble differ only in ice.seed (and ice.packing_file, name)",
                             runs[3].string(), runs[0].string()));
}

TEST(PackingEnsemble, RefusesAnotherHull) {
  const auto d = fresh_dir("hull");
  const auto runs = write_hand_set(d);
  RunSpec s = spec(2, 12);
  s.hull_bytes = "solid other\nendsolid other\n";
  write_run(runs[1], s);
  expect_refused(packing_ensemble(runs), fmt::format("{}/case.yaml differs from {}/case.yaml in hull.file:",
                                                     runs[1].string(), runs[0].string()));
}

// The case's name may differ (a seed's own case folder, named after it).
TEST(PackingEnsemble, AcceptsCasesNamedAfterTheirSeed) {
  const auto d = fresh_dir("name");
  const auto runs = write_hand_set(d);
  write_run(runs[1], spec(2, 12), case_text(2, "name: synthetic", "name: synthetic_s2"));
  const auto r = packing_ensemble(runs);
  EXPECT_EQ(r.rc, 0) << r.out;
  EXPECT_TRUE(fs::exists(d / "packing-ensemble-synthetic.json")) << r.out;  // the first run's name
}

TEST(PackingEnsemble, RefusesTwoRunsOfOneSeed) {
  const auto d = fresh_dir("seed");
  const auto runs = write_hand_set(d);
  write_run(runs[2], spec(2, 11));
  expect_refused(packing_ensemble(runs), fmt::format("{} and {} have the same ice.seed 2: one packing twice",
                                                     runs[1].string(), runs[2].string()));
}

TEST(PackingEnsemble, RefusesDifferentWindows) {
  const auto d = fresh_dir("window");
  const auto runs = write_hand_set(d);
  RunSpec s = spec(3, 11);
  s.window_s = {15.0, 32.5};
  write_run(runs[2], s, case_text(3, "window_s: [15.0, 40]", "window_s: [15.0, 32.5]"));
  const auto r = packing_ensemble(runs);
  EXPECT_EQ(r.rc, 2) << r.out;
  EXPECT_NE(r.out.find("differs from " + runs[0].string() + "/case.yaml in run.window_s"), std::string::npos)
      << r.out;
}

// An early stop ends each run's window at its own time: the runs asked for the same window (meta.json early_stop
// keeps it), so they are one ensemble; each row shows the window it used.
TEST(PackingEnsemble, RunsStoppedEarlyAtDifferentTimesAreOneEnsemble) {
  const auto d = fresh_dir("early");
  const auto runs = write_hand_set(d);
  RunSpec s = spec(3, 11);
  s.window_s = {15.0, 25.0};
  write_run(runs[2], s,
            case_text(3, "duration_s: 45.0\n  window_s: [15.0, 40]", "duration_s: 25.0\n  window_s: [15.0, 25]"));
  write_text(runs[2] / "meta.json",
             R"({"early_stop": {"t_s": 25.0, "requested_duration_s": 45.0, "requested_window_s": [15.0, 40.0]}})");
  const auto r = packing_ensemble(runs);
  EXPECT_EQ(r.rc, 0) << r.out;
  EXPECT_NE(r.out.find("| [15, 25] |"), std::string::npos) << r.out;
}

// Two synthetic runs post-processed by brash-post: the ensemble reads the reports it writes.
TEST(PackingEnsemble, ReadsTheReportsBrashPostWrites) {
  const auto d = fresh_dir("real");
  std::vector<fs::path> runs;
  std::vector<double> means;
  for (std::uint64_t seed : {3, 7}) {
    brash::post::testing::SyntheticRun s;
    s.mean_resistance_N = 2.0 + 0.1 * static_cast<double>(seed);
    runs.push_back(d / fmt::format("seed{}", seed));
    brash::post::testing::write_synthetic_run(runs.back(), s);
    // one hull path for both (a file that is not there, as in every synthetic run: nothing is measured)
    write_text(runs.back() / "case.yaml",
               case_text(seed, "file: hull.stl", "file: " + (d / "no_such_hull.stl").string()));
    const auto cmd = fmt::format("'{}' --no-plots --no-paraview '{}' > /dev/null 2>&1", BRASH_POST_EXE,
                                 runs.back().string());
    ASSERT_EQ(WEXITSTATUS(std::system(cmd.c_str())), 0) << cmd;
    means.push_back(json::parse(read_text(runs.back() / "report.json"))["resistance_model_N"]["mean"].get<double>());
  }
  const auto r = packing_ensemble(runs);
  ASSERT_EQ(r.rc, 0) << r.out;
  const json s = json::parse(read_text(d / "packing-ensemble-synthetic.json"));
  EXPECT_NEAR(s["mean_N"].get<double>(), 0.5 * (means[0] + means[1]), 1e-12);
  EXPECT_NEAR(s["sd_N"].get<double>(), std::abs(means[0] - means[1]) / std::sqrt(2.0), 1e-12);
  EXPECT_EQ(s["runs"][1]["seed"], 7);
  EXPECT_TRUE(s["runs"][0]["window_halves_drift"].is_boolean());
  EXPECT_TRUE(s["fsicr_R_CH_kN"].is_number());
}
