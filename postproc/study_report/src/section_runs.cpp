// (e) Runs and the commands that produced them (sections.hpp).
#include <fmt/format.h>

#include <brash/post/study_report/format.hpp>
#include <brash/post/study_report/sections.hpp>

namespace brash::post::study_report {

std::string section_runs(const Study& s) {
  std::string md =
      "## (e) Runs and the commands that produced them\n\n"
      "\"report files\": the folder holding the run's report.json and report.md, its force history, "
      "case.yaml "
      "and meta.json, from which this document was generated. For a complete run made by a study it is the "
      "copy kept in the repository (the study's own runs beside this document, the paper runs and the "
      "ensembles' summaries in docs/paper_runs); the command's `--out` folder, with the dumps and restarts, "
      "lives on the machine that ran it.\n\n"
      "| run | report files | case | engine | fluid model | status | command |\n"
      "|---|---|---|---|---|---|---|\n";
  for (const Run& r : s.runs)
    md += fmt::format("| {} | `{}` | {} | {} | {} | {} | `{}` |\n", r.ref, show_path(r.run_dir), r.case_name, r.engine,
                      r.model, status_cell(r), md_escape(r.command));
  return md + "\n";
}

}  // namespace brash::post::study_report
