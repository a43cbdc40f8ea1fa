// brash-study-report on synthetic report.json files: exact exponent fit on R = a U^n, tables carry the
// values, failed and missing runs are reported (never dropped), paper rows of reduced cases are labelled.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include "synthetic_run.hpp"

namespace fs = std::filesystem;
using brash::post::testing::read_text;
using nlohmann::json;

namespace {

fs::path fresh_dir(const std::string& name) { return brash::post::testing::fresh_dir("study", name); }

void write_report(const fs::path& run_dir, const std::string& engine, const std::string& model, double speed,
                  double mean, double ci, const std::string& status = "complete") {
  fs::create_directories(run_dir);
  const double lambda = 28.5, scale = std::pow(lambda, 3) * 1.025 / 1000.0;
  json j = {{"engine", engine}, {"fluid_model", model}, {"treatment", "implicit"}, {"case", run_dir.filename().string()},
            {"status", status}, {"complete", status == "complete"}, {"speed_m_s", speed},
            {"window_s", {0.75, 1.5}}, {"record", {{"t_last_s", 1.5}}},
            {"resistance_model_N", {{"mean", mean}, {"ci95", ci}, {"x", -mean}, {"y", 0.0}, {"z", 0.0},
                                    {"blocking", {{"plateau_found", true}}}}},
            {"lambda", lambda}, {"resistance_full_kN", mean * scale}, {"resistance_full_ci95_kN", ci * scale},
            {"fsicr", {{"params", {{"L_m", 199.5}, {"B_m", 32.06}, {"T_m", 11.76}, {"alpha_deg", 38.06},
                                   {"phi2_deg", 79.67}, {"A_wf_m2", 993.7}}},
                       {"R_CH_kN", 1327.25}}},
            {"ratio_fsicr_to_sim", 1327.25 / (mean * scale)}, {"wall_time_s", 100.0}, {"particle_steps", 5.0e7}};
  std::ofstream(run_dir / "report.json") << j.dump(2);
}

int run_tool(const fs::path& dir, const std::string& args) {
  // the paper's values come from the paper case's references, as in the repository
  const std::string cmd = fmt::format("'{}' --paper-case '{}/cases/jbc_ia_5kn/case.yaml' {} > '{}' 2>&1",
                                      BRASH_STUDY_REPORT_EXE, BRASH_SOURCE_DIR, args, (dir / "tool.log").string());
  return std::system(cmd.c_str());
}

constexpr const char* kHeader = "id\tgroup\tlabel\tparam\tvalue\tbaseline\tbase_case\texit_code\trun_dir\tcommand\n";

}  // namespace

TEST(StudyReport, ExponentFitIsExactOnPowerLaw) {
  const fs::path d = fresh_dir("fit");
  const double a = 40.0, n_am = 1.37, n_drag = 0.82;
  std::string m = kHeader;
  int i = 0;
  for (double u : {0.2, 0.4, 0.7, 1.0}) {
    for (auto [model, n] : {std::pair{"added_mass", n_am}, std::pair{"drag", n_drag}}) {
      const std::string rd = fmt::format("runs/s{}", ++i);
      write_report(d / rd, "liggghts", model, u, a * std::pow(u, n), 0.1);
      m += fmt::format("s{}\tspeed\tU {}\tspeed_m_s\t{}\t0\tjbc_bench\t0\t{}\tbrash-liggghts-run case_{} --model {}\n", i,
                       u, u, rd, i, model);
    }
  }
  std::ofstream(d / "manifest.tsv") << m;
  ASSERT_EQ(run_tool(d, fmt::format("'{}' --out '{}' --summary-json '{}'", (d / "manifest.tsv").string(),
                                    (d / "study.md").string(), (d / "summary.json").string())),
            0)
      << read_text(d / "tool.log");
  const json s = json::parse(read_text(d / "summary.json"));
  ASSERT_EQ(s["fits"].size(), 2u);
  for (const auto& f : s["fits"]) {
    const double n = f["fluid_model"] == "added_mass" ? n_am : n_drag;
    EXPECT_EQ(f["points"], 4);
    EXPECT_NEAR(f["n"].get<double>(), n, 1e-12);
    EXPECT_NEAR(f["n_se"].get<double>(), 0.0, 1e-9);
    EXPECT_NEAR(f["a"].get<double>(), a, 1e-9);
  }
  EXPECT_EQ(s["failed"], 0);
  const std::string md = read_text(d / "study.md");
  EXPECT_NE(md.find("## (b) Speed sweep"), std::string::npos);
  EXPECT_NE(md.find("1.370 ± 0.000 (SE 0.000)"), std::string::npos) << md;
  EXPECT_NE(md.find("0.820 ± 0.000"), std::string::npos);
  EXPECT_NE(md.find("brash-liggghts-run case_3 --model added_mass"), std::string::npos);  // command of the run
  if (std::system("command -v gnuplot > /dev/null 2>&1") == 0) {
    EXPECT_TRUE(fs::exists(d / "study_speed.png"));
    EXPECT_NE(md.find("![speed sweep](study_speed.png)"), std::string::npos);
  }
}

// With scatter about the power law the exponent's CI95 is t_{0.975, speeds - 2} times the slope's standard error
// (5 speeds: t_{0.975, 3} = 3.182, the table's 3 decimals), the SE from the residuals of the log-log line.
TEST(StudyReport, ExponentCarriesItsConfidenceInterval) {
  const fs::path d = fresh_dir("fit_ci");
  const std::vector<double> u{0.2, 0.3, 0.482, 0.7, 1.0}, e{0.02, -0.01, 0.0, -0.02, 0.01};
  std::string m = kHeader;
  for (std::size_t i = 0; i < u.size(); ++i) {
    const std::string rd = fmt::format("runs/c{}", i);
    write_report(d / rd, "liggghts", "both", u[i], 10.0 * std::pow(u[i], 1.2) * std::exp(e[i]), 0.1);
    m += fmt::format("c{}\tspeed\tU {}\tspeed_m_s\t{}\t0\tjbc_quick\t0\t{}\tcmd\n", i, u[i], u[i], rd);
  }
  std::ofstream(d / "manifest.tsv") << m;
  ASSERT_EQ(run_tool(d, fmt::format("'{}' --out '{}' --summary-json '{}' --plot none", (d / "manifest.tsv").string(),
                                    (d / "study.md").string(), (d / "summary.json").string())),
            0)
      << read_text(d / "tool.log");
  // the least-squares slope and its SE, written out
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < u.size(); ++i) mx += std::log(u[i]) / 5, my += (std::log(10.0 * std::pow(u[i], 1.2)) + e[i]) / 5;
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    sxx += std::pow(std::log(u[i]) - mx, 2);
    sxy += (std::log(u[i]) - mx) * (std::log(10.0 * std::pow(u[i], 1.2)) + e[i] - my);
  }
  const double n = sxy / sxx;
  double ssr = 0;
  for (std::size_t i = 0; i < u.size(); ++i)
    ssr += std::pow(std::log(10.0 * std::pow(u[i], 1.2)) + e[i] - my - n * (std::log(u[i]) - mx), 2);
  const double se = std::sqrt(ssr / 3 / sxx);
  const json s = json::parse(read_text(d / "summary.json"));
  ASSERT_EQ(s["fits"].size(), 1u);
  EXPECT_NEAR(s["fits"][0]["n"].get<double>(), n, 1e-12);
  EXPECT_NEAR(s["fits"][0]["n_se"].get<double>(), se, 1e-12);
  EXPECT_NEAR(s["fits"][0]["n_ci95"].get<double>(), 3.182 * se, 1e-12);
  EXPECT_NE(read_text(d / "study.md").find(fmt::format("{:.3f} ± {:.3f} (SE {:.3f})", n, 3.182 * se, se)),
            std::string::npos);
}

