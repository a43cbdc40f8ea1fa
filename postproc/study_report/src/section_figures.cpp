// Fig. 4, 5 and 6 analogs for the runs of section (a), next to the document in FIG_DIR (its previous content
// is replaced; sections.hpp): a bar chart of the runs' full-scale resistance with its CI against the paper's
// numbers and our R_CH (Fig. 6; the paper case's runs alone once one is complete), the paper case's histories
// in one plot, and each run's own force history (Fig. 5) and ice views from above and below (Fig. 4, first run
// of each engine), copied from the run directories that brash-post wrote them to.
#include <set>

#include <fmt/format.h>

#include <brash/post/study_report/analysis.hpp>
#include <brash/post/study_report/format.hpp>
#include <brash/post/study_report/plots.hpp>
#include <brash/post/study_report/sections.hpp>

namespace fs = std::filesystem;

namespace brash::post::study_report {
namespace {

struct Link {  // a file (the figure folder's, a run's own plot) as the document links it
  fs::path doc_dir;  // absolute
  // Relative to the document as the paths name it (links are not resolved: a page and the folders beside it may
  // be reached through one).
  std::string operator()(const fs::path& file) const {
    return fs::absolute(file).lexically_normal().lexically_relative(doc_dir).generic_string();
  }
};

// Fig. 6 analog: the paper case's runs beside the paper's numbers; reduced cases (their lambda^3-scaled
// scenes are not the paper's ship in the paper's channel) only when no paper-case run is complete.
std::string bars_figure(const Study& s, const TextTemplate& text, const std::vector<const Run*>& runs,
                        const fs::path& fig_dir, const Link& link) {
  const bool any_paper = any_paper_case(runs);
  std::vector<const Run*> bars;
  for (const Run* r : runs)
    if (!any_paper || r->base_case == kPaperCase) bars.push_back(r);
  const PlotFiles f = plot_files(fig_dir / "paper_bars.png");
  write_paper_bars(f, bars, s.paper, any_paper);
  const std::string err = run_gnuplot(f.gp, f.png);
  if (!err.empty()) return "Fig. 6 analog not produced: " + err + ".\n\n";
  const std::string blue = text.fill(any_paper ? "figures.bars_blue_paper_case" : "figures.bars_blue_reduced");
  return fmt::format("![full-scale resistance vs the paper]({})\n\n{}\n\n", link(f.png),
                     text.fill("figures.bars_caption",
                               {{"image", link(f.png)}, {"data", link(f.dat)}, {"script", link(f.gp)}, {"blue", blue}}));
}

// The paper case's resistance histories in one plot (full scale, 0.5 s bin means of -fx; runs still going
// too, up to where their record is): the shape of each fluid model's history beside the paper's two levels,
// which is what tells a plateau from a rise.
std::string histories_figure(const Study& s, const TextTemplate& text, const fs::path& fig_dir, const Link& link) {
  const PaperHistories h = paper_histories(s, 0.5);
  std::string md;
  for (const auto& [ref, why] : h.unreadable) md += fmt::format("(history of {} not readable: {})\n\n", ref, why);
  if (h.lines.empty()) return md;
  const PlotFiles f = plot_files(fig_dir / "paper_histories.png");
  write_paper_histories(f, h, s.paper);
  const std::string err = run_gnuplot(f.gp, f.png);
  if (!err.empty()) return md + "Paper-case history plot not produced: " + err + ".\n\n";
  return md + fmt::format("![paper-case resistance histories]({})\n\n{}\n\n", link(f.png),
                          text.fill("figures.histories_caption", {{"image", link(f.png)}, {"data", link(f.dat)}}));
}

// The newest ice_views_*.png of a folder, or an empty path.
fs::path latest_ice_views(const fs::path& dir) {
  fs::path views;
  if (!fs::is_directory(dir)) return views;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string n = e.path().filename().string();
    if (n.rfind("ice_views_", 0) == 0 && e.path().extension() == ".png" && (views.empty() || e.path() > views))
      views = e.path();
  }
  return views;
}

std::string paraview_note(const Run& r, const fs::path& full_dir, const TextTemplate& text) {
  const auto open = [&](const fs::path& dir) {
    return " " + text.fill("figures.paraview", {{"particles", show_path(dir / "particles.pvd")},
                                                {"hull", show_path(dir / "hull.pvd")}});
  };
  if (fs::exists(r.run_dir / "particles.pvd")) return open(r.run_dir);
  if (full_dir.empty()) return "";
  // a copy of the run's outputs (brash-study): the ParaView files stay in the full run directory
  return fs::exists(full_dir / "particles.pvd")
             ? open(full_dir)
             : " " + text.fill("figures.paraview_elsewhere", {{"run_dir", show_path(full_dir)}});
}

// Fig. 5 and 4 analogs of one run: its own plots, linked where they are (a copy would double the repository's
// figures); views for the first run of each engine (ENGINES_WITH_VIEWS) and for every paper-case run.
std::string run_figures(const Run& r, const TextTemplate& text, const Link& link,
                        std::set<std::string>& engines_with_views) {
  std::string md = fmt::format("**{}** ({} {}, {}):", r.ref, r.engine, r.model, scale_label(r));
  // the plots are in the run directory, or (a copy without its plots, brash-study's study_runs) in the full run
  // directory the copy came from
  const fs::path full_dir = source_run_dir(r.run_dir);
  const fs::path plot_dir = fs::exists(r.run_dir / "force_history.png") || full_dir.empty() ? r.run_dir : full_dir;
  const fs::path fh = plot_dir / "force_history.png";
  if (fs::exists(fh)) {
    md += fmt::format("\n\n![{} force history]({})\n\n{}", r.ref, link(fh),
                      text.fill("figures.force_history_caption", {{"source", show_path(fh)}}));
  } else {
    md += " " + text.fill("figures.no_force_history", {{"run_dir", show_path(r.run_dir)}});
  }
  const bool want_views = !engines_with_views.count(r.engine) || r.base_case == kPaperCase;
  const fs::path views = want_views ? latest_ice_views(plot_dir) : fs::path();
  if (!views.empty()) {
    engines_with_views.insert(r.engine);
    md += fmt::format("\n\n![{} ice views]({})\n\n{}", r.ref, link(views),
                      text.fill("figures.ice_views_caption", {{"source", show_path(views)}}));
  }
  return md + paraview_note(r, full_dir, text) + "\n\n";
}

}  // namespace

std::string section_figures(const Study& s, const TextTemplate& text, const fs::path& fig_dir,
                            const fs::path& doc_dir) {
  std::string md = "### Figures (analogs of the paper's Fig. 4, 5 and 6)\n\n";
  const auto runs = completed_runs(s, "paper");
  if (runs.empty()) return md + text.fill("figures.none") + "\n\n";
  std::error_code ec;
  fs::remove_all(fig_dir, ec);
  fs::create_directories(fig_dir);
  const fs::path doc_abs = fs::absolute(doc_dir.empty() ? fs::path(".") : doc_dir).lexically_normal();
  const Link link{doc_abs};
  md += bars_figure(s, text, runs, fig_dir, link);
  md += histories_figure(s, text, fig_dir, link);
  std::set<std::string> engines_with_views;
  for (const Run* r : runs) md += run_figures(*r, text, link, engines_with_views);
  return md;
}

}  // namespace brash::post::study_report
