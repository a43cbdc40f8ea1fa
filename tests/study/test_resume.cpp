// Resume and the run directories' outputs, without engines: a complete run made by the same command is kept (not
// re-run), anything else is run again; force records, archives, the paper runs' listed folder; the manifest's rows.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "brash/study/manifest.hpp"
#include "brash/study/plan.hpp"
#include "brash/study/run_outputs.hpp"
#include "brash/study/runner.hpp"

using namespace brash::study;
namespace fs = std::filesystem;

namespace {

void write(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

std::string read(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class StudyDir : public testing::Test {
 protected:
  fs::path root = fs::temp_directory_path() / ("brash_study_test_" + std::to_string(::getpid()) + "_" +
                                               testing::UnitTest::GetInstance()->current_test_info()->name());
  void SetUp() override { fs::remove_all(root), fs::create_directories(root); }
  void TearDown() override { fs::remove_all(root); }

  // A study of one LIGGGHTS run of jbc_bench, its executables in a folder that does not exist (so that a run that
  // is not kept fails at once instead of simulating).
  Settings settings() const {
    Settings s;
    s.repo = BRASH_SOURCE_DIR;
    s.bin = root / "no-bin";
    s.work = root / "work";
    s.paper_dir = root / "paper";
    s.archive_dir = root / "archive";
    s.doc = root / "docs" / "study.md";
    s.engines = {Engine::Liggghts};
    return s;
  }
  Plan one_run_plan() const {
    return plan_study(parse_study(R"(study: t
engines: [liggghts]
cases: {base: {base: cases/jbc_bench/case.yaml, set: {fluid.drag_coefficient: 1.0}}}
variants: [{id: base_am, case: base, engine: liggghts, model: added_mass}]
manifest: [{run: base_am, group: paper, label: "jbc_bench", base_case: jbc_bench}]
)", "t.yaml"),
                      settings());
  }
};

const char* kComplete = R"({"status": "complete", "mean_N": 1.0})";

}  // namespace

TEST_F(StudyDir, ReportCompleteReadsTheStatus) {
  write(root / "a/report.json", kComplete);
  write(root / "b/report.json", R"({"status": "failed"})");
  write(root / "c/report.json", "{ not json");
  EXPECT_TRUE(report_complete(root / "a"));
  EXPECT_FALSE(report_complete(root / "b"));
  EXPECT_FALSE(report_complete(root / "c"));
  EXPECT_FALSE(report_complete(root / "missing"));
}

TEST_F(StudyDir, CompleteRunOfTheSameCommandIsSkipped) {
  const Plan plan = one_run_plan();
  const PlannedRun& r = plan.runs.at(0);
  write(r.out / "report.json", kComplete);
  write(r.out / ".study_cmd", r.command_text + "\n");
  EXPECT_TRUE(keeps_complete_run(r));
  Listings listings;
  fs::create_directories(settings().work / "logs");
  run_variants(plan, settings(), listings);
  EXPECT_EQ(listings.at("base_am").exit_text, "0");
  EXPECT_TRUE(fs::exists(r.out / "report.json")) << "a kept run is not removed";
  EXPECT_FALSE(fs::exists(settings().work / "logs/base_am.log")) << "a kept run is not run";
  EXPECT_TRUE(fs::exists(settings().work / "cases/base/case.yaml")) << "its case is derived all the same";
}

TEST_F(StudyDir, RunOfAnotherCommandOrIncompleteIsRunAgain) {
  const Plan plan = one_run_plan();
  const PlannedRun& r = plan.runs.at(0);
  write(r.out / "report.json", kComplete);
  write(r.out / ".study_cmd", "an older command\n");
  EXPECT_FALSE(keeps_complete_run(r));
  write(r.out / ".study_cmd", r.command_text + "\n");
  write(r.out / "report.json", R"({"status": "incomplete"})");
  EXPECT_FALSE(keeps_complete_run(r));
  Listings listings;
  fs::create_directories(settings().work / "logs");
  run_variants(plan, settings(), listings);
  EXPECT_EQ(listings.at("base_am").exit_text, "127");  // the engine is not there: nice cannot start it
  EXPECT_FALSE(fs::exists(r.out / "report.json")) << "the old run directory is cleared before a run";
}

TEST_F(StudyDir, CaseThatCannotBeDerivedFailsItsRunsWithTheReason) {
  const Study study = parse_study(R"(study: t
engines: [liggghts]
cases: {bad: {base: cases/jbc_bench/case.yaml, set: {fluid.model: viscous}}}
variants: [{id: bad_am, case: bad, engine: liggghts, model: added_mass}]
manifest: [{run: bad_am, group: paper, label: "x", base_case: jbc_bench}]
)", "t.yaml");
  Listings listings;
  run_variants(plan_study(study, settings()), settings(), listings);
  const std::string e = listings.at("bad_am").exit_text;
  EXPECT_TRUE(e.starts_with("case generation failed: ")) << e;
  EXPECT_NE(e.find("fluid.model"), std::string::npos) << e;
}

TEST_F(StudyDir, ForceRowsLeaveOutAnUnfinishedLastRow) {
  write(root / "r/hull_force.csv", "t,fx,fy,fz\n0.1,1,2,3\n0.2,1,2\n0.3,1,2,3\n0.4,1,");
  EXPECT_EQ(complete_force_rows(root / "r/hull_force.csv"),
            (std::vector<std::string>{"t,fx,fy,fz", "0.1,1,2,3", "0.3,1,2,3"}));
  EXPECT_EQ(force_row_count(root / "r/hull_force.csv"), 2u);
  EXPECT_DOUBLE_EQ(model_time_reached(root / "r"), 0.3);
  write(root / "raw/hull_force.raw", "# step time fx\n100 0.05 1\n200 0.10 2\n");
  EXPECT_DOUBLE_EQ(model_time_reached(root / "raw"), 0.10);
  EXPECT_DOUBLE_EQ(model_time_reached(root / "none"), 0.0);
}

TEST_F(StudyDir, PartialArchiveGrowsOnly) {
  const fs::path run = root / "paper/paper-ode-drag-20s";
  write(run / "meta.json", "{}");
  write(run / "hull_force.csv", "t,fx\n0.1,1\n0.2,1\n0.3,1\n0.4");
  EXPECT_TRUE(archive_partial_run(run, root / "archive"));
  EXPECT_EQ(read(root / "archive/paper-ode-drag-20s/hull_force.csv"), "t,fx\n0.1,1\n0.2,1\n0.3,1\n");
  write(run / "hull_force.csv", "t,fx\n0.1,1\n");  // started again elsewhere: a shorter record
  EXPECT_FALSE(archive_partial_run(run, root / "archive"));
  EXPECT_EQ(force_row_count(root / "archive/paper-ode-drag-20s/hull_force.csv"), 3u);
}

TEST_F(StudyDir, CompleteArchiveCopiesOutputsNotDumps) {
  const fs::path run = root / "paper/paper-liggghts-drag-20s";
  for (const char* f : {"meta.json", "case.yaml", "report.md", "hull_force.csv", "force_history.png",
                        "ice_views_0001.png", "ice_views_0002.png", "particles/p.vtk"})
    write(run / f, f);
  write(run / "report.json", kComplete);
  EXPECT_TRUE(archive_complete_run(run, root / "archive"));
  const fs::path a = root / "archive/paper-liggghts-drag-20s";
  EXPECT_TRUE(fs::exists(a / "report.json") && fs::exists(a / "force_history.png") && fs::exists(a / "hull_force.csv"));
  EXPECT_TRUE(fs::exists(a / "ice_views_0002.png"));
  EXPECT_FALSE(fs::exists(a / "ice_views_0001.png")) << "only the newest views";
  EXPECT_FALSE(fs::exists(a / "particles"));
  EXPECT_EQ(read(a / "source_run_dir.txt"), "../../paper/paper-liggghts-drag-20s\n");
  EXPECT_FALSE(archive_complete_run(run, root / "archive")) << "the same report is not copied again";
  EXPECT_EQ(paper_listed_dir(run, root / "archive"), a);
}

TEST_F(StudyDir, PaperRunIsListedFromItsDirectoryUntilComplete) {
  const fs::path run = root / "paper/paper-ode-drag-20s", archive = root / "archive";
  EXPECT_EQ(paper_listed_dir(run, archive), run);
  write(archive / "paper-ode-drag-20s/meta.json", "{}");  // a partial record from another machine
  EXPECT_EQ(paper_listed_dir(run, archive), archive / "paper-ode-drag-20s");
  write(run / "meta.json", "{}");  // started here again
  EXPECT_EQ(paper_listed_dir(run, archive), run);
  EXPECT_FALSE(held_elsewhere(run));
}

TEST_F(StudyDir, EnsembleIsListedByItsSidesAndArchived) {
  const Study study = parse_study(R"(study: t
engines: [liggghts]
ensembles:
  - {id: ens, seeds: 3, side_a: "1:fluid.model=drag", side_b: "1:fluid.model=both", dir: fluid-reading}
  - {id: ens_none, seeds: 3, side_a: "1:fluid.model=drag", side_b: "2", dir: fluid-reading}
manifest: [{run: ens, group: paired, label: "both on drag", base_case: jbc_narrow}]
)", "t.yaml");
  write(root / "paper/fluid-reading/ensemble-x.json", R"({"side_a": "1:fluid.model=drag", "side_b": "1"})");
  write(root / "paper/fluid-reading/ensemble-y.json", R"({"side_a": "1:fluid.model=drag", "side_b": "1:fluid.model=both"})");
  Listings listings;
  run_ensembles(plan_study(study, settings()), settings(), listings);
  ASSERT_TRUE(listings.contains("ens"));
  EXPECT_FALSE(listings.contains("ens_none"));
  EXPECT_EQ(listings.at("ens").run_dir, root / "archive/ensembles/fluid-reading/ensemble-y.json");
  fs::remove_all(root / "paper/fluid-reading");
  Listings again;
  run_ensembles(plan_study(study, settings()), settings(), again);
  EXPECT_EQ(again.at("ens").run_dir, root / "archive/ensembles/fluid-reading/ensemble-y.json");
}

TEST_F(StudyDir, ManifestRowsOfListedRunsCopiedBesideTheDocument) {
  const Study study = parse_study(R"(study: t
engines: [liggghts]
speed_sweep: {speeds: ["0.2"], models: [both], base_case: jbc_quick}
manifest:
  - {run: quick_u0.2_both, group: paper, label: "a", base_case: jbc_quick}
  - speed_sweep
  - {run: quick_u0.2_both, group: cand, label: "b", base_case: jbc_quick, when_listed: quick_u0.2_both}
)", "t.yaml");
  const Settings s = settings();
  Listings listings{{"quick_u0.2_both", Listing{"cmd", "0", s.work / "runs/quick_u0.2_both", false}}};
  std::vector<ManifestRow> rows = manifest_rows(study, listings);
  ASSERT_EQ(rows.size(), 2u) << "the when_listed row needs a report";
  EXPECT_EQ(rows[1].group, "speed");
  EXPECT_EQ(rows[1].label, "U 0.2");
  EXPECT_EQ(rows[1].value, "0.2");
  write(s.work / "runs/quick_u0.2_both/report.json", kComplete);
  write(s.work / "runs/quick_u0.2_both/restart/r.bin", "x");
  write(s.doc.parent_path() / "study_runs/stale/report.json", kComplete);
  copy_study_runs(rows, s);
  EXPECT_EQ(rows[0].run_dir, s.doc.parent_path() / "study_runs/quick_u0.2_both");
  EXPECT_TRUE(fs::exists(rows[0].run_dir / "report.json"));
  EXPECT_FALSE(fs::exists(rows[0].run_dir / "restart"));
  EXPECT_FALSE(fs::exists(s.doc.parent_path() / "study_runs/stale"));
  const std::string text = manifest_text(rows, s, "title");
  EXPECT_NE(text.find("quick_u0.2_both\tspeed\tU 0.2\tspeed_m_s\t0.2\t0\tjbc_quick\t0\t../docs/study_runs/quick_u0.2_both\tcmd\n"),
            std::string::npos)
      << text;
}
