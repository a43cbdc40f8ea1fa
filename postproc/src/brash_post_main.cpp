// brash-post: postprocess a run directory (report, plots, ParaView files), print FSICR R_CH for given parameters,
// compare runs, replay the early stop, summarize a paired-seed ensemble or a packing ensemble. Thin CLI over
// brash_post.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <string_view>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <brash/error.hpp>
#include <brash/run/run_layout.hpp>
#include <brash/stats/early_stop.hpp>
#include <brash/stats/paired.hpp>
#include <brash/post/ensemble.hpp>
#include <brash/post/fsicr.hpp>
#include <brash/post/native_dump.hpp>
#include <brash/post/packing_ensemble.hpp>
#include <brash/post/particles.hpp>
#include <brash/post/plots.hpp>
#include <brash/post/report.hpp>
#ifdef BRASH_POST_HAVE_STABILITY
#include <brash/post/stability.hpp>
#endif
#ifdef BRASH_POST_HAVE_VTK
#include <brash/post/paraview.hpp>
#endif

namespace fs = std::filesystem;
using namespace brash::post;

namespace {

struct ReportOptions {
  bool plots = true, paraview = true;
  std::vector<double> snapshot_times_s;  // empty: start, middle and end of the averaging window
};

// Runs one output step; a failure becomes a note in the report (and exit status 1), not an abort,
// so the numbers are still written.
template <class F>
bool step(RunAnalysis& a, std::vector<std::string>& outputs, const char* what, F&& f) {
  try {
    for (const auto& p : f()) outputs.push_back(fs::relative(p, a.run_dir).string());
    return true;
  } catch (const std::exception& e) {
    a.notes.push_back(fmt::format("{} failed: {}", what, e.what()));
    return false;
  }
}

// Replays the early-stop rule on finished runs' records (early_stop.hpp) for each threshold and trend test and
// prints one markdown table: where each run would have stopped, the model time that saves, the window mean at the
// stop and the rule's estimate of the full window's mean against the full window's, and why the rule held or did
// not. Exact for a LIGGGHTS run: an early stop only truncates the same trajectory. A run that was stopped early is
// replayed on the window it asked for (meta.json early_stop.requested_window_s; before that was recorded, the window
// to early_stop.requested_duration_s) up to its record's end, with the runner's checks (every 1/200 of the duration
// asked for). The lag-1 autocorrelation and sd of each record's window (about its fitted line) are printed below
// the table: the surrogate records of tests/stats/test_early_stop.cpp are matched to them.
int run_early_stop(const std::vector<fs::path>& run_dirs, const std::vector<double>& thresholds,
                   const std::vector<std::string>& trends, double check_every_s) {
  std::vector<brash::stats::EarlyStopTrend> rules;
  for (const auto& name : trends) {
    try {
      rules.push_back(brash::stats::early_stop_trend_from_string(name));
    } catch (const std::invalid_argument& e) {
      throw brash::InputError(fmt::format("--trend: {}", e.what()));
    }
  }
  for (const double rel : thresholds)
    if (!(rel > 0)) throw brash::InputError(fmt::format("--rel-ci {}: must be > 0", rel));
  std::string notes;
  fmt::print("| run | window [s] | record to [s] | full window [N] | early_stop_rel_ci | trend test | stops at t [s] | "
             "model time saved | window mean at the stop | its estimate of the full window | why (at the stop or "
             "the last check) |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const auto& run_dir : run_dirs) {
    const auto a = analyze_run(run_dir);
    double t0 = a.window.requested_s[0], t1 = a.window.requested_s[1];
    double duration = a.force.t_s.empty() ? 0.0 : a.force.t_s.back();
    if (const auto& e = a.meta.early_stop) {
      t1 = e->requested_window_end_s.value_or(e->requested_duration_s);
      duration = e->requested_duration_s;
    }
    const double t_end = a.force.t_s.empty() ? 0.0 : a.force.t_s.back();
    const bool whole = !a.force.t_s.empty() && t_end >= t1 - 1e-9;
    if (a.force.t_s.empty() || (!a.meta.early_stop && (a.window.truncated || a.window.fallback)))
      throw brash::InputError(fmt::format("{}: the hull force record ends at t = {} s, before the window [{}, {}] s ends; "
                                          "the replay needs a finished run",
                                          run_dir.string(), t_end, t0, t1));
    const double every = check_every_s > 0 ? check_every_s : duration / 200.0;
    std::vector<double> r(a.force.fx_N.size());
    for (std::size_t i = 0; i < r.size(); ++i) r[i] = -a.force.fx_N[i];
    const auto& full = a.resistance;
    const std::string full_text =
        whole ? fmt::format("{:.4g} +- {:.3g}{}", full.mean, full.ci95, full.plateau_found ? "" : " (lower bound)")
              : "— (record ends first)";
    const auto vs_full = [&](double x) {
      return whole ? fmt::format(" ({:+.2f} %, {:+.2f} CI)", 100 * (x - full.mean) / full.mean,
                                 full.ci95 > 0 ? (x - full.mean) / full.ci95 : 0.0)
                   : std::string();
    };
    for (const double rel : thresholds)
      for (const auto rule : rules) {
        const auto e = brash::stats::replay_early_stop(a.force.t_s, r, t0, t1, rel, every, rule);
        const std::string stop =
            e.stopped ? fmt::format("{:.3f}", e.t_stop_s)
                      : (whole ? std::string("never") : fmt::format("not by {:.3f}", e.t_stop_s));
        const std::string saved =
            e.stopped ? fmt::format("{:.1f} % ({:.2f}x)", 100 * (duration - e.t_stop_s) / duration, duration / e.t_stop_s)
                      : "0 %";
        fmt::print("| {} | [{}, {}] | {:.3f} | {} | {:.3g} | {} | {} | {} | {} | {} | {} |\n",
                   run_dir.filename().string(), t0, t1, t_end, full_text, rel, to_string(rule), stop, saved,
                   e.stopped ? fmt::format("{:.4g} +- {:.3g}{}", e.at_stop.mean, e.at_stop.ci95, vs_full(e.at_stop.mean))
                             : std::string("—"),
                   e.stopped ? fmt::format("{:.4g} +- {:.3g}{}", e.estimate, e.estimate_ci95, vs_full(e.estimate))
                             : std::string("—"),
                   e.last.checked ? e.last.explain() : std::string("no check"));
      }
    // the record's window about its fitted line: what the surrogate records are matched to
    std::vector<double> w;
    for (std::size_t i = 0; i < r.size(); ++i)
      if (a.force.t_s[i] >= t0 - 1e-9 && a.force.t_s[i] <= t1 + 1e-9) w.push_back(r[i]);
    if (w.size() >= 3) {
      const double n = static_cast<double>(w.size()), im = 0.5 * (n - 1);
      double m = 0, sir = 0;
      for (const double x : w) m += x / n;
      for (std::size_t i = 0; i < w.size(); ++i) sir += (static_cast<double>(i) - im) * (w[i] - m);
      const double b = sir / (n * (n * n - 1) / 12);
      double c0 = 0, c1 = 0;
      for (std::size_t i = 0; i < w.size(); ++i) {
        const double d = w[i] - m - b * (static_cast<double>(i) - im);
        const double dp = i > 0 ? w[i - 1] - m - b * (static_cast<double>(i) - 1 - im) : 0.0;
        c0 += d * d, c1 += i > 0 ? d * dp : 0.0;
      }
      notes += fmt::format("- {}: window [{}, {:.3f}] s, {} samples: mean {:.4g} N, sd {:.3g} N about the fitted line, "
                           "lag-1 autocorrelation {:.2f}, drift {:+.2f} % over these samples\n",
                           run_dir.filename().string(), t0, std::min(t1, t_end), w.size(), m, std::sqrt(c0 / n),
                           c0 > 0 ? c1 / c0 : 0.0, 100 * b * (n - 1) / m);
    }
  }
  fmt::print("\nThe records' windows (AR(1) matching of the surrogates):\n\n{}", notes);
  return 0;
}

int run_report(const fs::path& run_dir, const ReportOptions& opt) {
  auto a = analyze_run(run_dir);
  const auto work = run_dir / "post";
  std::vector<std::string> outputs{"report.json", "report.md", "force_history.csv", "blocking.csv"};
  bool ok = true;
  auto entries = read_snapshot_index(run_dir / "particles", a.meta.in_progress());
  if (!fs::exists(run_dir / "particles/index.csv")) {  // an own deck's dump custom files, if any
    entries = native_dump_index(run_dir, {a.case_.timestep_s, a.case_.start_x_m, a.case_.speed_m_s, a.case_.water_level_m});
    if (!entries.empty())
      a.notes.push_back(fmt::format(
          "particle snapshots from {} LIGGGHTS dump custom file(s) ({} ...): times are step x run.timestep_s {} s of "
          "case.yaml, submerged fractions computed from each sphere's height, added-mass coefficients unknown",
          entries.size(), fs::relative(entries.front().file, run_dir).string(), a.case_.timestep_s));
  }
  if (opt.plots) {
    ok &= step(a, outputs, "force history plot", [&] { return std::vector{plot_force_history(a, run_dir, work)}; });
    ok &= step(a, outputs, "resistance bar chart", [&] { return std::vector{plot_resistance_bars(a, run_dir, work)}; });
    ok &= step(a, outputs, "ice views", [&] {
      auto times = opt.snapshot_times_s;
      if (times.empty()) times = {a.window.used_s[0], 0.5 * (a.window.used_s[0] + a.window.used_s[1]), a.window.used_s[1]};
      std::vector<fs::path> pngs;
      const auto waterline = entries.empty() ? std::vector<std::array<double, 2>>{}
                                             : hull_waterline(a.case_.hull_file, a.case_.draft_m);
      if (!entries.empty() && waterline.empty())
        a.notes.push_back(fmt::format("ice views: the hull mesh {} could not be read: the hull is drawn as its Lpp x B "
                                      "rectangle", a.case_.hull_file.string()));
      for (const auto i : nearest_snapshots(entries, times)) {
        const auto& e = entries[i];
        if (!fs::exists(e.file)) continue;
        pngs.push_back(plot_ice_views(read_snapshot(e, a.meta.in_progress(), Pieces::All), e, a.case_, run_dir, work, waterline));
      }
      if (entries.empty())
        a.notes.push_back("no particle snapshots (no particles/index.csv, no LIGGGHTS dump custom file): no ice views");
      return pngs;
    });
  }
  if (a.case_.band_m && !entries.empty()) {
    ok &= step(a, outputs, "contact band check", [&] {
      const auto& b = *(a.band = check_contact_band(entries, (*a.case_.band_m)[0], a.case_.water_level_m,
                                                    a.meta.in_progress()));
      if (b.passed_under())
        a.notes.push_back(fmt::format(
            "contact band: up to {} pieces at once (t = {:.2f} s) reached below the hull's contact band (hull.band_m: "
            "{:.3g} m below the waterline; deepest piece bottom {:.3g} m below at t = {:.2f} s): the band has no "
            "triangles there, so wherever such a piece touches the hull below the band that contact is missing; "
            "deepen hull.band_m",
            b.pieces_below_max, b.pieces_below_t_s, b.band_below_m, b.deepest_bottom_m, b.deepest_t_s));
      return std::vector<fs::path>{};
    });
  }
#ifdef BRASH_POST_HAVE_ICE_AROUND_HULL
  ok &= step(a, outputs, "the ice around the hull", [&] {
    add_ice_around_hull(a, entries);
    std::vector<fs::path> files;
    if (!a.ice_around) return files;
    if (opt.plots) files.push_back(plot_ice_around_hull(a, run_dir, work));
#ifdef BRASH_POST_HAVE_VTK
    if (opt.paraview)
      if (const auto hull = load_case_hull(a.case_, a.notes))
        files.push_back(write_hull_contact_field(run_dir, *hull, a.ice_around->triangle_contact_fraction,
                                                 a.ice_around->triangle_pressure_Pa));
#endif
    return files;
  });
#else
  a.ice_around_missing = "brash-post was built without the hull library (brash_hull)";
#endif
#ifdef BRASH_POST_HAVE_VTK
  if (opt.paraview && !entries.empty()) {
    ok &= step(a, outputs, "ParaView output", [&] {
      const auto hull = load_case_hull(a.case_, a.notes);
      const auto pv = write_paraview(run_dir, entries, hull, a.case_, a.meta.in_progress(), a.notes);
      std::vector<fs::path> files{pv.particles_pvd};
      if (!pv.hull_pvd.empty()) files.push_back(pv.hull_pvd);
      return files;
    });
  }
#else
  if (opt.paraview) a.notes.push_back("ParaView output skipped: brash-post was built without VTK");
#endif
  auto j = report_json(a);
  j["outputs"] = outputs;
  brash::run::write_atomic(run_dir / "report.json", j.dump(2) + "\n");
  brash::run::write_atomic(run_dir / "report.md", report_markdown(a));
  brash::run::write_atomic(run_dir / "force_history.csv", force_history_csv(a));
  brash::run::write_atomic(run_dir / "blocking.csv", blocking_csv(a.resistance));
  if (a.met_no_ice)
    fmt::print("{}: the hull met no ice in the window [{:.3f}, {:.3f}] s: no resistance", run_dir.string(),
               a.window.used_s[0], a.window.used_s[1]);
  else
    fmt::print("{}: resistance {:.4f} ± {:.4f} N model, {:.1f} ± {:.1f} kN full scale", run_dir.string(),
               a.resistance.mean, a.resistance.ci95, a.resistance_full_kN, a.resistance_full_ci95_kN);
  if (a.fsicr.result) fmt::print("; FSICR R_CH {:.1f} kN", a.fsicr.result->R_CH_N / 1000);
  fmt::print("\n");
  for (const auto& n : a.notes) fmt::print("note: {}\n", n);
  for (const auto& w : a.fsicr.warnings) fmt::print("fsicr warning: {}\n", w);
  return ok ? 0 : 1;
}

int run_compare(const std::vector<fs::path>& runs, const fs::path& out) {
  std::vector<CompareRow> rows;
  for (const auto& r : runs) rows.push_back(compare_row(analyze_run(r)));
  fs::create_directories(out);
  const auto md = compare_markdown(rows);
  brash::run::write_atomic(out / "compare.md", md);
  brash::run::write_atomic(out / "compare.csv", compare_csv(rows));
  plot_compare(rows, out, out / "post");
  fmt::print("{}", md);
  fmt::print("wrote {}, {}, {}\n", (out / "compare.md").string(), (out / "compare.csv").string(), (out / "compare.png").string());
  return 0;
}

int run_fsicr(const brash::FsicrParams& p, const std::string& ice_class) {
  const auto ic = parse_ice_class(ice_class);
  // Geometry no hull has is an input error naming the option, before anything is computed; values outside the
  // rule's validity range are warnings below the result.
  static const std::map<std::string_view, std::string> kOption = {
      {"L_m", "--L"},         {"B_m", "--B"},         {"T_m", "--T"},         {"alpha_deg", "--alpha"},
      {"phi1_deg", "--phi1"}, {"phi2_deg", "--phi2"}, {"L_par_m", "--Lpar"},  {"L_bow_m", "--Lbow"},
      {"A_wf_m2", "--Awf"}};
  const auto impossible = fsicr_impossible_values(p, [](std::string_view field) { return kOption.at(field); });
  if (!impossible.empty()) {
    std::string all;
    for (const auto& m : impossible) all += (all.empty() ? "" : "; ") + m;
    throw brash::InputError("fsicr: " + all);
  }
  const auto r = fsicr_channel_resistance(p, ic);
  fmt::print("ice class {}: H_M = {:.3f} m, H_F = {:.3f} m\n", brash::to_string(ic), r.H_M_m, r.H_F_m);
  fmt::print("psi = {:.3f} deg, Cmu = {:.4f}, Cpsi = {:.4f}\n", r.psi_deg, r.Cmu, r.Cpsi);
  fmt::print("(L T / B^2)^3 = {:.3f} (used {:.3f})\n", r.LTB3_raw, r.LTB3_used);
  if (ic == IceClass::IA_super) fmt::print("C1 = {:.1f} N, C2 = {:.1f} N\n", r.C1_N, r.C2_N);
  fmt::print("R_CH = {:.1f} kN\n", r.R_CH_N / 1000);
  for (const auto& w : fsicr_validity_warnings(p)) fmt::print("warning: {}\n", w);
  return 0;
}

// The paired-seed ensemble summary (ensemble.hpp): table and statement on stdout, the JSON beside the runs.
int run_paired_ensemble(const EnsembleSpec& spec) {
  const auto s = summarize_ensemble(spec, read_ensemble(spec));
  if (s.json) brash::run::write_atomic(s.json_path, s.json->dump(1));
  fmt::print("{}", s.text);
  return 0;
}

// The packing-ensemble summary (packing_ensemble.hpp): table on stdout, the JSON beside the runs or in OUT.
int run_packing_ensemble(const std::vector<fs::path>& run_dirs, const fs::path& out) {
  const auto s = summarize_packing_ensemble(read_packing_runs(run_dirs), out);
  brash::run::write_atomic(s.json_path, s.json.dump(1) + "\n");
  fmt::print("{}wrote {}\n", s.text, s.json_path.string());
  return 0;
}

// A run's model-scale resistance from its report.json: (mean, ci95) [N].
std::pair<double, double> report_resistance(const fs::path& run_dir) {
  const fs::path file = run_dir / "report.json";
  const auto j = nlohmann::json::parse(std::ifstream(file), nullptr, false);
  if (j.is_discarded() || !j.contains("resistance_model_N"))
    throw brash::InputError(file.string() + ": no report (run brash-post " + run_dir.string() + " first)");
  if (j.value("met_no_ice", false))
    throw brash::InputError(file.string() + ": the hull met no ice in the run's window: it has no resistance");
  const auto& r = j["resistance_model_N"];
  const double nan = std::numeric_limits<double>::quiet_NaN();  // (a float NAN default would read floats)
  return {r.value("mean", nan), r.value("ci95", nan)};
}

// Two separate runs' resistance (brash::stats::independent_relative_difference): JSON on stdout.
int run_difference(const fs::path& reference_run, const fs::path& run) {
  const auto [ref, ref_ci] = report_resistance(reference_run);
  const auto [mean, ci] = report_resistance(run);
  const auto d = brash::stats::independent_relative_difference(ref, ref_ci, mean, ci);
  const nlohmann::json out = {{"reference_N", ref}, {"reference_ci95_N", ref_ci}, {"mean_N", mean},
                              {"ci95_N", ci},        {"diff_rel", d.relative},   {"ci95_rel", d.ci95_relative},
                              {"resolved", d.resolved()}};
  fmt::print("{}\n", out.dump());
  return 0;
}

// Mean, standard deviation, standard error and Student-t 95 % CI of numbers (whitespace separated) in a file or
// on stdin ("-"), assuming independent samples: JSON on stdout.
int run_sample_stats(const std::string& source) {
  std::ifstream file;
  if (source != "-") {
    file.open(source);
    if (!file) throw brash::InputError(source + ": cannot be read");
  }
  std::istream& in = source == "-" ? std::cin : file;
  std::vector<double> x;
  for (std::string word; in >> word;) {
    std::size_t used = 0;
    double v = NAN;
    try {
      v = std::stod(word, &used);
    } catch (const std::exception&) {
    }
    if (used != word.size() || !std::isfinite(v))
      throw brash::InputError(fmt::format("{}: '{}' (value {}) is not a finite number", source, word, x.size() + 1));
    x.push_back(v);
  }
  if (x.size() < 2) throw brash::InputError(fmt::format("{}: {} number(s); at least 2 are needed", source, x.size()));
  const auto m = brash::stats::mean_ci95(x);
  const nlohmann::json out = {{"n", m.n}, {"mean", m.mean}, {"sd", m.sd}, {"se", m.sd / std::sqrt(double(m.n))},
                              {"ci95", m.ci95}};
  fmt::print("{}\n", out.dump());
  return 0;
}

#ifdef BRASH_POST_HAVE_STABILITY
// Stability verdict and measures of one run (docs/stability.md, "Engine stability map"): JSON on stdout and
// in OUT (default RUN_DIR/stability.json).
int run_stability(const fs::path& run_dir, const StabilityOptions& opt, fs::path out) {
  const auto r = analyze_stability(run_dir, opt);
  const auto text = stability_json(r).dump(2) + "\n";
  if (out.empty()) out = run_dir / "stability.json";
  brash::run::write_atomic(out, text);
  fmt::print("{}", text);
  return 0;
}
#endif

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"brash-post: resistance, FSICR, report, plots and ParaView output of a brash run",
               "brash-post"};
  app.require_subcommand(0, 1);
  fs::path run_dir;
  app.add_option("RUN_DIR", run_dir, "run directory (docs/case_format.md layout)")->check(CLI::ExistingDirectory);

  auto* fsicr = app.add_subcommand("fsicr", "print FSICR channel resistance R_CH for given full-scale parameters");
  brash::FsicrParams p;
  std::string ice_class = "IA";
  fsicr->add_option("--L", p.L_m, "length between perpendiculars [m]")->required();
  fsicr->add_option("--B", p.B_m, "breadth [m]")->required();
  fsicr->add_option("--T", p.T_m, "draught [m]")->required();
  fsicr->add_option("--alpha", p.alpha_deg, "waterline angle at B/4 [deg]")->required();
  fsicr->add_option("--phi1", p.phi1_deg, "stem rake [deg] (90 = bulbous bow)")->capture_default_str();
  fsicr->add_option("--phi2", p.phi2_deg, "bow rake at B/4 [deg]")->required();
  fsicr->add_option("--Lpar", p.L_par_m, "parallel mid-body length [m]")->required();
  fsicr->add_option("--Lbow", p.L_bow_m, "bow length [m]")->required();
  fsicr->add_option("--Awf", p.A_wf_m2, "bow waterline area [m^2]")->required();
  fsicr->add_option("--class", ice_class, "ice class IA_super | IA | IB | IC")->capture_default_str();

  ReportOptions ropt;
  bool no_plots = false, no_paraview = false;
  app.add_flag("--no-plots", no_plots, "skip the PNG plots");
  app.add_flag("--no-paraview", no_paraview, "skip the .pvd/.vtu files");
  app.add_option("--snapshot-times", ropt.snapshot_times_s, "times [s] of the ice views (nearest snapshots); default: window start, middle, end")
      ->delimiter(',');

  auto* compare = app.add_subcommand("compare", "one table (markdown + CSV) and one plot across runs");
  std::vector<fs::path> compare_runs;
  fs::path compare_out = ".";
  compare->add_option("RUN_DIR", compare_runs, "run directories")->required()->check(CLI::ExistingDirectory);
  compare->add_option("--out", compare_out, "output folder")->capture_default_str();

  auto* early = app.add_subcommand(
      "early-stop",
      "replay the early-stop rule (speedups.early_stop_rel_ci) on finished runs: where it would have stopped, the "
      "model time saved, the window mean and the estimate of the full window's it would have reported, and why");
  std::vector<fs::path> early_runs;
  std::vector<double> early_rel{0.02, 0.05, 0.1, 0.2};
  double early_every = 0;
  early->add_option("RUN_DIR", early_runs, "finished run directories (a run stopped early is replayed to its record's end)")
      ->required()
      ->check(CLI::ExistingDirectory);
  early->add_option("--rel-ci", early_rel, "thresholds: 95 % CI as a fraction of the mean")
      ->delimiter(',')
      ->capture_default_str();
  std::vector<std::string> early_trend{"slope"};
  early->add_option("--trend", early_trend,
                    "trend tests: slope (the runners' rule), halves (the rule before the slope test), none (the CI "
                    "alone)")
      ->delimiter(',')
      ->capture_default_str();
  bool early_no_trend = false;
  early->add_flag("--no-trend-check", early_no_trend, "the rule on the CI alone (--trend none; "
                                                      "speedups.early_stop_trend_check: false)");
  early->add_option("--check-every", early_every,
                    "model time between checks [s] (default: the runners', 1/200 of the duration asked for)");

  auto* ensemble = app.add_subcommand(
      "paired-ensemble",
      "a paired-seed ensemble (bench/rank_ensemble.sh): B's effect (B - A) / A of the ensemble means with its 95 % "
      "CI (delta method), as a table and DIR/ensemble-<A>-vs-<B>.json");
  EnsembleSpec espec;
  double tol_pct = 1;
  ensemble->add_option("DIR", espec.dir, "folder holding the runs s<seed>-<run name>")
      ->required()
      ->check(CLI::ExistingDirectory);
  ensemble->add_option("--seeds", espec.seeds, "seeds 1 .. N")->required();
  ensemble->add_option("--case", espec.case_name, "case name (table title, JSON \"case\")")->required();
  ensemble->add_option("--side-a", espec.a.spec, "side A as given to rank_ensemble.sh (JSON \"side_a\")")->required();
  ensemble->add_option("--side-b", espec.b.spec, "side B (JSON \"side_b\")")->required();
  ensemble->add_option("--name-a", espec.a.run_name, "run name of side A: runs are DIR/s<seed>-<name>")->required();
  ensemble->add_option("--name-b", espec.b.run_name, "run name of side B")->required();
  ensemble->add_option("--label-a", espec.a.label, "side A as the table prints it (default: its run name)");
  ensemble->add_option("--label-b", espec.b.label, "side B as the table prints it");
  ensemble->add_option("--tol-pct", tol_pct, "tolerance the CI is tested against [%]")->capture_default_str();

  auto* packing = app.add_subcommand(
      "packing-ensemble",
      "runs of one case on different packings (ice.seed): the mean resistance with its between-packing 95 % CI "
      "(Student t, n - 1 dof), beside each run's own CI, model and full scale, as a table and a JSON summary");
  std::vector<fs::path> packing_runs;
  fs::path packing_out;
  packing->add_option("RUN_DIR", packing_runs, "run folders with case.yaml and report.json (2 or more)")
      ->required()
      ->check(CLI::ExistingDirectory);
  packing->add_option("--out", packing_out,
                      "JSON summary (default: the first run's parent folder / packing-ensemble-<case name>.json)");

  auto* difference = app.add_subcommand(
      "difference", "two separate runs' resistance: relative difference to the reference with the combined 95 % CI "
                    "(JSON)");
  fs::path diff_ref, diff_run;
  difference->add_option("REFERENCE_RUN", diff_ref, "run directory of the reference (with report.json)")
      ->required()
      ->check(CLI::ExistingDirectory);
  difference->add_option("RUN_DIR", diff_run, "run directory compared with it")->required()->check(CLI::ExistingDirectory);

  auto* sample = app.add_subcommand(
      "sample-stats", "mean, sd, standard error and Student-t 95 % CI of independent samples (JSON)");
  std::string sample_source = "-";
  sample->add_option("FILE", sample_source, "numbers separated by white space; - for stdin")->capture_default_str();

