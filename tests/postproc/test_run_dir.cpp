// brash-post on synthetic run directories: report.json values, bad input, runs still being written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>

#include <nlohmann/json.hpp>

#include <brash/error.hpp>
#include <brash/post/csv.hpp>
#include <brash/post/plots.hpp>
#include <brash/post/report.hpp>
#ifdef BRASH_JBC_MODEL_STL
#include <brash/hull/hydrostatics.hpp>
#include <brash/hull/mesh.hpp>
#endif

#include "synthetic_run.hpp"

using namespace brash::post;
using brash::post::testing::SyntheticRun;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  return fs::temp_directory_path() / fmt::format("brash_post_test_{}_{}", ::getpid(), name);
}

nlohmann::json run_cli(const fs::path& dir) {
  const auto cmd = fmt::format("{} {} > {} 2>&1", BRASH_POST_EXE, dir.string(), (dir / "cli.log").string());
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::ifstream in(dir / "report.json");
  return nlohmann::json::parse(in);
}

// Expects analyze_run to throw InputError whose message contains every string of `parts`.
void expect_input_error(const fs::path& dir, std::initializer_list<std::string> parts) {
  try {
    (void)analyze_run(dir);
    ADD_FAILURE() << "no InputError";
  } catch (const brash::InputError& e) {
    for (const auto& p : parts) EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << e.what() << " lacks " << p;
  }
}

void replace_line(const fs::path& file, int line_1based, const std::string& text) {
  std::ifstream in(file);
  std::string all, line;
  for (int i = 1; std::getline(in, line); ++i) all += (i == line_1based ? text : line) + "\n";
  in.close();
  brash::post::testing::write_text(file, all);
}

}  // namespace

TEST(RunDir, ReportJsonHasEveryKeyWithCorrectValues) {
  const auto dir = scratch("complete");
  SyntheticRun r;
  write_synthetic_run(dir, r);
  const auto j = run_cli(dir);

  const double mean_fx = brash::post::testing::window_mean(r.t_s, r.fx_N, 15.0, 40.0);
  const double mean_fy = brash::post::testing::window_mean(r.t_s, r.fy_N_series, 15.0, 40.0);
  const double mean_fz = brash::post::testing::window_mean(r.t_s, r.fz_N_series, 15.0, 40.0);
  EXPECT_EQ(j["engine"], "synthetic");
  EXPECT_EQ(j["fluid_model"], "added_mass");
  EXPECT_NEAR(j["window_s"][0].get<double>(), 15.0, 1e-9);
  EXPECT_NEAR(j["window_s"][1].get<double>(), 40.0, 1e-9);
  EXPECT_FALSE(j["window_truncated"].get<bool>());
  EXPECT_TRUE(j["complete"].get<bool>());
  const auto& R = j["resistance_model_N"];
  EXPECT_NEAR(R["mean"].get<double>(), -mean_fx, 1e-9);
  EXPECT_NEAR(R["x"].get<double>(), mean_fx, 1e-9);
  EXPECT_NEAR(R["y"].get<double>(), mean_fy, 1e-9);
  EXPECT_NEAR(R["z"].get<double>(), mean_fz, 1e-9);
  EXPECT_NEAR(R["mean"].get<double>(), 2.0, 0.05);  // the plateau value written
  // AR(1) phi 0.8, sd 0.3, 2501 samples: exact sd of the mean = 0.3 sqrt((1+phi)/(1-phi)/N) = 0.018.
  const double sem_exact = 0.3 * std::sqrt(1.8 / 0.2 / 2501);
  EXPECT_GT(R["ci95"].get<double>(), 1.96 * sem_exact * 0.6);
  EXPECT_LT(R["ci95"].get<double>(), 1.96 * sem_exact * 1.6);
  EXPECT_EQ(j["lambda"].get<double>(), 28.5);
  EXPECT_NEAR(j["resistance_full_kN"].get<double>(), -mean_fx * std::pow(28.5, 3) / 1000, 1e-6);
  EXPECT_NEAR(j["fsicr"]["R_CH_kN"].get<double>(), 990.29, 0.01);  // fsicr.md worked example 1
  EXPECT_NEAR(j["fsicr"]["params"]["L_m"].get<double>(), 199.11, 1e-9);
  EXPECT_NEAR(j["fsicr"]["params"]["B_m"].get<double>(), 32.0, 1e-9);
  EXPECT_NEAR(j["fsicr"]["params"]["T_m"].get<double>(), 11.733, 1e-9);
  EXPECT_EQ(j["fsicr"]["source"]["alpha_deg"], "override");
  EXPECT_EQ(j["fsicr"]["source"]["L_m"], "case");
  EXPECT_NEAR(j["fsicr"]["intermediate"]["H_F_m"].get<double>(), 5.917, 5e-4);
  EXPECT_NEAR(j["ratio_fsicr_to_sim"].get<double>(),
              j["fsicr"]["R_CH_kN"].get<double>() / j["resistance_full_kN"].get<double>(), 1e-12);
  // the synthetic case declares no published values: the report compares with none
  EXPECT_TRUE(j["reference"].is_null()) << j["reference"].dump();
  EXPECT_FALSE(j.contains("paper_full_kN"));
  const std::string md = brash::post::read_text_file(dir / "report.md");
  const std::string body = md.substr(md.find('\n'));  // after the title, which names the folder (and its pid)
  for (const char* paper : {"393", "378", "999", "2.54", "Published reference", "aper"})
    EXPECT_EQ(body.find(paper), std::string::npos) << paper;
  EXPECT_EQ(j["wall_time_s"].get<double>(), 123.5);
  EXPECT_EQ(j["particle_steps"].get<double>(), 4.2e9);
  EXPECT_EQ(j["exits"].get<long>(), 0);  // no meta.json "exits": none
  for (const auto* f : {"report.md", "force_history.csv", "blocking.csv"}) EXPECT_TRUE(fs::exists(dir / f)) << f;
  fs::remove_all(dir);
}

