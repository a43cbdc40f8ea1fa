// brash-study: runs a study file (study/<name>.yaml) one simulation at a time, then writes the study document.
//   brash-study --study study/short.yaml [--out DOC] [--work DIR]      (`STUDY=short make study`)
// Every run is its own run directory <work>/runs/<id>; a run whose report.json is complete and that was made by the
// same command is not re-run (the study resumes where it stopped). The paper runs (days) live in the paper dir and
// are archived in evidence/ (the repository's curated report files, read by `make validation`); the study's own
// runs are copied beside the document (<work>/study.md by default: <doc stem>_runs/<id>); the
// manifest <work>/manifest.tsv (copy: <doc stem>_manifest.tsv) lists every row with its command. Format of a study
// file: study/README.md.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cstdlib>
#include <iostream>
#include <thread>

#include "brash/error.hpp"
#include "brash/paths.hpp"
#include "brash/study/study.hpp"
#include "brash/study/runner.hpp"

namespace fs = std::filesystem;
using namespace brash::study;

namespace {

struct Options {
  std::string study, doc, work, paper_dir, archive_dir, bin, repo;
  int ranks = std::thread::hardware_concurrency() >= 2 ? 2 : 1;
  int nice = 5;
  std::vector<std::string> engines;
  bool with_yade = false, run_paper = false, run_ensembles = false, plan_only = false;
};

fs::path absolute(const std::string& p) { return fs::absolute(p).lexically_normal(); }

// The folder of this executable: the other tools are built (or installed) beside it.
fs::path own_bin_dir() { return brash::paths::executable_dir(); }

// The repository a study file belongs to: study files live in <repo>/study/, so the folder above the file's
// folder, with symbolic links resolved (<build>/share/brash/study links to the repository's study/).
fs::path repo_of(const fs::path& study_file) {
  std::error_code ec;
  const fs::path real = fs::weakly_canonical(fs::absolute(study_file), ec);
  return (ec ? fs::absolute(study_file) : real).parent_path().parent_path();
}

std::vector<Engine> engines_of(const Options& o, const Study& study) {
  std::vector<Engine> engines = study.engines;
  if (!o.engines.empty()) {
    engines.clear();
    for (const auto& name : o.engines) {
      const auto known = {Engine::Liggghts, Engine::Ode, Engine::Yade};
      const auto it = std::ranges::find(known, name, [](Engine e) { return std::string(to_string(e)); });
      if (it == known.end()) throw brash::InputError(fmt::format("--engines: '{}' is not liggghts, ode or yade", name));
      engines.push_back(*it);
    }
  }
  if (o.with_yade && std::ranges::find(engines, Engine::Yade) == engines.end()) engines.push_back(Engine::Yade);
  return engines;
}

Settings settings_of(const Options& o, const Study& study) {
  Settings s;
  s.repo = absolute(o.repo);
  s.bin = o.bin.empty() ? own_bin_dir() : absolute(o.bin);
  s.work = absolute(o.work.empty() ? (s.repo / "runs" / ("study-" + study.name)).string() : o.work);
  s.paper_dir = absolute(o.paper_dir.empty() ? (s.repo / "runs").string() : o.paper_dir);
  s.archive_dir = absolute(o.archive_dir.empty() ? (s.repo / "evidence").string() : o.archive_dir);
  s.doc = absolute(o.doc.empty() ? (s.work / "study.md").string() : o.doc);
  s.ranks = o.ranks;
  s.nice = o.nice;
  s.run_paper = study.run_paper || o.run_paper;
  s.run_ensembles = study.run_ensembles || o.run_ensembles;
  s.engines = engines_of(o, study);
  return s;
}

void print_plan(const Plan& plan) {
  for (const auto& r : plan.runs) std::cout << r.id << "\t" << r.command_text << "\n";
  for (const auto& why : plan.left_out) std::cout << "# left out: " << why << "\n";
  for (const auto& e : plan.ensembles) std::cout << e.def->id << "\t" << e.command_text << "\n";
  for (const auto& p : plan.paper_runs) std::cout << p.def->id << "\t" << p.command_text << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"brash-study: run a study file (study/<name>.yaml) and write the study document",
               "brash-study"};
  Options o;
  app.add_option("--study", o.study, "study file (default: <data>/study/$STUDY.yaml, STUDY=full; data = "
                                     "<prefix>/share/brash or $BRASH_DATA_DIR)");
  app.add_option("--out", o.doc, "the document (default <work>/study.md)")->envname("STUDY_DOC");
  app.add_option("--work", o.work, "work dir: cases, runs, logs, manifest (default runs/study-<name>)")->envname("STUDY_WORK");
  app.add_option("--paper-dir", o.paper_dir, "where the paper runs, shared cases and ensembles live (default runs)")
      ->envname("STUDY_PAPER_DIR");
  app.add_option("--archive", o.archive_dir, "archive of complete paper runs and ensemble summaries (default "
                                             "evidence)")->envname("STUDY_ARCHIVE");
  app.add_option("--bin", o.bin, "the executables (default: this program's folder)")->envname("BRASH_BIN");
  app.add_option("--repo", o.repo, "the repository (the study file's paths are relative to it; default: the folder "
                                   "above the study file's folder)");
  app.add_option("--ranks", o.ranks, "MPI ranks / threads per run")->envname("BRASH_RANKS")->capture_default_str();
  app.add_option("--nice", o.nice, "nice level of the engines")->envname("STUDY_NICE")->capture_default_str();
  app.add_option("--engines", o.engines, "engines whose variants run (default: the study file's)")->delimiter(',');
  app.add_flag("--with-yade", o.with_yade, "add the YADE variants")->envname("STUDY_YADE");
  app.add_flag("--run-paper", o.run_paper, "start or resume the paper runs")->envname("STUDY_PAPER");
  app.add_flag("--run-ensembles", o.run_ensembles, "run or continue the paired ensembles")->envname("STUDY_ENSEMBLES");
  app.add_flag("--plan", o.plan_only, "print the planned runs and their commands, run nothing");
  CLI11_PARSE(app, argc, argv);
  try {
    if (o.study.empty()) {
      const char* mode = std::getenv("STUDY");
      const fs::path file = fs::path("study") / fmt::format("{}.yaml", mode && *mode ? mode : "full");
      o.study = (o.repo.empty() ? brash::paths::data_file(file, "the study file") : fs::path(o.repo) / file).string();
    }
    if (o.repo.empty()) o.repo = repo_of(o.study).string();
    const Study study = load_study(o.study);
    Settings s = settings_of(o, study);
    if (o.plan_only) {
      print_plan(plan_study(study, s));
      return 0;
    }
    s.engines = available_engines(s.engines, s);
    return run_study(study, s);
  } catch (const brash::InputError& e) {
    std::cerr << "brash-study: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "brash-study: error: " << e.what() << "\n";
    return 1;
  }
}
