// The study file loader: a good file read into its parts, and each kind of bad input refused with the file, the
// line and the key in the message; the committed study files load.
#include <gtest/gtest.h>

#include <string>

#include "brash/error.hpp"
#include "brash/study/study_file.hpp"

using namespace brash::study;

namespace {

const std::string kGood = R"(study: demo
engines: [liggghts, ode]
run_ensembles: true
cases:
  base:
    base: cases/jbc_bench/case.yaml
    set:
      ship.speed_m_s: 0.482
      run.window_s: [0.375, 0.75]
shared_cases:
  paper_20s:
    base: cases/jbc_ia_5kn/case.yaml
    set: {run.duration_s: 20.0}
variants:
  - {id: base_am, case: base, engine: liggghts, model: added_mass}
  - {id: ode_base_drag, case: base, engine: ode, model: drag}
speed_sweep: {speeds: ["0.2", "1.0"], models: [both], base_case: jbc_quick}
ensembles:
  - {id: ens_a, seeds: 3, side_a: "1:fluid.model=drag", side_b: "1:fluid.model=both", dir: fluid-reading}
paper_runs:
  - {id: paper_ode_drag, case: paper_20s, engine: ode, model: drag, out: paper-ode-drag-20s, dt_s: 1e-3}
manifest:
  - {run: base_am, group: paper, label: "jbc_bench added mass", baseline: true, base_case: jbc_bench}
  - speed_sweep
  - {run: ode_base_drag, group: drag_cd, label: "C_D 0.44", param: fluid.drag_coefficient, value: "0.44",
     base_case: jbc_bench}
  - {run: paper_ode_drag, group: paper, label: "paper", base_case: jbc_ia_5kn, when_listed: ens_a}
)";

// The message of the InputError that parsing `text` throws ("" when it parses).
std::string error_of(const std::string& text) {
  try {
    (void)parse_study(text, "bad.yaml");
  } catch (const brash::InputError& e) {
    return e.what();
  }
  return "";
}

// kGood with the first occurrence of `from` replaced by `to`.
std::string good_with(const std::string& from, const std::string& to) {
  std::string s = kGood;
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return s.replace(at, from.size(), to);
}

}  // namespace

TEST(StudyFile, ReadsEveryPart) {
  const Study s = parse_study(kGood, "good.yaml");
  EXPECT_EQ(s.name, "demo");
  EXPECT_EQ(s.engines, (std::vector<Engine>{Engine::Liggghts, Engine::Ode}));
  EXPECT_FALSE(s.run_paper);
  EXPECT_TRUE(s.run_ensembles);
  ASSERT_EQ(s.cases.size(), 1u);
  EXPECT_EQ(s.cases[0].base, "cases/jbc_bench/case.yaml");
  EXPECT_EQ(s.cases[0].overrides,
            (std::vector<Override>{{"ship.speed_m_s", "0.482"}, {"run.window_s", "[0.375, 0.75]"}}));
  ASSERT_EQ(s.variants.size(), 2u);
  EXPECT_EQ(s.variants[1].engine, Engine::Ode);
  EXPECT_EQ(s.variants[1].model, "drag");
  ASSERT_TRUE(s.speed_sweep);
  EXPECT_EQ(s.speed_sweep->speeds, (std::vector<std::string>{"0.2", "1.0"}));  // as written: ids hold "1.0"
  ASSERT_EQ(s.ensembles.size(), 1u);
  EXPECT_EQ(s.ensembles[0].seeds, 3);
  EXPECT_EQ(s.ensembles[0].side_b, "1:fluid.model=both");
  ASSERT_EQ(s.paper_runs.size(), 1u);
  EXPECT_EQ(s.paper_runs[0].dt_s, "1e-3");
  EXPECT_EQ(s.paper_runs[0].restart_every_s, "0.5");
  ASSERT_EQ(s.manifest.size(), 4u);
  EXPECT_TRUE(s.manifest[0].baseline);
  EXPECT_TRUE(s.manifest[1].sweep);
  EXPECT_EQ(s.manifest[2].value, "0.44");
  EXPECT_FALSE(s.manifest[2].baseline);
  EXPECT_EQ(s.manifest[3].when_listed, "ens_a");
}

// Each kind of bad input: the message holds `where` (file:line: key '...') and the problem.
struct BadInput {
  std::string from, to, expected;
};

class StudyFileRefuses : public testing::TestWithParam<BadInput> {};