TEST(StudyReport, TablesCarryValuesAndFailuresAreReported) {
  const fs::path d = fresh_dir("tables");
  write_report(d / "runs/am", "liggghts", "added_mass", 0.482, 12.5, 1.5);
  write_report(d / "runs/drag", "liggghts", "drag", 0.482, 10.0, 1.0);
  write_report(d / "runs/ode", "ode", "added_mass", 0.482, 14.25, 2.0);
  write_report(d / "runs/fric", "liggghts", "added_mass", 0.482, 20.0, 1.5);
  write_report(d / "runs/broken", "liggghts", "added_mass", 0.482, 3.0, 1.0, "failed");
  std::string m = kHeader;
  m += "p1\tpaper\tbaseline am\t\t\t1\tjbc_bench\t0\truns/am\tbrash-liggghts-run am\n";
  m += "p2\tpaper\tbaseline drag\t\t\t1\tjbc_bench\t0\truns/drag\tbrash-liggghts-run drag\n";
  m += "e1\tengine\tode am\t\t\t0\tjbc_bench\t0\truns/ode\tbrash-ode am\n";
  m += "f0\tfriction_ice\tmu 1.35\tfriction.ice_ice\t1.35\t1\tjbc_bench\t0\truns/am\tbrash-liggghts-run am\n";
  m += "f1\tfriction_ice\tmu 0.5\tfriction.ice_ice\t0.5\t0\tjbc_bench\t0\truns/fric\tbrash-liggghts-run fric\n";
  m += "d1\tdensity_ice\trho 850\tice.density_kg_m3\t850\t0\tjbc_bench\t0\truns/broken\tbrash-liggghts-run broken\n";
  m += "d2\tdensity_ice\trho 950\tice.density_kg_m3\t950\t0\tjbc_bench\t0\truns/never_ran\tbrash-liggghts-run never\n";
  m += "c1\tca\tCa text\tfluid.ca_table\ttext\t0\tjbc_bench\t137\t\tbrash-liggghts-run killed\n";
  m += "c2\tca\tCa zero\tfluid.ca_table\tzero\t0\tjbc_bench\tcase generation failed\truns/c2\tbrash-case new c2\n";
  m += "p3\tpaper\tpaper case am\t\t\t1\tjbc_ia_5kn\tin progress: model time 7.70 s of 40 s reached\truns/paper\tbrash-liggghts-run paper\n";
  std::ofstream(d / "manifest.tsv") << m;
  ASSERT_EQ(run_tool(d, fmt::format("'{}' --out '{}' --plot none --summary-json '{}'", (d / "manifest.tsv").string(),
                                    (d / "study.md").string(), (d / "summary.json").string())),
            0)
      << read_text(d / "tool.log");
  const std::string md = read_text(d / "study.md");
  // (a) paper table: values, paper numbers, reduced-case labels, added mass vs drag +25 %.
  EXPECT_NE(md.find("## (a) Paper comparison"), std::string::npos);
  EXPECT_NE(md.find("12.50 ± 1.50"), std::string::npos) << md;
  EXPECT_NE(md.find("10.00 ± 1.00"), std::string::npos);
  EXPECT_NE(md.find("No completed run of the paper case"), std::string::npos);
  EXPECT_NE(md.find("**reduced case**"), std::string::npos);
  EXPECT_NE(md.find("| 393 |"), std::string::npos);
  EXPECT_NE(md.find("| 378 |"), std::string::npos);
  EXPECT_NE(md.find("| 1327 |"), std::string::npos);
  EXPECT_NE(md.find("+25.0 %"), std::string::npos);
  // the paper's ratio is stated for its added-mass result only; for drag it is derived from 999 and 378
  EXPECT_NE(md.find("| added_mass | 12.50 ± 1.50 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 2.54 | ok |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 2.64 (999 / 378) | ok |"), std::string::npos) << md;
  // (c) sensitivity: delta vs baseline and delta / combined CI = 7.5 / sqrt(2 * 1.5^2) = 3.54.
  EXPECT_NE(md.find("### friction_ice"), std::string::npos);
  EXPECT_NE(md.find("+7.50 (+60.0 %)"), std::string::npos);
  EXPECT_NE(md.find("+3.54"), std::string::npos);
  // (d) engine table with both engines.
  EXPECT_NE(md.find("## (d) Engines"), std::string::npos);
  EXPECT_NE(md.find("14.25 ± 2.00"), std::string::npos);
  // ODE against the LIGGGHTS run of the same case and model: 14.25 / 12.5 = +14.0 %, CI 1.14 x hypot(2
  // / 14.25, 1.5 / 12.5) = 21.1 %
  EXPECT_NE(md.find("| +14.0 % ± 21.1 % (R1) |"), std::string::npos) << md;
  EXPECT_NE(md.find("| reference |"), std::string::npos);
  // failures: status failed, missing report, runner exit code; all listed.
  EXPECT_NE(md.find("run status 'failed'"), std::string::npos);
  EXPECT_NE(md.find("no report.json"), std::string::npos);
  EXPECT_NE(md.find("runner exited with code 137"), std::string::npos);
  EXPECT_NE(md.find("runner: case generation failed"), std::string::npos);
  EXPECT_NE(md.find("**4 of 9 run(s) have no usable result.**"), std::string::npos) << md;
  // a long run still going is "in progress", not a failure, and says how far it is
  EXPECT_NE(md.find("## Runs in progress"), std::string::npos);
  EXPECT_NE(md.find("| R9 | `"), std::string::npos);
  EXPECT_NE(md.find("**IN PROGRESS** (in progress: model time 7.70 s of 40 s reached)"), std::string::npos);
  // the paper case's run folder does not exist: no set-up table (nothing to read it from)
  EXPECT_EQ(md.find("set-up vs the paper's"), std::string::npos);
  const json s = json::parse(read_text(d / "summary.json"));
  EXPECT_EQ(s["failed"], 4);
  EXPECT_EQ(s["in_progress"], 1);
  EXPECT_EQ(s["runs"].size(), 9u);
}

