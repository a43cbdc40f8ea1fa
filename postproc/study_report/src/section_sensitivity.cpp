// (c) Sensitivities (sections.hpp): each group's runs against the group's baseline of the same engine and
// fluid model.
#include <algorithm>

#include <fmt/format.h>

#include <brash/post/study_report/analysis.hpp>
#include <brash/post/study_report/format.hpp>
#include <brash/post/study_report/sections.hpp>

namespace brash::post::study_report {
namespace {

std::string group_row(const Study& s, const Row& row, const Baselines& base) {
  const Run& r = s.run_of(row);
  const std::string value = row.value + (row.baseline ? " (baseline)" : "");
  if (!r.ok)
    return fmt::format("| {} | {} | {} | {} | — | — | — | — | {} |\n", r.ref, md_escape(value), r.engine, r.model,
                       status_cell(r));
  std::string d = "no baseline", dci = "—";
  if (row.baseline) {
    d = "—";
  } else if (const Run* b = base.of(r)) {
    const ChangeVsBaseline c = change_vs_baseline(r, *b);
    d = fmt::format("{:+.2f} ({:+.1f} %)", c.delta_N, c.delta_pct);
    dci = c.delta_over_ci ? fmt::format("{:+.2f}", *c.delta_over_ci) : "n/a";
  }
  return fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", r.ref, md_escape(value), r.engine, r.model,
                     pm(r.mean_N, r.ci_N), pm(r.full_kN, r.full_ci_kN, 1), d, dci, status_cell(r));
}

std::string group_table(const Study& s, const std::string& group, const TextTemplate& text) {
  const Baselines base = baselines_of(s, group);
  std::string md = fmt::format(
      "### {} (parameter `{}`)\n\n{}\n\n"
      "| run | value | engine | fluid model | R model [N] ± CI95 | R full [kN] ± CI95 | Δ vs baseline [N] "
      "| Δ / CI | status |\n"
      "|---|---|---|---|---|---|---|---|---|\n",
      group, base.param.empty() ? "?" : base.param,
      text.fill(base.varies_model ? "sensitivity.intro_model_group" : "sensitivity.intro"));
  for (const Row* row : rows_of(s, group)) md += group_row(s, *row, base);
  return md + "\n";
}

}  // namespace

std::string section_sensitivity(const Study& s, const TextTemplate& text) {
  std::string md = "## (c) Sensitivities\n\n";
  const auto groups = sensitivity_groups(s);
  for (const char* expected : {"ca", "friction_ice", "density_ice"})
    if (std::find(groups.begin(), groups.end(), expected) == groups.end())
      md += text.fill("sensitivity.group_missing", {{"group", expected}}) + "\n\n";
  for (const auto& g : groups) md += group_table(s, g, text);
  return md;
}

}  // namespace brash::post::study_report
