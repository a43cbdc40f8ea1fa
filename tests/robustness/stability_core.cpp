// brash-stability-core: prints the stability map of the core (stability_core.hpp) as Markdown tables.
//   brash-stability-core [--quick]      (--quick: fewer time steps and a shorter run, for tests)
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "stability_core.hpp"

using namespace brash;
using stability::Cell;
using stability::run_cell;

int main(int argc, char** argv) {
  CLI::App app{"brash-stability-core: the stability map of the core's fluid forces (one ice sphere, "
               "ReferenceSphere) over time step x Ca x treatment x density ratio x impact speed, as Markdown tables "
               "(docs/stability.md)",
               "brash-stability-core"};
  bool quick = false;
  app.add_flag("--quick", quick, "fewer time steps and a shorter run per cell (for tests)");
  CLI11_PARSE(app, argc, argv);
  const double paper_speed = 0.482;
  const std::vector<double> dts = quick ? std::vector<double>{5e-5, 1e-3, 2e-2}
                                        : std::vector<double>{1e-5, 5e-5, 1e-4, 1e-3, 5e-3, 1e-2, 2e-2, 5e-2};
  const std::vector<double> cas = {0, 0.5, 2, 10};
  const std::vector<double> ratios = {0.5, 0.7, 0.9, 0.95, 0.99};
  const std::vector<double> speeds = {0.25, 1.0, 4.0};  // x paper speed
  const double duration = quick ? 0.5 : 2.0;

  fmt::print("# Core stability map (ReferenceSphere, model both, C_D 0.44, d = 0.017578 m, {} s per cell)\n\n", duration);
  fmt::print("Cell = S (stable) or U (unstable); columns: time step [s]. Impact velocity (v0, 0, -v0) at floating "
             "equilibrium, v0 = k x 0.482 m/s.\n\n");
  long stable = 0, total = 0;
  for (const auto treatment : {core::Treatment::Implicit, core::Treatment::Explicit}) {
    fmt::print("## {} treatment\n\n| Ca | rho_i/rho_w | v0 / U_paper | theory m_a/m at rest = Ca |", core::to_string(treatment));
    for (double dt : dts) fmt::print(" {:g} |", dt);
    fmt::print("\n|---|---|---|---|");
    for (std::size_t i = 0; i < dts.size(); ++i) fmt::print("---|");
    fmt::print("\n");
    for (double ca : cas)
      for (double ratio : ratios)
        for (double k : speeds) {
          fmt::print("| {:g} | {:g} | {:g} | {:.2f} |", ca, ratio, k, ca);
          for (double dt : dts) {
            Cell c{.dt_s = dt, .ca = ca, .treatment = treatment, .density_ratio = ratio, .impact_m_s = k * paper_speed,
                   .duration_s = duration};
            const auto r = run_cell(c);
            ++total, stable += r.stable;
            fmt::print(" {} |", r.stable ? "S" : "U");
          }
          fmt::print("\n");
        }
    fmt::print("\n");
  }
  fmt::print("{} of {} cells stable\n\n", stable, total);

  fmt::print("## Explicit boundary vs theory (dt = 5e-5 s)\n\n"
             "Ca_crit: largest uniform Ca with a stable explicit run (bisection, 1e-3). Theory: unstable when "
             "m_a/m = Ca rho_w s / rho_i > 1, s = largest submerged fraction reached, i.e. Ca_crit = rho_i / (rho_w s).\n\n"
             "| rho_i/rho_w | v0 / U_paper | Ca_crit | s_max (at Ca_crit) | theory rho_i/(rho_w s_max) | ratio |\n"
             "|---|---|---|---|---|---|\n");
  for (double ratio : ratios)
    for (double k : speeds) {
      Cell c{.dt_s = 5e-5, .density_ratio = ratio, .impact_m_s = k * paper_speed, .duration_s = duration};
      const double ca_crit = stability::explicit_critical_ca(c, 0.0, 10.0, quick ? 1e-2 : 1e-3);
      c.ca = ca_crit, c.treatment = core::Treatment::Explicit;
      const auto r = run_cell(c);
      const double theory = ratio / r.max_submerged_fraction;
      fmt::print("| {:g} | {:g} | {:.3f} | {:.3f} | {:.3f} | {:.3f} |\n", ratio, k, ca_crit, r.max_submerged_fraction,
                 theory, ca_crit / theory);
    }

  fmt::print("\n## Paper settings (Table 1, rho 900/1000, d = 0.017578 m) and margin\n\n"
             "| table | treatment | v0 / U_paper | dt 5e-5 | largest stable dt (doubling from 5e-5) | margin |\n"
             "|---|---|---|---|---|---|\n");
  for (const auto& [name, table] : {std::pair{"table1", core::CaTable::table1()}, std::pair{"text (Ca_z 2 on reversal)", core::CaTable::text_variant()}})
    for (const auto treatment : {core::Treatment::Implicit, core::Treatment::Explicit})
      for (double k : speeds) {
        Cell c{.dt_s = 5e-5, .ca = -1, .table = table, .treatment = treatment, .density_ratio = 0.9,
               .impact_m_s = k * paper_speed, .duration_s = duration};
        const bool at_paper = run_cell(c).stable;
        double dt_ok = 0;
        for (double dt = 5e-5; dt <= 0.2; dt *= 2) {
          c.dt_s = dt;
          if (!run_cell(c).stable) break;
          dt_ok = dt;
        }
        fmt::print("| {} | {} | {:g} | {} | {:.3g} s | {:.0f}x |\n", name, core::to_string(treatment), k,
                   at_paper ? "stable" : "UNSTABLE", dt_ok, dt_ok / 5e-5);
      }
  return 0;
}