// A group that varies the fluid model itself (fluid.model: added_mass vs both) compares each run with the
// baseline of its engine, whatever its model; other groups keep comparing like models only.
TEST(StudyReport, FluidModelGroupComparesAcrossModels) {
  const fs::path d = fresh_dir("fluid_model");
  write_report(d / "runs/am", "liggghts", "added_mass", 0.482, 10.0, 1.0);
  write_report(d / "runs/both", "liggghts", "both", 0.482, 13.0, 1.0);
  write_report(d / "runs/drag", "liggghts", "drag", 0.482, 9.0, 1.0);
  std::string m = kHeader;
  m += "m0\tfluid_model\tadded mass\tfluid.model\tadded_mass\t1\tjbc_bench\t0\truns/am\tbrash-liggghts-run "
       "am\n";
  m += "m1\tfluid_model\tboth\tfluid.model\tboth\t0\tjbc_bench\t0\truns/both\tbrash-liggghts-run both\n";
  m += "c0\tdrag_cd\tC_D 0.44\tfluid.drag_coefficient\t0.44\t1\tjbc_bench\t0\truns/am\tbrash-liggghts-run "
       "am\n";
  m += "c1\tdrag_cd\tC_D 1.0\tfluid.drag_coefficient\t1.0\t0\tjbc_bench\t0\truns/drag\tbrash-liggghts-run "
       "drag\n";
  for (const char* model : {"am", "both", "drag"})
    m += fmt::format("p_{0}\tpaper\t{0}\t\t\t1\tjbc_bench\t0\truns/{0}\tbrash-liggghts-run {0}\n", model);
  std::ofstream(d / "manifest.tsv") << m;
  ASSERT_EQ(run_tool(d, fmt::format("'{}' --out '{}' --plot none", (d / "manifest.tsv").string(),
                                    (d / "study.md").string())),
            0)
      << read_text(d / "tool.log");
  const std::string md = read_text(d / "study.md");
  EXPECT_NE(md.find("### fluid_model (parameter `fluid.model`)"), std::string::npos) << md;
  // 3 / sqrt(1 + 1) = 2.12
  EXPECT_NE(md.find("| both | liggghts | both | 13.00 ± 1.00 | "), std::string::npos) << md;
  EXPECT_NE(md.find("+3.00 (+30.0 %) | +2.12 |"), std::string::npos) << md;
  // the C_D group's drag run has no drag baseline (its baseline row is an added_mass run): not compared
  EXPECT_NE(md.find("| no baseline | — |"), std::string::npos) << md;
  // section (a): both readings of the paper's added-mass model against drag (13 / 9 - 1, 10 / 9 - 1)
  EXPECT_NE(md.find("| liggghts | jbc_bench | both | 13.00 ± 1.00 (R2) | 9.00 ± 1.00 (R3) | +44.4 % |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| liggghts | jbc_bench | added_mass | 10.00 ± 1.00 (R1) | 9.00 ± 1.00 (R3) | +11.1 % |"),
            std::string::npos);
}

// A completed paper-case run gets its gap to the paper's number, and every sensitivity change with a baseline
// is listed beside it (sign, size, CI, whether resolved); without a paper-case result there is no such
// section.
TEST(StudyReport, GapToThePaperListsEveryMeasuredCandidate) {
  const fs::path d = fresh_dir("gap");
  write_report(d / "runs/paper", "liggghts", "added_mass", 0.482, 12.0, 0.6);
  write_report(d / "runs/am", "liggghts", "added_mass", 0.482, 10.0, 1.0);
  write_report(d / "runs/both", "liggghts", "both", 0.482, 13.0, 1.0);
  write_report(d / "runs/rho", "liggghts", "added_mass", 0.482, 10.5, 1.0);
  std::string m = kHeader;
  m += "p\tpaper\tpaper case\t\t\t1\tjbc_ia_5kn\t0\truns/paper\tbrash-liggghts-run paper\n";
  m += "m0\tfluid_model\tam\tfluid.model\tadded_mass\t1\tjbc_bench\t0\truns/am\tbrash-liggghts-run am\n";
  m += "m1\tfluid_model\tboth\tfluid.model\tboth\t0\tjbc_bench\t0\truns/both\tbrash-liggghts-run both\n";
  m += "r0\tdensity_ice\t900\tice.density_kg_m3\t900\t1\tjbc_bench\t0\truns/am\tbrash-liggghts-run am\n";
  m += "r1\tdensity_ice\t850\tice.density_kg_m3\t850\t0\tjbc_bench\t0\truns/rho\tbrash-liggghts-run rho\n";
  std::ofstream(d / "manifest.tsv") << m;
  ASSERT_EQ(run_tool(d, fmt::format("'{}' --out '{}' --plot none", (d / "manifest.tsv").string(),
                                    (d / "study.md").string())),
            0)
      << read_text(d / "tool.log");
  const std::string md = read_text(d / "study.md");
  const double full = 12.0 * std::pow(28.5, 3) * 1.025 / 1000.0;
  ASSERT_NE(md.find("### The gap to the paper"), std::string::npos) << md;
  EXPECT_NE(md.find(fmt::format("the paper's 393 kN is **{:+.1f} %** on it", 100.0 * (393.0 / full - 1.0))),
            std::string::npos)
      << md;
  // both: +30 % +- sqrt(2) * 10 % = 14.1 %, resolved; rho 850: +5 % +- 14.1 %, not resolved
  EXPECT_NE(md.find("| fluid.model: both | jbc_bench, liggghts, both | +30.0 % ± 14.1 % | R3 vs R2 |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| ice.density_kg_m3: 850 | jbc_bench, liggghts, added_mass | +5.0 % ± 14.1 % (not "
                    "resolved) | R4 vs R2 |"),
            std::string::npos)
      << md;
  // without the paper-case run: no gap section
  std::string m2 = kHeader;
  m2 += m.substr(m.find("m0\t"));
  std::ofstream(d / "manifest2.tsv") << m2;
  ASSERT_EQ(run_tool(d, fmt::format("'{}' --out '{}' --plot none", (d / "manifest2.tsv").string(),
                                    (d / "study2.md").string())),
            0);
  EXPECT_EQ(read_text(d / "study2.md").find("### The gap to the paper"), std::string::npos);
}

