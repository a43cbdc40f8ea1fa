// gnuplot-driven PNG plots (Figs. 4, 5, 6 analogs) and the run comparison table/plot.
#include <brash/post/plots.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>

#include <fmt/format.h>

#include <brash/run/run_layout.hpp>
#include <brash/post/csv.hpp>
#ifdef BRASH_POST_HAVE_HULL
#include <brash/hull/flow.hpp>
#endif

namespace brash::post {
namespace fs = std::filesystem;
namespace {

// Single-quoted gnuplot string: a quote is doubled.
std::string q(const fs::path& p) {
  std::string s = p.string(), out = "'";
  for (const char ch : s) out += ch == '\'' ? std::string("''") : std::string(1, ch);
  return out + "'";
}

// Writes the script, renders into a temp PNG, renames it to `png` (readers never see half a PNG).
fs::path render(const fs::path& png, const fs::path& work_dir, const std::string& name, const std::string& body,
                int width_px, int height_px) {
  fs::create_directories(work_dir);
  const auto tmp = brash::run::temp_path_for(png);
  const auto script = work_dir / (name + ".gp");
  brash::run::write_atomic(script, fmt::format("set terminal pngcairo size {},{} font 'Sans,11' noenhanced\nset output {}\n{}\nunset output\n",
                                        width_px, height_px, q(tmp), body));
  run_gnuplot(script);
  fs::rename(tmp, png);
  return png;
}

}  // namespace

void run_gnuplot(const fs::path& script) {
  const auto log = script.parent_path() / (script.stem().string() + ".log");
  const auto cmd = fmt::format("gnuplot '{}' > '{}' 2>&1", script.string(), log.string());
  const int st = std::system(cmd.c_str());
  if (st == -1 || !WIFEXITED(st) || WEXITSTATUS(st) != 0) {
    std::string tail;
    if (fs::exists(log)) {
      tail = read_text_file(log);
      if (tail.size() > 600) tail = "..." + tail.substr(tail.size() - 600);
    }
    throw std::runtime_error(fmt::format("gnuplot failed (status {}) on {}: {}", st, script.string(), tail));
  }
}

namespace {

// The window mean of fx (the curve it belongs to) as a line, labelled as fx and as the resistance -fx it gives; a
// run whose hull met no ice has none, and the label says so.
std::string mean_label(const RunAnalysis& a) {
  const auto& w = a.window.used_s;
  if (a.met_no_ice) return "set label 1 'the hull met no ice in the averaging window' at graph 0.35, graph 0.95 front";
  return fmt::format("set arrow 1 from {}, {} to {}, {} nohead lw 2 lc rgb 'black' front\n"
                     "set label 1 sprintf('black line: window mean of fx = %.4g N, i.e. resistance -fx = %.4g +- %.2g N "
                     "(95 %%)', {}, {}, {}) at graph 0.3, graph 0.95 front",
                     w[0], -a.resistance.mean, w[1], -a.resistance.mean, -a.resistance.mean, a.resistance.mean,
                     a.resistance.ci95);
}

}  // namespace

fs::path plot_force_history(const RunAnalysis& a, const fs::path& out_dir, const fs::path& work_dir) {
  fs::create_directories(work_dir);
  const auto data = work_dir / "force_history.csv";
  // force_history_csv with an empty line before the first row after each gap of the record: gnuplot breaks
  // the line there instead of drawing it straight across a stretch that has no record
  const auto& t = a.force.t_s;
  const auto gaps = t.empty() ? std::vector<RecordGap>{} : record_gaps(t, t.front(), t.back());
  std::istringstream rows(force_history_csv(a));
  std::string text, line;
  for (std::size_t k = 0, g = 0; std::getline(rows, line); ++k) {  // k = 0: the header
    if (k > 0 && g < gaps.size() && t[k - 1] == gaps[g].to_s) text += '\n', ++g;
    text += line + '\n';
  }
  brash::run::write_atomic(data, text);
  const auto& w = a.window.used_s;
  const std::string body = fmt::format(R"(set datafile separator ','
set title 'Force of the ice on the hull ({} / {}), model scale; shaded: averaging window [{:.2f}, {:.2f}] s'
set xlabel 'time t [s]'
set ylabel 'force [N]'
set grid
set key top left
set object 1 rect from {}, graph 0 to {}, graph 1 behind fc rgb '#e8e8e8' fs solid 1.0 noborder
{}
plot {} using 1:2 with lines lw 1 lc rgb '#c0392b' title 'x (heading): fx', \
     '' using 1:3 with lines lw 1 lc rgb '#2e86c1' title 'y: fy', \
     '' using 1:4 with lines lw 1 lc rgb '#27ae60' title 'z: fz'
)", a.meta.engine, a.meta.fluid_model, w[0], w[1], w[0], w[1], mean_label(a), q(data));
  return render(out_dir / "force_history.png", work_dir, "force_history", body, 1200, 600);
}

fs::path plot_resistance_bars(const RunAnalysis& a, const fs::path& out_dir, const fs::path& work_dir) {
  fs::create_directories(work_dir);
  const auto data = work_dir / "resistance_bars.dat";
  const std::string model = run_fluid_model(a);
  const double rch = a.fsicr.result ? a.fsicr.result->R_CH_N / 1000 : NAN;
  // columns: x label value err colour; the published values only where the case declares them
  std::vector<std::string> bars{
      fmt::format("\"FSICR R_CH\\n(ours, {})\" {} 0 1", a.fsicr.ice_class, std::isnan(rch) ? 0.0 : rch)};
  if (!a.met_no_ice)  // a run whose hull met no ice has no resistance to draw
    bars.insert(bars.begin(), fmt::format("\"simulation\\n({} {})\" {} {} 0", a.meta.engine, model,
                                          a.resistance_full_kN, a.resistance_full_ci95_kN));
  const auto& ref = a.reference;
  if (ref && ref->resistance_full_kN)
    bars.push_back(fmt::format("\"published simulation\\n({})\" {} 0 2", model, *ref->resistance_full_kN));
  if (ref && ref->fsicr_R_CH_kN) bars.push_back(fmt::format("\"published FSICR R_CH\" {} 0 2", *ref->fsicr_R_CH_kN));
  std::string d;
  for (std::size_t i = 0; i < bars.size(); ++i) d += fmt::format("{} {}\n", i, bars[i]);
  brash::run::write_atomic(data, d);
  // Two short title lines (gnuplot's double-quoted "\n"), so a 900 px chart shows the whole title.
  std::string subtitle = a.ratio_fsicr_to_sim ? fmt::format("FSICR / simulation = {:.2f}", *a.ratio_fsicr_to_sim)
                                              : std::string("R_CH not available");
  if (ref && ref->ratio_fsicr_to_sim)
    subtitle += fmt::format(" (published: {:.2f})", *ref->ratio_fsicr_to_sim);
  const std::string body = fmt::format(R"(set title "Full-scale channel resistance (lambda = {})\n{}"
set ylabel 'resistance [kN]'
set yrange [0:*]
set offsets 0, 0, graph 0.12, 0
set tmargin 4
set bmargin 5
set xrange [-0.6:{}]
set style fill solid 0.8 border -1
set boxwidth 0.6
set grid ytics
set palette defined (0 '#2e86c1', 1 '#c0392b', 2 '#bbbbbb')
set cbrange [0:2]
unset colorbox
set key off
plot {} using 1:3:5:xtic(2) with boxes lc palette, \
     '' using 1:3:4 with yerrorbars lc rgb 'black' pt -1 lw 2, \
     '' using 1:3:(sprintf('%.0f kN', $3)) with labels offset 0,1
)", a.case_.scale_lambda, subtitle, static_cast<double>(bars.size()) - 0.4, q(data));
  return render(out_dir / "resistance_full_scale.png", work_dir, "resistance_bars", body, 900, 600);
}

fs::path plot_ice_around_hull(const RunAnalysis& a, const fs::path& out_dir, const fs::path& work_dir) {
  fs::create_directories(work_dir);
  const auto& r = a.ice_around.value();
  const auto data = work_dir / "ice_around_hull.dat";
  // two blocks: ahead (distance ahead of the stem, band centre), beside (hull-frame x, band centre)
  std::string d = "# ahead_m thickness_m\n";
  for (const auto& b : r.ahead) d += fmt::format("{} {}\n", 0.5 * (b.from_m + b.to_m), b.thickness_m);
  d += "\n\n# x_m thickness_m\n";
  for (const auto& b : r.beside) d += fmt::format("{} {}\n", 0.5 * (b.from_m + b.to_m), b.thickness_m);
  brash::run::write_atomic(data, d);
  const std::string hf = r.H_F_fsicr_model_m
                             ? fmt::format("{0} with lines lw 2 dt 2 lc rgb '#c0392b' title sprintf(\"FSICR H_F / "
                                           "lambda = %.4f m\", {0}), ",
                                           *r.H_F_fsicr_model_m)
                             : std::string();
  const std::string bed = fmt::format("{0} with lines lw 1 dt 3 lc rgb '#555555' title sprintf(\"ice.thickness_m "
                                      "= %.4f m\", {0})",
                                      r.ice_thickness_m);
  const std::string body = fmt::format(R"(set multiplot layout 1,2 title 'Brash thickness around the hull over the window [{:.2f}, {:.2f}] s ({} snapshots), model scale'
set grid
set key top right
set yrange [0:*]
set ylabel 'thickness: ice volume per area / (1 - porosity) [m]'
set xlabel 'distance ahead of the stem [m] (over the beam)'
set title 'ahead of the bow'
plot {} index 0 using 1:2 with linespoints lw 2 pt 7 lc rgb '#2e86c1' title 'measured', {}{}
set xlabel 'x, hull frame [m] (strip of {:.3f} m beside the waterline)'
set title 'beside the hull'
plot {} index 1 using 1:2 with linespoints lw 2 pt 7 lc rgb '#27ae60' title 'measured', {}{}
unset multiplot
)", r.window_s[0], r.window_s[1], r.snapshots, q(data), hf, bed, r.strip_m, q(data), hf, bed);
  return render(out_dir / "ice_around_hull.png", work_dir, "ice_around_hull", body, 1400, 550);
}

std::vector<std::array<double, 2>> hull_waterline(const fs::path& hull_file, double draft_m) {
  std::vector<std::array<double, 2>> outline;
#ifdef BRASH_POST_HAVE_HULL
  try {
    const auto mesh = brash::hull::read_mesh(hull_file);
    double x0 = mesh.vertices.front().x(), x1 = x0;
    for (const auto& v : mesh.vertices) x0 = std::min(x0, v.x()), x1 = std::max(x1, v.x());
    constexpr int kStations = 241;
    std::vector<double> xs(kStations);
    for (int i = 0; i < kStations; ++i) xs[i] = x0 + (x1 - x0) * i / (kStations - 1.0);
    const double z[] = {draft_m};
    const auto half = brash::hull::half_breadths(mesh, xs, z);
    for (int i = 0; i < kStations; ++i)
      if (half[i] > 0) outline.push_back({xs[i], -half[i]});
    for (int i = kStations - 1; i >= 0; --i)
      if (half[i] > 0) outline.push_back({xs[i], half[i]});
    if (!outline.empty()) outline.push_back(outline.front());
  } catch (const std::exception&) {
    outline.clear();  // no mesh: the caller draws the rectangle and says so
  }
#else
  (void)hull_file, (void)draft_m;
#endif
  return outline;
}

fs::path plot_ice_views(const Snapshot& s, const SnapshotEntry& e, const PostCase& c, const fs::path& out_dir,
                        const fs::path& work_dir, const std::vector<std::array<double, 2>>& waterline) {
  fs::create_directories(work_dir);
  // Region: one hull length behind the stern to half a length ahead of the bow.
  const double x0 = e.hull_x_m - 0.5 * c.lpp_m, x1 = e.hull_x_m + 1.5 * c.lpp_m;
  std::vector<std::size_t> idx, outside;  // the pieces in the scene; those outside it (the moving window's)
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s.x[i] >= x0 && s.x[i] <= x1) (s.state.empty() || s.state[i] == kScene ? idx : outside).push_back(i);
  // a snapshot without velocities (an own deck's dump without vx vy vz): the top view shows the height instead
  const bool speeds = std::none_of(idx.begin(), idx.end(), [&](std::size_t i) { return std::isnan(s.vx[i]); });
  const auto write_sorted = [&](const fs::path& p, bool top) {
    auto order = idx;
    // Top view: the highest particle is what one sees, so it is drawn last; bottom view: the lowest.
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return top ? s.z[a] < s.z[b] : s.z[a] > s.z[b]; });
    std::string d = "# x_m y_m radius_m value\n";
    for (const auto i : order) {
      const double v = !top   ? s.submerged_fraction[i]
                       : speeds ? std::sqrt(s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i] + s.vz[i] * s.vz[i])
                                : s.z[i];
      d += fmt::format("{} {} {} {}\n", s.x[i], s.y[i], s.radius[i], v);
    }
    brash::run::write_atomic(p, d);
  };
  const auto top = work_dir / fmt::format("ice_top_{}.dat", e.step);
  const auto bottom = work_dir / fmt::format("ice_bottom_{}.dat", e.step);
  write_sorted(top, true);
  write_sorted(bottom, false);
  // the moving window's pieces outside the scene, grey under the scene's: light where held out ahead, dark where
  // removed (brash/post/particles.hpp)
  std::string grey_layer;
  if (!outside.empty()) {
    const auto grey = work_dir / fmt::format("ice_outside_{}.dat", e.step);
    std::string d = "# x_m y_m radius_m rgb\n";
    for (const auto i : outside)
      d += fmt::format("{} {} {} {}\n", s.x[i], s.y[i], s.radius[i], s.state[i] == kHeldOut ? 0xd9d9d9 : 0x8c8c8c);
    brash::run::write_atomic(grey, d);
    grey_layer = fmt::format("{} using 1:2:3:4 with circles lc rgb variable fs solid 1.0 noborder notitle, ", q(grey));
  }
  const double hw = c.channel_width_m > 0 ? c.channel_width_m / 2 : 1.5 * c.beam_m;
  std::string hull;
  if (waterline.empty()) {
    hull = fmt::format("set object 1 rect from {},{} to {},{} front fs empty border lc rgb 'black' dt 2 lw 1.5\n"
                       "set label 1 'hull Lpp x B (no hull mesh read)' at {},{} front\n",
                       e.hull_x_m, -c.beam_m / 2, e.hull_x_m + c.lpp_m, c.beam_m / 2, e.hull_x_m + 0.02 * c.lpp_m,
                       c.beam_m / 2 + 0.05 * hw);
  } else {  // the waterline drawn where the engine had the hull at this snapshot (mesh x + hull position)
    hull = "set object 1 polygon from ";
    for (std::size_t i = 0; i < waterline.size(); ++i)
      hull += fmt::format("{}{},{}", i ? " to " : "", waterline[i][0] + e.hull_x_m, waterline[i][1]);
    hull += fmt::format(" front fs empty border lc rgb 'black' lw 1.5\nset label 1 'hull waterline' at {},{} front\n",
                        e.hull_x_m + 0.02 * c.lpp_m, c.beam_m / 2 + 0.05 * hw);
  }
  const std::string common = fmt::format("set xrange [{}:{}]\nset yrange [{}:{}]\nset size ratio -1\nset xlabel 'x [m] (heading)'\nset ylabel 'y [m]'\n{}",
                                         x0, x1, -hw, hw, hull);
  const std::string shown =
      outside.empty() ? fmt::format("{} particles shown", idx.size())
                      : fmt::format("{} particles in the scene; grey: {} outside it, light held out, dark removed",
                                    idx.size(), outside.size());
  const std::string body = fmt::format(R"(set multiplot layout 2,1 title 't = {:.2f} s: ice around the hull ({})'
{}
set title 'top view, coloured by {}'
set palette rgbformulae 22,13,-31
set cbrange [{}:*]
plot {}{} using 1:2:3:4 with circles lc palette fs solid 1.0 noborder notitle
set title 'bottom view (from below, same axes), coloured by submerged fraction [-]'
set palette defined (0 '#f7fbff', 0.5 '#6baed6', 1 '#08306b')
set cbrange [0:1]
plot {}{} using 1:2:3:4 with circles lc palette fs solid 1.0 noborder notitle
unset multiplot
)", e.t_s, shown, common, speeds ? "speed |v| [m/s]" : "height z [m] (the snapshot has no velocities)",
                                       speeds ? "0" : "", grey_layer, q(top), grey_layer, q(bottom));
  // Height follows the channel's aspect ratio so the two panels are not mostly margin.
  const int panel_px = std::clamp(static_cast<int>(1200.0 * 2 * hw / (x1 - x0)), 150, 700);
  return render(out_dir / fmt::format("ice_views_{:06.2f}s.png", e.t_s), work_dir, fmt::format("ice_views_{}", e.step), body,
                1400, 2 * panel_px + 260);
}

