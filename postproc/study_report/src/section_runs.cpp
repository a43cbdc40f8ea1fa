// (e) Runs and the commands that produced them (sections.hpp).
#include <fmt/format.h>

#include <brash/post/study_report/format.hpp>
#include <brash/post/study_report/sections.hpp>

namespace brash::post::study_report {

std::string section_runs(const Study& s, const TextTemplate& text) {
  std::string md =
      "## (e) Runs and the commands that produced them\n\n" + text.fill("runs.intro") +
      "\n\n"
      "| run | report files | case | engine | fluid model | status | command |\n"
      "|---|---|---|---|---|---|---|\n";
  for (const Run& r : s.runs)
    md += fmt::format("| {} | `{}` | {} | {} | {} | {} | `{}` |\n", r.ref, show_path(r.run_dir), r.case_name, r.engine,
                      r.model, status_cell(r), md_escape(r.command));
  return md + "\n";
}

}  // namespace brash::post::study_report