// A case that declares published values (references:) gets them beside its own, for its fluid model only;
// the ratio is the stated one where declared, else the source's R_CH over its resistance.
TEST(RunDir, PublishedReferencesComeFromTheCase) {
  const auto dir = scratch("references");
  SyntheticRun r;
  write_synthetic_run(dir, r);
  std::ofstream(dir / "case.yaml", std::ios::app) << "references:\n  source: \"Test source, Fig. 6\"\n"
                                                      "  resistance_full_kN: {added_mass: 40.0, drag: 50.0}\n"
                                                      "  fsicr_R_CH_kN: 100.0\n"
                                                      "  ratio_fsicr_to_sim: {both: 2.54}\n";
  const auto j = run_cli(dir);  // meta.json: fluid model added_mass
  ASSERT_TRUE(j["reference"].is_object()) << j.dump(2);
  EXPECT_EQ(j["reference"]["source"], "Test source, Fig. 6");
  EXPECT_EQ(j["reference"]["fluid_model"], "added_mass");
  EXPECT_EQ(j["reference"]["resistance_full_kN"].get<double>(), 40.0);
  EXPECT_EQ(j["reference"]["fsicr_R_CH_kN"].get<double>(), 100.0);
  EXPECT_EQ(j["reference"]["ratio_fsicr_to_sim"].get<double>(), 2.5);  // 100 / 40: no stated ratio for added_mass
  EXPECT_FALSE(j["reference"]["ratio_stated"].get<bool>());
  EXPECT_NEAR(j["reference"]["resistance_over_reference"].get<double>(),
              j["resistance_full_kN"].get<double>() / 40.0, 1e-12);
  const std::string md = brash::post::read_text_file(dir / "report.md");
  EXPECT_NE(md.find("## Published reference (Test source, Fig. 6)"), std::string::npos) << md;
  EXPECT_NE(md.find("| 40 kN (this run "), std::string::npos) << md;
  EXPECT_NE(md.find("| 2.50 (its R_CH over its resistance) |"), std::string::npos) << md;
  EXPECT_EQ(md.find("50 kN"), std::string::npos) << "the drag value is not this run's model";
  fs::remove_all(dir);
}

// The paper case's archived both run (evidence/), post-processed again: its case declares the paper's
// values, so the report compares with them (393 kN for both, R_CH 999 kN, the stated ratio 2.54).
TEST(RunDir, PaperCaseArchiveComparesWithThePapersDeclaredValues) {
  const auto dir = scratch("paper_archive");
  fs::remove_all(dir);
  fs::copy(fs::path(BRASH_SOURCE_DIR) / "evidence/paper-liggghts-both-20s", dir, fs::copy_options::recursive);
  const auto cmd = fmt::format("{} {} --no-plots --no-paraview > {} 2>&1", BRASH_POST_EXE, dir.string(),
                               (dir / "cli.log").string());
  ASSERT_EQ(std::system(cmd.c_str()), 0) << brash::post::read_text_file(dir / "cli.log");
  std::ifstream in(dir / "report.json");
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["fluid_model"], "both");
  EXPECT_NEAR(j["resistance_full_kN"].get<double>(), 568.1, 0.05);
  const auto& ref = j["reference"];
  ASSERT_TRUE(ref.is_object()) << j.dump(2);
  EXPECT_NE(ref["source"].get<std::string>().find("Fluid Force Modelling"), std::string::npos);
  EXPECT_EQ(ref["resistance_full_kN"].get<double>(), 393.0);
  EXPECT_EQ(ref["fsicr_R_CH_kN"].get<double>(), 999.0);
  EXPECT_EQ(ref["ratio_fsicr_to_sim"].get<double>(), 2.54);
  EXPECT_TRUE(ref["ratio_stated"].get<bool>());
  EXPECT_NEAR(ref["resistance_over_reference"].get<double>(), 568.1 / 393.0, 1e-3);
  EXPECT_NE(brash::post::read_text_file(dir / "report.md").find("| 393 kN (this run +44.6 %) |"), std::string::npos);
  fs::remove_all(dir);
}

// The window's two halves: a stationary record shows no drift; one rising 0.02 N/s (+0.5 N over the 25 s
// window, ~14 x the CI of the difference) is flagged in report.json, in the notes and in report.md.
TEST(RunDir, ResistanceRisingThroughTheWindowIsFlagged) {
  const auto dir = scratch("drift");
  SyntheticRun r;
  write_synthetic_run(dir, r);
  auto j = run_cli(dir);
  const auto& h = j["resistance_model_N"]["window_halves"];
  EXPECT_FALSE(h["drifts"].get<bool>()) << h;
  EXPECT_NEAR(h["difference"].get<double>(), 0.0, 0.1);
  EXPECT_EQ(j["notes"].dump().find("not stationary"), std::string::npos) << j["notes"];

  r = SyntheticRun{};
  r.drift_N_per_s = 0.02;
  write_synthetic_run(dir, r);
  j = run_cli(dir);
  const auto& d = j["resistance_model_N"]["window_halves"];
  EXPECT_TRUE(d["drifts"].get<bool>()) << d;
  // halves [15, 27.5] and [27.5, 40] s: their means differ by 0.02 N/s x 12.5 s = 0.25 N
  EXPECT_NEAR(d["difference"].get<double>(), 0.25, 0.06);
  EXPECT_NEAR(d["second_mean"].get<double>() - d["first_mean"].get<double>(), d["difference"].get<double>(),
              1e-12);
  EXPECT_NE(j["notes"].dump().find("not stationary over the window"), std::string::npos) << j["notes"];
  const std::string text = brash::post::read_text_file(dir / "report.md");
  EXPECT_NE(text.find("**the record drifts**"), std::string::npos);
  fs::remove_all(dir);
}

