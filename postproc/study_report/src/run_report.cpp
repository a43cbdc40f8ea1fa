// One run of the study read from its folder (study.hpp): report.json (brash-post) and meta.json (the runner),
// and a paired-seed ensemble's summary JSON.
#include <cmath>
#include <fstream>

#include <fmt/format.h>

#include <brash/post/study_report/study.hpp>

namespace fs = std::filesystem;
using nlohmann::json;
using Pointer = nlohmann::json::json_pointer;

namespace brash::post::study_report {
namespace {

template <class T>
std::optional<T> opt(const json& j, const Pointer& p) {
  if (!j.contains(p) || j.at(p).is_null()) return std::nullopt;
  try {
    return j.at(p).get<T>();
  } catch (const json::exception&) {
    return std::nullopt;
  }
}

void add_problem(Run& r, const std::string& problem) { r.problem += (r.problem.empty() ? "" : "; ") + problem; }

void read_meta(Run& r) {
  if (r.run_dir.empty()) return;
  if (std::ifstream in(r.run_dir / "meta.json"); in) {
    json m = json::parse(in, nullptr, /*allow_exceptions=*/false);
    if (m.is_object()) r.meta = std::move(m);
  }
}

// The report's numbers of a complete run.
void read_values(const json& j, Run& r) {
  r.ci_N = opt<double>(j, Pointer("/resistance_model_N/ci95")).value_or(NAN);
  r.full_kN = opt<double>(j, Pointer("/resistance_full_kN")).value_or(NAN);
  r.full_ci_kN = opt<double>(j, Pointer("/resistance_full_ci95_kN")).value_or(NAN);
  r.speed = opt<double>(j, Pointer("/speed_m_s")).value_or(NAN);
  r.lambda = opt<double>(j, Pointer("/lambda")).value_or(NAN);
  r.window0 = opt<double>(j, Pointer("/window_s/0")).value_or(NAN);
  r.window1 = opt<double>(j, Pointer("/window_s/1")).value_or(NAN);
  r.t_last = opt<double>(j, Pointer("/record/t_last_s")).value_or(NAN);
  r.wall_s = opt<double>(j, Pointer("/wall_time_s")).value_or(NAN);
  r.psteps = opt<double>(j, Pointer("/particle_steps")).value_or(NAN);
  r.rch_kN = opt<double>(j, Pointer("/fsicr/R_CH_kN"));
  r.ratio = opt<double>(j, Pointer("/ratio_fsicr_to_sim"));
  r.lpp = opt<double>(j, Pointer("/fsicr/params/L_m"));
  r.beam = opt<double>(j, Pointer("/fsicr/params/B_m"));
  r.draft = opt<double>(j, Pointer("/fsicr/params/T_m"));
  r.alpha = opt<double>(j, Pointer("/fsicr/params/alpha_deg"));
  r.phi2 = opt<double>(j, Pointer("/fsicr/params/phi2_deg"));
  r.awf = opt<double>(j, Pointer("/fsicr/params/A_wf_m2"));
}

// Why an otherwise complete report is not complete (truncated or fallback window, gaps in the record).
void add_incomplete_warnings(const json& j, Run& r) {
  if (opt<bool>(j, Pointer("/complete")) != false) return;
  if (opt<bool>(j, Pointer("/window_truncated")).value_or(false)) r.warnings.push_back("window truncated");
  if (opt<bool>(j, Pointer("/window_fallback")).value_or(false)) r.warnings.push_back("window fallback (last half)");
  const json gaps = j.contains(Pointer("/record/gaps_in_window_s")) ? j.at(Pointer("/record/gaps_in_window_s"))
                                                                    : json::array();
  if (gaps.is_array() && !gaps.empty()) {
    std::string list;
    for (const auto& g : gaps)
      list += fmt::format("{}{:.2f}-{:.2f} s", list.empty() ? "" : ", ", g.at(0).get<double>(),
                          g.at(1).get<double>());
    r.warnings.push_back("RECORD HAS GAPS in the window (no force record " + list + ")");
  }
  if (r.warnings.empty()) r.warnings.push_back("report not complete");
}

// The caveats of a complete run's result: incomplete report, CI without a plateau, drift, early stop.
void add_warnings(const json& j, Run& r) {
  add_incomplete_warnings(j, r);
  if (opt<bool>(j, Pointer("/resistance_model_N/blocking/plateau_found")) == false)
    r.warnings.push_back("CI is a lower bound (no blocking plateau)");
  if (opt<bool>(j, Pointer("/resistance_model_N/window_halves/drifts")).value_or(false)) {
    const double a = opt<double>(j, Pointer("/resistance_model_N/window_halves/first_mean")).value_or(NAN);
    const double d = opt<double>(j, Pointer("/resistance_model_N/window_halves/difference")).value_or(NAN);
    r.warnings.push_back(fmt::format("not stationary: the window's second half {:+.1f} % on its first",
                                     100 * d / std::abs(a)));
  }
  // not a problem, but the window ends early: said where the window is read (speedups.early_stop_rel_ci)
  if (const auto t = opt<double>(j, Pointer("/early_stop/t_s")))
    r.warnings.push_back(
        fmt::format("stopped early at t = {:.2f} s of {:g} s (95 % CI below {:g} % of the mean)", *t,
                    opt<double>(j, Pointer("/early_stop/requested_duration_s")).value_or(NAN),
                    100 * opt<double>(j, Pointer("/early_stop/rel_ci_threshold")).value_or(NAN)));
}

// The run's report.json (brash-post), when the runner's exit code and the report's status allow a result.
void read_report(Run& r) {
  const fs::path rp = r.run_dir / "report.json";
  if (!fs::exists(rp)) return add_problem(r, "no report.json");
  json j;
  try {
    std::ifstream in(rp);
    j = json::parse(in);
  } catch (const std::exception& e) {
    return add_problem(r, fmt::format("report.json unreadable ({})", e.what()));
  }
  r.engine = opt<std::string>(j, Pointer("/engine")).value_or("?");
  r.model = opt<std::string>(j, Pointer("/fluid_model")).value_or("?");
  r.case_name = opt<std::string>(j, Pointer("/case")).value_or("?");
  const auto status = opt<std::string>(j, Pointer("/status")).value_or("?");
  const auto mean = opt<double>(j, Pointer("/resistance_model_N/mean"));
  if (status != "complete") add_problem(r, fmt::format("run status '{}'", status));
  if (opt<bool>(j, Pointer("/met_no_ice")).value_or(false))
    add_problem(r, "the hull met no ice in the averaging window (report.json met_no_ice): no resistance");
  else if (!mean)
    add_problem(r, "report.json has no resistance_model_N.mean");
  if (!r.problem.empty()) return;
  r.ok = true;
  r.mean_N = *mean;
  read_values(j, r);
  add_warnings(j, r);
}

}  // namespace

Run load_run(const Row& row, std::string ref) {
  Run r;
  r.ref = std::move(ref);
  r.run_dir = row.run_dir;
  r.command = row.command;
  r.base_case = row.base_case;
  r.exit_code = row.exit_code;
  r.exit_text = row.exit_text;
  if (r.exit_code && *r.exit_code != 0) r.problem = fmt::format("runner exited with code {}", *r.exit_code);
  read_meta(r);
  if (r.exit_text.rfind("in progress", 0) == 0) {
    r.in_progress = true;
    r.problem = r.exit_text;
    // engine and model of a run still going: from its meta.json (written at its start)
    r.engine = r.meta.value("engine", r.engine);
    r.model = r.meta.value("fluid_model", r.model);
    return r;
  }
  if (!r.exit_text.empty()) r.problem = "runner: " + r.exit_text;
  if (r.run_dir.empty()) {
    if (r.problem.empty()) r.problem = "no run directory recorded";
    return r;
  }
  read_report(r);
  return r;
}

bool Paired::resolved() const {
  return effect.has_ci() ? effect.resolved() : std::abs(effect.pair_mean_diff_rel) > effect.pair_mean_ci95_rel;
}

Paired load_paired(const Row& row, int index) {
  Paired p;
  p.ref = fmt::format("P{}", index);
  p.row = row;
  std::ifstream in(row.run_dir);
  if (row.run_dir.empty() || !in) {
    p.problem = fmt::format("no ensemble summary at {}", row.run_dir.string());
    return p;
  }
  try {
    const json j = json::parse(in);
    p.side_a = j.at("side_a").get<std::string>();
    p.side_b = j.at("side_b").get<std::string>();
    p.case_name = j.value("case", std::string("?"));
    p.effect = read_ensemble_summary(j);
    p.pairs = p.effect.pairs;
    p.ok = p.pairs >= 2 && std::isfinite(p.effect.effect_rel) &&
           (p.effect.has_ci() || std::isfinite(p.effect.pair_mean_ci95_rel));
    if (!p.ok) p.problem = fmt::format("{}: fewer than 2 pairs or no finite difference", row.run_dir.string());
  } catch (const json::exception& e) {
    p.problem = fmt::format("{}: {}", row.run_dir.string(), e.what());
  } catch (const std::invalid_argument& e) {
    p.problem = fmt::format("{}: {}", row.run_dir.string(), e.what());
  }
  return p;
}

fs::path source_run_dir(const fs::path& run_dir) {
  std::ifstream in(run_dir / "source_run_dir.txt");
  std::string line;
  if (!in || !std::getline(in, line) || line.empty()) return {};
  return join_logical(run_dir, line);
}

}  // namespace brash::post::study_report
