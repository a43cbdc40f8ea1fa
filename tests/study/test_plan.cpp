// The planner: variants -> runs with their case overrides and commands, engines left out, the paper runs' start
// and resume commands, the ensembles' and the sweep's bench commands; and the committed smoke study's plan.
#include <gtest/gtest.h>

#include "brash/study/plan.hpp"

using namespace brash::study;

namespace {

const std::string kStudy = R"(study: demo
engines: [liggghts, ode]
cases:
  base:
    base: cases/jbc_bench/case.yaml
    set: {ship.speed_m_s: 0.482, run.window_s: [0.375, 0.75]}
  cd1.0:
    base: cases/jbc_bench/case.yaml
    set: {fluid.drag_coefficient: 1.0}
shared_cases:
  wide: {base: cases/jbc_narrow/case.yaml, set: {channel.width_m: 2.25}}
  paper_20s: {base: cases/jbc_ia_5kn/case.yaml, set: {run.duration_s: 20.0}}
variants:
  - {id: base_am, case: base, engine: liggghts, model: added_mass}
  - {id: ode_base_drag, case: base, engine: ode, model: drag}
  - {id: yade_base_drag, case: base, engine: yade, model: drag}
  - {id: cd1.0_drag, case: cd1.0, engine: liggghts, model: drag}
speed_sweep: {speeds: ["0.2", "1.0"], models: [both, drag], base_case: jbc_quick}
ensembles:
  - {id: ens_wide, seeds: 3, side_a: "1:fluid.model=drag", side_b: "1:fluid.model=both", case: wide,
     dir: fluid-reading-wide}
paper_runs:
  - {id: paper_ode_drag, case: paper_20s, engine: ode, model: drag, out: paper-ode-drag-20s, dt_s: 1e-3}
  - {id: paper_liggghts_drag, case: paper_20s, engine: liggghts, model: drag, out: paper-liggghts-drag-20s}
manifest:
  - speed_sweep
)";

Settings settings() {
  Settings s;
  s.repo = "/repo";
  s.bin = "/repo/build/bin";
  s.work = "/scratch/work";
  s.paper_dir = "/repo/runs";
  s.archive_dir = "/repo/evidence";
  s.doc = "/repo/runs/study-short/study.md";
  s.ranks = 2;
  s.nice = 5;
  s.engines = {Engine::Liggghts, Engine::Ode};
  return s;
}

Plan demo_plan() { return plan_study(parse_study(kStudy, "demo.yaml"), settings()); }

}  // namespace

TEST(Plan, VariantsBecomeRunsInOrderWithTheirCaseOverrides) {
  const Plan p = demo_plan();
  ASSERT_EQ(p.runs.size(), 3u);
  EXPECT_EQ(p.runs[0].id, "base_am");
  EXPECT_EQ(p.runs[1].id, "ode_base_drag");
  EXPECT_EQ(p.runs[2].id, "cd1.0_drag");
  EXPECT_EQ(p.runs[0].out, "/scratch/work/runs/base_am");
  EXPECT_EQ(p.runs[0].case_step.dir, "/scratch/work/cases/base");
  EXPECT_EQ(p.runs[0].case_step.base, "/repo/cases/jbc_bench/case.yaml");
  const brash::CaseOverrides expected{{"name", "base"}, {"ship.speed_m_s", "0.482"}, {"run.window_s", "[0.375, 0.75]"}};
  EXPECT_EQ(p.runs[0].case_step.overrides, expected);
  EXPECT_EQ(p.runs[2].case_step.overrides, (brash::CaseOverrides{{"name", "cd1.0"}, {"fluid.drag_coefficient", "1.0"}}));
}

TEST(Plan, EngineNotInTheStudyIsLeftOutWithItsReason) {
  const Plan p = demo_plan();
  ASSERT_EQ(p.left_out.size(), 1u);
  EXPECT_EQ(p.left_out[0], "yade_base_drag (yade is not among this study's engines)");
  Settings with_yade = settings();
  with_yade.engines.push_back(Engine::Yade);
  const Plan all = plan_study(parse_study(kStudy, "demo.yaml"), with_yade);
  ASSERT_EQ(all.runs.size(), 4u);
  EXPECT_EQ(all.runs[2].steps.at(0).argv,
            (std::vector<std::string>{"/repo/build/bin/brash-yade-run", "/scratch/work/cases/base", "--out",
                                      "/scratch/work/runs/yade_base_drag", "--model", "drag", "-j", "2"}));
}