// A hull that meets no ice in the window (a short run, a window before the bow reaches the channel) records only
// zero forces there: the report says so and shows no resistance (not 0 ± 0 N), nor a comparison with the
// published value; the same whether the record has no contact at all or contacts only outside the window.
TEST(RunDir, HullThatMetNoIceInTheWindowHasNoResistance) {
  const auto dir = scratch("no_ice");
  SyntheticRun r;
  write_synthetic_run(dir, r);
  EXPECT_FALSE(run_cli(dir)["met_no_ice"].get<bool>());
  std::ofstream(dir / "case.yaml", std::ios::app) << "references:\n  source: \"Test source\"\n"
                                                      "  resistance_full_kN: {added_mass: 40.0}\n";
  for (const double contact_until_s : {0.0, 10.0}) {  // no contact at all; contacts at 2-10 s, before the window
    std::string csv = "t_s,fx_N,fy_N,fz_N\n";
    for (std::size_t i = 0; i < r.t_s.size(); ++i)
      csv += r.t_s[i] > 1.995 && r.t_s[i] < contact_until_s ? fmt::format("{},-1.5,0.1,-0.2\n", r.t_s[i]) : fmt::format("{},0,0,0\n", r.t_s[i]);
    brash::post::testing::write_text(dir / "hull_force.csv", csv);
    const auto j = run_cli(dir);
    const std::string notes = j["notes"].dump();
    EXPECT_TRUE(j["met_no_ice"].get<bool>()) << contact_until_s;
    EXPECT_TRUE(j["resistance_model_N"].is_null()) << j["resistance_model_N"];
    EXPECT_TRUE(j["resistance_full_kN"].is_null());
    EXPECT_TRUE(j["resistance_full_ci95_kN"].is_null());
    EXPECT_TRUE(j["ratio_fsicr_to_sim"].is_null());
    EXPECT_TRUE(j["reference"]["resistance_over_reference"].is_null());
    EXPECT_NE(notes.find("met NO ICE in the averaging window [15.000, 40.000] s"), std::string::npos) << notes;
    EXPECT_NE(notes.find(contact_until_s > 0 ? "first contact is at t = 2.000 s" : "touches no ice anywhere"),
              std::string::npos) << notes;
    EXPECT_EQ(notes.find("no plateau"), std::string::npos) << notes;
    const std::string md = brash::post::read_text_file(dir / "report.md");
    EXPECT_NE(md.find("**The hull met no ice in the averaging window [15.000, 40.000] s**"), std::string::npos) << md;
    EXPECT_EQ(md.find("mean resistance |"), std::string::npos) << md;
    EXPECT_NE(md.find("| met no ice | 40 kN |"), std::string::npos) << md;
    const std::string printed = brash::post::read_text_file(dir / "cli.log");
    EXPECT_NE(printed.find("the hull met no ice in the window [15.000, 40.000] s: no resistance"), std::string::npos)
        << printed;
    EXPECT_EQ(printed.find("resistance 0.0000"), std::string::npos) << printed;
    const auto row = compare_row(analyze_run(dir));
    EXPECT_NE(compare_markdown({row}).find("| met no ice | met no ice |"), std::string::npos) << compare_markdown({row});
    EXPECT_EQ(compare_markdown({row}).find("Published resistance"), std::string::npos);
    EXPECT_NE(compare_csv({row}).find(",0.482,,,,,"), std::string::npos) << compare_csv({row});
  }
  fs::remove_all(dir);
}

