// The plan of a study: every case folder it derives and every process it runs, with the command line the manifest
// lists for it. Planning runs nothing and touches no file, so it is tested without engines.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "brash/case_derive.hpp"
#include "brash/study/study_file.hpp"

namespace brash::study {

// Where a study reads and writes, and how it runs the engines (brash-study's options).
struct Settings {
  std::filesystem::path repo;         // the repository: the study file's paths (cases/..., bench/...) are relative to it
  std::filesystem::path bin;          // the executables (build/bin)
  std::filesystem::path work;         // <work>/cases, <work>/runs/<id>, <work>/logs, <work>/manifest.tsv
  std::filesystem::path paper_dir;    // the paper runs, the shared cases (<paper dir>/cases), the ensembles
  std::filesystem::path archive_dir;  // complete paper runs and ensemble summaries (evidence/)
  std::filesystem::path doc;          // the document (<work>/study.md by default)
  int ranks = 2;
  int nice = 5;
  std::vector<Engine> engines;  // engines whose variants run
  bool run_paper = false, run_ensembles = false;
};

// One process: argv (argv[0] a path or a name on PATH), extra environment, run under `nice -n` when niced, in cwd
// (empty: the current folder).
struct Command {
  std::vector<std::string> argv;
  std::vector<std::pair<std::string, std::string>> env;
  bool niced = false;
  std::filesystem::path cwd;
};

// The command as a shell line for the manifest: "nice -n 5 build/bin/brash-liggghts-run ...", the repository's
// folder dropped from paths, a word with a space, quote or bracket in double quotes.
std::string shell_text(const Command& c, const Settings& s);
// `text` with the repository's folder dropped from the paths in it.
std::string without_repo(std::string text, const Settings& s);
// Several commands joined by " && ".
std::string shell_text(const std::vector<Command>& cs, const Settings& s);

// A case folder derived from its base with brash::write_derived_case: the case's name, then its overrides.
struct CaseStep {
  std::string name;
  std::filesystem::path base;  // absolute
  std::filesystem::path dir;
  CaseOverrides overrides;
  std::string text;  // the same as a command: brash-case derive BASE --set name=NAME ... --out DIR --force
};

// One engine run of a variant, in <work>/runs/<id>.
struct PlannedRun {
  std::string id;
  Engine engine = Engine::Liggghts;
  std::string model;
  CaseStep case_step;
  std::filesystem::path out;
  std::vector<Command> steps;  // the engine; for ODE then brash-post
  std::string command_text;    // case_step.text && steps: the manifest's command and the resume key
};

// A paper run, in <paper dir>/<out>: started from its case, or resumed from its restart files.
struct PlannedPaperRun {
  const PaperRun* def = nullptr;
  CaseStep case_step;
  std::filesystem::path out;
  std::vector<Command> start, resume;
  std::string command_text;  // "<case> && <start> (resumed with: <resume> when interrupted)"
};

// A paired ensemble: bench/rank_ensemble.sh into <paper dir>/<dir>, on a shared case or the script's own.
struct PlannedEnsemble {
  const Ensemble* def = nullptr;
  std::filesystem::path dir;
  std::optional<CaseStep> case_step;  // the shared case it runs on (made when missing), or the script's own
  Command command;
  std::string command_text;
};

struct Plan {
  std::vector<PlannedRun> runs;                // in the study file's order
  std::vector<std::string> left_out;           // variants whose engine this study does not run, with the reason
  std::vector<Command> sweep;                  // bench/quick_speed_sweep.sh, or nothing
  std::vector<PlannedEnsemble> ensembles;
  std::vector<PlannedPaperRun> paper_runs;
};

Plan plan_study(const Study& study, const Settings& settings);

}  // namespace brash::study
