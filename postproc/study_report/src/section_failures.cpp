// Runs in progress and runs or ensembles without a usable result (sections.hpp): listed, never dropped.
#include <fmt/format.h>

#include <brash/post/study_report/format.hpp>
#include <brash/post/study_report/sections.hpp>

namespace brash::post::study_report {
namespace {

// One row per run: its id, its folder and CELL (its state or reason).
std::string run_table(const std::vector<const Run*>& runs, const std::string& cell_head) {
  std::string md = fmt::format("| run | run dir | {} |\n|---|---|---|\n", cell_head);
  for (const Run* r : runs) md += fmt::format("| {} | `{}` | {} |\n", r->ref, show_path(r->run_dir), md_escape(r->problem));
  return md + "\n";
}

std::string missing_ensembles(const Study& s) {
  std::vector<const Paired*> missing;
  for (const Paired& p : s.paired)
    if (!p.ok) missing.push_back(&p);
  if (missing.empty()) return "";
  std::string md = fmt::format("**{} paired ensemble(s) have no usable summary** (kept in section (c)):\n\n",
                               missing.size());
  for (const Paired* p : missing) md += fmt::format("- {}: {}\n", p->ref, md_escape(p->problem));
  return md + "\n";
}

}  // namespace

std::string section_failures(const Study& s) {
  std::vector<const Run*> bad, running;
  for (const Run& r : s.runs) {
    if (r.in_progress)
      running.push_back(&r);
    else if (!r.ok)
      bad.push_back(&r);
  }
  std::string md;
  if (!running.empty())
    md += fmt::format(
              "## Runs in progress\n\n{} run(s) have no result yet: still running (resumed in pieces), or "
              "stopped part-way with the machine that ran them (the state says which, and how far each got); "
              "their rows below have no result.\n\n",
              running.size()) +
          run_table(running, "state");
  md += "## Runs that failed or are missing\n\n" + missing_ensembles(s);
  if (bad.empty())
    return md + (running.empty() ? "None: every run listed in the manifest has a complete report.json.\n\n"
                                 : "None: every other run listed in the manifest has a complete report.json.\n\n");
  md += fmt::format("**{} of {} run(s) have no usable result.** They are kept in every table below with "
                    "their reason, never dropped.\n\n",
                    bad.size(), s.runs.size());
  return md + run_table(bad, "reason");
}

}  // namespace brash::post::study_report
