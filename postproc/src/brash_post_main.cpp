// brash-post: postprocess a run directory (report, plots, ParaView files), print FSICR R_CH for
// given parameters, or compare runs. Thin CLI over brash_post.
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <brash/error.hpp>
#include <brash/post/atomic_write.hpp>
#include <brash/post/fsicr.hpp>
#include <brash/post/report.hpp>

namespace fs = std::filesystem;
using namespace brash::post;

namespace {

int run_report(const fs::path& run_dir) {
  const auto a = analyze_run(run_dir);
  write_file_atomic(run_dir / "report.json", report_json(a).dump(2) + "\n");
  write_file_atomic(run_dir / "report.md", report_markdown(a));
  write_file_atomic(run_dir / "force_history.csv", force_history_csv(a));
  write_file_atomic(run_dir / "blocking.csv", blocking_csv(a.resistance));
  fmt::print("{}: resistance {:.4f} ± {:.4f} N model, {:.1f} ± {:.1f} kN full scale",
             run_dir.string(), a.resistance.mean, a.resistance.ci95, a.resistance_full_kN, a.resistance_full_ci95_kN);
  if (a.fsicr.result) fmt::print("; FSICR R_CH {:.1f} kN", a.fsicr.result->R_CH_N / 1000);
  fmt::print("\n");
  for (const auto& n : a.notes) fmt::print("note: {}\n", n);
  for (const auto& w : a.fsicr.warnings) fmt::print("fsicr warning: {}\n", w);
  return 0;
}

int run_fsicr(const brash::FsicrParams& p, const std::string& ice_class) {
  const auto ic = parse_ice_class(ice_class);
  const auto r = fsicr_channel_resistance(p, ic);
  fmt::print("ice class {}: H_M = {:.3f} m, H_F = {:.3f} m\n", to_string(ic), r.H_M_m, r.H_F_m);
  fmt::print("psi = {:.3f} deg, Cmu = {:.4f}, Cpsi = {:.4f}\n", r.psi_deg, r.Cmu, r.Cpsi);
  fmt::print("(L T / B^2)^3 = {:.3f} (used {:.3f})\n", r.LTB3_raw, r.LTB3_used);
  if (ic == IceClass::IA_super) fmt::print("C1 = {:.1f} N, C2 = {:.1f} N\n", r.C1_N, r.C2_N);
  fmt::print("R_CH = {:.1f} kN\n", r.R_CH_N / 1000);
  for (const auto& w : fsicr_validity_warnings(p)) fmt::print("warning: {}\n", w);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"brash-post: resistance, FSICR, report, plots and ParaView output of a brash run"};
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

  CLI11_PARSE(app, argc, argv);
  try {
    if (fsicr->parsed()) return run_fsicr(p, ice_class);
    if (run_dir.empty()) {
      std::cerr << app.help();
      return 2;
    }
    return run_report(run_dir);
  } catch (const brash::InputError& e) {
    fmt::print(stderr, "brash-post: input error: {}\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "brash-post: error: {}\n", e.what());
    return 1;
  }
}