#ifdef BRASH_POST_HAVE_STABILITY
  auto* stability = app.add_subcommand(
      "stability",
      "stability verdict of a run: how it ended, hull penetration, sphere overlap, escaped pieces, energy");
  fs::path stability_run, stability_out;
  StabilityOptions sopt;
  double above_water = -1;
  stability->add_option("RUN_DIR", stability_run, "run directory")->required()->check(CLI::ExistingDirectory);
  stability->add_option("--out", stability_out, "JSON file (default RUN_DIR/stability.json)");
  stability->add_option("--above-water-m", above_water,
                        "count pieces whose centre is higher above the water "
                        "(default 2 ice thicknesses)");
  stability->add_option("--silent-penetration-d", sopt.silent_penetration_d, "hull penetration limit [d]")
      ->capture_default_str();
  stability->add_option("--silent-overlap-d", sopt.silent_overlap_d, "sphere overlap limit [d]")
      ->capture_default_str();
  stability->add_option("--silent-energy", sopt.silent_energy_excess, "energy excess limit [N 1/2 m U^2]")
      ->capture_default_str();
#endif

  CLI11_PARSE(app, argc, argv);
  ropt.plots = !no_plots;
  ropt.paraview = !no_paraview;
  try {
    if (fsicr->parsed()) return run_fsicr(p, ice_class);
    if (compare->parsed()) return run_compare(compare_runs, compare_out);
    if (early->parsed())
      return run_early_stop(early_runs, early_rel, early_no_trend ? std::vector<std::string>{"none"} : early_trend,
                            early_every);
    if (difference->parsed()) return run_difference(diff_ref, diff_run);
    if (packing->parsed()) return run_packing_ensemble(packing_runs, packing_out);
    if (sample->parsed()) return run_sample_stats(sample_source);
    if (ensemble->parsed()) {
      espec.tol = tol_pct / 100;
      return run_paired_ensemble(espec);
    }
#ifdef BRASH_POST_HAVE_STABILITY
    if (stability->parsed()) {
      if (above_water > 0) sopt.above_water_m = above_water;
      return run_stability(stability_run, sopt, stability_out);
    }
#endif
    if (run_dir.empty()) {
      std::cerr << app.help();
      return 2;
    }
    return run_report(run_dir, ropt);
  } catch (const brash::InputError& e) {
    fmt::print(stderr, "brash-post: input error: {}\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "brash-post: error: {}\n", e.what());
    return 1;
  }
}
