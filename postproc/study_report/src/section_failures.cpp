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

std::string missing_ensembles(const Study& s, const TextTemplate& text) {
  std::vector<const Paired*> missing;
  for (const Paired& p : s.paired)
    if (!p.ok) missing.push_back(&p);
  if (missing.empty()) return "";
  std::string md = text.fill("failures.missing_ensembles", {{"count", std::to_string(missing.size())}}) + "\n\n";
  for (const Paired* p : missing) md += fmt::format("- {}: {}\n", p->ref, md_escape(p->problem));
  return md + "\n";
}

}  // namespace

std::string section_failures(const Study& s, const TextTemplate& text) {
  std::vector<const Run*> bad, running;
  for (const Run& r : s.runs) {
    if (r.in_progress)
      running.push_back(&r);
    else if (!r.ok)
      bad.push_back(&r);
  }
  std::string md;
  if (!running.empty())
    md += "## Runs in progress\n\n" + text.fill("failures.in_progress", {{"count", std::to_string(running.size())}}) +
          "\n\n" + run_table(running, "state");
  md += "## Runs that failed or are missing\n\n" + missing_ensembles(s, text);
  if (bad.empty()) return md + text.fill(running.empty() ? "failures.none" : "failures.none_other") + "\n\n";
  md += text.fill("failures.unusable",
                  {{"count", std::to_string(bad.size())}, {"total", std::to_string(s.runs.size())}}) +
        "\n\n";
  return md + run_table(bad, "reason");
}

}  // namespace brash::post::study_report
