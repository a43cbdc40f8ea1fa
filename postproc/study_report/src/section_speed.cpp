// (b) Speed sweep (sections.hpp): R ∝ U^n per engine and fluid model, the speed law in three forms, with its plot.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

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

// A parameter with its 95 % interval, "—" where the form has none, the value alone where it is not estimable.
std::string param_cell(double v, double ci) {
  if (!std::isfinite(v)) return "—";
  return std::isfinite(ci) ? pm(v, ci, 3) : num(v, 3);
}

std::string law_table(const std::vector<SpeedFit>& fits) {
  std::string md =
      "| engine | fluid model | form | a ± CI95 | b ± CI95 | n ± CI95 | SSE [N²] | AICc | residuals R - fit [N] |\n"
      "|---|---|---|---|---|---|---|---|---|\n";
  for (const SpeedFit& f : fits)
    for (std::size_t i = 0; i < f.laws.size(); ++i) {
      const auto& l = f.laws[i];
      std::vector<std::string> res;
      for (double e : l.residuals) res.push_back(fmt::format("{:+.2f}", e));
      const std::string form = i == f.best_law ? fmt::format("**R = {}** (lowest AICc)", l.form)
                                               : fmt::format("R = {}", l.form);
      md += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", f.engine, f.model, form,
                        param_cell(l.a, l.a_ci95), param_cell(l.b, l.b_ci95),
                        std::isfinite(l.b) && l.params == 2 ? num(l.n, 0) + " (fixed)" : param_cell(l.n, l.n_ci95),
                        num(l.sse, 3), std::isfinite(l.aicc) ? num(l.aicc, 2) : "— (too few speeds)",
                        res.empty() ? "—" : join(res, ", "));
    }
  return md + "\n";
}

// What the preferred form says about the exponent: U R'(U) / R at the lowest and the highest speed.
std::string law_reading(const std::vector<SpeedFit>& fits, const TextTemplate& text) {
  std::string md;
  for (const SpeedFit& f : fits) {
    if (f.best_law >= f.laws.size() || f.runs.empty()) continue;
    const auto& l = f.laws[f.best_law];
    double u_lo = f.runs.front()->speed, u_hi = u_lo;
    for (const Run* r : f.runs) u_lo = std::min(u_lo, r->speed), u_hi = std::max(u_hi, r->speed);
    const auto local_n = [&](double u) {
      return std::isfinite(l.b) ? l.n * l.b * std::pow(u, l.n) / l.at(u) : l.n;
    };
    md += text.fill(std::isfinite(l.b) ? "speed.law_with_constant" : "speed.law_power",
                    {{"engine", f.engine}, {"model", f.model}, {"form", std::string(l.form)},
                     {"a", num(l.a, 2)}, {"share", num(100 * l.a / l.at(u_hi), 0)}, {"u_low", num(u_lo, 3)},
                     {"u_high", num(u_hi, 3)}, {"n_low", num(local_n(u_lo), 2)}, {"n_high", num(local_n(u_hi), 2)}}) +
          "\n\n";
  }
  return md;
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
  md += run_table(s, rows) + fit_table(fits) + text.fill("speed.laws") + "\n\n" + law_table(fits) +
        law_reading(fits, text);
  return plot_png.empty() ? md : md + speed_plot(fits, plot_png, text);
}

}  // namespace brash::post::study_report
