// The study document and its summary (document.hpp).
#include <cmath>

#include <brash/post/study_report/analysis.hpp>
#include <brash/post/study_report/document.hpp>
#include <brash/post/study_report/sections.hpp>

using nlohmann::json;

namespace brash::post::study_report {

std::string render_document(const Study& s, const TextTemplate& text, const DocumentOptions& options) {
  std::string md = section_header(text, options.title, options.manifest_name, options.study_command);
  md += section_failures(s, text);
  md += section_paper(s, text);
  md += section_setup(s, text);
  md += section_gap(s, text);
  if (options.figure_dir) md += section_figures(s, text, *options.figure_dir, options.doc_dir);
  md += section_speed(s, text, options.speed_plot);
  md += section_sensitivity(s, text);
  md += section_paired(s, text);
  md += section_engines(s, text);
  md += section_runs(s, text);
  return md;
}

namespace {

json finite_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

// The three forms of the speed law, the preferred one flagged.
json speed_laws_json(const SpeedFit& f) {
  json laws = json::array();
  for (std::size_t i = 0; i < f.laws.size(); ++i) {
    const auto& l = f.laws[i];
    laws.push_back({{"form", std::string(l.form)}, {"a", finite_or_null(l.a)}, {"a_ci95", finite_or_null(l.a_ci95)},
                    {"b", finite_or_null(l.b)}, {"b_ci95", finite_or_null(l.b_ci95)}, {"n", finite_or_null(l.n)},
                    {"n_ci95", finite_or_null(l.n_ci95)}, {"sse", finite_or_null(l.sse)},
                    {"aicc", finite_or_null(l.aicc)}, {"preferred", i == f.best_law}});
  }
  return laws;
}

}  // namespace

json summary_json(const Study& s) {
  json summary;
  summary["fits"] = json::array();
  for (const SpeedFit& f : speed_fits(s))
    summary["fits"].push_back({{"engine", f.engine}, {"fluid_model", f.model}, {"points", f.points},
                               {"n", finite_or_null(f.n)}, {"n_se", finite_or_null(f.n_se)},
                               {"n_ci95", finite_or_null(f.n_ci95)}, {"a", finite_or_null(f.a)},
                               {"speed_laws", speed_laws_json(f)}});
  summary["runs"] = json::array();
  std::size_t failed = 0, running = 0;
  for (const Run& r : s.runs) {
    failed += r.ok || r.in_progress ? 0 : 1;
    running += r.in_progress ? 1 : 0;
    summary["runs"].push_back({{"ref", r.ref}, {"run_dir", r.run_dir.string()}, {"ok", r.ok},
                               {"in_progress", r.in_progress}, {"problem", r.problem}});
  }
  summary["paired"] = json::array();
  for (const Paired& p : s.paired) {
    failed += p.ok ? 0 : 1;
    summary["paired"].push_back({{"ref", p.ref}, {"summary", p.row.run_dir.string()}, {"ok", p.ok},
                                 {"problem", p.problem}});
  }
  summary["failed"] = failed;
  summary["in_progress"] = running;
  return summary;
}

}  // namespace brash::post::study_report