// Paired-seed ensembles (group `paired`, run_dir = bench/rank_ensemble.sh's summary JSON): tabled in section
// (c) with their commands, listed among the gap's candidates (resolved or not), and a missing summary is
// named in the failures section and counted as failed, never dropped. Every effect is on side A: a summary with
// per-pair values gives its CI on A (pairs (10, 11), (20, 22), (30, 34): +11.67 % ± 5.48 %), one written before
// them (the mean of (B - A) / mean of the pair, -0.50 % ± 0.90 %) its effect on A from its means (38.9 -> 38.7 N:
// -0.51 %) and its recorded CI, named as such.
TEST(StudyReport, PairedEnsemblesAreTabledAndAMissingOneIsNamed) {
  const fs::path d = fresh_dir("paired");
  write_report(d / "runs/paper", "liggghts", "drag", 0.482, 23.76, 0.07);
  const std::string soft = "1:contact.youngs_modulus_pa=3.125e5";
  auto write_summary = [&](const std::string& name, const std::string& side_b, int pairs, double a, double b,
                           const json& statistics) {
    fs::create_directories(d / "ens");
    json j = {{"case", "jbc_quick"}, {"side_a", soft + ",fluid.model=drag"},
              {"side_b", side_b},    {"pairs", pairs},
              {"mean_a_N", a},       {"mean_b_N", b}};
    j.update(statistics);
    std::ofstream(d / "ens" / name) << j.dump(1);
  };
  write_summary("both.json", soft + ",fluid.model=both", 3, 20.0, 67.0 / 3,
                {{"effect_rel", 0.1167}, {"a_N", {10.0, 20.0, 30.0}}, {"b_N", {11.0, 22.0, 34.0}}});
  write_summary("rho.json", soft + ",fluid.model=drag,ice.density_kg_m3=850", 3, 38.9, 38.7,
                {{"diff_rel", -0.0050}, {"ci95_rel", 0.0090}});
  std::string m = kHeader;
  m += "p\tpaper\tpaper case\t\t\t1\tjbc_ia_5kn\t0\truns/paper\tbrash-liggghts-run paper\n";
  m += "e1\tpaired\tboth on drag\tfluid.model\tboth\t0\tjbc_quick\t0\tens/both.json\tSIDE_B=both bash "
       "bench/rank_ensemble.sh 8 ens\n";
  m += "e2\tpaired\t\tice.density_kg_m3\t850\t0\tjbc_quick\t0\tens/rho.json\tSIDE_B=rho bash "
       "bench/rank_ensemble.sh 3 ens\n";
  m += "e3\tpaired\tmu\tfriction.ice_ice\t0.5\t0\tjbc_quick\t0\tens/mu.json\tSIDE_B=mu bash "
       "bench/rank_ensemble.sh 3 ens\n";
  std::ofstream(d / "manifest.tsv") << m;
  ASSERT_EQ(run_tool(d, fmt::format("'{}' --out '{}' --plot none --figures none --summary-json '{}'",
                                    (d / "manifest.tsv").string(), (d / "study.md").string(),
                                    (d / "summary.json").string())),
            0)
      << read_text(d / "tool.log");
  const std::string md = read_text(d / "study.md");
  EXPECT_NE(
      md.find("| P1 | fluid.model: both | both on drag | jbc_quick | `" + soft + ",fluid.model=drag` → `" +
              soft + ",fluid.model=both` | 3 | 20.00 / 22.33 | +11.67 % ± 5.48 % | yes |"),
      std::string::npos)
      << md;
  EXPECT_NE(md.find("| 38.90 / 38.70 | -0.51 % (CI on A not recomputable; recorded on the pair mean: ± 0.90 %) | "
                    "no (as recorded) |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("- P1 (`"), std::string::npos) << md;
  EXPECT_NE(md.find("`SIDE_B=both bash bench/rank_ensemble.sh 8 ens`"), std::string::npos) << md;
  // the gap's candidates, beside the one-run rows
  EXPECT_NE(
      md.find("| fluid.model: both | jbc_quick, 3 paired packings, both on drag | +11.7 % ± 5.5 % | P1 |"),
      std::string::npos)
      << md;
  EXPECT_NE(
      md.find("| ice.density_kg_m3: 850 | jbc_quick, 3 paired packings, drag | -0.5 % (CI on A not recomputable; "
              "recorded on the pair mean: ± 0.9 %) (not resolved) | P2 |"),
      std::string::npos)
      << md;
  // the missing one: in its table row, in the failures section, counted as failed
  EXPECT_NE(md.find("| P3 | friction.ice_ice: 0.5 | mu | jbc_quick | — | — | — | — | **MISSING: no ensemble "
                    "summary at"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("**1 paired ensemble(s) have no usable summary**"), std::string::npos) << md;
  const json summary = json::parse(read_text(d / "summary.json"));
  EXPECT_EQ(summary.at("failed").get<int>(), 1);
  ASSERT_EQ(summary.at("paired").size(), 3u);
  EXPECT_FALSE(summary.at("paired").at(2).at("ok").get<bool>());
  // a paired row is not a run: it is not in the runs table, and R-numbers are the runs' alone
  EXPECT_EQ(md.find("`ens/both.json` | "), std::string::npos) << md;
  fs::remove_all(d);
}

// Section (a)'s figures: the Fig. 6 analog bar chart (data with our runs, the paper's numbers and our R_CH) and
// each run's own force history / newest ice views linked where they are (not copied); the figure folder is
// replaced each time.
TEST(StudyReport, FiguresOfThePaperSectionAreLinkedAndPlotted) {
  const fs::path d = fresh_dir("figs");
  write_report(d / "runs/am", "liggghts", "added_mass", 0.482, 12.5, 1.5);
  write_report(d / "runs/ode", "ode", "drag", 0.482, 11.0, 1.0);
  std::ofstream(d / "runs/am/force_history.png") << "force history of am";
  std::ofstream(d / "runs/am/ice_views_000.50s.png") << "early views";
  std::ofstream(d / "runs/am/ice_views_001.00s.png") << "late views";
  std::string m = kHeader;
  m += "p1\tpaper\tam\t\t\t1\tjbc_bench\t0\truns/am\tbrash-liggghts-run am\n";
  m += "p2\tpaper\tode drag\t\t\t1\tjbc_bench\t0\truns/ode\tbrash-ode drag\n";
  std::ofstream(d / "manifest.tsv") << m;
  fs::create_directories(d / "doc/study_figs");
  std::ofstream(d / "doc/study_figs/R9_stale.png") << "from an older study";
  ASSERT_EQ(run_tool(d, fmt::format("'{}' --out '{}' --plot none", (d / "manifest.tsv").string(),
                                    (d / "doc/study.md").string())),
            0)
      << read_text(d / "tool.log");
  const fs::path figs = d / "doc/study_figs";
  EXPECT_FALSE(fs::exists(figs / "R9_stale.png"));
  EXPECT_FALSE(fs::exists(figs / "R1_force_history.png"));  // linked, not copied
  EXPECT_FALSE(fs::exists(figs / "R1_ice_views.png"));
  const std::string dat = read_text(figs / "paper_bars.dat");
  EXPECT_NE(dat.find("\"R1 liggghts added_mass\" " + fmt::format("{}", 12.5 * std::pow(28.5, 3) * 1.025 / 1000.0)),
            std::string::npos)
      << dat;
  EXPECT_NE(dat.find("\"paper added mass\" 393 0"), std::string::npos);
  EXPECT_NE(dat.find("\"paper drag\" 378 0"), std::string::npos);
  EXPECT_NE(dat.find("\"FSICR R_CH ours (R1)\" 1327.25 0"), std::string::npos);  // one bar: both runs have the same
  EXPECT_EQ(dat.find("FSICR R_CH ours (R2)"), std::string::npos);
  EXPECT_NE(dat.find("\"paper FSICR R_CH\" 999 0"), std::string::npos);
  EXPECT_NE(read_text(figs / "paper_bars.gp").find("REDUCED-CASE runs, not the paper case"), std::string::npos);
  const std::string md = read_text(d / "doc/study.md");
  EXPECT_NE(md.find("![R1 force history](../runs/am/force_history.png)"), std::string::npos) << md;
  EXPECT_NE(md.find("![R1 ice views](../runs/am/ice_views_001.00s.png)"), std::string::npos);  // the newest dump's
  EXPECT_NE(md.find("no force_history.png in"), std::string::npos);  // the ODE run has none: said so in the text
  if (std::system("command -v gnuplot > /dev/null 2>&1") == 0) {
    EXPECT_TRUE(fs::exists(figs / "paper_bars.png"));
    EXPECT_NE(md.find("![full-scale resistance vs the paper](study_figs/paper_bars.png)"), std::string::npos);
  }
  // --figures none: no folder, no section content beyond the heading
  fs::remove_all(figs);
  ASSERT_EQ(run_tool(d, fmt::format("'{}' --out '{}' --plot none --figures none", (d / "manifest.tsv").string(),
                                    (d / "doc/study.md").string())),
            0);
  EXPECT_FALSE(fs::exists(figs));
}

// Once a paper-case run is complete, the Fig. 6 analog shows the paper case's runs alone: a reduced case's
// lambda^3-scaled number is not the paper's ship in the paper's channel.
TEST(StudyReport, Fig6BarsShowThePaperCaseAloneWhenItIsThere) {
  const fs::path d = fresh_dir("bars");
  write_report(d / "runs/am", "liggghts", "added_mass", 0.482, 12.5, 1.5);
  write_report(d / "runs/paper", "liggghts", "drag", 0.482, 23.0, 0.1);
  std::string m = kHeader;
  m += "p1\tpaper\tam\t\t\t1\tjbc_bench\t0\truns/am\tbrash-liggghts-run am\n";
  m += "p2\tpaper\tpaper drag\t\t\t1\tjbc_ia_5kn\t0\truns/paper\tbrash-liggghts-run paper\n";
  std::ofstream(d / "manifest.tsv") << m;
  ASSERT_EQ(run_tool(d, fmt::format("'{}' --out '{}' --plot none", (d / "manifest.tsv").string(),
                                    (d / "doc/study.md").string())),
            0)
      << read_text(d / "tool.log");
  const std::string dat = read_text(d / "doc/study_figs/paper_bars.dat");
  EXPECT_NE(dat.find("\"R2 liggghts drag\""), std::string::npos) << dat;
  EXPECT_EQ(dat.find("\"R1 "), std::string::npos) << dat;
  EXPECT_NE(dat.find("\"FSICR R_CH ours (R2)\""), std::string::npos) << dat;
  EXPECT_EQ(read_text(d / "doc/study_figs/paper_bars.gp").find("REDUCED-CASE"), std::string::npos);
  // both runs still have their Fig. 5 analog text and their row in section (a)
  EXPECT_NE(read_text(d / "doc/study.md").find("| R1 | **reduced case**"), std::string::npos);
}

// A copy of a run's outputs without its plots (brash-study's study_runs) names its full run directory in
// source_run_dir.txt, relative to the copy: its plots and ParaView files are found from there whatever the
// tool's working directory (here the test's, not the study's folder).
TEST(StudyReport, ACopyFindsItsFullRunDirectoryFromAnyWorkingDirectory) {
  const fs::path d = fresh_dir("copy");
  write_report(d / "work/runs/am", "liggghts", "added_mass", 0.482, 12.5, 1.5);
  std::ofstream(d / "work/runs/am/force_history.png") << "force history of am";
  std::ofstream(d / "work/runs/am/ice_views_001.00s.png") << "views of am";
  std::ofstream(d / "work/runs/am/particles.pvd") << "<VTKFile/>";
  fs::create_directories(d / "doc/study_runs/am");
  fs::copy_file(d / "work/runs/am/report.json", d / "doc/study_runs/am/report.json");
  std::ofstream(d / "doc/study_runs/am/source_run_dir.txt") << "../../../work/runs/am\n";
  ASSERT_NE(fs::current_path().lexically_normal(), d.lexically_normal());
  std::string m = kHeader;
  m += "p1\tpaper\tam\t\t\t1\tjbc_bench\t0\t../doc/study_runs/am\tbrash-liggghts-run am\n";
  std::ofstream(d / "work/manifest.tsv") << m;
  ASSERT_EQ(run_tool(d, fmt::format("'{}' --out '{}' --plot none", (d / "work/manifest.tsv").string(),
                                    (d / "doc/study.md").string())),
            0)
      << read_text(d / "tool.log");
  const std::string md = read_text(d / "doc/study.md");
  EXPECT_NE(md.find("![R1 force history](../work/runs/am/force_history.png)"), std::string::npos) << md;
  EXPECT_NE(md.find("![R1 ice views](../work/runs/am/ice_views_001.00s.png)"), std::string::npos) << md;
  EXPECT_NE(md.find("work/runs/am/particles.pvd` and `"), std::string::npos) << md;
  EXPECT_EQ(md.find("no force_history.png in"), std::string::npos) << md;
}

// The paper case's histories in one plot: every paper-case run with a force record, runs still going too (up
// to their last complete row), 0.5 s bin means at full scale; a stretch without rows breaks the line without
// starting a new gnuplot data set (two blank lines would, and shift every later run's title).
TEST(StudyReport, PaperCaseHistoriesShowEveryRunAndBreakAtGaps) {
  const fs::path d = fresh_dir("histories");
  write_report(d / "runs/a", "liggghts", "added_mass", 0.482, 2.0, 0.1);
  fs::create_directories(d / "runs/b");
  std::ofstream(d / "runs/a/case.yaml") << "name: jbc_ia_5kn\nfluid: {model: added_mass}\n";
  std::ofstream(d / "runs/b/case.yaml") << "name: jbc_ia_5kn\nfluid: {model: drag}\n";
  std::ofstream(d / "runs/b/meta.json") << json{{"engine", "liggghts"}, {"fluid_model", "drag"}}.dump();
  {
    std::ofstream a(d / "runs/a/hull_force.csv");
    a << "t_s,fx_N,fy_N,fz_N\n";
    for (int k = 0; k <= 30; ++k)
      if (k < 10 || k >= 20) a << fmt::format("{:.1f},-2,0,0\n", 0.1 * k);  // no rows in 1.0-2.0 s
    std::ofstream b(d / "runs/b/hull_force.csv");
    b << "t_s,fx_N,fy_N,fz_N\n";
    for (int k = 0; k <= 10; ++k) b << fmt::format("{:.1f},-4,0,0\n", 0.1 * k);
    b << "1.1,-4,0";  // the row being written
  }
  std::string m = kHeader;
  m += "pa\tpaper\tpaper am\t\t\t1\tjbc_ia_5kn\t0\truns/a\tcmd a\n";
  m += "pb\tpaper\tpaper drag\t\t\t1\tjbc_ia_5kn\tin progress: model time 1.1 s of 40 s reached\truns/b\tcmd "
       "b\n";
  std::ofstream(d / "manifest.tsv") << m;
  ASSERT_EQ(run_tool(d, fmt::format("'{}' --out '{}' --plot none", (d / "manifest.tsv").string(),
                                    (d / "doc/study.md").string())),
            0)
      << read_text(d / "tool.log");
  const std::string dat = read_text(d / "doc/study_figs/paper_histories.dat");
  const double kN = std::pow(28.5, 3) / 1000.0;
  EXPECT_NE(dat.find("# R1 liggghts added_mass\n0.25 " + fmt::format("{}", 2.0 * kN)), std::string::npos)
      << dat;
  EXPECT_NE(dat.find("# R2 liggghts drag (in progress, t = 1.0 s)\n0.25 " + fmt::format("{}", 4.0 * kN)),
            std::string::npos)
      << dat;
  // R1: bins 0-1 s, one blank line for the empty 1.0-2.0 s, bins 2-3 s; data sets end with two blank lines
  EXPECT_NE(dat.find(fmt::format("0.75 {}\n\n2.25 {}\n", 2.0 * kN, 2.0 * kN)), std::string::npos) << dat;
  std::size_t sets = 0;
  for (auto at = dat.find("\n\n\n"); at != std::string::npos; at = dat.find("\n\n\n", at + 3)) ++sets;
  EXPECT_EQ(sets, 2u) << dat;
  const std::string gp = read_text(d / "doc/study_figs/paper_histories.gp");
  EXPECT_NE(gp.find("index 0 using 1:2 with lines lw 2 title 'R1 liggghts added_mass'"), std::string::npos)
      << gp;
  EXPECT_NE(gp.find("index 1 using 1:2 with lines lw 2 title 'R2 liggghts drag (in progress"),
            std::string::npos);
  if (std::system("command -v gnuplot > /dev/null 2>&1") == 0) {
    EXPECT_NE(
        read_text(d / "doc/study.md").find("![paper-case resistance histories](study_figs/paper_histories.png)"),
        std::string::npos);
  }
}

// An ODE paper run still going (or stopped with its machine) beside the complete LIGGGHTS run of the same
// fluid model: the engine section tables the two in whole bins up to where both records reach.
TEST(StudyReport, UnfinishedEngineRunIsBinnedBesideLiggghts) {
  const fs::path d = fresh_dir("engine_bins");
  write_report(d / "runs/l", "liggghts", "drag", 0.482, 2.0, 0.1);
  fs::create_directories(d / "runs/o");
  std::ofstream(d / "runs/o/meta.json") << json{{"engine", "ode"}, {"fluid_model", "drag"}}.dump();
  {
    // LIGGGHTS: 2 N for t in (0, 2] s, 3 N after; ODE: 2.5 N, then 2.7 N, reaching 4.55 s (rows stamped at
    // the end of their 0.05 s interval)
    std::ofstream l(d / "runs/l/hull_force.csv"), o(d / "runs/o/hull_force.csv");
    l << "t_s,fx_N,fy_N,fz_N\n0,-100,0,0\n";  // a row at t = 0 (no interval) is not in the first bin
    o << "t_s,fx_N,fy_N,fz_N\n";
    for (int k = 1; k <= 100; ++k) l << fmt::format("{:.2f},{},0,0\n", 0.05 * k, k <= 40 ? -2.0 : -3.0);
    for (int k = 1; k <= 91; ++k) o << fmt::format("{:.2f},{},0,0\n", 0.05 * k, k <= 40 ? -2.5 : -2.7);
  }
  std::string m = kHeader;
  m += "pl\tpaper\tpaper drag\t\t\t1\tjbc_ia_5kn\t0\truns/l\tcmd l\n";
  m += "po\tpaper\tpaper ode drag\t\t\t1\tjbc_ia_5kn\tin progress, stopped: model time 4.55 s of 20 s "
       "reached\truns/o\tcmd o\n";
  std::ofstream(d / "manifest.tsv") << m;
  ASSERT_EQ(run_tool(d, fmt::format("'{}' --out '{}' --plot none", (d / "manifest.tsv").string(),
                                    (d / "doc/study.md").string())),
            0)
      << read_text(d / "tool.log");
  const std::string md = read_text(d / "doc/study.md");
  EXPECT_NE(md.find("R2 (ode drag, jbc_ia_5kn) has reached t = 4.55 s; beside R1 (liggghts drag)"),
            std::string::npos)
      << md;
  // whole seconds (the record reaches past 4 s): 0-1, 1-2 (ODE +25 %), 2-3 and 3-4 (2.7 on 3: -10 %); 4-5 is
  // not whole for ODE
  EXPECT_NE(md.find("| 0-1 | 2.000 | 2.500 | +25.0 % |\n| 1-2 | 2.000 | 2.500 | +25.0 % |\n"
                    "| 2-3 | 3.000 | 2.700 | -10.0 % |\n| 3-4 | 3.000 | 2.700 | -10.0 % |\n\n"),
            std::string::npos)
      << md;
  EXPECT_EQ(md.find("| 4-5 |"), std::string::npos) << md;
  EXPECT_NE(md.find("stopped part-way (the state says which"), std::string::npos) << md;
}

TEST(StudyReport, BadManifestIsAnError) {
  const fs::path d = fresh_dir("bad");
  std::ofstream(d / "manifest.tsv") << "group\trun_dir\n";  // no command column
  EXPECT_NE(run_tool(d, fmt::format("'{}' --out '{}'", (d / "manifest.tsv").string(), (d / "study.md").string())), 0);
  EXPECT_NE(read_text(d / "tool.log").find("command"), std::string::npos);
  EXPECT_NE(run_tool(d, fmt::format("'{}' --out '{}'", (d / "nothing.tsv").string(), (d / "study.md").string())), 0);
}

// Where we differ from the paper, say why: the paper-case set-up table is read from each paper run's own
// case.yaml and meta.json (started runs too), never typed: a changed stiffness, step or far-field rule shows
// up in it.
TEST(StudyReport, PaperSetUpTableComesFromEachRunsCaseAndMeta) {
  const fs::path d = fresh_dir("setup");
  fs::create_directories(d / "runs/pl");
  fs::create_directories(d / "runs/po");
  std::ofstream(d / "runs/pl/case.yaml") << "name: jbc_ia_5kn\ncontact: {youngs_modulus_pa: 3.125e5, "
                                            "rolling_friction: 0.05}\n"
                                            "ice: {settle: true}\n"
                                            "speedups: {farfield: true, farfield_wake_force_weight: 0, "
                                            "moving_window: true}\n";
  std::ofstream(d / "runs/pl/meta.json") << json{
      {"engine", "liggghts"},
      {"fluid_model", "added_mass"},
      {"dt_s", 4e-4},
      {"particles", 417415}}.dump();
  std::ofstream(d / "runs/po/case.yaml") << "name: jbc_ia_5kn\nice: {diameter_sd_m: 0.001}\n";
  std::ofstream(d / "runs/po/meta.json")
      << json{{"engine", "ode"},
              {"fluid_model", "drag"},
              {"dt_s", 1e-3},
              {"particles", 417000},
              {"ode_options", {{"erp", 0.2}, {"cfm", 1e-5}, {"iterations", 20}, {"cull", false}, {"end_walls", true}}}}
             .dump();
  std::string m = kHeader;
  m += "pl\tpaper\tpaper am\t\t\t1\tjbc_ia_5kn\tin progress: model time 1.00 s of 40 s reached\truns/pl\tcmd "
       "pl\n";
  m += "po\tpaper\tpaper ode\t\t\t1\tjbc_ia_5kn\tin progress: model time 2.00 s of 40 s "
       "reached\truns/po\tcmd po\n";
  std::ofstream(d / "manifest.tsv") << m;
  ASSERT_EQ(run_tool(d, fmt::format("'{}' --out '{}' --plot none --figures none",
                                    (d / "manifest.tsv").string(), (d / "study.md").string())),
            0)
      << read_text(d / "tool.log");
  const std::string md = read_text(d / "study.md");
  const auto at = md.find("### Our paper-case set-up vs the paper's");
  ASSERT_NE(at, std::string::npos) << md;
  const std::string t = md.substr(at, md.find("\n\n", md.find("| item |", at)) - at);
  EXPECT_NE(t.find("| R1 (liggghts added_mass) | R2 (ode drag) |"), std::string::npos) << t;
  // the rows of the runs still going name their engine and model (from meta.json), not "?"
  EXPECT_NE(md.find("| R1 | paper am | liggghts | added_mass |"), std::string::npos) << md;
  EXPECT_NE(md.find("| R2 | paper ode | ode | drag |"), std::string::npos) << md;
  EXPECT_NE(
      t.find("| Hertz-Mindlin, E = 3.125e+05 Pa, ν = 0.3, e = 0.3, rolling resistance μ_r = 0.05 | ODE rigid, "
             "contact joints (ERP 0.2, CFM 1e-05, 20 iterations) |"),
      std::string::npos)
      << t;
  EXPECT_NE(t.find("| time step | not stated | 0.0004 s | 0.001 s |"), std::string::npos) << t;
  EXPECT_NE(t.find("417415 spheres, d = 0.017578 m ± 0.0008789 m"), std::string::npos) << t;
  EXPECT_NE(t.find("417000 spheres, d = 0.017578 m ± 0.001 m"), std::string::npos) << t;
  EXPECT_NE(t.find("| far field, window alone (biased high); moving window | every piece integrated |"),
            std::string::npos)
      << t;
  EXPECT_NE(t.find("| 1.35 / 0.1 | 1.35 / 0.1 | 1.35 / 0.1 |"), std::string::npos) << t;
  // LIGGGHTS has side walls only; an ODE run says whether it closed the ends (--end-walls)
  EXPECT_NE(t.find("| 21 x 2.25 m, side walls, ends open | 21 x 2.25 m, side walls, ends walled (x = 0 and x = "
                   "length) |"),
            std::string::npos)
      << t;
}

// A run whose report.json says the window's record drifts (brash-post's window_halves) carries that in its
// status, with the size of the drift; a stationary one does not.
// The status column names a drifting record, a gap in the record and an early stop (the window ends at the
// stop).
TEST(StudyReport, StatusNamesDriftGapsAndEarlyStop) {
  const fs::path d = fresh_dir("drift");
  write_report(d / "runs/a", "liggghts", "added_mass", 0.482, 11.6, 0.4);
  write_report(d / "runs/b", "liggghts", "drag", 0.482, 11.0, 0.4);
  json ja = json::parse(read_text(d / "runs/a/report.json")), jb = json::parse(read_text(d / "runs/b/report.json"));
  ja["resistance_model_N"]["window_halves"] = {{"first_mean", 11.1},
                                               {"second_mean", 12.09},
                                               {"difference", 0.99},
                                               {"difference_ci95", 0.38},
                                               {"drifts", true}};
  jb["resistance_model_N"]["window_halves"] = {{"first_mean", 11.0},
                                               {"second_mean", 11.1},
                                               {"difference", 0.1},
                                               {"difference_ci95", 0.38},
                                               {"drifts", false}};
  jb["early_stop"] = {{"t_s", 25.0}, {"requested_duration_s", 40.0}, {"rel_ci_threshold", 0.01}};
  std::ofstream(d / "runs/a/report.json") << ja.dump(2);
  std::ofstream(d / "runs/b/report.json") << jb.dump(2);
  std::string m = kHeader;
  m += "a\tspeed\tU 0.482\tspeed_m_s\t0.482\t1\tjbc_bench\t0\truns/a\tbrash-liggghts-run a --model "
       "added_mass\n";
  m += "b\tspeed\tU 0.482\tspeed_m_s\t0.482\t1\tjbc_bench\t0\truns/b\tbrash-liggghts-run b --model drag\n";
  std::ofstream(d / "manifest.tsv") << m;
  ASSERT_EQ(
      run_tool(d, fmt::format("'{}' --out '{}'", (d / "manifest.tsv").string(), (d / "study.md").string())),
      0)
      << read_text(d / "tool.log");
  const std::string md = read_text(d / "study.md");
  EXPECT_NE(md.find("| 11.60 ± 0.40 |"), std::string::npos) << md;
  EXPECT_NE(md.find("not stationary: the window's second half +8.9 % on its first"), std::string::npos) << md;
  EXPECT_EQ(md.find("+0.9 % on its first"), std::string::npos) << md;  // b: within its CI, not flagged
  EXPECT_EQ(md.find("RECORD HAS GAPS"), std::string::npos) << md;
  EXPECT_NE(md.find("stopped early at t = 25.00 s of 40 s (95 % CI below 1 % of the mean)"),
            std::string::npos)
      << md;
  {  // b's rows only (a ran to its end)
    std::istringstream lines(md);
    int rows = 0;
    for (std::string line; std::getline(lines, line);)
      if (line.find("stopped early") != std::string::npos) {
        ++rows;
        EXPECT_EQ(line.find("11.60"), std::string::npos) << line;
        EXPECT_EQ(line.find("runs/a"), std::string::npos) << line;
      }
    EXPECT_GE(rows, 1);
  }

  // a force record with a stretch missing in the window (report.json record.gaps_in_window_s, complete false)
  ja["complete"] = false;
  ja["record"]["gaps_in_window_s"] = json::array({json::array({21.9, 32.5})});
  std::ofstream(d / "runs/a/report.json") << ja.dump(2);
  ASSERT_EQ(
      run_tool(d, fmt::format("'{}' --out '{}'", (d / "manifest.tsv").string(), (d / "study.md").string())),
      0)
      << read_text(d / "tool.log");
  EXPECT_NE(read_text(d / "study.md").find("RECORD HAS GAPS in the window (no force record 21.90-32.50 s)"),
            std::string::npos)
      << read_text(d / "study.md");
  fs::remove_all(d);
}

// The document's prose comes from the text template (--template, default the source tree's
// postproc/study_report/templates/study.md.tmpl): a block's wrapped lines become one paragraph, its
// {{placeholders}} are filled with the tool's numbers, and an edited block shows up in the document.
namespace {

const fs::path kTemplate = fs::path(BRASH_SOURCE_DIR) / "postproc/study_report/templates/study.md.tmpl";

// The source template with the text of each block named in TEXTS replaced (written to DIR/study.md.tmpl).
fs::path template_with(const fs::path& dir, const std::map<std::string, std::string>& texts) {
  std::istringstream in(read_text(kTemplate));
  std::string out;
  bool skipping = false;
  for (std::string line; std::getline(in, line);) {
    const bool header = line.rfind("=== ", 0) == 0;
    if (header) skipping = texts.count(line.substr(4, line.size() - 8)) > 0;
    if (skipping && !header) continue;
    out += line + "\n";
    if (skipping) out += texts.at(line.substr(4, line.size() - 8)) + "\n\n";
  }
  const fs::path p = dir / "study.md.tmpl";
  std::ofstream(p) << out;
  return p;
}

// A study of one speed run (its section (b) uses the speed blocks).
void write_speed_study(const fs::path& d) {
  write_report(d / "runs/s1", "liggghts", "drag", 0.5, 2.0, 0.1);
  std::ofstream(d / "manifest.tsv") << std::string(kHeader) +
                                           "s1\tspeed\tU 0.5\tspeed_m_s\t0.5\t0\tjbc_quick\t0\truns/s1\tcmd s1\n";
}

}  // namespace

TEST(StudyReport, TemplateBlocksWriteTheProse) {
  const fs::path d = fresh_dir("template");
  write_speed_study(d);
  const fs::path tmpl = template_with(
      d, {{"speed.method",
           "# a comment line\nThe resistance rises with speed;\n  these lines join into one paragraph.\n\n"
           "A second paragraph."},
          {"sensitivity.group_missing", "No {{group}} runs\nhere."}});
  ASSERT_EQ(run_tool(d, fmt::format("'{}' --out '{}' --plot none --template '{}'", (d / "manifest.tsv").string(),
                                    (d / "study.md").string(), tmpl.string())),
            0)
      << read_text(d / "tool.log");
  const std::string md = read_text(d / "study.md");
  EXPECT_NE(md.find("The resistance rises with speed; these lines join into one paragraph.\n\n"
                    "A second paragraph.\n\n| run | engine |"),
            std::string::npos)
      << md;
  EXPECT_EQ(md.find("Tanks show a linear trend"), std::string::npos) << md;
  EXPECT_EQ(md.find("a comment line"), std::string::npos) << md;
  EXPECT_NE(md.find("No ca runs here.\n\nNo friction_ice runs here."), std::string::npos) << md;
  fs::remove_all(d);
}

TEST(StudyReport, MissingPlaceholderNamesTheTemplateAndThePlaceholder) {
  const fs::path d = fresh_dir("template_bad");
  write_speed_study(d);
  const fs::path tmpl = template_with(d, {{"speed.method", "n rises by {{no_such_value}} per speed."}});
  EXPECT_NE(run_tool(d, fmt::format("'{}' --out '{}' --plot none --template '{}'", (d / "manifest.tsv").string(),
                                    (d / "study.md").string(), tmpl.string())),
            0);
  const std::string log = read_text(d / "tool.log");
  EXPECT_NE(log.find(tmpl.string()), std::string::npos) << log;
  EXPECT_NE(log.find("{{no_such_value}}"), std::string::npos) << log;
  EXPECT_NE(log.find("speed.method"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(d / "study.md"));  // no half-filled document
  fs::remove_all(d);
}

TEST(StudyReport, MissingTemplateOrBlockIsAnError) {
  const fs::path d = fresh_dir("template_missing");
  write_speed_study(d);
  const std::string args = fmt::format("'{}' --out '{}' --plot none", (d / "manifest.tsv").string(),
                                       (d / "study.md").string());
  EXPECT_NE(run_tool(d, args + fmt::format(" --template '{}'", (d / "none.tmpl").string())), 0);
  EXPECT_NE(read_text(d / "tool.log").find((d / "none.tmpl").string()), std::string::npos) << read_text(d / "tool.log");
  // a template that lacks a block the tool needs: the block is named with the template's file
  std::string without;
  std::istringstream in(read_text(kTemplate));
  bool skipping = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("=== ", 0) == 0) skipping = line == "=== speed.method ===";
    if (!skipping) without += line + "\n";
  }
  std::ofstream(d / "without.tmpl") << without;
  EXPECT_NE(run_tool(d, args + fmt::format(" --template '{}'", (d / "without.tmpl").string())), 0);
  const std::string log = read_text(d / "tool.log");
  EXPECT_NE(log.find((d / "without.tmpl").string()), std::string::npos) << log;
  EXPECT_NE(log.find("=== speed.method ==="), std::string::npos) << log;
  fs::remove_all(d);
}