CompareRow compare_row(const RunAnalysis& a) {
  CompareRow r;
  r.run = a.run_dir.filename().string();
  if (r.run.empty()) r.run = a.run_dir.parent_path().filename().string();
  r.engine = a.meta.engine;
  r.fluid_model = run_fluid_model(a);
  if (a.reference && a.reference->resistance_full_kN) r.reference_full_kN = *a.reference->resistance_full_kN;
  r.speed_m_s = a.case_.speed_m_s;
  if (!a.force.t_s.empty()) r.duration_s = a.force.t_s.back();
  r.window_s = a.window.used_s;
  r.met_no_ice = a.met_no_ice;
  if (!a.met_no_ice) {  // else NaN: no resistance (compare_markdown says "met no ice", the CSV leaves it empty)
    r.mean_N = a.resistance.mean;
    r.ci95_N = a.resistance.ci95;
    r.full_kN = a.resistance_full_kN;
    r.full_ci95_kN = a.resistance_full_ci95_kN;
  }
  if (a.fsicr.result) r.R_CH_kN = a.fsicr.result->R_CH_N / 1000;
  if (a.ratio_fsicr_to_sim) r.ratio = *a.ratio_fsicr_to_sim;
  r.complete = a.meta.status == "complete" && !a.force.tail_dropped && !a.window.truncated && !a.window.fallback;
  return r;
}

