// (d) Engines (sections.hpp): each engine's run against the LIGGGHTS run of the same case and fluid model, and
// an unfinished run of another engine binned beside it for as far as it has got.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include <brash/post/study_report/analysis.hpp>
#include <brash/post/study_report/format.hpp>
#include <brash/post/study_report/sections.hpp>

namespace brash::post::study_report {
namespace {

std::string vs_liggghts_cell(const Run& r, const std::vector<const Run*>& runs) {
  if (r.engine == "liggghts") return "reference";
  const auto v = vs_liggghts(r, runs);
  return v ? fmt::format("{:+.1f} % ± {:.1f} % ({})", v->rel_pct, v->ci_pct, v->liggghts->ref) : "—";
}

std::string engine_table(const std::vector<const Run*>& runs) {
  std::string md =
      "| run | case | fluid model | engine | R model [N] ± CI95 | R full [kN] ± CI95 | vs LIGGGHTS ± CI95 | "
      "wall time [s] | particle-steps/s | status |\n"
      "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Run* r : runs) {
    if (!r->ok) {
      md += fmt::format("| {} | {} | {} | {} | — | — | — | — | — | {} |\n", r->ref, r->base_case, r->model, r->engine,
                        status_cell(*r));
      continue;
    }
    md += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", r->ref, r->base_case, r->model,
                      r->engine, pm(r->mean_N, r->ci_N), pm(r->full_kN, r->full_ci_kN, 1), vs_liggghts_cell(*r, runs),
                      num(r->wall_s, 0), r->wall_s > 0 ? fmt::format("{:.3g}", r->psteps / r->wall_s) : "n/a",
                      status_cell(*r));
  }
  return md + "\n";
}

std::string so_far_table(const EngineSoFar& e, const TextTemplate& text) {
  const Run &r = *e.run, &l = *e.liggghts;
  if (!e.error.empty()) return fmt::format("(the record of {} or {} is not readable: {})\n\n", r.ref, l.ref, e.error);
  std::string md = text.fill("engines.so_far", {{"run", r.ref},
                                                {"engine", r.engine},
                                                {"model", r.model},
                                                {"case", r.base_case},
                                                {"t_reached", fmt::format("{:.2f}", e.t_reached_s)},
                                                {"liggghts_run", l.ref},
                                                {"liggghts_model", l.model},
                                                {"bin", fmt::format("{}", e.bin_s)}});
  md += fmt::format("\n\n| t [s] | {} liggghts [N] | {} {} [N] | {} / {} - 1 |\n|---|---|---|---|\n", l.ref, r.ref,
                    r.engine, r.ref, l.ref);
  for (std::size_t b = 0; b < e.run_N.size(); ++b) {
    const double mine = e.run_N[b], ref = e.liggghts_N[b];
    const bool both = std::isfinite(mine) && std::isfinite(ref) && ref != 0.0;
    md += fmt::format("| {:g}-{:g} | {} | {} | {} |\n", b * e.bin_s, (b + 1) * e.bin_s, num(ref, 3), num(mine, 3),
                      both ? fmt::format("{:+.1f} %", 100.0 * (mine / ref - 1.0)) : "—");
  }
  return md + "\n";
}

}  // namespace

std::string section_engines(const Study& s, const TextTemplate& text) {
  std::string md = "## (d) Engines\n\n";
  const auto runs = engine_runs(s);
  const auto engines = engines_with_results(s);
  if (engines.size() < 2)
    md += text.fill("engines.too_few", {{"count", std::to_string(engines.size())},
                                        {"engines", engines.empty() ? std::string("none") : *engines.begin()}}) +
          "\n\n";
  const bool failed = std::any_of(runs.begin(), runs.end(), [](const Run* r) { return !r->ok; });
  if (engines.size() < 2 && !failed) return md;
  md += engine_table(runs);
  for (const auto& e : engines_so_far(runs)) md += so_far_table(e, text);
  return md;
}

}  // namespace brash::post::study_report