TEST_P(StudyFileRefuses, NamingFileLineAndKey) {
  const BadInput& b = GetParam();
  const std::string e = error_of(good_with(b.from, b.to));
  EXPECT_NE(e.find(b.expected), std::string::npos) << "got: " << e;
}

INSTANTIATE_TEST_SUITE_P(
    BadInputs, StudyFileRefuses,
    testing::Values(
        BadInput{"    base: cases/jbc_bench", "    bse: cases/jbc_bench", "bad.yaml:6: key 'cases.base.bse': unknown key"},
        BadInput{"run_ensembles: true", "run_ensembles: yes please", "bad.yaml:3: key 'run_ensembles': 'yes please' is not true or false"},
        BadInput{"engines: [liggghts, ode]", "engines: [liggghts, lammps]", "bad.yaml:2: key 'engines': 'lammps' is not an engine"},
        BadInput{"engine: ode, model: drag}", "engine: ode, model: viscous}", "bad.yaml:16: key 'variants[1].model': 'viscous' is not a fluid model"},
        BadInput{"case: base, engine: liggghts", "case: bas, engine: liggghts", "bad.yaml:15: key 'variants[0].case': 'bas' is not in cases"},
        BadInput{"{id: ode_base_drag,", "{id: base_am,", "bad.yaml:16: key 'variants[1].id': run id 'base_am' given twice"},
        BadInput{"seeds: 3", "seeds: three", "bad.yaml:19: key 'ensembles[0].seeds': 'three' is not a whole number"},
        BadInput{"seeds: 3, ", "", "bad.yaml:19: key 'ensembles[0].seeds': missing (required)"},
        BadInput{"speeds: [\"0.2\"", "speeds: [\"fast\"", "bad.yaml:17: key 'speed_sweep.speeds': 'fast' is not a number"},
        BadInput{"ship.speed_m_s: 0.482", "speed: 0.482", "bad.yaml:8: key 'cases.base.set.speed': a case key is written section.key"},
        BadInput{"      ship.speed_m_s: 0.482\n", "      ship.speed_m_s: 0.482\n      ship.speed_m_s: 0.5\n",
                 "bad.yaml:9: key 'cases.base.set.ship.speed_m_s': given twice (first at line 8)"},
        BadInput{"engine: ode, model: drag, out", "engine: yade, model: drag, out", "key 'paper_runs[0].engine': paper runs are liggghts or ode"},
        BadInput{"when_listed: ens_a", "when_listed: ens_b", "bad.yaml:27: key 'manifest[3]': run 'ens_b' is not defined"},
        BadInput{"  - speed_sweep\n", "  - speed_sweeps\n", "bad.yaml:24: key 'manifest[1]': 'speed_sweeps'"},
        BadInput{"label: \"C_D 0.44\"", "label: [C_D]", "key 'manifest[2].label': expected a single value"},
        BadInput{"study: demo", "study: demo\nstudy: again", "bad.yaml:2: key 'study.study': given twice (first at line 1)"},
        BadInput{"cases/jbc_ia_5kn/case.yaml", "/abs/case.yaml", "key 'shared_cases.paper_20s.base': expected a case.yaml path relative"},
        BadInput{"label: \"paper\"", "label: \"paper\", group2: x", "bad.yaml:27: key 'manifest[3].group2': unknown key"},
        BadInput{"dir: fluid-reading}", "dir: ../up}", "key 'ensembles[0].dir': '../up' is not a name"}));

TEST(StudyFile, RefusesSyntaxErrorsAndEmptyFiles) {
  EXPECT_NE(error_of("study: [demo").find("bad.yaml:"), std::string::npos);
  EXPECT_NE(error_of("").find("bad.yaml: empty study file"), std::string::npos);
  EXPECT_NE(error_of("study: demo\nengines: [liggghts]\n").find("key 'manifest': missing (required)"), std::string::npos);
}

TEST(StudyFile, MissingFileIsAnInputError) {
  EXPECT_THROW((void)load_study("/nonexistent/study.yaml"), brash::InputError);
}

// The committed study files load and hold what each mode runs.
TEST(StudyFile, CommittedStudiesLoad) {
  for (const char* name : {"smoke", "short", "full"}) {
    const Study s = load_study(std::string(BRASH_SOURCE_DIR) + "/study/" + name + ".yaml");
    EXPECT_EQ(s.name, name);
    EXPECT_FALSE(s.manifest.empty()) << name;
  }
}
