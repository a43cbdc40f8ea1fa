// The paper runs: days each, in the paper dir, shared by every study; archived as they go.
#include <fmt/chrono.h>
#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <ctime>

#include "brash/study/process.hpp"
#include "brash/study/run_outputs.hpp"
#include "brash/study/runner.hpp"

namespace fs = std::filesystem;

namespace brash::study {

namespace {

// A complete run's outputs to the archive; a started one's record so far when it reaches further than the copy.
void archive_progress(const PlannedPaperRun& p, const Settings& s) {
  const std::string& id = p.def->id;
  try {
    if (report_complete(p.out)) {
      if (archive_complete_run(p.out, s.archive_dir)) say(fmt::format("{}: archived {}'s study outputs", id, p.out.string()));
    } else if (fs::exists(p.out / "meta.json") && !report_complete(s.archive_dir / p.def->out)) {
      if (archive_partial_run(p.out, s.archive_dir))
        say(fmt::format("{}: archived {}'s partial record (model time {:.2f} s)", id, p.out.string(),
                        model_time_reached(s.archive_dir / p.def->out)));
    }
  } catch (const std::exception& e) {
    say(fmt::format("{}: cannot archive {} in {}: {}", id, p.out.string(), s.archive_dir.string(), e.what()));
  }
}

// run.duration_s of the case a run wrote, as written ("?" when it cannot be read).
std::string duration_of(const fs::path& run_dir) {
  try {
    const YAML::Node d = YAML::LoadFile((run_dir / "case.yaml").string())["run"]["duration_s"];
    return d.IsScalar() ? d.Scalar() : "?";
  } catch (const std::exception&) {
    return "?";
  }
}

// The exit-code cell of a started, unfinished run listed from `listed`.
std::string in_progress_text(const PlannedPaperRun& p, const fs::path& listed, bool busy) {
  const double t = model_time_reached(listed);
  if (listed != p.out)
    return fmt::format("in progress, stopped: model time {:.2f} s of {} s reached (its record so far is kept here; the "
                       "run resumes from its own restart files): STUDY=full starts it again",
                       t, duration_of(listed));
  const std::time_t now = std::time(nullptr);
  return fmt::format("in progress: model time {:.2f} s of {} s reached ({:%Y-%m-%dT%H:%MZ}); {}", t,
                     duration_of(listed), fmt::gmtime(now),
                     busy ? "running then on the machine that made this document" : "STUDY=full resumes it");
}

// Starts the run from its case (derived when missing), or resumes it from its restart files.
std::string start_or_resume(const PlannedPaperRun& p, const Settings& s) {
  const std::string& id = p.def->id;
  if (!fs::exists(p.case_step.dir / "case.yaml")) {
    try {
      (void)write_derived_case(p.case_step.base, p.case_step.overrides, p.case_step.dir, true);
    } catch (const std::exception& e) {
      say(fmt::format("{}: cannot make {}: {}", id, p.case_step.dir.string(), e.what()));
      return fmt::format("case generation failed: {}", e.what());
    }
  }
  const bool resume = fs::exists(p.out / "meta.json");
  say(resume ? fmt::format("{}: resuming {}", id, p.out.string())
             : fmt::format("{}: {} {} paper case, hours to days", id, to_string(p.def->engine), p.def->model));
  return std::to_string(run_steps(resume ? p.resume : p.start, s, s.work / "logs" / (id + ".log")));
}

}  // namespace

void run_paper_runs(const Plan& plan, const Settings& s, Listings& out) {
  bool another_busy = false;  // a paper run another process works on: no other starts beside it
  for (const PlannedPaperRun& p : plan.paper_runs) {
    archive_progress(p, s);
    const fs::path listed = paper_listed_dir(p.out, s.archive_dir);
    const bool busy = held_elsewhere(p.out);
    Listing l{p.command_text, "", listed, fs::exists(listed / "report.json")};
    if (report_complete(listed)) {
      l.exit_text = "0";
    } else if (!s.run_paper || busy || another_busy) {
      if (!fs::exists(listed / "meta.json")) continue;  // never started: not listed
      if (busy) {
        another_busy = true;
        say(fmt::format("{}: {} is being run by another process: listed, not resumed", p.def->id, p.out.string()));
      }
      l.exit_text = in_progress_text(p, listed, busy);
    } else {
      l.exit_text = start_or_resume(p, s);
    }
    out[p.def->id] = l;
  }
}

}  // namespace brash::study
