// (b) Speed sweep (sections.hpp): R ∝ U^n per engine and fluid model, with its plot.
#include <fmt/format.h>

#include <brash/post/study_report/analysis.hpp>
#include <brash/post/study_report/format.hpp>
#include <brash/post/study_report/plots.hpp>
#include <brash/post/study_report/sections.hpp>

namespace brash::post::study_report {
namespace {

std::string run_table(const Study& s, const std::vector<const Row*>& rows) {
  std::string md =
      "| run | engine | fluid model | U [m/s] | R model [N] ± CI95 | R full [kN] ± CI95 | case / scale | status |\n"
      "|---|---|---|---|---|---|---|---|\n";
  for (const Row* row : rows) {
    const Run& r = s.run_of(*row);
    if (!r.ok)
      md += fmt::format("| {} | {} | {} | {} | — | — | {} | {} |\n", r.ref, r.engine, r.model, row->value,
                        md_escape(row->base_case), status_cell(r));
    else
      md += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} |\n", r.ref, r.engine, r.model, num(r.speed, 3),
                        pm(r.mean_N, r.ci_N), pm(r.full_kN, r.full_ci_kN, 1), scale_label(r), status_cell(r));
  }
  return md;
}

std::string exponent_cell(const SpeedFit& f) {
  if (std::isfinite(f.n_se)) return fmt::format("{:.3f} ± {:.3f} (SE {:.3f})", f.n, f.n_ci95, f.n_se);
  if (std::isfinite(f.n)) return fmt::format("{:.3f} (no SE: {} speeds)", f.n, f.points);
  return fmt::format("n/a ({} usable speed(s))", f.points);
}

std::string fit_table(const std::vector<SpeedFit>& fits) {
  std::string md =
      "\n| engine | fluid model | speeds | n ± CI95 (SE) | a in R = a U^n [N] | runs |\n|---|---|---|---|---|---|\n";
  for (const SpeedFit& f : fits) {
    std::vector<std::string> refs;
    for (const Run* r : f.runs) refs.push_back(r->ref);
    md += fmt::format("| {} | {} | {} | {} | {} | {} |\n", f.engine, f.model, f.points, exponent_cell(f),
                      num(f.a, 3), join(refs, ", "));
  }
  return md + "\n";
}

// Points with CI bars and the fitted lines, log-log (gnuplot pngcairo).
std::string speed_plot(const std::vector<SpeedFit>& fits, const std::filesystem::path& plot_png,
                       const TextTemplate& text) {
  const PlotFiles f = plot_files(plot_png);
  write_speed_sweep(f, fits);
  const std::string err = run_gnuplot(f.gp, f.png);
  if (!err.empty()) return "Plot not produced: " + err + ".\n\n";
  return fmt::format("![speed sweep]({})\n\n{}\n\n", f.png.filename().string(),
                     text.fill("speed.plot_caption", {{"image", f.png.filename().string()},
                                                      {"data", f.dat.filename().string()},
                                                      {"script", f.gp.filename().string()}}));
}

}  // namespace

std::string section_speed(const Study& s, const TextTemplate& text, const std::filesystem::path& plot_png) {
  std::string md = "## (b) Speed sweep: R ∝ U^n\n\n";
  const auto rows = rows_of(s, "speed");
  if (rows.empty()) return md + text.fill("speed.no_runs") + "\n\n";
  md += text.fill("speed.method") + "\n\n";
  const auto fits = speed_fits(s);
  md += run_table(s, rows) + fit_table(fits);
  return plot_png.empty() ? md : md + speed_plot(fits, plot_png, text);
}

}  // namespace brash::post::study_report
