// The paper case's set-up as each of its runs used it (the run folder's case.yaml and meta.json), beside the
// paper's own set-up (section 3 and Table 1 of the paper; "not stated" where it gives none), with why we
// differ and where that choice is measured (sections.hpp). Started runs count too: the set-up is known before
// the result.
#include <functional>

#include <fmt/format.h>

#include <brash/post/study_report/analysis.hpp>
#include <brash/post/study_report/format.hpp>
#include <brash/post/study_report/sections.hpp>

using nlohmann::json;

namespace brash::post::study_report {
namespace {

struct Column {  // one started paper-case run
  std::string head;
  const brash::Case* c = nullptr;
  const json* meta = nullptr;
  bool ode() const { return meta->value("engine", std::string()) == "ode"; }
  // brash-ode's settings in meta.json, of runs from before the case's ode: section (later: the case's)
  json ode_options() const { return meta->value("ode_options", json::object()); }
  bool old_ode() const { return ode() && meta->contains("ode_options"); }
};

// the contact model's rolling resistance (docs/physics.md), named only when a run has it
std::string rolling(const Column& col) {
  const double mu_r = col.c->contact.rolling_friction;
  return mu_r != 0 ? fmt::format(", rolling resistance μ_r = {}", mu_r) : std::string();
}

std::string our_contacts(const Column& col) {
  if (col.old_ode()) {
    const json o = col.ode_options();
    return fmt::format("ODE rigid, contact joints (ERP {}, CFM {}, {} iterations)", o.value("erp", NAN),
                       o.value("cfm", NAN), o.value("iterations", 0));
  }
  if (col.ode())
    return fmt::format("ODE rigid, contact joints (ERP {}, CFM {}, {} iterations){}", col.c->ode.erp, col.c->ode.cfm,
                       col.c->ode.iterations, rolling(col));
  const auto& contact = col.c->contact;
  return fmt::format("Hertz-Mindlin, E = {:.4g} Pa, ν = {}, e = {}{}", contact.youngs_modulus_pa,
                     contact.poisson_ratio, contact.restitution, rolling(col));
}

std::string our_time_step(const Column& col) {
  const json dt = col.meta->value("dt_s", json());
  return dt.is_number() ? fmt::format("{:g} s", dt.get<double>()) : fmt::format("{:g} s (case)", col.c->run.timestep_s);
}

std::string our_ice(const Column& col) {
  const json n = col.meta->value("particles", json());
  const auto& ice = col.c->ice;
  return fmt::format("{} spheres, d = {:g} m ± {:g} m (cut at ± {:g} sd), porosity {:g}, packing {}",
                     n.is_number() ? fmt::format("{}", n.get<long long>()) : std::string("?"), ice.diameter_mean_m,
                     ice.diameter_sd_m, ice.diameter_truncation_sd, ice.porosity, brash::to_string(ice.packing_mode));
}

std::string our_far_field(const Column& col) {
  if (col.old_ode()) return col.ode_options().value("cull", false) ? "culled (window alone: biased high)" : "every piece integrated";
  const std::string window = col.c->speedups.moving_window ? "; moving window" : "";
  if (!col.c->speedups.farfield) return (window.empty() ? "every piece integrated" : "every piece in the window integrated") + window;
  if (farfield_window_alone(col.c->speedups)) return "far field, window alone (biased high)" + window;
  const WakeBy by = col.c->speedups.farfield_wake_by;
  return (by == WakeBy::Force           ? "far field with the wake rule"
          : by == WakeBy::NeighbourSpeed ? "far field, woken by a neighbour's speed"
                                         : "far field, its front following the push") +
         window;
}

std::string our_channel(const Column& col) {
  // the case's channel.ends; older ODE runs recorded brash-ode's --end-walls in their options instead
  const bool walls = col.c->channel.ends == ChannelEnds::Walls ||
                     (col.old_ode() && col.ode_options().value("end_walls", false));
  return fmt::format("{:g} x {:g} m, side walls, ends {}", col.c->channel.length_m, col.c->channel.width_m,
                     walls ? "walled (x = 0 and x = length)" : "open");
}

struct Item {  // one row of the table
  std::string name;
  std::string text_block;  // the template's <text_block>.paper (the paper's set-up) and <text_block>.why
  std::function<std::string(const Column&)> ours;
};

std::vector<Item> items() {
  return {
      {"engine, contacts", "setup.contacts", our_contacts},
      {"time step", "setup.time_step", our_time_step},
      {"ice pieces", "setup.ice", our_ice},
      {"friction ice-ice / ice-hull", "setup.friction",
       [](const Column& c) { return fmt::format("{:g} / {:g}", c.c->friction.ice_ice, c.c->friction.ice_hull); }},
      {"added mass", "setup.added_mass",
       [](const Column& c) {
         return fmt::format("{}, {}", brash::to_string(c.c->fluid.ca_table), brash::to_string(c.c->fluid.treatment));
       }},
      {"fluid model", "setup.fluid_model",
       [](const Column& c) { return std::string(brash::to_string(c.c->fluid.model)); }},
      {"drag (Eq. 1)", "setup.drag",
       [](const Column& c) {
         return fmt::format("C_D = {:g}, {}", c.c->fluid.drag_coefficient, brash::to_string(c.c->fluid.drag_law));
       }},
      {"idle far-field ice", "setup.far_field", our_far_field},
      {"channel ends", "setup.channel_ends", our_channel},
      {"FSICR R_CH hull parameters", "setup.fsicr",
       [](const Column&) { return std::string("measured on the STL (table above)"); }},
  };
}

std::string setup_table(const std::vector<Column>& cols, const TextTemplate& text) {
  std::string md =
      "### Our paper-case set-up vs the paper's (from each run's case.yaml and meta.json)\n\n| item | paper |";
  for (const auto& c : cols) md += " " + c.head + " |";
  md += " why we differ, and where it is measured |\n|---|---|";
  for (std::size_t i = 0; i < cols.size(); ++i) md += "---|";
  md += "---|\n";
  for (const auto& it : items()) {
    md += fmt::format("| {} | {} |", it.name, text.fill(it.text_block + ".paper"));
    for (const auto& c : cols) md += " " + md_escape(it.ours(c)) + " |";
    md += " " + text.fill(it.text_block + ".why") + " |\n";
  }
  return md + "\n";
}

}  // namespace

std::string section_setup(const Study& s, const TextTemplate& text) {
  std::string md;
  std::vector<Column> cols;
  for (const Run* r : started_paper_case_runs(s)) {
    if (!r->resolved_case) {
      md += fmt::format("(set-up of {} not readable: {})\n\n", r->ref, r->case_error);
      continue;
    }
    cols.push_back({fmt::format("{} ({} {})", r->ref, r->meta.value("engine", std::string("?")),
                                r->meta.value("fluid_model", std::string("?"))),
                    &*r->resolved_case, &r->meta});
  }
  return cols.empty() ? md : md + setup_table(cols, text);
}

}  // namespace brash::post::study_report