// The drift check runs on every window, short ones too: a 1 s run whose resistance ramps from 0.3 to 1.4 N is
// flagged (its mean, ~0.85 N, depends on where the window ends), a flat one of the same length is not, and a window
// too short for two halves says that it could not be checked.
TEST(RunDir, ShortRampIsFlaggedAsDrifting) {
  const auto dir = scratch("short_ramp");
  SyntheticRun r;
  write_synthetic_run(dir, r);
  brash::post::testing::write_text(dir / "case.yaml", std::regex_replace(brash::post::testing::synthetic_case_yaml(1.0),
                                                                         std::regex("window_s: \\[15.0,"),
                                                                         "window_s: [0.0,"));
  const auto record = [&](double slope_N_per_s) {
    std::string csv = "t_s,fx_N,fy_N,fz_N\n";
    for (int i = 0; i <= 100; ++i) {
      const double t = 0.01 * i, wiggle = i % 2 ? 0.05 : -0.05;
      csv += fmt::format("{},{},0.01,-0.02\n", t, -(0.3 + slope_N_per_s * t + wiggle));
    }
    brash::post::testing::write_text(dir / "hull_force.csv", csv);
    return run_cli(dir);
  };
  const auto ramp = record(1.1);
  ASSERT_TRUE(ramp["resistance_model_N"].contains("window_halves")) << ramp.dump(2);
  EXPECT_TRUE(ramp["resistance_model_N"]["window_halves"]["drifts"].get<bool>()) << ramp.dump(2);
  EXPECT_NEAR(ramp["resistance_model_N"]["window_halves"]["difference"].get<double>(), 0.55, 0.02);
  EXPECT_NE(ramp["notes"].dump().find("not stationary over the window"), std::string::npos) << ramp["notes"];
  EXPECT_NE(brash::post::read_text_file(dir / "report.md").find("**the record drifts**"), std::string::npos);
  const auto flat = record(0.0);
  EXPECT_FALSE(flat["resistance_model_N"]["window_halves"]["drifts"].get<bool>()) << flat.dump(2);
  EXPECT_EQ(flat["notes"].dump().find("not stationary"), std::string::npos) << flat["notes"];
  brash::post::testing::write_text(dir / "hull_force.csv", "t_s,fx_N,fy_N,fz_N\n0,-0.3,0,0\n0.5,-0.8,0,0\n1,-1.4,0,0\n");
  const auto three = run_cli(dir);
  EXPECT_FALSE(three["resistance_model_N"].contains("window_halves"));
  EXPECT_NE(three["notes"].dump().find("the window holds 3 samples: too few to check whether the resistance drifts"),
            std::string::npos) << three["notes"];
  fs::remove_all(dir);
}

TEST(RunDir, PiecesGoneThroughTheChannelEndsAreReported) {
  const auto dir = scratch("exits");
  SyntheticRun r;
  r.exits = 46;
  write_synthetic_run(dir, r);
  const auto j = run_cli(dir);
  EXPECT_EQ(j["exits"].get<long>(), 46);
  const std::string text = brash::post::read_text_file(dir / "report.md");
  EXPECT_NE(text.find("| pieces gone through the channel's ends | 46 |"), std::string::npos) << text;
  fs::remove_all(dir);
}

// A run the LIGGGHTS runner stopped early (speedups.early_stop_rel_ci): its report says where and why, so a
// reader of a window ending at 25 s of a 40 s case knows it was not cut short by a failure.
TEST(RunDir, EarlyStoppedRunSaysWhereAndWhy) {
  const auto dir = scratch("early_stopped");
  SyntheticRun r;
  r.meta_extra_json = R"(, "early_stop": {"t_s": 25.0, "requested_duration_s": 40.0, "rel_ci_threshold": 0.01,
 "mean_N": 2.0, "ci95_N": 0.01})";
  write_synthetic_run(dir, r);
  const auto j = run_cli(dir);
  ASSERT_TRUE(j.contains("early_stop")) << j.dump(1);
  EXPECT_DOUBLE_EQ(j["early_stop"]["t_s"].get<double>(), 25.0);
  EXPECT_DOUBLE_EQ(j["early_stop"]["requested_duration_s"].get<double>(), 40.0);
  EXPECT_DOUBLE_EQ(j["early_stop"]["rel_ci_threshold"].get<double>(), 0.01);
  const std::string text = brash::post::read_text_file(dir / "report.md");
  EXPECT_NE(text.find("| early stop | at t = 25.000 s of the 40 s asked for"), std::string::npos) << text;
  EXPECT_NE(text.find("below 1 % of it"), std::string::npos) << text;
  // a meta.json from before the slope test has no reason: no row for it
  EXPECT_EQ(text.find("early stop: why"), std::string::npos) << text;
  // since the slope test: the rule's reason and its estimate of the full window's mean
  r.meta_extra_json = R"(, "early_stop": {"t_s": 25.0, "requested_duration_s": 40.0, "rel_ci_threshold": 0.01,
 "requested_window_s": [15.0, 40.0], "mean_N": 2.0, "ci95_N": 0.01, "estimate_N": 1.98, "estimate_ci95_N": 0.03,
 "reason": "CI 0.50 % < 1.00 %, drift -1.00 %/window within its CI 2.50 %"})";
  write_synthetic_run(dir, r);
  const auto j3 = run_cli(dir);
  EXPECT_DOUBLE_EQ(j3["early_stop"]["full_window_estimate_N"].get<double>(), 1.98);
  EXPECT_DOUBLE_EQ(j3["early_stop"]["full_window_estimate_ci95_N"].get<double>(), 0.03);
  EXPECT_NE(j3["early_stop"]["reason"].get<std::string>().find("drift -1.00 %/window"), std::string::npos);
  const std::string text3 = brash::post::read_text_file(dir / "report.md");
  EXPECT_NE(text3.find("| early stop: why | CI 0.50 % < 1.00 %, drift -1.00 %/window within its CI 2.50 %; the full "
                       "window (to 40 s) estimated 1.98 +- 0.03 N (drift extrapolated) |"),
            std::string::npos)
      << text3;
  // a run with the early stop on that went on: its last check says why
  r.meta_extra_json = R"(, "early_stop_last_check": {"t_s": 39.8, "stop": false,
 "reason": "drift -1.20 %/window > CI 0.90 %"})";
  write_synthetic_run(dir, r);
  const auto j4 = run_cli(dir);
  EXPECT_FALSE(j4.contains("early_stop"));
  EXPECT_EQ(j4["early_stop_last_check"]["reason"].get<std::string>(), "drift -1.20 %/window > CI 0.90 %");
  EXPECT_NE(brash::post::read_text_file(dir / "report.md")
                .find("| early stop | did not hold; at its last check (t = 39.800 s): drift -1.20 %/window > CI 0.90 % |"),
            std::string::npos);
  // a run without the keys has neither
  SyntheticRun plain;
  write_synthetic_run(dir, plain);
  const auto j2 = run_cli(dir);
  EXPECT_FALSE(j2.contains("early_stop"));
  EXPECT_EQ(brash::post::read_text_file(dir / "report.md").find("early stop"), std::string::npos);
  fs::remove_all(dir);
}