std::string compare_markdown(const std::vector<CompareRow>& rows) {
  std::string s = "| run | engine | fluid model | speed [m/s] | run [s] | window [s] | R model [N] | R full [kN] | "
                  "FSICR R_CH [kN] | FSICR / sim | complete |\n"
                  "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows)
    s += fmt::format("| {} | {} | {} | {:.3f} | {:.3f} | {:.3f}-{:.3f} | {} | {} | {:.1f} | {:.2f} | {} |\n", r.run,
                     r.engine, r.fluid_model, r.speed_m_s, r.duration_s, r.window_s[0], r.window_s[1], r.met_no_ice ? "met no ice" : fmt::format("{:.4f} ± {:.4f}", r.mean_N, r.ci95_N),
                     r.met_no_ice ? "met no ice" : fmt::format("{:.1f} ± {:.1f}", r.full_kN, r.full_ci95_kN),
                     r.R_CH_kN, r.ratio, r.complete ? "yes" : "NO");
  s += "\n± = 95 % confidence interval (block averaging).\n";
  std::string refs;
  for (const auto& r : rows)
    if (!std::isnan(r.reference_full_kN) && !r.met_no_ice)
      refs += fmt::format("{}{}: {:.0f} kN ({:+.1f} %)", refs.empty() ? "" : "; ", r.run, r.reference_full_kN,
                          100 * (r.full_kN / r.reference_full_kN - 1));
  if (!refs.empty()) s += "Published resistance declared by the run's case (full scale): " + refs + ".\n";
  return s;
}

