// (a) Paper comparison (sections.hpp): our runs of group paper beside the paper's numbers.
#include <cmath>

#include <fmt/format.h>

#include <brash/post/study_report/analysis.hpp>
#include <brash/post/study_report/format.hpp>
#include <brash/post/study_report/sections.hpp>

namespace brash::post::study_report {
namespace {

std::string paper_rch_cell(const brash::ReferenceSpec& paper) {
  return paper.fsicr_R_CH_kN ? num(*paper.fsicr_R_CH_kN, 0) : "n/a";
}

// The paper's numbers as the paper case declares them, for the text's placeholders.
TextValues paper_values(const brash::ReferenceSpec& paper) {
  const double paper_am = paper_full_kN(paper, "added_mass"), paper_drag = paper_full_kN(paper, "drag");
  return {{"paper_added_mass_kN", fmt::format("{:.0f}", paper_am)},
          {"paper_drag_kN", fmt::format("{:.0f}", paper_drag)},
          {"paper_difference", fmt::format("{:+.1f}", 100 * (paper_am / paper_drag - 1))},
          {"paper_R_CH_kN", paper_rch_cell(paper)},
          {"paper_ratio_added_mass", paper_ratio_cell(paper, "added_mass")},
          {"paper_ratio_drag", paper_ratio_cell(paper, "drag")}};
}

std::string comparison_table(const Study& s, const std::vector<const Row*>& rows) {
  std::string md =
      "| run | case / scale | engine | fluid model | R model [N] ± CI95 | R full [kN] ± CI95 | paper R full [kN] | "
      "R_CH ours [kN] | paper R_CH [kN] | ratio ours | paper ratio | status |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  const std::string paper_rch = paper_rch_cell(s.paper);
  for (const Row* row : rows) {
    const Run& r = s.run_of(*row);
    const double paper_kN = paper_full_kN(s.paper, r.model);
    const std::string paper_R = std::isfinite(paper_kN) ? num(paper_kN, 0) : "n/a";
    if (!r.ok) {
      md += fmt::format("| {} | {} | {} | {} | — | — | {} | — | {} | — | {} | {} |\n", r.ref,
                        md_escape(row->label.empty() ? row->base_case : row->label), r.engine, r.model, paper_R,
                        paper_rch, paper_ratio_cell(s.paper, r.model), status_cell(r));
      continue;
    }
    md += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", r.ref, scale_label(r),
                      r.engine, r.model, pm(r.mean_N, r.ci_N), pm(r.full_kN, r.full_ci_kN, 1), paper_R,
                      optnum(r.rch_kN, 0), paper_rch, optnum(r.ratio), paper_ratio_cell(s.paper, r.model),
                      status_cell(r));
  }
  return md;
}

std::string hull_parameters(const std::vector<const Run*>& completed, const TextTemplate& text) {
  std::string md =
      "\n" + text.fill("paper.hull_parameters") +
      "\n\n| run | L [m] | B [m] | T [m] | alpha [deg] | phi2 [deg] | A_wf [m²] |\n|---|---|---|---|---|---|---|\n";
  for (const Run* r : completed)
    md += fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", r->ref, optnum(r->lpp), optnum(r->beam),
                      optnum(r->draft), optnum(r->alpha, 1), optnum(r->phi2, 1), optnum(r->awf, 0));
  return md;
}

// Added mass vs drag, per engine and base case: our added_mass (Eq. 2 replacing Eq. 1) and our both (Eq. 2
// added to Eq. 1), the two readings of the paper's added-mass model, each against drag.
std::string added_mass_vs_drag_table(const Study& s, const TextTemplate& text) {
  std::string md =
      "\n" + text.fill("paper.added_mass_vs_drag", paper_values(s.paper)) +
      "\n\n| engine | case | added-mass model | R added mass [N] | R drag [N] | difference | CI95 of the "
      "difference |\n"
      "|---|---|---|---|---|---|---|\n";
  const auto pairs = added_mass_vs_drag(s);
  for (const auto& c : pairs)
    md += fmt::format("| {} | {} | {} | {} ({}) | {} ({}) | {:+.1f} % | ± {:.1f} % |\n", c.engine, c.base_case,
                      c.added_model, pm(c.added->mean_N, c.added->ci_N), c.added->ref,
                      pm(c.drag->mean_N, c.drag->ci_N), c.drag->ref, c.difference_pct, c.ci_pct);
  if (pairs.empty()) md += "| — | — | — | — | — | no completed added-mass + drag pair | — |\n";
  return md + "\n";
}

}  // namespace

std::string section_paper(const Study& s, const TextTemplate& text) {
  std::string md = "## (a) Paper comparison\n\n";
  const auto rows = rows_of(s, "paper");
  if (rows.empty()) return md + text.fill("paper.no_runs") + "\n\n";
  const auto completed = completed_runs(s, "paper");
  const TextValues paper = paper_values(s.paper);
  if (!any_paper_case(completed)) md += text.fill("paper.no_paper_case", paper) + "\n\n";
  return md + text.fill("paper.values", paper) + "\n\n" + comparison_table(s, rows) +
         hull_parameters(completed, text) + added_mass_vs_drag_table(s, text);
}

}  // namespace brash::post::study_report