TEST(RunDir, GapInTheRecordIsNamedAndTheReportIsNotComplete) {
  // The paper run's lesson: a resumed run's retry overwrote an attempt's rows, and the window mean silently
  // covered 14 of its 25 s. A missing stretch inside the window is named in the notes, report.json lists it
  // and says complete: false; one before the window is not a concern of the window's numbers.
  const auto dir = scratch("gap");
  SyntheticRun r;
  r.gap_from_s = 21.9;
  r.gap_to_s = 32.5;
  write_synthetic_run(dir, r);
  auto j = run_cli(dir);
  ASSERT_EQ(j["record"]["gaps_in_window_s"].size(), 1u) << j["record"];
  EXPECT_NEAR(j["record"]["gaps_in_window_s"][0][0].get<double>(), 21.9, 1e-9);
  EXPECT_NEAR(j["record"]["gaps_in_window_s"][0][1].get<double>(), 32.5, 1e-9);
  EXPECT_FALSE(j["complete"].get<bool>());
  EXPECT_NE(
      j["notes"].dump().find("1 gap(s) in the window: no record between 21.90-32.50 s (10.6 s, 42 % of the "
                             "window missing)"),
      std::string::npos)
      << j["notes"];
  // the mean is over the rows there are
  EXPECT_NEAR(j["resistance_model_N"]["mean"].get<double>(),
              -brash::post::testing::window_mean(r.t_s, r.fx_N, 15.0, 40.0), 1e-9);

  r = SyntheticRun{};
  r.gap_from_s = 5.0;
  r.gap_to_s = 8.0;
  write_synthetic_run(dir, r);
  j = run_cli(dir);
  EXPECT_TRUE(j["record"]["gaps_in_window_s"].empty());
  EXPECT_TRUE(j["complete"].get<bool>());
  EXPECT_EQ(j["notes"].dump().find("gap(s) in the window"), std::string::npos) << j["notes"];
  fs::remove_all(dir);
}

TEST(RunDir, ShortRunShortensWindowAndSaysSo) {
  const auto dir = scratch("short");
  SyntheticRun r;
  r.duration_s = 30.0;
  write_synthetic_run(dir, r);
  const auto a = analyze_run(dir);
  EXPECT_TRUE(a.window.truncated);
  EXPECT_NEAR(a.window.used_s[1], 30.0, 1e-9);
  EXPECT_NEAR(a.resistance.mean, -brash::post::testing::window_mean(r.t_s, r.fx_N, 15.0, 30.0), 1e-9);
  const auto j = report_json(a);
  EXPECT_TRUE(j["window_truncated"].get<bool>());
  EXPECT_FALSE(j["complete"].get<bool>());
  ASSERT_FALSE(a.notes.empty());
  EXPECT_NE(report_markdown(a).find("before the window end"), std::string::npos);

  // Shorter than the window start: last half of the record, flagged as fallback.
  SyntheticRun s;
  s.duration_s = 10.0;
  write_synthetic_run(dir, s);
  const auto b = analyze_run(dir);
  EXPECT_TRUE(b.window.fallback);
  EXPECT_NEAR(b.window.used_s[0], 5.0, 1e-9);
  EXPECT_NE(report_markdown(b).find("NOT the paper's window"), std::string::npos);
  fs::remove_all(dir);
}

// A record of two or three samples before the window (a run of a few steps): the last two are averaged, not one.
TEST(RunDir, FewSamplesBeforeTheWindowAverageTheLastTwo) {
  for (const std::vector<double>& t : {std::vector<double>{0.01, 0.02}, std::vector<double>{0.01, 0.02, 0.03}}) {
    const auto w = brash::post::select_window(t, {5.5, 11.0}, "hull_force.csv");
    EXPECT_TRUE(w.fallback);
    EXPECT_EQ(w.i1, t.size());
    EXPECT_EQ(w.i1 - w.i0, 2u) << t.size();
  }
}

TEST(RunDir, RunStillBeingWrittenUsesCompleteRecordsOnly) {
  const auto dir = scratch("running");
  SyntheticRun r;
  r.status = "running";
  r.truncated_tail = true;
  write_synthetic_run(dir, r);
  const auto a = analyze_run(dir);
  EXPECT_TRUE(a.force.tail_dropped);
  EXPECT_EQ(a.force.t_s.size(), r.t_s.size());
  EXPECT_NEAR(a.resistance.mean, -brash::post::testing::window_mean(r.t_s, r.fx_N, 15.0, 40.0), 1e-9);
  const auto j = report_json(a);
  EXPECT_FALSE(j["complete"].get<bool>());
  EXPECT_TRUE(j["record"]["incomplete_tail_dropped"].get<bool>());
  bool said = false;
  for (const auto& n : j["notes"]) said |= n.get<std::string>().find("last line incomplete") != std::string::npos;
  EXPECT_TRUE(said);

  // The same truncated line in a run that claims to be complete is an error naming file and line.
  r.status = "complete";
  write_synthetic_run(dir, r);
  expect_input_error(dir, {"hull_force.csv:4503:", "2 fields"});
  fs::remove_all(dir);
}