TEST(Plan, CommandTextsNameTheCaseAndTheEngine) {
  const Plan p = demo_plan();
  EXPECT_EQ(p.runs[0].command_text,
            "brash-case derive cases/jbc_bench/case.yaml --set name=base --set ship.speed_m_s=0.482 "
            "--set \"run.window_s=[0.375, 0.75]\" --out /scratch/work/cases/base --force && nice -n 5 "
            "build/bin/brash-liggghts-run /scratch/work/cases/base --np 2 --out /scratch/work/runs/base_am --model "
            "added_mass");
  // ODE: the engine niced; like every runner it ends with brash-post on its run directory
  ASSERT_EQ(p.runs[1].steps.size(), 1u);
  EXPECT_TRUE(p.runs[1].steps[0].niced);
  EXPECT_EQ(p.runs[1].steps[0].argv.at(0), "/repo/build/bin/brash-ode");
  EXPECT_EQ(p.runs[1].command_text.find("brash-post"), std::string::npos) << p.runs[1].command_text;
}

TEST(Plan, PaperRunsStartFromTheirSharedCaseAndResumeFromTheirFolder) {
  const Plan p = demo_plan();
  ASSERT_EQ(p.paper_runs.size(), 2u);
  const PlannedPaperRun& ode = p.paper_runs[0];
  EXPECT_EQ(ode.out, "/repo/runs/paper-ode-drag-20s");
  EXPECT_EQ(ode.case_step.dir, "/repo/runs/cases/paper_20s");
  EXPECT_EQ(ode.start.at(0).argv,
            (std::vector<std::string>{"/repo/build/bin/brash-ode", "/repo/runs/cases/paper_20s", "--out",
                                      "/repo/runs/paper-ode-drag-20s", "--model", "drag", "--restart-every", "0.5",
                                      "--dt", "1e-3", "--no-progress"}));
  EXPECT_EQ(ode.resume.at(0).argv, (std::vector<std::string>{"/repo/build/bin/brash-ode", "--resume",
                                                              "/repo/runs/paper-ode-drag-20s", "--no-progress"}));
  EXPECT_EQ(ode.resume.size(), 1u);  // brash-ode runs brash-post itself
  EXPECT_EQ(p.paper_runs[1].resume.at(0).argv,
            (std::vector<std::string>{"/repo/build/bin/brash-liggghts-run", "--resume", "/repo/runs/paper-liggghts-drag-20s",
                                      "--np", "2", "--restart-every", "0.5"}));
  EXPECT_NE(p.paper_runs[1].command_text.find(
                " (resumed with: nice -n 5 build/bin/brash-liggghts-run --resume runs/paper-liggghts-drag-20s --np 2 "
                "--restart-every 0.5 when interrupted)"),
            std::string::npos)
      << p.paper_runs[1].command_text;
}

TEST(Plan, EnsembleRunsTheBenchScriptOnItsSharedCase) {
  const Plan p = demo_plan();
  ASSERT_EQ(p.ensembles.size(), 1u);
  const PlannedEnsemble& e = p.ensembles[0];
  ASSERT_TRUE(e.case_step);
  EXPECT_EQ(e.case_step->dir, "/repo/runs/cases/wide");
  EXPECT_EQ(e.dir, "/repo/runs/fluid-reading-wide");
  EXPECT_EQ(e.command_text,
            "BRASH_BIN=build/bin CASE=runs/cases/wide SIDE_A=1:fluid.model=drag SIDE_B=1:fluid.model=both TOL_PCT=2 "
            "JOBS=1 nice -n 5 bash bench/rank_ensemble.sh 3 runs/fluid-reading-wide");
}

TEST(Plan, SpeedSweepRunsTheBenchScriptIntoTheWorkRuns) {
  const Plan p = demo_plan();
  ASSERT_EQ(p.sweep.size(), 1u);
  EXPECT_EQ(p.sweep[0].argv, (std::vector<std::string>{"bash", "/repo/bench/quick_speed_sweep.sh", "/scratch/work/runs"}));
  EXPECT_EQ(p.sweep[0].env.at(0), (std::pair<std::string, std::string>{"SPEEDS", "0.2 1.0"}));
  EXPECT_EQ(p.sweep[0].env.at(1), (std::pair<std::string, std::string>{"MODELS", "both drag"}));
}

// The committed smoke study: its three jbc_bench runs, in order, on LIGGGHTS.
TEST(Plan, SmokeStudyPlansItsThreeRuns) {
  const Plan p = plan_study(load_study(std::string(BRASH_SOURCE_DIR) + "/study/smoke.yaml"), settings());
  ASSERT_EQ(p.runs.size(), 3u);
  EXPECT_EQ(p.runs[0].id, "smoke_am");
  EXPECT_EQ(p.runs[1].id, "smoke_drag");
  EXPECT_EQ(p.runs[2].id, "smoke_u0.8_am");
  EXPECT_EQ(p.runs[2].case_step.overrides,
            (brash::CaseOverrides{{"name", "smoke_u0.8"}, {"ship.speed_m_s", "0.8"}, {"run.duration_s", "0.3"},
                                  {"run.window_s", "[0.15, 0.3]"}}));
  for (const auto& r : p.runs) EXPECT_EQ(r.engine, Engine::Liggghts) << r.id;
  EXPECT_TRUE(p.sweep.empty());
  EXPECT_EQ(p.paper_runs.size(), 7u);
}
