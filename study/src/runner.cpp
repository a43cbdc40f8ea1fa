// The variants, the speed sweep and the ensembles of a planned study.
#include "brash/study/runner.hpp"

#include <fmt/chrono.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include "brash/study/process.hpp"
#include "brash/study/run_outputs.hpp"

namespace fs = std::filesystem;

namespace brash::study {

namespace {

std::string read_first_line(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  return line;
}

std::string clock_time() {
  const std::time_t now = std::time(nullptr);
  return fmt::format("{:%H:%M:%S}", fmt::localtime(now));
}

fs::path log_of(const Settings& s, const std::string& id) { return s.work / "logs" / (id + ".log"); }

// Derives a case folder the first time a study needs it; returns "" or why it failed.
std::string derive_once(const CaseStep& step, std::map<std::string, std::string>& derived) {
  if (const auto it = derived.find(step.dir.string()); it != derived.end()) return it->second;
  std::string failure;
  try {
    (void)write_derived_case(step.base, step.overrides, step.dir, true);
  } catch (const std::exception& e) {
    failure = fmt::format("case generation failed: {}", e.what());
  }
  derived[step.dir.string()] = failure;
  return failure;
}

void run_variant(const PlannedRun& r, const std::string& progress, const std::string& case_failure, const Settings& s,
                 Listings& out) {
  Listing& l = out[r.id];
  l.command = r.command_text;
  l.run_dir = r.out;
  if (!case_failure.empty()) {
    say(fmt::format("{} {}: {}", progress, r.id, case_failure));
    l.exit_text = case_failure;
    return;
  }
  if (keeps_complete_run(r)) {
    say(fmt::format("{} {}: complete report of the same command exists, not re-run", progress, r.id));
    l.exit_text = "0";
    l.has_report = true;
    return;
  }
  fs::remove_all(r.out);
  fs::remove(log_of(s, r.id));
  say(fmt::format("{} {}: {} {} {} ({})", progress, r.id, to_string(r.engine), r.model, r.case_step.name, clock_time()));
  const auto t0 = std::chrono::steady_clock::now();
  const int rc = run_steps(r.steps, s, log_of(s, r.id));
  if (fs::is_directory(r.out)) std::ofstream(r.out / ".study_cmd") << r.command_text << "\n";
  const auto seconds = std::chrono::duration_cast<std::chrono::seconds>(std::chrono::steady_clock::now() - t0).count();
  say(fmt::format("{} {}: exit {} after {} s (log {})", progress, r.id, rc, seconds, log_of(s, r.id).string()));
  l.exit_text = std::to_string(rc);
  l.has_report = fs::exists(r.out / "report.json");
}

// The summary rank_ensemble.sh wrote in `dir` for these two sides (ensemble-*.json), if any.
std::optional<fs::path> ensemble_summary(const fs::path& dir, const Ensemble& e) {
  if (!fs::is_directory(dir)) return std::nullopt;
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.starts_with("ensemble-") && name.ends_with(".json")) files.push_back(entry.path());
  }
  std::ranges::sort(files);
  for (const auto& f : files) {
    std::ifstream in(f);
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    if (j.is_object() && j.value("side_a", "") == e.side_a && j.value("side_b", "") == e.side_b) return f;
  }
  return std::nullopt;
}

void run_ensemble(const PlannedEnsemble& e, const Settings& s, std::map<std::string, std::string>& derived,
                  Listings& out) {
  const std::string& id = e.def->id;
  if (s.run_ensembles) {
    const std::string failure =
        e.case_step && !fs::exists(e.case_step->dir / "case.yaml") ? derive_once(*e.case_step, derived) : "";
    if (failure.empty()) {
      say(fmt::format("{}: paired ensemble, {} seeds ({})", id, e.def->seeds, clock_time()));
      fs::remove(log_of(s, id));
      if (const int rc = run_process(e.command, s, log_of(s, id)); rc != 0)
        say(fmt::format("{}: exit {} (log {})", id, rc, log_of(s, id).string()));
    } else {
      say(fmt::format("{}: {}", id, failure));
    }
  }
  const fs::path archive = s.archive_dir / "ensembles" / e.dir.filename();
  std::optional<fs::path> summary = ensemble_summary(e.dir, *e.def);
  if (summary) {
    fs::create_directories(archive);
    fs::copy_file(*summary, archive / summary->filename(), fs::copy_options::overwrite_existing);
    summary = archive / summary->filename();
  } else {
    summary = ensemble_summary(archive, *e.def);
  }
  if (summary) out[id] = Listing{e.command_text, "0", *summary, true};
}

}  // namespace

void say(const std::string& line) { std::cerr << "brash-study: " << line << "\n" << std::flush; }

bool keeps_complete_run(const PlannedRun& r) {
  return report_complete(r.out) && read_first_line(r.out / ".study_cmd") == r.command_text;
}

void run_variants(const Plan& plan, const Settings& s, Listings& out) {
  std::map<std::string, std::string> derived;
  for (const auto& why : plan.left_out) say("left out: " + why);
  for (std::size_t i = 0; i < plan.runs.size(); ++i) {
    const PlannedRun& r = plan.runs[i];
    const std::string failure = derive_once(r.case_step, derived);
    run_variant(r, fmt::format("[{}/{}]", i + 1, plan.runs.size()), failure, s, out);
  }
}

void run_speed_sweep(const Study& study, const Plan& plan, const Settings& s, Listings& out) {
  if (plan.sweep.empty()) return;
  say(fmt::format("speed sweep on cases/jbc_quick ({})", clock_time()));
  const fs::path log = s.work / "logs" / "quick-speed.log";
  fs::remove(log);
  if (run_steps(plan.sweep, s, log) != 0) say("speed sweep: see " + log.string());
  for (const auto& u : study.speed_sweep->speeds)
    for (const auto& m : study.speed_sweep->models) {
      const std::string id = fmt::format("quick_u{}_{}", u, m);
      const fs::path run_dir = s.work / "runs" / id, cmd = s.work / "runs" / (id + ".cmd");
      const bool complete = report_complete(run_dir);
      out[id] = Listing{fs::exists(cmd) ? without_repo(read_first_line(cmd), s) : "not run",
                        complete ? "0" : fmt::format("no complete report (see {}.log)", run_dir.string()), run_dir,
                        fs::exists(run_dir / "report.json")};
    }
}

void run_ensembles(const Plan& plan, const Settings& s, Listings& out) {
  std::map<std::string, std::string> derived;
  for (const auto& e : plan.ensembles) run_ensemble(e, s, derived, out);
}

}  // namespace brash::study