TEST(RunDir, BadForceCsvNamesFileAndLine) {
  const auto dir = scratch("bad");
  SyntheticRun r;
  write_synthetic_run(dir, r);
  const auto csv = dir / "hull_force.csv";
  replace_line(csv, 7, "0.05,abc,0,0");
  expect_input_error(dir, {"hull_force.csv:7:", "fx_N", "'abc' is not a number"});

  write_synthetic_run(dir, r);
  replace_line(csv, 9, "0.07,1,2");
  expect_input_error(dir, {"hull_force.csv:9:", "3 fields, expected 4"});

  write_synthetic_run(dir, r);
  replace_line(csv, 11, "0.09,1,nan,2");
  expect_input_error(dir, {"hull_force.csv:11:", "fy_N", "not finite"});

  write_synthetic_run(dir, r);
  replace_line(csv, 1, "time,fx,fy,fz");
  expect_input_error(dir, {"hull_force.csv:1:", "header"});

  write_synthetic_run(dir, r);
  replace_line(csv, 20, "0.01,1,2,3");
  expect_input_error(dir, {"hull_force.csv:20:", "does not increase"});

  // CLI: exit status 2 and the message on stderr.
  const auto cmd = fmt::format("{} {} > /dev/null 2>&1", BRASH_POST_EXE, dir.string());
  EXPECT_EQ(WEXITSTATUS(std::system(cmd.c_str())), 2);
  fs::remove_all(dir);
}

// A run from a user's own LIGGGHTS input (docs/case_format.md, "A run from your own input"): case.yaml and the
// fix ave/time file hull_force.raw, no meta.json. Same numbers as the CSV record; notes say what is unknown.
TEST(RunDir, RunWithoutMetaReadsTheAveTimeRecord) {
  const auto dir = scratch("ave_time");
  SyntheticRun r;
  write_synthetic_run(dir, r);
  const auto from_csv = analyze_run(dir);
  fs::remove(dir / "meta.json");
  fs::remove(dir / "hull_force.csv");
  std::string raw = "# Time-averaged data for fix hf\n# TimeStep v_t f_hull[1] f_hull[2] f_hull[3]\n";
  for (std::size_t i = 0; i < r.t_s.size(); ++i)
    raw += fmt::format("{} {} {} {} {}\n", 200 * i, r.t_s[i], r.fx_N[i], r.fy_N_series[i], r.fz_N_series[i]);
  brash::post::testing::write_text(dir / "hull_force.raw", raw);
  const auto a = analyze_run(dir);
  EXPECT_EQ(a.force.t_s.size(), r.t_s.size());
  EXPECT_NEAR(a.resistance.mean, from_csv.resistance.mean, 1e-9);
  EXPECT_EQ(a.meta.status, "unknown");
  EXPECT_EQ(run_fluid_model(a), "added_mass");  // the case's
  auto has_note = [&](const std::string& part) {
    return std::any_of(a.notes.begin(), a.notes.end(), [&](const auto& n) { return n.find(part) != std::string::npos; });
  };
  EXPECT_TRUE(has_note("no meta.json"));
  EXPECT_TRUE(has_note("hull_force.raw"));
  const auto j = run_cli(dir);
  EXPECT_FALSE(j["complete"].get<bool>());

  replace_line(dir / "hull_force.raw", 12, "1800 0.09 1 2");
  expect_input_error(dir, {"hull_force.raw:12:", "expected 5 columns", "got 4"});
  replace_line(dir / "hull_force.raw", 12, "1800 0.09 1 x 2");
  expect_input_error(dir, {"hull_force.raw:12:", "fy", "'x' is not a number"});
  fs::remove(dir / "hull_force.raw");
  expect_input_error(dir, {"no hull force record", "hull_force.csv", "hull_force.raw"});
  fs::remove_all(dir);
}

TEST(RunDir, MeasuredHullGivesFsicrParameters) {
#ifdef BRASH_JBC_MODEL_STL
  PostCase c;
  c.hull_file = BRASH_JBC_MODEL_STL;
  c.draft_m = 0.4125;
  c.lpp_m = 7.0;
  c.beam_m = 1.125;
  c.scale_lambda = 28.5;
  if (!fs::exists(c.hull_file)) GTEST_SKIP() << "JBC model STL not generated: " << c.hull_file;
  std::vector<std::string> notes;
  const auto m = measure_case_hull_full_scale(c, notes);
  ASSERT_TRUE(m.has_value()) << (notes.empty() ? "" : notes.front());
  EXPECT_NEAR(m->L_m, 199.5, 1e-9);  // 7.0 * 28.5
  EXPECT_NEAR(m->B_m, 1.125 * 28.5, 0.02 * 32);
  const auto s = resolve_fsicr(c, m);
  ASSERT_TRUE(s.result.has_value());
  EXPECT_EQ(s.source.at("alpha_deg"), "measured");
  EXPECT_GT(s.result->R_CH_N, 300e3);
  EXPECT_LT(s.result->R_CH_N, 3000e3);
#else
  GTEST_SKIP() << "built without brash_hull";
#endif
}

