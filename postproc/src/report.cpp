// One run directory -> analysis -> report.json / report.md / CSV text.
#include <brash/post/report.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <optional>
#include <regex>

#include <fmt/format.h>

#include <brash/error.hpp>

namespace brash::post {
namespace {

std::vector<double> slice(const std::vector<double>& v, std::size_t i0, std::size_t i1) {
  return {v.begin() + static_cast<std::ptrdiff_t>(i0), v.begin() + static_cast<std::ptrdiff_t>(i1)};
}

std::vector<double> negated(std::vector<double> v) {
  for (auto& x : v) x = -x;
  return v;
}

// FsicrParams fields by name, so overrides and sources are handled by one loop.
using Field = double FsicrParams::*;
const std::vector<std::pair<std::string, Field>>& fsicr_fields() {
  static const std::vector<std::pair<std::string, Field>> f{
      {"L_m", &FsicrParams::L_m},         {"B_m", &FsicrParams::B_m},
      {"T_m", &FsicrParams::T_m},         {"alpha_deg", &FsicrParams::alpha_deg},
      {"phi1_deg", &FsicrParams::phi1_deg}, {"phi2_deg", &FsicrParams::phi2_deg},
      {"L_par_m", &FsicrParams::L_par_m}, {"L_bow_m", &FsicrParams::L_bow_m},
      {"A_wf_m2", &FsicrParams::A_wf_m2}};
  return f;
}

nlohmann::ordered_json blocking_json(const stats::BlockingResult& b) {
  const auto& L = b.levels[b.level];
  return {{"mean", b.mean}, {"ci95", b.ci95}, {"sem", b.sem}, {"samples", b.n_samples},
          {"block_size", L.block_size}, {"n_blocks", L.n_blocks}, {"correction", b.correction}, {"plateau_found", b.plateau_found}};
}

nlohmann::ordered_json opt(const std::optional<double>& v) { return v ? nlohmann::ordered_json(*v) : nullptr; }

// The record holds contact forces only: samples [i0, i1) all exactly zero mean the hull touched no ice there.
bool no_contact(const ForceHistory& f, std::size_t i0, std::size_t i1) {
  for (std::size_t i = i0; i < i1; ++i)
    if (f.fx_N[i] != 0 || f.fy_N[i] != 0 || f.fz_N[i] != 0) return false;
  return true;
}

// Why a window with no contact has no resistance, and where the record's first contact is.
std::string met_no_ice_note(const ForceHistory& f, const WindowSelection& w) {
  std::string first = "the hull touches no ice anywhere in the record";
  for (std::size_t i = 0; i < f.t_s.size(); ++i)
    if (!no_contact(f, i, i + 1)) {
      first = fmt::format("its first contact is at t = {:.3f} s", f.t_s[i]);
      break;
    }
  return fmt::format("the hull met NO ICE in the averaging window [{:.3f}, {:.3f}] s: every hull force sample there "
                     "is zero (the record holds contact forces only), so there is no resistance to report; {} "
                     "(run longer, or start the window after the bow reaches the ice)",
                     w.used_s[0], w.used_s[1], first);
}

}  // namespace

WindowSelection select_window(std::span<const double> t, std::array<double, 2> w, const std::filesystem::path& source) {
  if (t.size() < 2)
    throw InputError(fmt::format("{}: {} complete record(s), need at least 2 to average", source.string(), t.size()));
  WindowSelection s;
  s.requested_s = w;
  const auto lo = std::lower_bound(t.begin(), t.end(), w[0]);
  const auto hi = std::upper_bound(t.begin(), t.end(), w[1]);
  s.i0 = static_cast<std::size_t>(lo - t.begin());
  s.i1 = static_cast<std::size_t>(hi - t.begin());
  s.truncated = t.back() < w[1];
  if (s.i1 < s.i0 + 2) {  // nothing usable inside the window: take the last half of the record
    s.fallback = true;
    s.i1 = t.size();
    s.i0 = std::min(t.size() / 2, t.size() - 2);  // two samples at least (a record of two has a one-sample half)
  }
  s.used_s = {t[s.i0], t[s.i1 - 1]};
  return s;
}

FsicrParams to_full_scale(const FsicrParams& m, double lambda) {
  FsicrParams f = m;
  f.L_m *= lambda;
  f.B_m *= lambda;
  f.T_m *= lambda;
  f.L_par_m *= lambda;
  f.L_bow_m *= lambda;
  f.A_wf_m2 *= lambda * lambda;
  return f;
}

FsicrSummary resolve_fsicr(const PostCase& c, const std::optional<FsicrParams>& measured) {
  FsicrSummary s;
  s.ice_class = c.ice_class;
  for (const auto& [name, field] : fsicr_fields()) {
    if (measured) {
      s.params.*field = (*measured).*field;
      s.source[name] = "measured";
    } else {
      s.source[name] = "missing";
    }
  }
  if (!measured) {  // main dimensions are known from the case even without the hull tool
    const double lam = c.scale_lambda;
    const std::vector<std::pair<std::string, double>> dims{
        {"L_m", c.lpp_m * lam}, {"B_m", c.beam_m * lam}, {"T_m", c.draft_m * lam}};
    for (const auto& [name, v] : dims)
      if (v > 0) {
        for (const auto& [n2, field] : fsicr_fields())
          if (n2 == name) s.params.*field = v;
        s.source[name] = "case";
      }
    s.params.phi1_deg = 90;  // bulbous bow convention of the rules; only IA Super uses it
    s.source["phi1_deg"] = "default (bulbous bow)";
  }
  for (const auto& [name, v] : c.fsicr_overrides)
    for (const auto& [n2, field] : fsicr_fields())
      if (n2 == name) {
        s.params.*field = v;
        s.source[name] = "override";
      }
  s.params.psi_deg = c.psi_override_deg ? *c.psi_override_deg : fsicr_psi_deg(s.params.alpha_deg, s.params.phi2_deg);
  s.source["psi_deg"] = c.psi_override_deg ? "override" : "computed";
  std::vector<std::string> missing;
  for (const auto& [name, src] : s.source)
    if (src == "missing") missing.push_back(name);
  IceClass ic = IceClass::IA;
  try {
    ic = parse_ice_class(c.ice_class);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: ship.ice_class: {}", c.file.string(), e.what()));
  }
  if (!missing.empty()) {
    s.warnings.push_back(fmt::format("R_CH not computed: missing hull parameter(s) {} (no hull measurement; set them in the case's fsicr: section)",
                                     fmt::join(missing, ", ")));
    return s;
  }
  // values no hull has (a measurement of an odd mesh): no R_CH rather than a meaningless one
  const auto impossible = fsicr_impossible_values(
      s.params, [&](std::string_view field) { return fmt::format("{} ({})", field, s.source.at(std::string(field))); });
  if (!impossible.empty()) {
    s.warnings.push_back(fmt::format("R_CH not computed: {}", fmt::join(impossible, "; ")));
    return s;
  }
  s.result = fsicr_channel_resistance(s.params, ic, {}, c.psi_override_deg);
  s.warnings = fsicr_validity_warnings(s.params);
  return s;
}

namespace {

// FSICR and the published reference: the run's hull and case, with or without a resistance to set them beside.
void finish_analysis(RunAnalysis& a) {
  const auto measured = measure_case_hull_full_scale(a.case_, a.notes);
  a.fsicr = resolve_fsicr(a.case_, measured);
  if (a.fsicr.result && !a.met_no_ice && a.resistance_full_kN > 0)
    a.ratio_fsicr_to_sim = a.fsicr.result->R_CH_N / 1000.0 / a.resistance_full_kN;
  a.reference = published_reference(a.case_.references, run_fluid_model(a));
}

// A run without meta.json (an own LIGGGHTS deck): the fluid model and treatment fix icefluid printed into the deck's
// log ("fix icefluid: model drag, treatment implicit"), the last such line of the first log found; the log's name.
std::optional<std::string> fluid_from_deck_log(const std::filesystem::path& run_dir, RunMeta& meta) {
  static const std::regex line(R"(^fix icefluid: model ([a-z_]+), treatment ([a-z_]+)\s*$)");
  for (const char* name : {"log.liggghts", "log.lammps", "log.txt"}) {
    std::ifstream in(run_dir / name);
    std::string text, model, treatment;
    std::smatch m;
    while (std::getline(in, text))
      if (std::regex_match(text, m, line)) model = m[1], treatment = m[2];
    if (model.empty()) continue;
    meta.fluid_model = model, meta.treatment = treatment;
    return std::string(name);
  }
  return std::nullopt;
}

}  // namespace

RunAnalysis analyze_run(const std::filesystem::path& run_dir) {
  RunAnalysis a;
  a.run_dir = run_dir;
  const bool has_meta = std::filesystem::exists(run_dir / "meta.json");
  if (has_meta) a.meta = read_run_meta(run_dir / "meta.json");
  a.case_ = read_post_case(run_dir / "case.yaml");
  const auto force_path = force_record_file(run_dir);
  a.force = read_force_record(force_path, a.meta.in_progress());
  if (!has_meta) {
    const auto log = fluid_from_deck_log(run_dir, a.meta);
    a.notes.push_back(fmt::format(
        "no meta.json (a run made without a brash runner): engine, run status and cost are unknown, the fluid model "
        "is {}, and the record is taken as it stands: nothing says whether the run finished (docs/case_format.md, "
        "\"A run from your own input\")",
        log ? fmt::format("the deck's own ({}, fix icefluid's line)", *log)
            : std::string("the case's (no log.liggghts, log.lammps or log.txt with fix icefluid's line)")));
  }
  if (force_path.filename() != "hull_force.csv")
    a.notes.push_back(fmt::format("hull force read from {} (fix ave/time: TimeStep t fx fy fz)",
                                  force_path.filename().string()));

  if (a.meta.in_progress())
    a.notes.push_back("run still in progress (meta.json status 'running'): every number is provisional");
  if (a.case_.farfield_window_alone || a.meta.culled_far_field)
    a.notes.push_back("far field with the window alone (speedups.farfield_wake_force_weight: 0, or brash-ode --cull): "
                      "ice outside the window was an immovable wall and the mean resistance is biased high "
                      "(docs/performance.md, \"The idle far field\")");
  if (a.meta.status == "failed")
    a.notes.push_back(fmt::format("run FAILED (meta.json reason: '{}'): numbers cover the record written before the failure", a.meta.reason));
  if (a.force.tail_dropped)
    a.notes.push_back(fmt::format("hull_force.csv: last line incomplete (no newline, run still being written): ignored; {} complete records used",
                                  a.force.t_s.size()));

  a.window = select_window(a.force.t_s, a.case_.window_s, force_path);
  const auto& w = a.window;
  if (w.fallback)
    a.notes.push_back(fmt::format("record ends at t = {:.3f} s, before the averaging window [{}, {}] s starts: "
                                  "the last half of the record [{:.3f}, {:.3f}] s is averaged instead (NOT the paper's window)",
                                  a.force.t_s.back(), w.requested_s[0], w.requested_s[1], w.used_s[0], w.used_s[1]));
  else if (w.truncated)
    a.notes.push_back(fmt::format("record ends at t = {:.3f} s, before the window end {} s: window shortened to [{:.3f}, {:.3f}] s",
                                  a.force.t_s.back(), w.requested_s[1], w.used_s[0], w.used_s[1]));

  a.gaps = record_gaps(a.force.t_s, w.used_s[0], w.used_s[1]);
  if (!a.gaps.empty()) {
    double missing = 0;
    std::string list;
    for (const auto& g : a.gaps) {
      missing += std::min(g.to_s, w.used_s[1]) - std::max(g.from_s, w.used_s[0]);
      list += fmt::format("{}{:.2f}-{:.2f} s", list.empty() ? "" : ", ", g.from_s, g.to_s);
    }
    const double span = w.used_s[1] - w.used_s[0];
    a.notes.push_back(fmt::format(
        "hull_force.csv has {} gap(s) in the window: no record between {} ({:.3g} s, {:.0f} % of the window "
        "missing); every number covers the {:.3g} s recorded, not the whole window",
        a.gaps.size(), list, missing, 100 * missing / span, span - missing));
  }

  a.met_no_ice = no_contact(a.force, w.i0, w.i1);
  if (a.met_no_ice) a.notes.insert(a.notes.begin(), met_no_ice_note(a.force, w));
  a.fx = stats::block_average(slice(a.force.fx_N, w.i0, w.i1));
  a.fy = stats::block_average(slice(a.force.fy_N, w.i0, w.i1));
  a.fz = stats::block_average(slice(a.force.fz_N, w.i0, w.i1));
  const auto resistance_N = negated(slice(a.force.fx_N, w.i0, w.i1));
  a.resistance = stats::block_average(resistance_N);
  for (const auto& part : a.force.split_N) {
    const auto samples = slice(part, w.i0, w.i1);
    a.resistance_split.push_back(stats::block_average(negated(samples)));
    a.split_contact.push_back(std::any_of(samples.begin(), samples.end(), [](double f) { return f != 0; }));
  }
  if (a.force.split_N.empty())
    a.split_not_recorded =
        !a.meta.hull_split_not_recorded.empty() ? a.meta.hull_split_not_recorded
        : force_path.filename() != "hull_force.csv"
            ? fmt::format("not recorded: {} holds the total force only", force_path.filename().string())
            : "not recorded: hull_force.csv has no split columns (a run from before the split, or an engine that "
              "does not record it)";
  if (a.met_no_ice) {  // no resistance: neither its notes nor its full-scale value
    finish_analysis(a);
    return a;
  }
  if (!a.resistance.plateau_found)
    a.notes.push_back("block averaging found no plateau of the variance of the mean: the CI95 is a lower bound "
                      "(window too short for the signal's correlation time)");
  if (w.i1 - w.i0 < kMinTrendSamples) {
    a.notes.push_back(fmt::format("the window holds {} samples: too few to check whether the resistance drifts "
                                  "(its two halves need {} at least); the mean may depend on where the window ends",
                                  w.i1 - w.i0, kMinTrendSamples));
  } else {  // short windows too: a ramp over a short run is the drift most worth flagging
    const auto& t = *(a.resistance_trend = stats::halves_trend(resistance_N));
    if (t.drifts())
      a.notes.push_back(fmt::format(
          "the resistance is not stationary over the window: its second half averages {:.4g} N, the first "
          "{:.4g} N "
          "({:+.1f} %, outside the 95 % CI of the difference, ± {:.2g} N); the window mean depends on where "
          "the "
          "window ends, and its CI95 (block averaging assumes a stationary record) does not count that",
          t.second.mean, t.first.mean, 100 * t.difference / std::abs(t.first.mean), t.ci95));
  }

  const double lam3 = std::pow(a.case_.scale_lambda, 3);
  a.resistance_full_kN = a.resistance.mean * lam3 / 1000.0;
  a.resistance_full_ci95_kN = a.resistance.ci95 * lam3 / 1000.0;
  finish_analysis(a);
  return a;
}

std::string run_fluid_model(const RunAnalysis& a) {
  return a.meta.fluid_model.empty() ? a.case_.fluid_model : a.meta.fluid_model;
}

namespace {

nlohmann::ordered_json reference_json(const RunAnalysis& a) {
  if (!a.reference) return nullptr;
  const auto& r = *a.reference;
  nlohmann::ordered_json j{{"source", r.source},
                           {"fluid_model", r.fluid_model},
                           {"resistance_full_kN", opt(r.resistance_full_kN)},
                           {"fsicr_R_CH_kN", opt(r.fsicr_R_CH_kN)},
                           {"ratio_fsicr_to_sim", opt(r.ratio_fsicr_to_sim)},
                           {"ratio_stated", r.ratio_stated}};
  j["resistance_over_reference"] = r.resistance_full_kN && !a.met_no_ice
                                       ? nlohmann::ordered_json(a.resistance_full_kN / *r.resistance_full_kN)
                                       : nullptr;
  return j;
}

std::string reference_markdown(const RunAnalysis& a) {
  if (!a.reference) return "";
  const auto& r = *a.reference;
  std::string md = fmt::format("## Published reference ({})\n\n| quantity | this run | published |\n|---|---|---|\n",
                               r.source);
  if (r.resistance_full_kN && a.met_no_ice)
    md += fmt::format("| resistance, full scale ({}) | met no ice | {:.0f} kN |\n", r.fluid_model,
                      *r.resistance_full_kN);
  else if (r.resistance_full_kN)
    md += fmt::format("| resistance, full scale ({}) | {:.1f} ± {:.1f} kN | {:.0f} kN (this run {:+.1f} %) |\n",
                      r.fluid_model, a.resistance_full_kN, a.resistance_full_ci95_kN, *r.resistance_full_kN,
                      100 * (a.resistance_full_kN / *r.resistance_full_kN - 1));
  if (r.fsicr_R_CH_kN)
    md += fmt::format("| FSICR R_CH | {} | {:.0f} kN |\n",
                      a.fsicr.result ? fmt::format("{:.1f} kN", a.fsicr.result->R_CH_N / 1000) : "n/a",
                      *r.fsicr_R_CH_kN);
  if (r.ratio_fsicr_to_sim)
    md += fmt::format("| FSICR / simulation | {} | {:.2f} ({}) |\n",
                      a.ratio_fsicr_to_sim ? fmt::format("{:.2f}", *a.ratio_fsicr_to_sim) : "n/a",
                      *r.ratio_fsicr_to_sim, r.ratio_stated ? "stated" : "its R_CH over its resistance");
  return md + "\n";
}

// The resistance table, its block averaging and the stationarity check.
std::string resistance_markdown(const RunAnalysis& a) {
  const auto& L = a.resistance.levels[a.resistance.level];
  std::string md;
  md += fmt::format("| quantity | model scale | full scale |\n|---|---|---|\n"
                    "| mean resistance | {:.4f} ± {:.4f} N | {:.1f} ± {:.1f} kN |\n"
                    "| mean force x, y, z | {:.4f}, {:.4f}, {:.4f} N | |\n\n",
                    a.resistance.mean, a.resistance.ci95, a.resistance_full_kN, a.resistance_full_ci95_kN,
                    a.fx.mean, a.fy.mean, a.fz.mean);
  md += fmt::format("± is the 95 % interval from block averaging (blocks of {} samples, {} blocks, plateau {}). "
                    "Full scale = model * lambda^3.\n\n",
                    L.block_size, L.n_blocks, a.resistance.plateau_found ? "found" : "NOT found");
  if (const auto& t = a.resistance_trend)
    md += fmt::format(
        "Stationarity: the window's first half averages {:.4f} ± {:.4f} N, the second {:.4f} ± {:.4f} N; "
        "difference {:+.4f} ± {:.4f} N ({}).\n\n",
        t->first.mean, t->first.ci95, t->second.mean, t->second.ci95, t->difference, t->ci95,
        t->drifts() ? "**the record drifts**: outside its CI" : "within its CI: no drift detected");
  return md;
}

// The hull force split's rows: what each part is, in kSplitParts' order.
std::array<std::string, 5> split_part_labels(const RunMeta& m) {
  const auto& p = m.hull_split_par_m;
  return {p ? fmt::format("bow (x > {:.3f} m, ahead of the parallel mid-body)", (*p)[1]) : "bow",
          p ? fmt::format("parallel mid-body ({:.3f} to {:.3f} m)", (*p)[0], (*p)[1]) : "parallel mid-body",
          p ? fmt::format("stern (x < {:.3f} m)", (*p)[0]) : "stern",
          "normal (push, along each contact's normal)", "tangential (friction)"};
}

// Where the resistance comes from: the hull force split's table (a few lines), or why there is none.
std::string split_markdown(const RunAnalysis& a) {
  std::string md = "## Where the resistance comes from (hull force split)\n\n";
  if (a.resistance_split.empty())
    return md + fmt::format("The hull force split is {}.\n\n", a.split_not_recorded);
  const double to_kN = std::pow(a.case_.scale_lambda, 3) / 1000.0;
  md += "| part (x: hull frame, from the aft perpendicular) | model scale | share | full scale |\n|---|---|---|---|\n";
  const auto labels = split_part_labels(a.meta);
  for (std::size_t k = 0; k < a.resistance_split.size(); ++k) {
    const auto& b = a.resistance_split[k];
    if (!a.split_contact[k]) {  // every sample exactly zero: the part touched no ice (nothing measured, not 0 N)
      md += fmt::format("| {} | no contact | 0 % | no contact |\n", labels[k]);
      continue;
    }
    md += fmt::format("| {} | {:.4f} ± {:.4f} N | {} | {:.1f} ± {:.1f} kN |\n", labels[k], b.mean, b.ci95,
                      a.resistance.mean != 0 ? fmt::format("{:.0f} %", 100 * b.mean / a.resistance.mean) : "n/a",
                      b.mean * to_kN, b.ci95 * to_kN);
  }
  return md + "\nBow + mid-body + stern and normal + tangential each add up to the resistance (docs/physics.md, "
              "\"The hull force split\").\n\n";
}

// R_CH with the brash thickness in front of the bow that the run measured (full scale) in place of the rule's H_F:
// what the rule's H_F carries. None without the ice around the hull.
std::optional<FsicrResult> fsicr_with_measured_hf(const RunAnalysis& a) {
  if (!a.fsicr.result || !a.ice_around) return std::nullopt;
  return fsicr_channel_resistance(a.fsicr.params, parse_ice_class(a.fsicr.ice_class), {}, a.case_.psi_override_deg,
                                  a.ice_around->H_F_measured_m * a.case_.scale_lambda);
}

// R_CH's terms beside the hull force split's parts, full scale (docs/fsicr_vs_paper.md): the bow term against the
// bow, the mid-body term against the parallel mid-body; the form term and the stern have no counterpart. With the
// ice around the hull, a column of the terms with the run's measured H_F.
std::string fsicr_terms_markdown(const RunAnalysis& a) {
  const auto& r = a.fsicr.result;
  if (!r) return {};
  const bool split = !a.resistance_split.empty() && !a.met_no_ice;
  const double to_kN = std::pow(a.case_.scale_lambda, 3) / 1000.0;
  const auto part = [&](std::size_t k) {
    if (!split) return std::string("not recorded");
    if (!a.split_contact[k]) return std::string("no contact");
    return fmt::format("{:.1f} ± {:.1f} kN", a.resistance_split[k].mean * to_kN, a.resistance_split[k].ci95 * to_kN);
  };
  const auto ratio = [&](double term_N, std::size_t k) {
    if (!split || !a.split_contact[k] || a.resistance_split[k].mean <= 0) return std::string("n/a");
    return fmt::format("{:.2f}", term_N / 1000.0 / (a.resistance_split[k].mean * to_kN));
  };
  const auto m = fsicr_with_measured_hf(a);
  const auto with_hf = [&](double FsicrResult::*term) {
    return m ? fmt::format(" {:.1f} kN |", (*m).*term / 1000) : std::string();
  };
  std::string md = "| FSICR term | R_CH's part | this run's part | term / part |";
  md += m ? fmt::format(" the term with this run's H_F = {:.2f} m |\n|---|---|---|---|---|\n", m->H_F_m)
          : std::string("\n|---|---|---|---|\n");
  md += fmt::format("| bow: C3 Cmu (H_F + H_M)^2 (B + Cpsi H_F) | {:.1f} kN | bow {} | {} |{}\n", r->bow_term_N / 1000,
                    part(0), ratio(r->bow_term_N, 0), with_hf(&FsicrResult::bow_term_N));
  md += fmt::format("| parallel mid-body: C4 L_par H_F^2 | {:.1f} kN | mid-body {} | {} |{}\n",
                    r->midbody_term_N / 1000, part(1), ratio(r->midbody_term_N, 1),
                    with_hf(&FsicrResult::midbody_term_N));
  md += fmt::format("| hull form: C5 (L T / B^2)^3 A_wf / L | {:.1f} kN | (no region: stern {}) | n/a |{}\n",
                    r->form_term_N / 1000, part(2), with_hf(&FsicrResult::form_term_N));
  if (r->C1_N + r->C2_N != 0)
    md += fmt::format("| C1 + C2 (IA Super: the consolidated layer) | {:.1f} kN | (none) | n/a |{}\n",
                      (r->C1_N + r->C2_N) / 1000, m ? fmt::format(" {:.1f} kN |", (m->C1_N + m->C2_N) / 1000) : "");
  if (m)
    md += fmt::format("| R_CH | {:.1f} kN | resistance {:.1f} ± {:.1f} kN | {:.2f} | {:.1f} kN |\n", r->R_CH_N / 1000,
                      a.resistance_full_kN, a.resistance_full_ci95_kN,
                      a.resistance_full_kN > 0 ? r->R_CH_N / 1000 / a.resistance_full_kN : 0.0, m->R_CH_N / 1000);
  return md + "\n";
}

// The ice around the hull (ice_around_hull.hpp): report.json's object, or why there is none.
nlohmann::ordered_json ice_around_json(const RunAnalysis& a) {
  using J = nlohmann::ordered_json;
  if (!a.ice_around) return {{"not_available", a.ice_around_missing}};
  const auto& r = *a.ice_around;
  const auto bands = [](const std::vector<ThicknessBand>& v) {
    J out = J::array();
    for (const auto& b : v) out.push_back({{"from_m", b.from_m}, {"to_m", b.to_m}, {"thickness_m", b.thickness_m}});
    return out;
  };
  J contact = J::object();
  for (std::size_t k = 0; k < kHullRegions.size(); ++k)
    contact[kHullRegions[k]] = {{"wetted_area_m2", r.wetted_area_m2[k]}, {"touched_fraction", r.contact_fraction[k]}};
  contact["all"] = {{"wetted_area_m2", r.wetted_area_all_m2}, {"touched_fraction", r.contact_fraction_all}};
  return {{"window_s", {r.window_s[0], r.window_s[1]}},
          {"snapshots", r.snapshots},
          {"thickness", {{"definition", "ice volume of the pieces centred in a patch per patch area / (1 - porosity)"},
                         {"ice_thickness_m", r.ice_thickness_m},
                         {"band_m", r.band_m},
                         {"strip_m", r.strip_m},
                         {"ahead_of_stem", bands(r.ahead)},
                         {"beside_hull_x", bands(r.beside)}}},
          {"H_F_measured_m", r.H_F_measured_m},
          {"H_F_fsicr_model_m", opt(r.H_F_fsicr_model_m)},
          {"H_M_fsicr_model_m", opt(r.H_M_model_m)},
          {"x_par_m", {r.x_par_m[0], r.x_par_m[1]}},
          {"contact", contact},
          {"touching_pieces_mean", r.touching_pieces_mean},
          {"touching_on_bottom_share", r.on_bottom_share},
          {"deepest_touching_bottom_below_waterline_m", {{"mean", r.deepest_touching_mean_m},
                                                         {"max", r.deepest_touching_max_m}}},
          {"draft_m", r.draft_m},
          {"below_keel", {{"pieces_mean", r.below_keel_pieces_mean}, {"deepest_below_keel_m", r.below_keel_deepest_m}}},
          {"pressure_field", r.pressure_missing.empty() ? J("hull.vtu cell data contact_pressure_Pa")
                                                        : J(nullptr)},
          {"pressure_missing", r.pressure_missing.empty() ? J(nullptr) : J(r.pressure_missing)},
          {"notes", r.notes}};
}

std::string ice_around_markdown(const RunAnalysis& a) {
  std::string md = "## The ice around the hull\n\n";
  if (!a.ice_around) return md + fmt::format("Not available: {}.\n\n", a.ice_around_missing);
  const auto& r = *a.ice_around;
  md += fmt::format("Over the window [{:.3f}, {:.3f}] s ({} snapshots); x in the hull frame, from the aft "
                    "perpendicular. Thickness: the ice volume of the pieces centred in a patch per patch area, over "
                    "(1 - porosity), as the case packs ice.thickness_m = {:.4g} m.\n\n",
                    r.window_s[0], r.window_s[1], r.snapshots, r.ice_thickness_m);
  const auto fsicr = [](const std::optional<double>& v) { return v ? fmt::format("{:.4f} m", *v) : std::string("n/a"); };
  md += fmt::format("| quantity | model scale |\n|---|---|\n"
                    "| brash in front of the bow, next to the stem (0 to {:.3f} m ahead): H_F measured | {:.4f} m |\n"
                    "| FSICR's H_F = 0.26 m + (B H_M)^0.5, / lambda | {} |\n"
                    "| FSICR's H_M of the ice class, / lambda | {} |\n",
                    r.band_m, r.H_F_measured_m, fsicr(r.H_F_fsicr_model_m), fsicr(r.H_M_model_m));
  RunMeta regions = a.meta;  // the regions this section used (meta.json's hull_split, else measured on the hull)
  if (std::isfinite(r.x_par_m[0]) && std::isfinite(r.x_par_m[1])) regions.hull_split_par_m = r.x_par_m;
  const auto labels = split_part_labels(regions);
  for (std::size_t k = 0; k < kHullRegions.size(); ++k)
    md += fmt::format("| wetted hull touched by ice: {} | {:.3g} % of {:.3g} m^2 |\n", labels[k],
                      100 * r.contact_fraction[k], r.wetted_area_m2[k]);
  md += fmt::format("| wetted hull touched by ice: all | {:.3g} % of {:.3g} m^2 |\n"
                    "| pieces touching the hull (per snapshot) | {:.1f}, {:.3g} % of them on the bottom |\n"
                    "| deepest touching piece's bottom below the waterline | {:.4f} m mean, {:.4f} m max (draft "
                    "{:.4f} m) |\n"
                    "| pieces below the keel within the hull's plan (per snapshot) | {:.2f}, deepest {:.4f} m below "
                    "the keel |\n\n",
                    100 * r.contact_fraction_all, r.wetted_area_all_m2, r.touching_pieces_mean, 100 * r.on_bottom_share,
                    r.deepest_touching_mean_m, r.deepest_touching_max_m, r.draft_m, r.below_keel_pieces_mean,
                    r.below_keel_deepest_m);
  md += fmt::format("Thickness ahead of the stem (over the beam) and beside the hull (a strip of a quarter beam "
                    "outside the waterline, both sides): ice_around_hull.png. A piece touches the hull when its "
                    "centre is within {:g} radii of it; the touched share is the touching pieces' cross sections "
                    "pi r^2 (touching below the waterline) over the wetted area: a square array of equal spheres "
                    "against the hull touches pi/4 = 79 % of it; on the bottom: the triangle touched faces down.\n\n",
                    1 + kContactTolerance);
  md += r.pressure_missing.empty()
            ? std::string("hull.vtu (hull frame) holds per triangle the touched share (contact_fraction) and the "
                          "mean contact pressure over the window (contact_pressure_Pa).\n\n")
            : fmt::format("hull.vtu (hull frame) holds per triangle the touched share (contact_fraction). No contact "
                          "pressure: {}.\n\n",
                          r.pressure_missing);
  for (const auto& n : r.notes) md += fmt::format("- {}\n", n);
  return r.notes.empty() ? md : md + "\n";
}

}  // namespace

nlohmann::ordered_json report_json(const RunAnalysis& a) {
  using J = nlohmann::ordered_json;
  J params = J::object();
  for (const auto& [name, field] : fsicr_fields()) params[name] = a.fsicr.params.*field;
  params["psi_deg"] = a.fsicr.params.psi_deg;
  J fsicr{{"ice_class", a.fsicr.ice_class}, {"params", params}, {"source", a.fsicr.source}};
  if (const auto& r = a.fsicr.result) {
    fsicr["R_CH_kN"] = r->R_CH_N / 1000.0;
    fsicr["intermediate"] = {{"H_M_m", r->H_M_m}, {"H_F_m", r->H_F_m}, {"psi_deg", r->psi_deg},
                             {"Cmu", r->Cmu}, {"Cpsi", r->Cpsi}, {"LTB2_cubed_raw", r->LTB3_raw},
                             {"LTB2_cubed_used", r->LTB3_used}, {"C1_N", r->C1_N}, {"C2_N", r->C2_N}};
    fsicr["terms_kN"] = {{"C1_C2", (r->C1_N + r->C2_N) / 1000.0}, {"bow", r->bow_term_N / 1000.0},
                         {"midbody", r->midbody_term_N / 1000.0}, {"form", r->form_term_N / 1000.0}};
    if (const auto m = fsicr_with_measured_hf(a))
      fsicr["with_measured_H_F"] = {{"H_F_m", m->H_F_m},
                                    {"R_CH_kN", m->R_CH_N / 1000.0},
                                    {"terms_kN",
                                     {{"C1_C2", (m->C1_N + m->C2_N) / 1000.0},
                                      {"bow", m->bow_term_N / 1000.0},
                                      {"midbody", m->midbody_term_N / 1000.0},
                                      {"form", m->form_term_N / 1000.0}}}};
  } else {
    fsicr["R_CH_kN"] = nullptr;
  }
  fsicr["warnings"] = a.fsicr.warnings;

  const auto& w = a.window;
  J j;
  j["engine"] = a.meta.engine;
  j["engine_version"] = a.meta.engine_version;
  j["fluid_model"] = run_fluid_model(a);
  j["treatment"] = a.meta.treatment;
  j["case"] = a.case_.name;
  j["status"] = a.meta.status;
  j["complete"] =
      a.meta.status == "complete" && !a.force.tail_dropped && !w.truncated && !w.fallback && a.gaps.empty();
  j["speed_m_s"] = a.case_.speed_m_s;
  j["window_s"] = {w.used_s[0], w.used_s[1]};
  j["window_requested_s"] = {w.requested_s[0], w.requested_s[1]};
  j["window_truncated"] = w.truncated;
  j["window_fallback"] = w.fallback;
  j["record"] = {{"samples", a.force.t_s.size()}, {"t_first_s", a.force.t_s.front()},
                 {"t_last_s", a.force.t_s.back()}, {"incomplete_tail_dropped", a.force.tail_dropped}};
  j["record"]["gaps_in_window_s"] = J::array();
  for (const auto& g : a.gaps) j["record"]["gaps_in_window_s"].push_back({g.from_s, g.to_s});
  j["met_no_ice"] = a.met_no_ice;  // then no resistance: resistance_model_N and the full-scale values are null
  j["resistance_model_N"] = {{"mean", a.resistance.mean}, {"ci95", a.resistance.ci95},
                             {"x", a.fx.mean}, {"y", a.fy.mean}, {"z", a.fz.mean},
                             {"ci95_xyz", {a.fx.ci95, a.fy.ci95, a.fz.ci95}},
                             {"blocking", blocking_json(a.resistance)}};
  if (const auto& t = a.resistance_trend)
    j["resistance_model_N"]["window_halves"] = {{"first_mean", t->first.mean},
                                                {"second_mean", t->second.mean},
                                                {"difference", t->difference},
                                                {"difference_ci95", t->ci95},
                                                {"drifts", t->drifts()}};
  if (a.resistance_split.empty()) {
    j["resistance_split_model_N"] = nullptr;
    j["resistance_split_not_recorded"] = a.split_not_recorded;
  } else {
    J split = J::object();
    for (std::size_t k = 0; k < a.resistance_split.size(); ++k)
      split[kSplitParts[k]] = {{"mean", a.resistance_split[k].mean},
                               {"ci95", a.resistance_split[k].ci95},
                               {"plateau_found", a.resistance_split[k].plateau_found},
                               {"contact", a.split_contact[k]}};
    if (const auto& p = a.meta.hull_split_par_m) split["x_par_m"] = {(*p)[0], (*p)[1]};
    j["resistance_split_model_N"] = split;
  }
  j["lambda"] = a.case_.scale_lambda;
  j["resistance_full_kN"] = a.resistance_full_kN;
  j["resistance_full_ci95_kN"] = a.resistance_full_ci95_kN;
  if (a.met_no_ice)
    for (const char* key : {"resistance_model_N", "resistance_full_kN", "resistance_full_ci95_kN",
                            "resistance_split_model_N"})
      j[key] = nullptr;
  j["fsicr"] = fsicr;
  j["ratio_fsicr_to_sim"] = opt(a.ratio_fsicr_to_sim);
  j["wall_time_s"] = opt(a.meta.wall_time_s);
  j["particle_steps"] = opt(a.meta.particle_steps);
  j["exits"] = a.meta.exits;  // pieces that left through the channel's open ends (removed from the scene)
  if (const auto& e = a.meta.early_stop) {
    j["early_stop"] = {{"t_s", e->t_s},
                       {"requested_duration_s", e->requested_duration_s},
                       {"rel_ci_threshold", e->rel_ci_threshold}};
    if (!e->reason.empty()) j["early_stop"]["reason"] = e->reason;
    if (e->estimate_N && e->estimate_ci95_N) {
      // the full window's mean as the rule estimated it at the stop (the drift extrapolated, its CI counted)
      j["early_stop"]["full_window_estimate_N"] = *e->estimate_N;
      j["early_stop"]["full_window_estimate_ci95_N"] = *e->estimate_ci95_N;
    }
  }
  if (const auto& e = a.meta.early_stop_last_check)
    j["early_stop_last_check"] = {{"t_s", e->t_s}, {"reason", e->reason}};
  j["reference"] = reference_json(a);  // null: the case declares no published values
  if (a.band)
    j["contact_band"] = {{"band_below_m", a.band->band_below_m},
                         {"deepest_piece_bottom_below_waterline_m", a.band->deepest_bottom_m},
                         {"deepest_t_s", a.band->deepest_t_s},
                         {"pieces_below_band_max", a.band->pieces_below_max},
                         {"pieces_below_band_t_s", a.band->pieces_below_t_s},
                         {"snapshots", a.band->snapshots},
                         {"ok", !a.band->passed_under()}};
  j["ice_around_hull"] = ice_around_json(a);
  j["notes"] = a.notes;
  return j;
}

std::string report_markdown(const RunAnalysis& a) {
  const auto& w = a.window;
  const auto fluid = run_fluid_model(a);
  // the run folder's own name, also for "." or a path ending in '/'
  const std::string name = std::filesystem::weakly_canonical(std::filesystem::absolute(a.run_dir)).filename().string();
  std::string md = fmt::format("# brash run report: {}\n\n", name);
  if (!a.notes.empty()) {
    md += "## Read first\n\n";
    for (const auto& n : a.notes) md += fmt::format("- **{}**\n", n);
    md += "\n";
  }
  md += fmt::format("| item | value |\n|---|---|\n| case | {} |\n| engine | {} {} |\n| fluid model / treatment | {} / {} |\n"
                    "| status | {} |\n| ship speed | {} m/s (model) |\n| scale lambda | {} |\n",
                    a.case_.name, a.meta.engine, a.meta.engine_version, fluid, a.meta.treatment, a.meta.status,
                    a.case_.speed_m_s, a.case_.scale_lambda);
  md += fmt::format("| averaging window | [{:.3f}, {:.3f}] s (requested [{}, {}] s){} |\n", w.used_s[0], w.used_s[1],
                    w.requested_s[0], w.requested_s[1], w.fallback ? " FALLBACK" : (w.truncated ? " TRUNCATED" : ""));
  if (const auto& e = a.meta.early_stop)
    md += fmt::format(
        "| early stop | at t = {:.3f} s of the {} s asked for: the window mean's 95 % CI had fallen below "
        "{} % of it (speedups.early_stop_rel_ci); the window ends there |\n",
        e->t_s, e->requested_duration_s, 100 * e->rel_ci_threshold);
  if (const auto& e = a.meta.early_stop; e && !e->reason.empty())
    md += fmt::format("| early stop: why | {}{} |\n", e->reason,
                      e->estimate_N && e->estimate_ci95_N
                          ? fmt::format("; the full window{} estimated {:.4g} +- {:.3g} N (drift extrapolated)",
                                        e->requested_window_end_s
                                            ? fmt::format(" (to {} s)", *e->requested_window_end_s)
                                            : std::string(),
                                        *e->estimate_N, *e->estimate_ci95_N)
                          : std::string());
  if (const auto& e = a.meta.early_stop_last_check)
    md += fmt::format("| early stop | did not hold; at its last check (t = {:.3f} s): {} |\n", e->t_s, e->reason);
  md += fmt::format(
      "| wall time | {} |\n| particle steps | {} |\n| pieces gone through the channel's ends | {} |\n\n",
      a.meta.wall_time_s ? fmt::format("{:.1f} s", *a.meta.wall_time_s) : "n/a",
      a.meta.particle_steps ? fmt::format("{:.4g}", *a.meta.particle_steps) : "n/a", a.meta.exits);
  md += "## Resistance (resistance = -fx, force of the ice on the hull, contacts only)\n\n";
  if (a.met_no_ice)
    md += fmt::format("**The hull met no ice in the averaging window [{:.3f}, {:.3f}] s**: every force sample there is "
                      "zero, so this run has no resistance (see \"Read first\").\n\n",
                      w.used_s[0], w.used_s[1]);
  else
    md += resistance_markdown(a) + split_markdown(a);
  md += ice_around_markdown(a);
  md += fmt::format("## FSICR channel resistance (ice class {})\n\n| parameter | value | source |\n|---|---|---|\n", a.fsicr.ice_class);
  for (const auto& [name, field] : fsicr_fields())
    md += fmt::format("| {} | {:.4g} | {} |\n", name, a.fsicr.params.*field, a.fsicr.source.at(name));
  md += fmt::format("| psi_deg | {:.4g} | {} |\n\n", a.fsicr.params.psi_deg, a.fsicr.source.at("psi_deg"));
  if (const auto& r = a.fsicr.result)
    md += fmt::format("R_CH = **{:.1f} kN** (H_F {:.3f} m, H_M {:.1f} m, Cmu {:.4f}, Cpsi {:.4f}, (LT/B^2)^3 {:.2f} used {:.2f}).\n\n",
                      r->R_CH_N / 1000, r->H_F_m, r->H_M_m, r->Cmu, r->Cpsi, r->LTB3_raw, r->LTB3_used);
  for (const auto& wmsg : a.fsicr.warnings) md += fmt::format("- warning: {}\n", wmsg);
  md += "\n" + fsicr_terms_markdown(a);
  if (a.ratio_fsicr_to_sim) md += fmt::format("FSICR / simulation = **{:.2f}**.\n\n", *a.ratio_fsicr_to_sim);
  md += reference_markdown(a);
  return md;
}

std::string force_history_csv(const RunAnalysis& a) {
  std::string s = "t_s,fx_N,fy_N,fz_N,resistance_N,in_window\n";
  const auto& f = a.force;
  for (std::size_t i = 0; i < f.t_s.size(); ++i)
    s += fmt::format("{},{},{},{},{},{}\n", f.t_s[i], f.fx_N[i], f.fy_N[i], f.fz_N[i], -f.fx_N[i],
                     (i >= a.window.i0 && i < a.window.i1) ? 1 : 0);
  return s;
}

std::string blocking_csv(const stats::BlockingResult& b) {
  std::string s = "level,block_size,n_blocks,var_of_mean,var_error,lag1_corr,chosen\n";
  for (std::size_t k = 0; k < b.levels.size(); ++k) {
    const auto& L = b.levels[k];
    s += fmt::format("{},{},{},{},{},{},{}\n", k, L.block_size, L.n_blocks, L.var_of_mean, L.var_error, L.lag1_corr, k == b.level ? 1 : 0);
  }
  return s;
}

}  // namespace brash::post
