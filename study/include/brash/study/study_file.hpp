// A study file (study/<name>.yaml, format in study/README.md): the case folders a study derives from base cases,
// the engine runs of those cases (variants), the speed sweep, the paired-seed ensembles, the paper-case runs and
// the rows of the study's manifest, in the order brash-study-report lists them. load_study() reads and validates
// one; every error is a brash::InputError naming the file, the line and the key.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace brash::study {

enum class Engine { Liggghts, Ode, Yade };
std::string_view to_string(Engine e);

// One case key set on a derived case: "fluid.model" = "drag", "run.window_s" = "[0.375, 0.75]" (the value's YAML
// text, a list in flow style).
struct Override {
  std::string key, value;
  bool operator==(const Override&) const = default;
};

// A case folder derived from a base case.yaml (a path relative to the repository) with keys set.
struct CaseDef {
  std::string name;
  std::filesystem::path base;
  std::vector<Override> overrides;
};

// One engine run of a case of the work dir: <work>/runs/<id>.
struct Variant {
  std::string id, case_name;
  Engine engine = Engine::Liggghts;
  std::string model;
};

// bench/quick_speed_sweep.sh: speeds x models on cases/jbc_quick, runs <work>/runs/quick_u<speed>_<model>.
struct SpeedSweep {
  std::vector<std::string> speeds, models;  // as written (the run ids hold them: quick_u1.0_both)
  std::string base_case;                    // the manifest's base_case column
};

// A paired-seed ensemble (bench/rank_ensemble.sh) in <paper dir>/<dir>; its summary is listed once written.
struct Ensemble {
  std::string id;
  int seeds = 0;
  std::string side_a, side_b;  // NP[:section.key=value,...] as rank_ensemble.sh takes them
  std::string shared_case;     // a shared case's name, or empty for the script's own (cases/jbc_narrow)
  std::string dir;             // folder under the paper dir
};

// A paper-case run: days, in <paper dir>/<out>, resumed where it stopped and archived once complete.
struct PaperRun {
  std::string id, case_name, out;  // case_name: a shared case
  Engine engine = Engine::Liggghts;
  std::string model;
  std::string restart_every_s = "0.5";
  std::string dt_s;  // ODE only; empty: the engine's default
};

// A manifest row (the columns of brash-study-report's manifest), or the speed sweep's rows (sweep = true).
// A row whose run is not listed (an engine this study leaves out, a paper run never started) is left out;
// with when_listed, also when that run is not listed or this run's listed folder has no report.json.
struct RowSpec {
  bool sweep = false;
  std::string run, group, label, param, value;
  bool baseline = false;
  std::string base_case, when_listed;
};

struct Study {
  std::filesystem::path file;
  std::string name;              // full | short | smoke: the document's title and re-run command
  std::vector<Engine> engines;   // engines whose variants run
  bool run_paper = false;        // start or resume the paper runs (else list them once started)
  bool run_ensembles = false;    // run or continue the ensembles (else list their summaries)
  std::vector<CaseDef> cases;         // in <work>/cases, made afresh by every study
  std::vector<CaseDef> shared_cases;  // in <paper dir>/cases, made once, when a run that needs one starts
  std::vector<Variant> variants;
  std::optional<SpeedSweep> speed_sweep;
  std::vector<Ensemble> ensembles;
  std::vector<PaperRun> paper_runs;
  std::vector<RowSpec> manifest;

  const CaseDef* find_case(std::string_view name) const;
  const CaseDef* find_shared_case(std::string_view name) const;
};

Study load_study(const std::filesystem::path& file);
// The same from text; `source` names it in errors.
Study parse_study(const std::string& yaml_text, const std::string& source);

}  // namespace brash::study
