// (c) Paired-seed ensembles (sections.hpp): each ensemble's change with its CI, and its command.
#include <fmt/format.h>

#include <brash/post/study_report/format.hpp>
#include <brash/post/study_report/sections.hpp>

namespace brash::post::study_report {

// The paired-seed ensembles: one run per value cannot resolve a change smaller than the run-to-run scatter of
// a chaotic contact scene (~10-20 % CI on the reduced cases); the same packings run both ways can.
std::string section_paired(const Study& s, const TextTemplate& text) {
  if (s.paired.empty()) return "";
  std::string md =
      "### Paired-seed ensembles\n\n" + text.fill("paired.intro") +
      "\n\n"
      "| ensemble | change (parameter: value) | what | case | side A → side B | pairs | mean A / B [N] | "
      "(B − A) / A ± CI95 | resolved |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const Paired& p : s.paired) {
    if (!p.ok) {
      md += fmt::format("| {} | {}: {} | {} | {} | — | — | — | — | **MISSING: {}** |\n", p.ref, p.row.param,
                        md_escape(p.row.value), md_escape(p.row.label), p.row.base_case, md_escape(p.problem));
      continue;
    }
    md += fmt::format("| {} | {}: {} | {} | {} | `{}` → `{}` | {} | {:.2f} / {:.2f} | {} | {}{} |\n", p.ref,
                      p.row.param, md_escape(p.row.value), md_escape(p.row.label), p.case_name, md_escape(p.side_a),
                      md_escape(p.side_b), p.pairs, p.effect.mean_a_N, p.effect.mean_b_N, effect_cell(p.effect),
                      p.resolved() ? "yes" : "no", p.effect.has_ci() ? "" : " (as recorded)");
  }
  md += "\n" + text.fill("paired.commands") + "\n\n";
  for (const Paired& p : s.paired)
    md += fmt::format("- {} (`{}`): `{}`\n", p.ref, show_path(p.row.run_dir), md_escape(p.row.command));
  return md + "\n";
}

}  // namespace brash::post::study_report
