// gnuplot data and scripts of the study document's figures (plots.hpp).
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>

#include <fmt/format.h>

#include <brash/post/study_report/plots.hpp>

namespace fs = std::filesystem;

namespace brash::post::study_report {

std::string run_gnuplot(const fs::path& gp, const fs::path& png) {
  const fs::path dir = fs::absolute(gp).parent_path();
  const int rc = std::system(fmt::format("cd '{}' && gnuplot '{}' 2>'{}.err'", dir.string(), gp.filename().string(),
                                         gp.filename().string())
                                 .c_str());
  if (rc == 0 && fs::exists(png)) {
    std::error_code ec;
    if (fs::file_size(gp.string() + ".err", ec) == 0 && !ec) fs::remove(gp.string() + ".err", ec);
    return "";
  }
  return fmt::format("`gnuplot {}` failed (exit {}); see `{}.err`", gp.string(), rc, gp.string());
}

PlotFiles plot_files(const fs::path& png) {
  return {fs::path(png).replace_extension(".dat"), fs::path(png).replace_extension(".gp"), png};
}

void write_paper_bars(const PlotFiles& f, const std::vector<const Run*>& bars, const brash::ReferenceSpec& paper,
                      bool paper_case_runs) {
  constexpr long kOurs = 0x5a9fd4, kRule = 0xcd6155, kPaper = 0xc8c8c8;
  std::ofstream d(f.dat);
  d << "# label  full-scale resistance [kN]  CI95 [kN]  colour\n";
  for (const Run* r : bars)
    d << fmt::format("\"{} {} {}\" {} {} {}\n", r->ref, r->engine, r->model, r->full_kN, r->full_ci_kN, kOurs);
  d << fmt::format("\"paper added mass\" {} 0 {}\n\"paper drag\" {} 0 {}\n", paper_full_kN(paper, "added_mass"),
                   kPaper, paper_full_kN(paper, "drag"), kPaper);
  std::set<long> rch;
  for (const Run* r : bars)
    if (r->rch_kN && rch.insert(std::lround(*r->rch_kN)).second)
      d << fmt::format("\"FSICR R_CH ours ({})\" {} 0 {}\n", r->ref, *r->rch_kN, kRule);
  if (paper.fsicr_R_CH_kN) d << fmt::format("\"paper FSICR R_CH\" {} 0 {}\n", *paper.fsicr_R_CH_kN, kPaper);
  std::ofstream p(f.gp);
  p << "set terminal pngcairo size 1100,650\nset output '" << f.png.filename().string() << "'\n"
    << "set termoption noenhanced\nset style fill solid 0.85 border -1\nset boxwidth 0.6\nset grid ytics\n"
    << "set yrange [0:*]\nset xtics rotate by -30 scale 0\nset bmargin 9\nset rmargin 14\n"
    << "set ylabel 'full-scale resistance [kN] (model x lambda^3)'\n"
    << "set title '"
    << (paper_case_runs ? "Full-scale resistance, our paper-case runs with CI95 vs the paper (Fig. 6 analog)"
                        : "Full-scale resistance (Fig. 6 analog): REDUCED-CASE runs, not the paper case")
    << "'\nplot '" << f.dat.filename().string()
    << "' using 0:2:(0.6):4:xtic(1) with boxes lc rgb variable notitle, \\\n"
    << "     '' using 0:2:3 with yerrorbars lc rgb 'black' pt 7 ps 0 notitle\n";
}

namespace {

void write_history_data(const fs::path& dat, const PaperHistories& h) {
  std::ofstream d(dat);
  d << "# full-scale resistance [kN], 0.5 s bin means of -fx; one block per run (blank line: a bin without "
       "rows)\n";
  for (const auto& l : h.lines) {
    d << "# " << l.title << "\n";
    bool broken = false;  // one blank line per run of empty bins: two would start a new gnuplot index
    for (const auto& [t, kN] : l.t_kN) {
      if (std::isfinite(kN))
        d << fmt::format("{} {}\n", t, kN);
      else if (!broken)
        d << "\n";
      broken = !std::isfinite(kN);
    }
    d << "\n\n";
  }
}

}  // namespace

void write_paper_histories(const PlotFiles& f, const PaperHistories& h, const brash::ReferenceSpec& paper) {
  write_history_data(f.dat, h);
  const double paper_am = paper_full_kN(paper, "added_mass"), paper_drag = paper_full_kN(paper, "drag");
  std::ofstream p(f.gp);
  p << "set terminal pngcairo size 1100,550\nset output '" << f.png.filename().string() << "'\n"
    << "set termoption noenhanced\nset grid\nset key right bottom\nset yrange [0:*]\n"
    << "set xlabel 'model time t [s]'\nset ylabel 'full-scale resistance [kN] (-fx x lambda^3, 0.5 s "
       "means)'\n"
    << "set title 'The paper case: resistance histories of our runs and the paper levels'\n"
    << fmt::format("set object 1 rect from {},graph 0 to {},graph 1 fc rgb '#eeeeee' fs solid 1 noborder behind\n",
                   h.window[0], h.window[1])
    << "plot ";
  for (std::size_t i = 0; i < h.lines.size(); ++i)
    p << fmt::format("'{}' index {} using 1:2 with lines lw 2 title '{}', ", f.dat.filename().string(), i,
                     h.lines[i].title);
  p << fmt::format("{} with lines dt 2 lc rgb 'black' title 'paper added mass ({:.0f} kN)', ", paper_am, paper_am)
    << fmt::format("{} with lines dt 3 lc rgb 'black' title 'paper drag ({:.0f} kN)'\n", paper_drag, paper_drag);
}

void write_speed_sweep(const PlotFiles& f, const std::vector<SpeedFit>& fits) {
  std::ofstream d(f.dat);
  for (const SpeedFit& fit : fits) {
    d << "# " << fit.engine << " " << fit.model << "\n";
    for (const Run* r : fit.runs) d << fmt::format("{} {} {}\n", r->speed, r->mean_N, r->ci_N);
    d << "\n\n";
  }
  std::ofstream p(f.gp);
  p << "set terminal pngcairo size 900,600\nset output '" << f.png.filename().string() << "'\n"
    << "set logscale xy\nset xlabel 'ship speed U [m/s] (model scale)'\nset ylabel 'resistance R [N] (model scale)'\n"
    << "set termoption noenhanced\nset offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05\n"
    << "set key left top\nset grid\nset title 'Speed sweep: each group with its preferred speed law (lowest AICc)'\nplot ";
  for (std::size_t i = 0; i < fits.size(); ++i) {
    const SpeedFit& fit = fits[i];
    if (i) p << ", ";
    p << fmt::format("'{}' index {} using 1:2:3 with yerrorbars pt 7 lc {} title '{} {}'", f.dat.filename().string(),
                     i, i + 1, fit.engine, fit.model);
    if (fit.best_law < fit.laws.size()) {  // the form with the lowest AICc
      const auto& l = fit.laws[fit.best_law];
      if (std::isfinite(l.b))
        p << fmt::format(", {} + {} * x**{} with lines lc {} title 'R = {:.3g} + {:.3g} U^{:.2f}'", l.a, l.b, l.n,
                         i + 1, l.a, l.b, l.n);
      else
        p << fmt::format(", {} * x**{} with lines lc {} title 'R = {:.3g} U^{:.2f}'", l.a, l.n, i + 1, l.a, l.n);
    }
  }
  p << "\n";
}

}  // namespace brash::post::study_report
