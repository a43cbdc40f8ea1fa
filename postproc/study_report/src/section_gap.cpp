// How far each completed paper-case run is from the paper's number, beside every candidate change the study
// measured (section (c)'s groups and the paired ensembles): a candidate can close the gap only with the gap's
// sign and size (sections.hpp).
#include <fmt/format.h>

#include <brash/post/study_report/analysis.hpp>
#include <brash/post/study_report/format.hpp>
#include <brash/post/study_report/sections.hpp>

namespace brash::post::study_report {
namespace {

std::string candidate_rows(const Study& s) {
  std::string md;
  for (const auto& c : candidate_changes(s))
    md += fmt::format("| {}: {} | {}, {}, {} | {:+.1f} % ± {:.1f} %{} | {} vs {} |\n", c.param,
                      md_escape(c.row->value), c.row->base_case, c.run->engine, c.run->model, 100.0 * c.rel,
                      100.0 * c.ci, c.resolved() ? "" : " (not resolved)", c.run->ref, c.baseline->ref);
  for (const Paired& p : s.paired) {
    if (!p.ok) continue;
    md += fmt::format("| {}: {} | {}, {} paired packings, {} | {}{} | {} |\n", p.row.param, md_escape(p.row.value),
                      p.case_name, p.pairs, md_escape(p.row.label.empty() ? side_model(p.side_b) : p.row.label),
                      effect_cell(p.effect, 1), p.resolved() ? "" : " (not resolved)", p.ref);
  }
  return md.empty() ? "| — | — | no completed sensitivity run with a baseline | — |\n" : md;
}

}  // namespace

std::string section_gap(const Study& s, const TextTemplate& text) {
  std::string gaps;
  for (const auto& g : gaps_to_paper(s))
    gaps += text.fill("gap.run", {{"run", g.run->ref},
                                  {"engine", g.run->engine},
                                  {"model", g.run->model},
                                  {"ours_kN", pm(g.run->full_kN, g.run->full_ci_kN, 1)},
                                  {"paper_kN", fmt::format("{:.0f}", g.paper_kN)},
                                  {"gap", fmt::format("{:+.1f}", g.gap_pct)},
                                  {"gap_ci", fmt::format("{:.1f}", g.ci_pct)}}) +
            "\n";
  if (gaps.empty()) return "";  // nothing to explain yet
  return "### The gap to the paper, and the candidates the study measured\n\n" + gaps + "\n" +
         text.fill("gap.candidates") +
         "\n\n"
         "| candidate (parameter: value) | case, engine, fluid model | change vs baseline ± CI95 | runs |\n"
         "|---|---|---|---|\n" +
         candidate_rows(s) + "\n";
}

}  // namespace brash::post::study_report
