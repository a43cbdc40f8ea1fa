// The study from its plan to its document.
#include "brash/study/study.hpp"

#include <fmt/chrono.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <ctime>
#include <memory>

#include "brash/error.hpp"
#include "brash/run/run_layout.hpp"
#include "brash/study/manifest.hpp"
#include "brash/study/process.hpp"
#include "brash/study/runner.hpp"

namespace fs = std::filesystem;

namespace brash::study {

namespace {

const char* executable_of(Engine e) {
  switch (e) {
    case Engine::Liggghts: return "brash-liggghts-run";
    case Engine::Ode: return "brash-ode";
    case Engine::Yade: return "brash-yade-run";
  }
  return "";
}

bool has(const std::vector<Engine>& engines, Engine e) { return std::ranges::find(engines, e) != engines.end(); }

// The repository's commit, short ("?" outside a git checkout).
std::string git_commit_of(const fs::path& repo) {
  const std::string cmd = fmt::format("git -C '{}' rev-parse --short HEAD 2>/dev/null", repo.string());
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(::popen(cmd.c_str(), "r"), ::pclose);
  std::array<char, 64> buf{};
  std::string out;
  if (pipe && std::fgets(buf.data(), buf.size(), pipe.get())) out = buf.data();
  while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
  return out.empty() ? "?" : out;
}

int write_document(const Study& study, const Settings& s, const fs::path& manifest) {
  const Command report{{(s.bin / "brash-study-report").string(), manifest.string(), "--out", s.doc.string(), "--title",
                        fmt::format("brash study (STUDY={})", study.name), "--study-command", rerun_command(study, s)},
                       {}, false, s.repo};
  return run_process(report, s, {});
}

}  // namespace

std::vector<Engine> available_engines(const std::vector<Engine>& wanted, const Settings& s) {
  for (const char* tool : {"brash-pack", "brash-post", "brash-study-report", "brash-liggghts-run"})
    if (!fs::exists(s.bin / tool))
      throw InputError(fmt::format("{} is missing: build first (make build, or --bin <build>/bin)", (s.bin / tool).string()));
  std::vector<Engine> engines;
  for (Engine e : wanted) {
    if (fs::exists(s.bin / executable_of(e))) engines.push_back(e);
    else say(fmt::format("{} is not built: its runs are left out", (s.bin / executable_of(e)).string()));
  }
  return engines;
}

std::string rerun_command(const Study& study, const Settings& s) {
  std::string cmd = "STUDY=" + study.name;
  if (has(s.engines, Engine::Yade) && !has(study.engines, Engine::Yade)) cmd += " STUDY_YADE=1";
  if (s.run_paper && !study.run_paper) cmd += " STUDY_PAPER=1";
  if (s.run_ensembles && !study.run_ensembles) cmd += " STUDY_ENSEMBLES=1";
  return cmd + " make study";
}

int run_study(const Study& study, const Settings& s) {
  for (const char* sub : {"cases", "runs", "logs"}) fs::create_directories(s.work / sub);
  say(fmt::format("STUDY={} ({}), work dir {}, document {}, {} rank(s), nice {}", study.name, study.file.string(),
                  s.work.string(), s.doc.string(), s.ranks, s.nice));
  const Plan plan = plan_study(study, s);
  Listings listings;
  run_variants(plan, s, listings);
  run_speed_sweep(study, plan, s, listings);
  run_ensembles(plan, s, listings);
  run_paper_runs(plan, s, listings);

  std::vector<ManifestRow> rows = manifest_rows(study, listings);
  fs::create_directories(s.doc.parent_path());
  copy_study_runs(rows, s);
  const fs::path manifest = s.work / "manifest.tsv";
  const std::string text = manifest_text(
      rows, s, fmt::format("brash-study STUDY={}, {:%Y-%m-%dT%H:%M:%SZ}, git {}", study.name,
                           fmt::gmtime(std::time(nullptr)), git_commit_of(s.repo)));
  run::write_atomic(manifest, text);
  if (const int rc = write_document(study, s, manifest); rc != 0) return rc;
  const fs::path copy = s.doc.parent_path() / (s.doc.stem().string() + "_manifest.tsv");
  run::write_atomic(copy, fmt::format("# copy of {} (run_dir relative to that folder)\n{}", manifest.string(), text));
  say(fmt::format("document {}, manifest {} (copy: {})", s.doc.string(), manifest.string(), copy.string()));
  return 0;
}

}  // namespace brash::study