// A measured hull whose parameters no hull has (a bow longer than the ship, from an odd mesh) gets no R_CH, and
// the warning names the parameter and where it came from, instead of a meaningless number.
TEST(RunDir, ImpossibleMeasuredHullGivesNoFsicrResult) {
  PostCase c;
  c.scale_lambda = 28.5;
  brash::FsicrParams m{};
  m.L_m = 199.5, m.B_m = 32, m.T_m = 11.7, m.alpha_deg = 38, m.phi1_deg = 90, m.phi2_deg = 80;
  m.L_par_m = 100, m.L_bow_m = 250, m.A_wf_m2 = 900;
  const auto s = resolve_fsicr(c, m);
  EXPECT_FALSE(s.result.has_value());
  ASSERT_FALSE(s.warnings.empty());
  EXPECT_NE(s.warnings.front().find("R_CH not computed"), std::string::npos) << s.warnings.front();
  EXPECT_NE(s.warnings.front().find("L_bow_m (measured) 250"), std::string::npos) << s.warnings.front();
  m.L_bow_m = 40;  // the same hull with a possible bow: a result
  EXPECT_TRUE(resolve_fsicr(c, m).result.has_value());
}

// `brash-post early-stop`: the rule replayed on a finished synthetic run (plateau from 10 s, window [15, 40] s,
// checks every 45 / 200 s). At 5 % the slope rule stops at the first check (25.2 s): the window mean is 1.4 %
// (0.71 CI) from the full window's, and the estimate of the full window, extrapolated along a drift of +15 %
// +- 24 %/window (no drift is there: AR(1) noise with phi 0.8), is +5.9 % off and inside its own CI (+- 7.7 %);
// the rule before (halves) stops at 25.425 s, 1 % (0.55 CI) off; at 0.1 % never, with the reason.
// A run whose record ends before the window end is refused.
TEST(RunDir, EarlyStopReplayTable) {
  const auto dir = scratch("early");
  SyntheticRun r;
  write_synthetic_run(dir, r);
  const auto out = dir / "early.txt";
  const auto cmd = fmt::format("{} early-stop {} --rel-ci 0.05,0.001 --trend slope,halves > {} 2>&1", BRASH_POST_EXE,
                               dir.string(), out.string());
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const std::string text = brash::post::read_text_file(out);
  EXPECT_NE(text.find("| 0.05 | slope | 25.200 | 44.0 % (1.79x) | 2.037 +- 0.0584 (+1.36 %, +0.71 CI) | 2.127 +- "
                      "0.156 (+5.85 %, +3.05 CI) | CI 2.87 % < 5.00 %, drift +14.97 %/window within its CI 24.07 %; "
                      "the full window's mean +- 7.67 % |"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("| 0.05 | halves | 25.425 | 43.5 % (1.77x) | 2.031 +- 0.0587 (+1.05 %, +0.55 CI) |"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("| 0.001 | slope | never | 0 % | — | — | CI 1.92 % >= 0.10 % |"), std::string::npos) << text;
  EXPECT_NE(text.find("lag-1 autocorrelation 0.82"), std::string::npos) << text;
  SyntheticRun s;
  s.duration_s = 30.0;
  write_synthetic_run(dir, s);
  const auto cmd2 = fmt::format("{} early-stop {} > {} 2>&1", BRASH_POST_EXE, dir.string(), out.string());
  EXPECT_EQ(WEXITSTATUS(std::system(cmd2.c_str())), 2);
  const std::string text2 = brash::post::read_text_file(out);
  EXPECT_NE(text2.find("the replay needs a finished run"), std::string::npos) << text2;
  fs::remove_all(dir);
}

// The hull force split: each part's resistance over the window, as the resistance is averaged, in report.json and a
// short table in report.md; the regions' bounds from meta.json "hull_split".
TEST(RunDir, HullForceSplitIsAveragedLikeTheResistance) {
  const auto dir = scratch("split");
  SyntheticRun r;
  r.split = true;
  r.meta_extra_json = R"(, "hull_split": {"x_par_aft_m": 1.25, "x_par_fwd_m": 4.5})";
  write_synthetic_run(dir, r);
  const auto j = run_cli(dir);
  const auto& S = j["resistance_split_model_N"];
  ASSERT_TRUE(S.is_object()) << j.dump(2);
  double regions = 0, mechanisms = 0;
  for (std::size_t k = 0; k < kSplitParts.size(); ++k) {
    const double mean = -brash::post::testing::window_mean(r.t_s, r.split_series[k], 15.0, 40.0);
    EXPECT_NEAR(S[kSplitParts[k]]["mean"].get<double>(), mean, 1e-9) << kSplitParts[k];
    EXPECT_GT(S[kSplitParts[k]]["ci95"].get<double>(), 0) << kSplitParts[k];
    (k < 3 ? regions : mechanisms) += S[kSplitParts[k]]["mean"].get<double>();
  }
  const double resistance = j["resistance_model_N"]["mean"].get<double>();
  EXPECT_NEAR(regions, resistance, 1e-9);
  EXPECT_NEAR(mechanisms, resistance, 1e-9);
  EXPECT_NEAR(S["x_par_m"][1].get<double>(), 4.5, 1e-12);
  EXPECT_FALSE(j.contains("resistance_split_not_recorded"));
  const std::string md = brash::post::read_text_file(dir / "report.md");
  EXPECT_NE(md.find("## Where the resistance comes from (hull force split)"), std::string::npos) << md;
  EXPECT_NE(md.find("| bow (x > 4.500 m, ahead of the parallel mid-body) | "), std::string::npos) << md;
  EXPECT_NE(md.find("| tangential (friction) | "), std::string::npos) << md;
  // FSICR's terms beside the parts: they add up to R_CH; the bow term's row holds the bow part and their ratio
  const auto& F = j["fsicr"];
  ASSERT_FALSE(F["R_CH_kN"].is_null()) << F.dump(2);
  const auto& T = F["terms_kN"];
  EXPECT_NEAR(T["C1_C2"].get<double>() + T["bow"].get<double>() + T["midbody"].get<double>() +
                  T["form"].get<double>(), F["R_CH_kN"].get<double>(), 1e-9);
  const double bow_kN = S["bow"]["mean"].get<double>() * std::pow(j["lambda"].get<double>(), 3) / 1000;
  EXPECT_NE(md.find(fmt::format("| bow: C3 Cmu (H_F + H_M)^2 (B + Cpsi H_F) | {:.1f} kN | bow {:.1f} ± ",
                                T["bow"].get<double>(), bow_kN)),
            std::string::npos) << md;
  EXPECT_NE(md.find(fmt::format(" | {:.2f} |\n", T["bow"].get<double>() / bow_kN)), std::string::npos) << md;
}

// A part of the hull that touched no ice in the window says so ("no contact"), never "0.0000 ± 0.0000 N".
TEST(RunDir, SplitPartThatTouchedNoIceSaysNoContact) {
  const auto dir = scratch("split_no_stern");
  SyntheticRun r;
  r.split = true;
  r.split_stern_untouched = true;
  write_synthetic_run(dir, r);
  const auto j = run_cli(dir);
  const auto& S = j["resistance_split_model_N"];
  ASSERT_TRUE(S.is_object()) << j.dump(2);
  EXPECT_FALSE(S["stern"]["contact"].get<bool>());
  for (const char* part : {"bow", "mid", "normal", "tangential"}) EXPECT_TRUE(S[part]["contact"].get<bool>()) << part;
  const std::string md = brash::post::read_text_file(dir / "report.md");
  EXPECT_NE(md.find("| stern | no contact | 0 % | no contact |"), std::string::npos) << md;
  EXPECT_EQ(md.find("0.0000 ± 0.0000 N"), std::string::npos) << md;
}

// A record without the split (an older run, YADE) has none, said in words: never a part of 0.
TEST(RunDir, RecordWithoutTheSplitSaysItIsNotRecorded) {
  const auto dir = scratch("nosplit");
  SyntheticRun r;
  write_synthetic_run(dir, r);
  auto j = run_cli(dir);
  EXPECT_TRUE(j["resistance_split_model_N"].is_null());
  EXPECT_NE(j["resistance_split_not_recorded"].get<std::string>().find("no split columns"), std::string::npos);
  std::string md = brash::post::read_text_file(dir / "report.md");
  EXPECT_NE(md.find("The hull force split is not recorded: hull_force.csv has no split columns"), std::string::npos)
      << md;
  const auto split_at = md.find("## Where the resistance comes from");
  ASSERT_NE(split_at, std::string::npos) << md;
  const std::string split_section = md.substr(split_at, md.find("\n## ", split_at + 1) - split_at);
  EXPECT_EQ(split_section.find("| bow"), std::string::npos) << split_section;
  // FSICR's terms say the part is not recorded, never 0
  EXPECT_NE(md.find(" | bow not recorded | n/a |"), std::string::npos) << md;
  // the engine's own words (YADE's meta.json)
  r.meta_extra_json = R"(, "hull_split": "not recorded: the YADE scene records the total hull force only")";
  write_synthetic_run(dir, r);
  j = run_cli(dir);
  EXPECT_EQ(j["resistance_split_not_recorded"], "not recorded: the YADE scene records the total hull force only");
  md = brash::post::read_text_file(dir / "report.md");
  EXPECT_NE(md.find("The hull force split is not recorded: the YADE scene records"), std::string::npos) << md;
}

// The ice views draw the hull's waterline from its mesh: on the JBC at its design draft the outline is closed,
// spans the waterline's length and is as wide as its beam (hull::hydrostatics on the same mesh), its bow near
// the mesh's forward end; an unreadable mesh gives no outline (the views then draw the Lpp x B rectangle).
TEST(IceViews, HullWaterlineFromTheMesh) {
#ifdef BRASH_JBC_MODEL_STL
  if (!fs::exists(BRASH_JBC_MODEL_STL)) GTEST_SKIP() << "JBC model STL not generated";
  const auto outline = brash::post::hull_waterline(BRASH_JBC_MODEL_STL, 0.4125);
  ASSERT_GT(outline.size(), 100u);
  EXPECT_EQ(outline.front(), outline.back());
  double x0 = 1e9, x1 = -1e9, ymax = 0;
  for (const auto& p : outline) x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]), ymax = std::max(ymax, std::abs(p[1]));
  const auto h = brash::hull::hydrostatics(brash::hull::read_mesh(BRASH_JBC_MODEL_STL), 0.4125, 7.0);
  const double station = 7.5 / 240;  // the stations' spacing (the mesh is ~7.3 m long)
  EXPECT_NEAR(x1 - x0, h.lwl_m, 2 * station);
  EXPECT_NEAR(2 * ymax, h.bwl_m, 0.01 * h.bwl_m);
  EXPECT_TRUE(brash::post::hull_waterline("no_such_hull.stl", 0.4).empty());
#else
  GTEST_SKIP() << "built without brash_hull";
#endif
}