namespace {

// A resistance cell: empty where the run has none (its hull met no ice).
std::string csv_value(double v) { return std::isnan(v) ? std::string() : fmt::format("{}", v); }

// A value for gnuplot: NaN (not drawn) where there is none.
std::string plot_value(double v) { return std::isnan(v) ? std::string("NaN") : fmt::format("{}", v); }

}  // namespace

std::string compare_csv(const std::vector<CompareRow>& rows) {
  std::string s = "run,engine,fluid_model,speed_m_s,mean_N,ci95_N,full_kN,full_ci95_kN,R_CH_kN,ratio_fsicr_to_sim,complete,"
                  "duration_s,window_start_s,window_end_s\n";
  for (const auto& r : rows)
    s += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", r.run, r.engine, r.fluid_model, r.speed_m_s,
                     csv_value(r.mean_N), csv_value(r.ci95_N), csv_value(r.full_kN), csv_value(r.full_ci95_kN),
                     r.R_CH_kN, r.ratio, r.complete ? 1 : 0, csv_value(r.duration_s), csv_value(r.window_s[0]),
                     csv_value(r.window_s[1]));
  return s;
}

fs::path plot_compare(const std::vector<CompareRow>& rows, const fs::path& out_dir, const fs::path& work_dir) {
  fs::create_directories(work_dir);
  const auto data = work_dir / "compare.dat";
  std::string d;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& r = rows[i];
    // column 6: the published resistance the run's case declares, NaN (not drawn) where it declares none
    d += fmt::format("{} \"{}\\n{} {:.3f} m/s{}\" {} {} {} {}\n", i, r.engine, r.fluid_model, r.speed_m_s,
                     r.met_no_ice ? "\\n(met no ice)" : (r.complete ? "" : "\\n(incomplete)"), plot_value(r.full_kN),
                     plot_value(r.full_ci95_kN), std::isnan(r.R_CH_kN) ? 0.0 : r.R_CH_kN,
                     plot_value(r.reference_full_kN));
  }
  brash::run::write_atomic(data, d);
  const bool with_reference =
      std::any_of(rows.begin(), rows.end(), [](const CompareRow& r) { return !std::isnan(r.reference_full_kN); });
  const std::string body = fmt::format(R"(set title 'Full-scale ice resistance per run (bars, 95 % CI) and FSICR R_CH (points)'
set ylabel 'resistance [kN]'
set yrange [0:*]
set offsets 0, 0, graph 0.12, 0
set bmargin 6
set xrange [-0.6:{}]
set style fill solid 0.7 border -1
set boxwidth 0.6
set grid ytics
set key top right
plot {} using 1:3:xtic(2) with boxes lc rgb '#2e86c1' title 'simulation', \
     '' using 1:3:4 with yerrorbars lc rgb 'black' pt -1 lw 2 notitle, \
     '' using 1:5 with points pt 7 ps 2 lc rgb '#c0392b' title 'FSICR R_CH'{}
)", static_cast<double>(rows.size()) - 0.4, q(data), with_reference ? ", \\\n     '' using 1:6 with points pt 5 ps 2 lc rgb '#888888' title 'published reference'" : "");
  return render(out_dir / "compare.png", work_dir, "compare", body, std::max<int>(800, 220 * static_cast<int>(rows.size())), 600);
}

}  // namespace brash::post
