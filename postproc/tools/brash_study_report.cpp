// brash-study-report: the study document (docs/study.md) generated from a study manifest and the
// report.json of every run it lists (issue 11). Nothing in the document is typed by hand: every number
// comes from a report.json and every run is listed with the command that produced it.
//
// Manifest (tab-separated, one header line naming the columns, '#' lines are comments):
//   id  group  label  param  value  baseline  base_case  exit_code  run_dir  command
// required: group, run_dir, command; the others may be empty. One run may appear in several rows
// (e.g. the baseline run is the reference of every sensitivity group). run_dir is relative to the
// manifest's folder unless absolute.
// Groups: `paper` (table a), `speed` (table b, value = speed), `engine` (table d), `paired` (a paired-seed
// ensemble: run_dir is the summary JSON of bench/rank_ensemble.sh, param / value the change of its side B on
// its side A; table c and the gap's candidates), anything else is a sensitivity group (table c) whose rows
// with baseline = 1 are the reference.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <brash/case.hpp>
#include <brash/error.hpp>
#include <brash/post/force_history.hpp>
#include <brash/post/report.hpp>
#include <brash/stats/power_law.hpp>

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct Row {  // one manifest row
  std::string id, group, label, param, value, base_case, command, exit_text;
  bool baseline = false;
  std::optional<int> exit_code;
  fs::path run_dir;
};

struct Run {  // one run directory (several rows may share it)
  std::string ref;  // R1, R2, ... in order of first appearance
  fs::path run_dir;
  std::string command, base_case;
  std::optional<int> exit_code;
  std::string exit_text;
  bool ok = false;
  std::string problem;  // why the run is not usable (missing, failed, ...)
  bool in_progress = false;  // exit_code column "in progress: ..." (a long run resumed in pieces, not failed)
  std::vector<std::string> warnings;
  std::string engine = "?", model = "?", case_name = "?";
  double mean_N = 0, ci_N = 0, full_kN = 0, full_ci_kN = 0, speed = 0, lambda = 0;
  double window0 = 0, window1 = 0, t_last = 0, wall_s = 0, psteps = 0;
  std::optional<double> rch_kN, ratio;
  std::optional<double> lpp, beam, draft, alpha, phi2, awf;
  json meta = json::object();  // the run's meta.json (empty object when missing or unreadable), read once
};

std::string trim(std::string s) {
  while (!s.empty() && (s.back() == '\r' || s.back() == ' ')) s.pop_back();
  std::size_t i = 0;
  while (i < s.size() && s[i] == ' ') ++i;
  return s.substr(i);
}

std::vector<std::string> split_tabs(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string f;
  while (std::getline(ss, f, '\t')) out.push_back(trim(f));
  if (!line.empty() && line.back() == '\t') out.emplace_back();
  return out;
}

// P (absolute, or relative to BASE) joined lexically: brash-study writes logical paths (realpath -s), which may
// pass through a symlinked folder (runs/ -> elsewhere), where the file system's ".." would climb from the link's
// target instead.
fs::path join_logical(const fs::path& base, const fs::path& p) {
  return (p.is_absolute() ? p : base / p).lexically_normal();
}

std::vector<Row> read_manifest(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(fmt::format("{}: cannot open the manifest", path.string()));
  std::vector<std::string> header;
  std::vector<Row> rows;
  std::string line;
  int lineno = 0;  // for messages
  const fs::path base = fs::absolute(path).parent_path();
  while (std::getline(in, line)) {
    ++lineno;
    if (trim(line).empty() || line[0] == '#') continue;
    auto f = split_tabs(line);
    if (header.empty()) {
      header = f;
      for (const char* need : {"group", "run_dir", "command"})
        if (std::find(header.begin(), header.end(), need) == header.end())
          throw std::runtime_error(fmt::format("{}: header lacks the column '{}'", path.string(), need));
      continue;
    }
    std::map<std::string, std::string> m;
    for (std::size_t i = 0; i < header.size(); ++i) m[header[i]] = i < f.size() ? f[i] : "";
    Row r;
    r.id = m["id"];
    r.group = m["group"];
    r.label = m["label"];
    r.param = m["param"];
    r.value = m["value"];
    r.base_case = m["base_case"];
    r.command = m["command"];
    r.baseline = m["baseline"] == "1" || m["baseline"] == "yes" || m["baseline"] == "true";
    if (!m["exit_code"].empty()) {  // an integer, or a text saying why nothing ran ("not run", ...)
      std::size_t used = 0;
      try {
        r.exit_code = std::stoi(m["exit_code"], &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != m["exit_code"].size()) {
        r.exit_code.reset();
        r.exit_text = m["exit_code"];
      }
    }
    if (r.group.empty()) throw std::runtime_error(fmt::format("{}:{}: empty group", path.string(), lineno));
    if (!m["run_dir"].empty()) {
      fs::path d = m["run_dir"];
      r.run_dir = join_logical(base, d);
    }
    rows.push_back(r);
  }
  if (header.empty()) throw std::runtime_error(fmt::format("{}: empty manifest", path.string()));
  return rows;
}

template <class T>
std::optional<T> opt(const json& j, const json::json_pointer& p) {
  if (!j.contains(p) || j.at(p).is_null()) return std::nullopt;
  try {
    return j.at(p).get<T>();
  } catch (const json::exception&) {
    return std::nullopt;
  }
}

void load_report(Run& r) {
  if (r.exit_code && *r.exit_code != 0) r.problem = fmt::format("runner exited with code {}", *r.exit_code);
  if (!r.run_dir.empty()) {
    if (std::ifstream in(r.run_dir / "meta.json"); in) {
      json m = json::parse(in, nullptr, /*allow_exceptions=*/false);
      if (m.is_object()) r.meta = std::move(m);
    }
  }
  if (r.exit_text.rfind("in progress", 0) == 0) {
    r.in_progress = true;
    r.problem = r.exit_text;
    // engine and model of a run still going: from its meta.json (written at its start)
    r.engine = r.meta.value("engine", r.engine);
    r.model = r.meta.value("fluid_model", r.model);
    return;
  }
  if (!r.exit_text.empty()) r.problem = "runner: " + r.exit_text;
  if (r.run_dir.empty()) {
    if (r.problem.empty()) r.problem = "no run directory recorded";
    return;
  }
  const fs::path rp = r.run_dir / "report.json";
  if (!fs::exists(rp)) {
    r.problem += (r.problem.empty() ? "" : "; ") + std::string("no report.json");
    return;
  }
  json j;
  try {
    std::ifstream in(rp);
    j = json::parse(in);
  } catch (const std::exception& e) {
    r.problem += (r.problem.empty() ? "" : "; ") + fmt::format("report.json unreadable ({})", e.what());
    return;
  }
  using P = json::json_pointer;
  r.engine = opt<std::string>(j, P("/engine")).value_or("?");
  r.model = opt<std::string>(j, P("/fluid_model")).value_or("?");
  r.case_name = opt<std::string>(j, P("/case")).value_or("?");
  const auto status = opt<std::string>(j, P("/status")).value_or("?");
  const auto mean = opt<double>(j, P("/resistance_model_N/mean"));
  if (status != "complete")
    r.problem += (r.problem.empty() ? "" : "; ") + fmt::format("run status '{}'", status);
  if (!mean) r.problem += (r.problem.empty() ? "" : "; ") + std::string("report.json has no resistance_model_N.mean");
  if (!r.problem.empty()) return;
  r.ok = true;
  r.mean_N = *mean;
  r.ci_N = opt<double>(j, P("/resistance_model_N/ci95")).value_or(NAN);
  r.full_kN = opt<double>(j, P("/resistance_full_kN")).value_or(NAN);
  r.full_ci_kN = opt<double>(j, P("/resistance_full_ci95_kN")).value_or(NAN);
  r.speed = opt<double>(j, P("/speed_m_s")).value_or(NAN);
  r.lambda = opt<double>(j, P("/lambda")).value_or(NAN);
  r.window0 = opt<double>(j, P("/window_s/0")).value_or(NAN);
  r.window1 = opt<double>(j, P("/window_s/1")).value_or(NAN);
  r.t_last = opt<double>(j, P("/record/t_last_s")).value_or(NAN);
  r.wall_s = opt<double>(j, P("/wall_time_s")).value_or(NAN);
  r.psteps = opt<double>(j, P("/particle_steps")).value_or(NAN);
  r.rch_kN = opt<double>(j, P("/fsicr/R_CH_kN"));
  r.ratio = opt<double>(j, P("/ratio_fsicr_to_sim"));
  r.lpp = opt<double>(j, P("/fsicr/params/L_m"));
  r.beam = opt<double>(j, P("/fsicr/params/B_m"));
  r.draft = opt<double>(j, P("/fsicr/params/T_m"));
  r.alpha = opt<double>(j, P("/fsicr/params/alpha_deg"));
  r.phi2 = opt<double>(j, P("/fsicr/params/phi2_deg"));
  r.awf = opt<double>(j, P("/fsicr/params/A_wf_m2"));
  if (opt<bool>(j, P("/complete")) == false) {
    if (opt<bool>(j, P("/window_truncated")).value_or(false)) r.warnings.push_back("window truncated");
    if (opt<bool>(j, P("/window_fallback")).value_or(false)) r.warnings.push_back("window fallback (last half)");
    const json gaps =
        j.contains(P("/record/gaps_in_window_s")) ? j.at(P("/record/gaps_in_window_s")) : json::array();
    if (gaps.is_array() && !gaps.empty()) {
      std::string list;
      for (const auto& g : gaps)
        list += fmt::format("{}{:.2f}-{:.2f} s", list.empty() ? "" : ", ", g.at(0).get<double>(),
                            g.at(1).get<double>());
      r.warnings.push_back("RECORD HAS GAPS in the window (no force record " + list + ")");
    }
    if (r.warnings.empty()) r.warnings.push_back("report not complete");
  }
  if (opt<bool>(j, P("/resistance_model_N/blocking/plateau_found")) == false)
    r.warnings.push_back("CI is a lower bound (no blocking plateau)");
  if (opt<bool>(j, P("/resistance_model_N/window_halves/drifts")).value_or(false)) {
    const double a = opt<double>(j, P("/resistance_model_N/window_halves/first_mean")).value_or(NAN);
    const double d = opt<double>(j, P("/resistance_model_N/window_halves/difference")).value_or(NAN);
    r.warnings.push_back(fmt::format("not stationary: the window's second half {:+.1f} % on its first",
                                     100 * d / std::abs(a)));
  }
  // not a problem, but the window ends early: said where the window is read (speedups.early_stop_rel_ci)
  if (const auto t = opt<double>(j, P("/early_stop/t_s")))
    r.warnings.push_back(
        fmt::format("stopped early at t = {:.2f} s of {:g} s (95 % CI below {:g} % of the mean)", *t,
                    opt<double>(j, P("/early_stop/requested_duration_s")).value_or(NAN),
                    100 * opt<double>(j, P("/early_stop/rel_ci_threshold")).value_or(NAN)));
}

// ---- numbers --------------------------------------------------------------------------------------
std::string num(double v, int prec = 2) {
  if (!std::isfinite(v)) return "n/a";
  return fmt::format("{:.{}f}", v, prec);
}
std::string pm(double v, double ci, int prec = 2) { return fmt::format("{} ± {}", num(v, prec), num(ci, prec)); }
std::string optnum(const std::optional<double>& v, int prec = 2) { return v ? num(*v, prec) : "n/a"; }

// R = a U^n per engine and fluid model (R in N at model scale, U in m/s): brash/stats/power_law.hpp.
struct Fit : brash::stats::PowerLawFit {
  std::string engine, model;
  std::vector<std::string> refs;
};

std::string scale_label(const Run& r) {
  const std::string window = fmt::format("window [{}, {}] s", num(r.window0), num(r.window1));
  if (r.base_case == "jbc_ia_5kn")
    return fmt::format("paper case jbc_ia_5kn, {}", window);
  return fmt::format("**reduced case** ({} based on {}; not the paper case), {}", r.case_name,
                     r.base_case.empty() ? std::string("?") : r.base_case, window);
}

std::string status_cell(const Run& r) {
  if (r.in_progress) return "**IN PROGRESS** (" + r.problem + ")";
  if (!r.ok) return "**FAILED/MISSING: " + r.problem + "**";
  std::string s;
  for (const auto& w : r.warnings) s += (s.empty() ? "" : "; ") + w;
  return s.empty() ? "ok" : s;
}

// A paired-seed ensemble's summary (bench/rank_ensemble.sh: OUT/ensemble-<A>-vs-<B>.json): every packing seed
// run as side A and as side B, the mean of the paired differences (B - A) / mean of the pair with its
// 95 % CI.
struct Paired {
  std::string ref;  // P1, P2, ...
  const Row* row = nullptr;
  bool ok = false;
  std::string problem;
  std::string side_a, side_b, case_name;
  int pairs = 0;
  double mean_a_N = NAN, mean_b_N = NAN, diff_rel = NAN, ci95_rel = NAN;
  bool resolved() const { return std::abs(diff_rel) > ci95_rel; }
};

Paired load_paired(const Row& row, int index) {
  Paired p;
  p.ref = fmt::format("P{}", index);
  p.row = &row;
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
    p.pairs = j.at("pairs").get<int>();
    p.mean_a_N = j.at("mean_a_N").get<double>();
    p.mean_b_N = j.at("mean_b_N").get<double>();
    p.diff_rel = j.at("diff_rel").get<double>();
    p.ci95_rel = j.at("ci95_rel").get<double>();
    p.ok = p.pairs >= 2 && std::isfinite(p.diff_rel) && std::isfinite(p.ci95_rel);
    if (!p.ok)
      p.problem = fmt::format("{}: fewer than 2 pairs or no finite difference", row.run_dir.string());
  } catch (const json::exception& e) {
    p.problem = fmt::format("{}: {}", row.run_dir.string(), e.what());
  }
  return p;
}

// The fluid model a side runs ("fluid.model=X" among its edits), else the case's own (the label when the
// manifest row has none).
std::string side_model(const std::string& side) {
  const auto at = side.find("fluid.model=");
  if (at == std::string::npos) return "case default";
  const auto from = at + std::string("fluid.model=").size();
  return side.substr(from, side.find(',', from) - from);
}

struct Study {
  std::vector<Row> rows;
  std::vector<Row> paired_rows;  // group `paired`, kept apart from the run rows
  std::vector<Paired> paired;
  std::map<fs::path, Run> runs;  // by run dir (empty path: one per failed row, keyed by a fake path)
  std::vector<fs::path> order;
  Run& run_of(const Row& r) { return runs.at(key_of(r)); }
  std::map<const Row*, fs::path> keys;
  fs::path key_of(const Row& r) const { return keys.at(&r); }
  brash::ReferenceSpec paper;  // the paper case's published values (its case.yaml's references)
};

void build(Study& s) {
  int fake = 0;
  for (const auto& row : s.rows) {
    fs::path key = row.run_dir.empty() ? fs::path(fmt::format("<no run dir #{}>", ++fake)) : row.run_dir.lexically_normal();
    s.keys[&row] = key;
    auto it = s.runs.find(key);
    if (it == s.runs.end()) {
      Run r;
      r.ref = fmt::format("R{}", s.order.size() + 1);
      r.run_dir = row.run_dir;
      r.command = row.command;
      r.base_case = row.base_case;
      r.exit_code = row.exit_code;
      r.exit_text = row.exit_text;
      load_report(r);
      s.runs.emplace(key, r);
      s.order.push_back(key);
    } else if (row.exit_code && *row.exit_code != 0 && it->second.ok) {
      it->second.ok = false;
      it->second.problem = fmt::format("runner exited with code {}", *row.exit_code);
    }
  }
}

// Run directories are shown relative to the working directory when they lie below it (repo-relative
// paths when the study is generated from the repository root). Lexically first: a run folder reached through
// a symbolic link below the working directory (runs -> /elsewhere/runs) is still shown as runs/...
std::string show_path(const fs::path& p) {
  if (p.empty()) return "";
  const auto below = [](const fs::path& rel) { return !rel.empty() && *rel.begin() != ".."; };
  const fs::path lexical = fs::absolute(p).lexically_normal().lexically_relative(fs::current_path());
  if (below(lexical)) return lexical.string();
  std::error_code ec;
  const fs::path rel = fs::relative(p, fs::current_path(), ec);
  if (!ec && below(rel)) return rel.string();
  return p.string();
}

// The full run directory of a folder that holds a copy of a run's outputs (brash-study writes its path,
// relative to the copy itself, to source_run_dir.txt in the copy); empty for a run directory itself. Resolved
// against the copy, so the tool finds it from any working directory.
fs::path source_run_dir(const fs::path& run_dir) {
  std::ifstream in(run_dir / "source_run_dir.txt");
  std::string line;
  if (!in || !std::getline(in, line) || line.empty()) return {};
  return join_logical(run_dir, line);
}

std::string md_escape(std::string s) {
  std::string o;
  for (char c : s) {
    if (c == '|') o += "\\|";
    else o += c;
  }
  return o;
}

// ---- sections -------------------------------------------------------------------------------------
void section_failures(const Study& s, std::string& md) {
  std::vector<const Run*> bad, running;
  for (const auto& k : s.order) {
    const Run& r = s.runs.at(k);
    if (r.in_progress) running.push_back(&r);
    else if (!r.ok) bad.push_back(&r);
  }
  if (!running.empty()) {
    md += fmt::format(
        "## Runs in progress\n\n{} run(s) have no result yet: still running (resumed in pieces), or "
        "stopped part-way with the machine that ran them (the state says which, and how far each got); "
        "their rows below have no result.\n\n| run | run dir | state |\n|---|---|---|\n",
        running.size());
    for (const Run* r : running)
      md += fmt::format("| {} | `{}` | {} |\n", r->ref, show_path(r->run_dir), md_escape(r->problem));
    md += "\n";
  }
  md += "## Runs that failed or are missing\n\n";
  std::vector<const Paired*> missing;
  for (const Paired& p : s.paired)
    if (!p.ok) missing.push_back(&p);
  if (!missing.empty()) {
    md += fmt::format("**{} paired ensemble(s) have no usable summary** (kept in section (c)):\n\n",
                      missing.size());
    for (const Paired* p : missing) md += fmt::format("- {}: {}\n", p->ref, md_escape(p->problem));
    md += "\n";
  }
  if (bad.empty()) {
    md += running.empty() ? "None: every run listed in the manifest has a complete report.json.\n\n"
                          : "None: every other run listed in the manifest has a complete report.json.\n\n";
    return;
  }
  md += fmt::format("**{} of {} run(s) have no usable result.** They are kept in every table below with "
                    "their reason, never dropped.\n\n| run | run dir | reason |\n|---|---|---|\n",
                    bad.size(), s.order.size());
  for (const Run* r : bad)
    md += fmt::format("| {} | `{}` | {} |\n", r->ref, show_path(r->run_dir), md_escape(r->problem));
  md += "\n";
}

// The completed runs of a manifest group, each once, in manifest order.
std::vector<const Run*> completed_runs(Study& s, const std::string& group) {
  std::vector<const Run*> runs;
  for (const auto& row : s.rows) {
    if (row.group != group) continue;
    const Run& r = s.run_of(row);
    if (r.ok && std::find(runs.begin(), runs.end(), &r) == runs.end()) runs.push_back(&r);
  }
  return runs;
}
bool any_paper_case(const std::vector<const Run*>& runs) {
  return std::any_of(runs.begin(), runs.end(), [](const Run* r) { return r->base_case == "jbc_ia_5kn"; });
}

// The paper case's runs of section (a) that have started (their run folder holds the resolved case.yaml),
// each once, in manifest order: what the set-up table and the history plot read, finished or not.
std::vector<const Run*> started_paper_case_runs(Study& s) {
  std::vector<const Run*> runs;
  std::set<fs::path> seen;
  for (const auto& row : s.rows) {
    if (row.group != "paper" || row.base_case != "jbc_ia_5kn") continue;
    const Run& r = s.run_of(row);
    if (!r.run_dir.empty() && seen.insert(r.run_dir).second && fs::exists(r.run_dir / "case.yaml"))
      runs.push_back(&r);
  }
  return runs;
}

// The paper's full-scale resistance for a fluid model, as the paper case declares it (NaN: none declared).
double paper_full_kN(const brash::ReferenceSpec& paper, const std::string& model) {
  const auto r = brash::post::published_reference(paper, model);
  return r && r->resistance_full_kN ? *r->resistance_full_kN : NAN;
}

// The paper's FSICR / simulation ratio for a fluid model: as stated where the case declares it, else derived
// from its two published numbers (the paper states no ratio for drag; brash::post::published_reference).
std::string paper_ratio_cell(const brash::ReferenceSpec& paper, const std::string& model) {
  const auto r = brash::post::published_reference(paper, model);
  if (!r || !r->ratio_fsicr_to_sim) return "n/a";
  if (r->ratio_stated) return fmt::format("{:.2f}", *r->ratio_fsicr_to_sim);
  return fmt::format("{:.2f} ({:.0f} / {:.0f})", *r->ratio_fsicr_to_sim, *r->fsicr_R_CH_kN, *r->resistance_full_kN);
}

// Sensitivity groups (every group but paper, speed and engine), in manifest order.
std::vector<std::string> sensitivity_groups(const Study& s) {
  std::vector<std::string> groups;
  for (const auto& r : s.rows)
    if (r.group != "paper" && r.group != "speed" && r.group != "engine" &&
        std::find(groups.begin(), groups.end(), r.group) == groups.end())
      groups.push_back(r.group);
  return groups;
}

// A sensitivity group's baseline for a run: the group's baseline row of the same engine and fluid model, or
// of the same engine alone when the group varies the fluid model itself. nullptr if there is none (or it
// failed).
struct Baselines {
  bool varies_model = false;
  std::map<std::pair<std::string, std::string>, const Run*> by_key;
  std::pair<std::string, std::string> key(const Run& r) const {
    return {r.engine, varies_model ? std::string() : r.model};
  }
  const Run* of(const Run& r) const {
    const auto it = by_key.find(key(r));
    return it == by_key.end() ? nullptr : it->second;
  }
};
Baselines baselines_of(Study& s, const std::string& group, std::string* param_out = nullptr) {
  Baselines b;
  std::string param;
  for (const auto& r : s.rows)
    if (r.group == group && !r.param.empty()) param = r.param;
  b.varies_model = param == "fluid.model";
  for (const auto& r : s.rows)
    if (r.group == group && r.baseline && s.run_of(r).ok) b.by_key[b.key(s.run_of(r))] = &s.run_of(r);
  if (param_out) *param_out = param;
  return b;
}

void section_paper(Study& s, std::string& md) {
  md += "## (a) Paper comparison\n\n";
  std::vector<const Row*> rows;
  for (const auto& r : s.rows)
    if (r.group == "paper") rows.push_back(&r);
  if (rows.empty()) {
    md += "No run of group `paper` in this study.\n\n";
    return;
  }
  const auto completed = completed_runs(s, "paper");
  if (!any_paper_case(completed))
    md += "**No completed run of the paper case (cases/jbc_ia_5kn) is in this study. Every row below is a "
          "reduced case: its full-scale number is the reduced scene scaled by lambda^3, NOT the paper's result "
          "and not comparable one to one with 393 / 378 kN.**\n\n";
  const double paper_am = paper_full_kN(s.paper, "added_mass"), paper_drag = paper_full_kN(s.paper, "drag");
  const std::string paper_rch = s.paper.fsicr_R_CH_kN ? num(*s.paper.fsicr_R_CH_kN, 0) : "n/a";
  md += fmt::format(
      "Paper (its values as the paper case declares them): added mass {:.0f} kN, drag {:.0f} kN (difference "
      "{:+.1f} %), FSICR R_CH {} kN, ratio R_CH / R_sim {} for its added-mass result (for drag, {} is derived, "
      "not stated). Our R_CH uses the hull parameters measured on our STL (columns L, B, T, alpha, phi2, A_wf "
      "at full scale).\n\n",
      paper_am, paper_drag, 100 * (paper_am / paper_drag - 1), paper_rch, paper_ratio_cell(s.paper, "added_mass"),
      paper_ratio_cell(s.paper, "drag"));
  md += "| run | case / scale | engine | fluid model | R model [N] ± CI95 | R full [kN] ± CI95 | paper R full [kN] | "
        "R_CH ours [kN] | paper R_CH [kN] | ratio ours | paper ratio | status |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Row* row : rows) {
    const Run& r = s.run_of(*row);
    const double paper_kN = paper_full_kN(s.paper, r.model);
    const std::string paper_R = std::isfinite(paper_kN) ? num(paper_kN, 0) : "n/a";
    if (!r.ok) {
      md += fmt::format("| {} | {} | {} | {} | — | — | {} | — | {} | — | {} | {} |\n", r.ref,
                        md_escape(row->label.empty() ? row->base_case : row->label), r.engine, r.model,
                        paper_R, paper_rch, paper_ratio_cell(s.paper, r.model), status_cell(r));
      continue;
    }
    md +=
        fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", r.ref, scale_label(r),
                    r.engine, r.model, pm(r.mean_N, r.ci_N), pm(r.full_kN, r.full_ci_kN, 1), paper_R,
                    optnum(r.rch_kN, 0), paper_rch, optnum(r.ratio), paper_ratio_cell(s.paper, r.model),
                    status_cell(r));
  }
  md += "\nHull parameters used for R_CH (full scale, measured on the STL by brash-post):\n\n"
        "| run | L [m] | B [m] | T [m] | alpha [deg] | phi2 [deg] | A_wf [m²] |\n|---|---|---|---|---|---|---|\n";
  for (const Run* r : completed)
    md += fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", r->ref, optnum(r->lpp), optnum(r->beam),
                      optnum(r->draft), optnum(r->alpha, 1), optnum(r->phi2, 1), optnum(r->awf, 0));
  // Added mass vs drag, per engine and base case: our added_mass (Eq. 2 replacing Eq. 1) and our both (Eq. 2
  // added to Eq. 1), the two readings of the paper's added-mass model, each against drag.
  md +=
      "\nAdded mass vs drag (same engine and case): (R_added - R_drag) / R_drag, where R_added is the "
      "added-mass model read as Eq. 2 alone (`added_mass`) or Eq. 2 added to the Eq. 1 drag (`both`); paper: "
      "(393 - 378) / 378 = +4.0 %.\n\n"
      "| engine | case | added-mass model | R added mass [N] | R drag [N] | difference | CI95 of the "
      "difference |\n"
      "|---|---|---|---|---|---|---|\n";
  std::map<std::pair<std::string, std::string>, std::map<std::string, const Run*>> by;
  for (const Row* row : rows) {
    const Run& r = s.run_of(*row);
    if (r.ok) by[{r.engine, r.base_case}][r.model] = &r;
  }
  bool any = false;
  for (const auto& [k, m] : by) {
    for (const char* added : {"added_mass", "both"}) {
      if (!m.count(added) || !m.count("drag")) continue;
      const Run& a = *m.at(added);
      const Run& d = *m.at("drag");
      const double diff = (a.mean_N - d.mean_N) / d.mean_N * 100.0;
      // first-order propagation of the two independent CIs into the ratio a/d
      const double ci = 100.0 * (a.mean_N / d.mean_N) * std::hypot(a.ci_N / a.mean_N, d.ci_N / d.mean_N);
      md += fmt::format("| {} | {} | {} | {} ({}) | {} ({}) | {:+.1f} % | ± {:.1f} % |\n", k.first, k.second,
                        added, pm(a.mean_N, a.ci_N), a.ref, pm(d.mean_N, d.ci_N), d.ref, diff, ci);
      any = true;
    }
  }
  if (!any) md += "| — | — | — | — | — | no completed added-mass + drag pair | — |\n";
  md += "\n";
}

// The paper case's set-up as each of its runs used it (the run folder's case.yaml and meta.json), beside the
// paper's own set-up (section 3 and Table 1 of the paper; "not stated" where it gives none), with why we
// differ and where that choice is measured. Started runs count too: the set-up is known before the result.
void section_setup(Study& s, std::string& md) {
  struct Col {
    std::string ref, head;
    brash::Case c;
    json meta;
  };
  std::vector<Col> cols;
  for (const Run* run : started_paper_case_runs(s)) {
    const Run& r = *run;
    Col col;
    col.ref = r.ref;
    col.meta = r.meta;
    try {
      col.c = brash::load_case(r.run_dir / "case.yaml");
    } catch (const std::exception& e) {
      md += fmt::format("(set-up of {} not readable: {})\n\n", r.ref, e.what());
      continue;
    }
    col.head = fmt::format("{} ({} {})", r.ref, col.meta.value("engine", std::string("?")),
                           col.meta.value("fluid_model", std::string("?")));
    cols.push_back(std::move(col));
  }
  if (cols.empty()) return;
  const auto is_ode = [](const Col& c) { return c.meta.value("engine", std::string()) == "ode"; };
  const auto ode_opt = [](const Col& c) { return c.meta.value("ode_options", json::object()); };
  struct Item {
    std::string name, paper, why;
    std::function<std::string(const Col&)> ours;
  };
  const std::vector<Item> items = {
      {"engine, contacts", "ODE: rigid spheres, contact joints",
       "LIGGGHTS is soft-sphere DEM: E is a numerical stiffness (sea ice has ~GPa); E / 16 with an 8x longer "
       "step "
       "measured −0.50 % ± 0.86 % against 5 MPa (paired ensembles, docs/performance.md \"Softer contacts\"). "
       "brash-ode is the paper's method",
       [&](const Col& c) {
         if (is_ode(c)) {
           const json o = ode_opt(c);
           return fmt::format("ODE rigid, contact joints (ERP {}, CFM {}, {} iterations)",
                              o.value("erp", NAN), o.value("cfm", NAN), o.value("iterations", 0));
         }
         return fmt::format("Hertz-Mindlin, E = {:.4g} Pa, ν = {}, e = {}", c.c.contact.youngs_modulus_pa,
                            c.c.contact.poisson_ratio, c.c.contact.restitution);
       }},
      {"time step", "not stated",
       "LIGGGHTS: 18 % of the Rayleigh time of the smallest sphere; ODE: dt checked in docs/ode.md",
       [](const Col& c) {
         const json dt = c.meta.value("dt_s", json());
         return dt.is_number() ? fmt::format("{:g} s", dt.get<double>())
                               : fmt::format("{:g} s (case)", c.c.run.timestep_s);
       }},
      {"ice pieces", "> 420,000 spheres, d = 0.017578 m normally distributed, two layers, porosity 0.28",
       "the paper gives no spread of d (5 % here); the porosity is kept as ice volume per channel area and "
       "the bed "
       "takes its natural thickness (docs/physics.md)",
       [](const Col& c) {
         const json n = c.meta.value("particles", json());
         return fmt::format("{} spheres, d = {:g} m ± {:g} m (cut at ± {:g} sd), porosity {:g}, packing {}",
                            n.is_number() ? fmt::format("{}", n.get<long long>()) : std::string("?"),
                            c.c.ice.diameter_mean_m, c.c.ice.diameter_sd_m, c.c.ice.diameter_truncation_sd,
                            c.c.ice.porosity, brash::to_string(c.c.ice.packing_mode));
       }},
      {"friction ice-ice / ice-hull", "1.35 / 0.1", "the paper's values",
       [](const Col& c) { return fmt::format("{:g} / {:g}", c.c.friction.ice_ice, c.c.friction.ice_hull); }},
      {"added mass", "Table 1 (Ca by situation; the text also names Ca = 2)",
       "Table 1 vs the text's Ca = 2 vs Ca = 0: section (c), parameter fluid.ca_table",
       [](const Col& c) {
         return fmt::format("{}, {}", brash::to_string(c.c.fluid.ca_table),
                            brash::to_string(c.c.fluid.treatment));
       }},
      {"fluid model",
       "added mass: \"an added mass model is implemented into the existing fluid force model\" "
       "(Eq. 1 drag); drag: Eq. 1 alone",
       "the paper's words allow Eq. 2 replacing Eq. 1 (our added_mass, docs/physics.md) or Eq. 2 added to it "
       "(our both); section (a)'s \"added mass vs drag\" table gives each against drag, the paper's +4 % is "
       "what both gives: docs/paper_gap.md, section (c) parameter fluid.model",
       [](const Col& c) { return std::string(brash::to_string(c.c.fluid.model)); }},
      {"drag (Eq. 1)", "C_D not stated",
       "sphere drag coefficient (docs/physics.md); with drag in, C_D sets the level: "
       "docs/paper_gap.md, section (c) parameter fluid.drag_coefficient",
       [](const Col& c) {
         return fmt::format("C_D = {:g}, {}", c.c.fluid.drag_coefficient,
                            brash::to_string(c.c.fluid.drag_law));
       }},
      {"idle far-field ice", "not stated",
       "a frozen far field is biased +8 to +20 % (docs/performance.md \"The far field's error\")",
       [&](const Col& c) {
         if (is_ode(c))
           return std::string(ode_opt(c).value("cull", false) ? "culled (window alone: biased high)"
                                                              : "every piece integrated");
         if (!c.c.speedups.farfield) return std::string("every piece integrated");
         return std::string(c.c.speedups.farfield_wake_force_weight > 0
                                ? "far field with the wake rule"
                                : "far field, window alone (biased high)");
       }},
      {"channel ends", "21.0 x 2.25 m; what bounds the ends is not stated",
       "open ends let the floating bed relax into open water, and late in a run that relaxation meets the "
       "bow's push (bench/channel_end_spread.py on each paper run, docs/paper_gap.md); an end wall would be "
       "the frozen wall the far-field ensembles measured (docs/performance.md)",
       [&](const Col& c) {
         const bool walls = is_ode(c) && ode_opt(c).value("end_walls", false);
         return fmt::format("{:g} x {:g} m, side walls, ends {}", c.c.channel.length_m, c.c.channel.width_m,
                            walls ? "walled (x = 0 and x = length)" : "open");
       }},
      {"FSICR R_CH hull parameters", "not given (R_CH = 999 kN)",
       "measured on our STL: docs/fsicr_vs_paper.md explains the difference to 999 kN",
       [](const Col&) { return std::string("measured on the STL (table above)"); }},
  };
  md +=
      "### Our paper-case set-up vs the paper's (from each run's case.yaml and meta.json)\n\n| item | paper "
      "|";
  for (const auto& c : cols) md += " " + c.head + " |";
  md += " why we differ, and where it is measured |\n|---|---|";
  for (size_t i = 0; i < cols.size(); ++i) md += "---|";
  md += "---|\n";
  for (const auto& it : items) {
    md += fmt::format("| {} | {} |", it.name, it.paper);
    for (const auto& c : cols) md += " " + md_escape(it.ours(c)) + " |";
    md += " " + it.why + " |\n";
  }
  md += "\n";
}

// How far each completed paper-case run is from the paper's number, beside every candidate change the study
// measured (section (c)'s groups): a candidate can close the gap only with the gap's sign and size.
void section_gap(Study& s, std::string& md) {
  std::string gaps;
  for (const Run* r : completed_runs(s, "paper")) {
    const double paper = paper_full_kN(s.paper, r->model);
    if (r->base_case != "jbc_ia_5kn" || !std::isfinite(paper)) continue;
    gaps += fmt::format(
        "- {} ({} {}): {} kN; the paper's {:.0f} kN is **{:+.1f} %** on it (± {:.1f} % from our "
        "CI95 alone)\n",
        r->ref, r->engine, r->model, pm(r->full_kN, r->full_ci_kN, 1), paper,
        100.0 * (paper / r->full_kN - 1.0), 100.0 * paper * r->full_ci_kN / (r->full_kN * r->full_kN));
  }
  if (gaps.empty()) return;  // nothing to explain yet
  md +=
      "### The gap to the paper, and the candidates the study measured\n\n" + gaps +
      "\nEach candidate below is a change of one input, measured on a reduced case (or on the paper case "
      "itself, group paper_candidates) against its baseline (section (c); one run per value, so a change "
      "inside its CI is not resolved; rows P1, P2, ... are paired-seed ensembles, which resolve a few per "
      "cent; jbc_bench's window is the bow's first second in the ice, too short for the fluid models' "
      "difference to build up, jbc_quick's is 2-4 s). A candidate can close the gap only if its change has "
      "the gap's sign and a similar size; the set-up table above says which inputs the paper does not "
      "state.\n\n"
      "| candidate (parameter: value) | case, engine, fluid model | change vs baseline ± CI95 | runs |\n"
      "|---|---|---|---|\n";
  bool any = false;
  for (const auto& g : sensitivity_groups(s)) {
    std::string param;
    const Baselines base = baselines_of(s, g, &param);
    for (const auto& row : s.rows) {
      if (row.group != g || row.baseline) continue;
      const Run& r = s.run_of(row);
      const Run* b = r.ok ? base.of(r) : nullptr;
      if (!b) continue;
      const double rel = r.mean_N / b->mean_N - 1.0;
      const double ci = std::hypot(r.ci_N, b->ci_N) / b->mean_N;
      md += fmt::format("| {}: {} | {}, {}, {} | {:+.1f} % ± {:.1f} %{} | {} vs {} |\n",
                        param.empty() ? g : param, md_escape(row.value), row.base_case, r.engine, r.model,
                        100.0 * rel, 100.0 * ci, std::abs(rel) < ci ? " (not resolved)" : "", r.ref, b->ref);
      any = true;
    }
  }
  for (const Paired& p : s.paired) {
    if (!p.ok) continue;
    md += fmt::format("| {}: {} | {}, {} paired packings, {} | {:+.1f} % ± {:.1f} %{} | {} |\n", p.row->param,
                      md_escape(p.row->value), p.case_name, p.pairs,
                      md_escape(p.row->label.empty() ? side_model(p.side_b) : p.row->label),
                      100.0 * p.diff_rel, 100.0 * p.ci95_rel, p.resolved() ? "" : " (not resolved)", p.ref);
    any = true;
  }
  if (!any) md += "| — | — | no completed sensitivity run with a baseline | — |\n";
  md += "\n";
}

// Runs `gnuplot GP` in GP's folder (file names in the script are relative to it, so it can be re-run there).
// Returns "" on success, else what went wrong (the script's stderr is kept in GP.err).
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

// The paper case's resistance histories in one plot (full scale, 0.5 s bin means of -fx; runs still going
// too, up to where their record is): the shape of each fluid model's history beside the paper's two levels,
// which is what tells a plateau from a rise.
void section_paper_histories(Study& s, std::string& md, const fs::path& fig_dir,
                             const std::function<std::string(const std::string&)>& link) {
  constexpr double kBin_s = 0.5;
  struct Line {
    std::string title;
    std::vector<std::pair<double, double>> t_kN;  // bin centre, bin mean (NAN: no row in the bin)
  };
  std::vector<Line> lines;
  std::array<double, 2> window{NAN, NAN};
  for (const Run* run : started_paper_case_runs(s)) {
    const Run& r = *run;
    if (!fs::exists(r.run_dir / "hull_force.csv")) continue;
    try {
      const brash::Case c = brash::load_case(r.run_dir / "case.yaml");
      const auto h = brash::post::read_force_history(r.run_dir / "hull_force.csv", !r.ok);
      if (h.t_s.empty()) continue;
      window = c.run.window_s;
      const double kN_per_N = std::pow(c.ship.scale_lambda, 3) / 1000.0;
      Line l;
      l.title = fmt::format("{} {} {}{}", r.ref, r.engine, brash::to_string(c.fluid.model),
                            r.ok ? "" : fmt::format(" (in progress, t = {:.1f} s)", h.t_s.back()));
      const auto nbins = static_cast<std::size_t>(std::ceil(h.t_s.back() / kBin_s));
      std::vector<double> sum(nbins + 1, 0.0);
      std::vector<int> n(nbins + 1, 0);
      for (std::size_t i = 0; i < h.t_s.size(); ++i) {
        const auto b = std::min(nbins, static_cast<std::size_t>(h.t_s[i] / kBin_s));
        sum[b] -= h.fx_N[i];
        ++n[b];
      }
      for (std::size_t b = 0; b < nbins; ++b)
        l.t_kN.emplace_back((b + 0.5) * kBin_s, n[b] ? sum[b] / n[b] * kN_per_N : NAN);
      lines.push_back(std::move(l));
    } catch (const std::exception& e) {
      md += fmt::format("(history of {} not readable: {})\n\n", r.ref, e.what());
    }
  }
  if (lines.empty()) return;
  const double paper_am = paper_full_kN(s.paper, "added_mass"), paper_drag = paper_full_kN(s.paper, "drag");
  const fs::path dat = fig_dir / "paper_histories.dat", gp = fig_dir / "paper_histories.gp",
                 png = fig_dir / "paper_histories.png";
  {
    std::ofstream d(dat);
    d << "# full-scale resistance [kN], 0.5 s bin means of -fx; one block per run (blank line: a bin without "
         "rows)\n";
    for (const auto& l : lines) {
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
    std::ofstream p(gp);
    p << "set terminal pngcairo size 1100,550\nset output '" << png.filename().string() << "'\n"
      << "set termoption noenhanced\nset grid\nset key right bottom\nset yrange [0:*]\n"
      << "set xlabel 'model time t [s]'\nset ylabel 'full-scale resistance [kN] (-fx x lambda^3, 0.5 s "
         "means)'\n"
      << "set title 'The paper case: resistance histories of our runs and the paper levels'\n"
      << fmt::format(
             "set object 1 rect from {},graph 0 to {},graph 1 fc rgb '#eeeeee' fs solid 1 noborder behind\n",
             window[0], window[1])
      << "plot ";
    for (std::size_t i = 0; i < lines.size(); ++i)
      p << fmt::format("'{}' index {} using 1:2 with lines lw 2 title '{}', ", dat.filename().string(), i,
                       lines[i].title);
    p << fmt::format("{} with lines dt 2 lc rgb 'black' title 'paper added mass ({:.0f} kN)', ",
                     paper_am, paper_am)
      << fmt::format("{} with lines dt 3 lc rgb 'black' title 'paper drag ({:.0f} kN)'\n", paper_drag,
                     paper_drag);
  }
  const std::string err = run_gnuplot(gp, png);
  if (err.empty())
    md += fmt::format(
        "![paper-case resistance histories]({})\n\nThe paper case's resistance histories (`{}`, data `{}`): "
        "full scale, 0.5 s means of the hull's x force, window shaded, the paper's two levels dashed (its "
        "Fig. 5 shows a plateau from ~15 s).\n\n",
        link(png.filename().string()), link(png.filename().string()), link(dat.filename().string()));
  else
    md += "Paper-case history plot not produced: " + err + ".\n\n";
}

// Fig. 4, 5 and 6 analogs for the runs of section (a), next to the document in FIG_DIR (its previous content
// is replaced): a bar chart of the runs' full-scale resistance with its CI against the paper's numbers and
// our R_CH (Fig. 6; the paper case's runs alone once one is complete), the paper case's histories in one
// plot, and each run's own force history (Fig. 5) and ice views from above and below (Fig. 4, first run of
// each engine), copied from the run directories that brash-post wrote them to.
void section_figures(Study& s, std::string& md, const fs::path& fig_dir, const fs::path& doc_dir) {
  md += "### Figures (analogs of the paper's Fig. 4, 5 and 6)\n\n";
  const auto runs = completed_runs(s, "paper");
  const bool any_paper = any_paper_case(runs);
  if (runs.empty()) {
    md += "No completed run in section (a): no figures.\n\n";
    return;
  }
  std::error_code ec;
  fs::remove_all(fig_dir, ec);
  fs::create_directories(fig_dir);
  const std::string rel =
      fs::relative(fs::absolute(fig_dir), fs::absolute(doc_dir.empty() ? fs::path(".") : doc_dir), ec).string();
  const auto link = [&](const std::string& f) { return rel.empty() || rel == "." ? f : rel + "/" + f; };
  // Fig. 6 analog: the paper case's runs beside the paper's numbers; reduced cases (their lambda^3-scaled
  // scenes are not the paper's ship in the paper's channel) only when no paper-case run is complete
  std::vector<const Run*> bars;
  for (const Run* r : runs)
    if (!any_paper || r->base_case == "jbc_ia_5kn") bars.push_back(r);
  const fs::path dat = fig_dir / "paper_bars.dat", gp = fig_dir / "paper_bars.gp", png = fig_dir / "paper_bars.png";
  {
    constexpr long kOurs = 0x5a9fd4, kRule = 0xcd6155, kPaper = 0xc8c8c8;
    std::ofstream d(dat);
    d << "# label  full-scale resistance [kN]  CI95 [kN]  colour\n";
    for (const Run* r : bars)
      d << fmt::format("\"{} {} {}\" {} {} {}\n", r->ref, r->engine, r->model, r->full_kN, r->full_ci_kN, kOurs);
    d << fmt::format("\"paper added mass\" {} 0 {}\n\"paper drag\" {} 0 {}\n",
                     paper_full_kN(s.paper, "added_mass"), kPaper, paper_full_kN(s.paper, "drag"), kPaper);
    std::set<long> rch;
    for (const Run* r : bars)
      if (r->rch_kN && rch.insert(std::lround(*r->rch_kN)).second)
        d << fmt::format("\"FSICR R_CH ours ({})\" {} 0 {}\n", r->ref, *r->rch_kN, kRule);
    if (s.paper.fsicr_R_CH_kN) d << fmt::format("\"paper FSICR R_CH\" {} 0 {}\n", *s.paper.fsicr_R_CH_kN, kPaper);
    std::ofstream p(gp);
    p << "set terminal pngcairo size 1100,650\nset output '" << png.filename().string() << "'\n"
      << "set termoption noenhanced\nset style fill solid 0.85 border -1\nset boxwidth 0.6\nset grid ytics\n"
      << "set yrange [0:*]\nset xtics rotate by -30 scale 0\nset bmargin 9\nset rmargin 14\n"
      << "set ylabel 'full-scale resistance [kN] (model x lambda^3)'\n"
      << "set title '"
      << (any_paper ? "Full-scale resistance, our paper-case runs with CI95 vs the paper (Fig. 6 analog)"
                    : "Full-scale resistance (Fig. 6 analog): REDUCED-CASE runs, not the paper case")
      << "'\nplot '" << dat.filename().string()
      << "' using 0:2:(0.6):4:xtic(1) with boxes lc rgb variable notitle, \\\n"
      << "     '' using 0:2:3 with yerrorbars lc rgb 'black' pt 7 ps 0 notitle\n";
  }
  const std::string err = run_gnuplot(gp, png);
  if (err.empty())
    md += fmt::format(
        "![full-scale resistance vs the paper]({})\n\nFig. 6 analog: `{}` (data `{}`, script `{}`). Blue: "
        "{} (CI95 bars); red: our FSICR R_CH from the measured hull; grey: the paper.\n\n",
        link(png.filename().string()), link(png.filename().string()), link(dat.filename().string()),
        link(gp.filename().string()),
        any_paper ? "our runs of the paper case (the reduced cases' are in the table above)"
                  : "our runs, reduced cases");
  else
    md += "Fig. 6 analog not produced: " + err + ".\n\n";
  section_paper_histories(s, md, fig_dir, link);
  // Fig. 5 and 4 analogs: the runs' own plots
  std::set<std::string> engines_with_views;
  for (const Run* r : runs) {
    md += fmt::format("**{}** ({} {}, {}):", r->ref, r->engine, r->model, scale_label(*r));
    // the plots are in the run directory, or (a copy without its plots, brash-study's study_runs) in the full run
    // directory the copy came from
    const fs::path full_dir = source_run_dir(r->run_dir);
    const fs::path plot_dir =
        fs::exists(r->run_dir / "force_history.png") || full_dir.empty() ? r->run_dir : full_dir;
    const fs::path fh = plot_dir / "force_history.png";
    if (fs::exists(fh)) {
      const std::string f = r->ref + "_force_history.png";
      fs::copy_file(fh, fig_dir / f, fs::copy_options::overwrite_existing);
      md += fmt::format("\n\n![{} force history]({})\n\nFig. 5 analog: hull force history x/y/z and the window mean "
                        "(from `{}`).",
                        r->ref, link(f), show_path(fh));
    } else {
      md += fmt::format(" no force_history.png in `{}` (run brash-post on it).", show_path(r->run_dir));
    }
    fs::path views;
    // views for the first run of each engine, and for every paper-case run (the study's headline runs)
    const bool want_views = !engines_with_views.count(r->engine) || r->base_case == "jbc_ia_5kn";
    if (want_views && fs::is_directory(plot_dir))
      for (const auto& e : fs::directory_iterator(plot_dir)) {
        const std::string n = e.path().filename().string();
        if (n.rfind("ice_views_", 0) == 0 && e.path().extension() == ".png" && (views.empty() || e.path() > views))
          views = e.path();
      }
    if (!views.empty()) {
      engines_with_views.insert(r->engine);
      const std::string f = r->ref + "_ice_views.png";
      fs::copy_file(views, fig_dir / f, fs::copy_options::overwrite_existing);
      md += fmt::format("\n\n![{} ice views]({})\n\nFig. 4 analog: the ice around the hull from above and below at "
                        "the last dump (from `{}`).",
                        r->ref, link(f), show_path(views));
    }
    if (fs::exists(r->run_dir / "particles.pvd")) {
      md += fmt::format(" ParaView: open `{}` and `{}`.", show_path(r->run_dir / "particles.pvd"),
                        show_path(r->run_dir / "hull.pvd"));
    } else if (!full_dir.empty()) {
      // a copy of the run's outputs (brash-study): the ParaView files stay in the full run directory
      md += fs::exists(full_dir / "particles.pvd")
                ? fmt::format(" ParaView: open `{}` and `{}`.", show_path(full_dir / "particles.pvd"),
                              show_path(full_dir / "hull.pvd"))
                : fmt::format(
                      " ParaView files: `particles.pvd` and `hull.pvd` in `{}`, on the machine that ran it.",
                      show_path(full_dir));
    }
    md += "\n\n";
  }
}

void section_speed(Study& s, std::string& md, const fs::path& plot_png, json& summary) {
  md += "## (b) Speed sweep: R ∝ U^n\n\n";
  std::vector<const Row*> rows;
  for (const auto& r : s.rows)
    if (r.group == "speed") rows.push_back(&r);
  summary["fits"] = json::array();
  if (rows.empty()) {
    md += "No run of group `speed` in this study.\n\n";
    return;
  }
  md += "Model-scale resistance vs model-scale speed; n = slope of a least-squares line through (ln U, ln R), "
        "± its 95 % confidence interval (Student t with speeds - 2 degrees of freedom times its standard error, SE; "
        "needs >= 3 speeds). Tanks show a linear trend (n ≈ 1), earlier simulations "
        "quadratic (n ≈ 2).\n\n"
        "| run | engine | fluid model | U [m/s] | R model [N] ± CI95 | R full [kN] ± CI95 | case / scale | status |\n"
        "|---|---|---|---|---|---|---|---|\n";
  std::map<std::pair<std::string, std::string>, std::vector<const Run*>> groups;
  for (const Row* row : rows) {
    const Run& r = s.run_of(*row);
    if (!r.ok) {
      md += fmt::format("| {} | {} | {} | {} | — | — | {} | {} |\n", r.ref, r.engine, r.model, row->value,
                        md_escape(row->base_case), status_cell(r));
      continue;
    }
    md += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} |\n", r.ref, r.engine, r.model, num(r.speed, 3),
                      pm(r.mean_N, r.ci_N), pm(r.full_kN, r.full_ci_kN, 1), scale_label(r), status_cell(r));
    auto& g = groups[{r.engine, r.model}];
    if (std::find(g.begin(), g.end(), &r) == g.end()) g.push_back(&r);
  }
  md += "\n| engine | fluid model | speeds | n ± CI95 (SE) | a in R = a U^n [N] | runs |\n|---|---|---|---|---|---|\n";
  std::vector<Fit> fits;
  for (auto& [k, g] : groups) {
    std::vector<double> speeds, means;
    std::vector<std::string> refs;
    for (const Run* r : g) {
      refs.push_back(r->ref);
      if (r->speed > 0 && r->mean_N > 0) speeds.push_back(r->speed), means.push_back(r->mean_N);
    }
    const Fit f{brash::stats::fit_power_law(speeds, means), k.first, k.second, refs};
    std::string refs_s;
    for (const auto& x : refs) refs_s += (refs_s.empty() ? "" : ", ") + x;
    const std::string nse = std::isfinite(f.n_se) ? fmt::format("{:.3f} ± {:.3f} (SE {:.3f})", f.n, f.n_ci95, f.n_se)
                            : std::isfinite(f.n)  ? fmt::format("{:.3f} (no SE: {} speeds)", f.n, f.points)
                                                  : fmt::format("n/a ({} usable speed(s))", f.points);
    md += fmt::format("| {} | {} | {} | {} | {} | {} |\n", f.engine, f.model, f.points, nse, num(f.a, 3), refs_s);
    summary["fits"].push_back({{"engine", f.engine}, {"fluid_model", f.model}, {"points", f.points},
                               {"n", std::isfinite(f.n) ? json(f.n) : json(nullptr)},
                               {"n_se", std::isfinite(f.n_se) ? json(f.n_se) : json(nullptr)},
                               {"n_ci95", std::isfinite(f.n_ci95) ? json(f.n_ci95) : json(nullptr)},
                               {"a", std::isfinite(f.a) ? json(f.a) : json(nullptr)}});
    fits.push_back(f);
  }
  md += "\n";
  // Plot (gnuplot pngcairo): points with CI bars and the fitted lines, log-log.
  if (plot_png.empty()) return;
  const fs::path dat = fs::path(plot_png).replace_extension(".dat");
  const fs::path gp = fs::path(plot_png).replace_extension(".gp");
  {
    std::ofstream d(dat);
    int block = 0;
    for (auto& [k, g] : groups) {
      d << "# " << k.first << " " << k.second << "\n";
      for (const Run* r : g) d << fmt::format("{} {} {}\n", r->speed, r->mean_N, r->ci_N);
      d << "\n\n";
      ++block;
    }
    std::ofstream p(gp);
    p << "set terminal pngcairo size 900,600\nset output '" << plot_png.filename().string() << "'\n"
      << "set logscale xy\nset xlabel 'ship speed U [m/s] (model scale)'\nset ylabel 'resistance R [N] (model scale)'\n"
      << "set termoption noenhanced\nset offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05\n"
      << "set key left top\nset grid\nset title 'Speed sweep: R = a U^n (least squares in log-log)'\nplot ";
    int i = 0;
    for (const Fit& f : fits) {
      if (i) p << ", ";
      p << fmt::format("'{}' index {} using 1:2:3 with yerrorbars pt 7 lc {} title '{} {}'", dat.filename().string(), i, i + 1,
                       f.engine, f.model);
      if (std::isfinite(f.n))
        p << fmt::format(", {} * x**{} with lines lc {} title 'fit n = {:.2f}'", f.a, f.n, i + 1, f.n);
      ++i;
    }
    p << "\n";
  }
  const std::string err = run_gnuplot(gp, plot_png);
  if (err.empty())
    md += fmt::format("![speed sweep]({})\n\nPlot: `{}` (data `{}`, script `{}`).\n\n", plot_png.filename().string(),
                      plot_png.filename().string(), dat.filename().string(), gp.filename().string());
  else
    md += "Plot not produced: " + err + ".\n\n";
}

void section_sensitivity(Study& s, std::string& md) {
  md += "## (c) Sensitivities\n\n";
  const auto groups = sensitivity_groups(s);
  for (const char* expected : {"ca", "friction_ice", "density_ice"})
    if (std::find(groups.begin(), groups.end(), expected) == groups.end())
      md += fmt::format("Group `{}`: no run in this study.\n\n", expected);
  for (const auto& g : groups) {
    std::string param;
    const Baselines base = baselines_of(s, g, &param);
    md += fmt::format(
        "### {} (parameter `{}`)\n\nChange vs the baseline of the same engine and fluid model{}; "
        "\"Δ / CI\" = change over the combined CI95 sqrt(CI² + CI_base²): |Δ / CI| < 1 means the "
        "change is not resolved by these runs.\n\n"
        "| run | value | engine | fluid model | R model [N] ± CI95 | R full [kN] ± CI95 | Δ vs baseline [N] "
        "| Δ / CI | status |\n"
        "|---|---|---|---|---|---|---|---|---|\n",
        g, param.empty() ? "?" : param,
        base.varies_model ? " (here the same engine: the group varies the fluid model)" : "");
    for (const auto& row : s.rows) {
      if (row.group != g) continue;
      const Run& r = s.run_of(row);
      const std::string value = row.value + (row.baseline ? " (baseline)" : "");
      if (!r.ok) {
        md += fmt::format("| {} | {} | {} | {} | — | — | — | — | {} |\n", r.ref, md_escape(value), r.engine, r.model,
                          status_cell(r));
        continue;
      }
      std::string d = "no baseline", dci = "—";
      if (row.baseline) {
        d = "—";
      } else if (const Run* b = base.of(r)) {
        const double delta = r.mean_N - b->mean_N;
        const double comb = std::hypot(r.ci_N, b->ci_N);
        d = fmt::format("{:+.2f} ({:+.1f} %)", delta, delta / b->mean_N * 100.0);
        dci = comb > 0 ? fmt::format("{:+.2f}", delta / comb) : "n/a";
      }
      md += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", r.ref, md_escape(value), r.engine, r.model,
                        pm(r.mean_N, r.ci_N), pm(r.full_kN, r.full_ci_kN, 1), d, dci, status_cell(r));
    }
    md += "\n";
  }
}

// The paired-seed ensembles: one run per value cannot resolve a change smaller than the run-to-run scatter of
// a chaotic contact scene (~10-20 % CI on the reduced cases); the same packings run both ways can.
void section_paired(const Study& s, std::string& md) {
  if (s.paired.empty()) return;
  md +=
      "### Paired-seed ensembles\n\n"
      "Each packing seed of the case runs as side A and as side B (the change); the change is the mean over "
      "the pairs of (B − A) / mean of the pair, with its 95 % CI (Student t), so the packings' own scatter "
      "cancels (`bench/rank_ensemble.sh`). Resolved: the CI excludes 0.\n\n"
      "| ensemble | change (parameter: value) | what | case | side A → side B | pairs | mean A / B [N] | "
      "(B − A) / mean ± CI95 | resolved |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const Paired& p : s.paired) {
    if (!p.ok) {
      md += fmt::format("| {} | {}: {} | {} | {} | — | — | — | — | **MISSING: {}** |\n", p.ref, p.row->param,
                        md_escape(p.row->value), md_escape(p.row->label), p.row->base_case,
                        md_escape(p.problem));
      continue;
    }
    md += fmt::format(
        "| {} | {}: {} | {} | {} | `{}` → `{}` | {} | {:.2f} / {:.2f} | {:+.2f} % ± {:.2f} % | {} |\n", p.ref,
        p.row->param, md_escape(p.row->value), md_escape(p.row->label), p.case_name, md_escape(p.side_a),
        md_escape(p.side_b), p.pairs, p.mean_a_N, p.mean_b_N, 100.0 * p.diff_rel, 100.0 * p.ci95_rel,
        p.resolved() ? "yes" : "no");
  }
  md += "\nCommands (each re-prints its table from the runs it finds and runs the missing ones):\n\n";
  for (const Paired& p : s.paired)
    md += fmt::format("- {} (`{}`): `{}`\n", p.ref, show_path(p.row->run_dir), md_escape(p.row->command));
  md += "\n";
}

// Mean resistance (-fx, model scale) in the whole bins [k w, (k + 1) w) that `h` covers up to `t_end_s`.
std::vector<double> bin_means(const brash::post::ForceHistory& h, double w_s, double t_end_s) {
  const auto nbins = static_cast<std::size_t>(std::floor(t_end_s / w_s + 1e-9));
  std::vector<double> sum(nbins, 0.0);
  std::vector<int> n(nbins, 0);
  for (std::size_t i = 0; i < h.t_s.size(); ++i) {
    // a row is stamped at the end of its output interval: it belongs to the bin its interval lies in (a row
    // at t = 0, LIGGGHTS' state before the first step, closes no interval)
    if (h.t_s[i] <= 0.0) continue;
    const auto b = static_cast<std::size_t>(std::floor((h.t_s[i] - 1e-9) / w_s));
    if (b >= nbins) continue;
    sum[b] -= h.fx_N[i];
    ++n[b];
  }
  std::vector<double> out(nbins, NAN);
  for (std::size_t b = 0; b < nbins; ++b)
    if (n[b]) out[b] = sum[b] / n[b];
  return out;
}

// An unfinished run of another engine (the ODE paper runs outlast a session's machine) beside the complete
// LIGGGHTS run of the same case and fluid model, in 1 s bins over the model time it has reached: the engine
// comparison on the scene itself for as far as it goes (the bow entering the ice, not the window).
void section_engines_so_far(const std::vector<const Run*>& runs, std::string& md) {
  for (const Run* r : runs) {
    if (!r->in_progress || r->engine == "liggghts" || !fs::exists(r->run_dir / "hull_force.csv")) continue;
    const auto lit = std::find_if(runs.begin(), runs.end(), [&](const Run* l) {
      return l->ok && l->engine == "liggghts" && l->base_case == r->base_case && l->model == r->model &&
             fs::exists(l->run_dir / "hull_force.csv");
    });
    if (lit == runs.end()) continue;
    const Run& l = **lit;
    try {
      const auto h = brash::post::read_force_history(r->run_dir / "hull_force.csv", true);
      const auto hl = brash::post::read_force_history(l.run_dir / "hull_force.csv", false);
      if (h.t_s.empty() || hl.t_s.empty()) continue;
      const double t_end = std::min(h.t_s.back(), hl.t_s.back());
      // whole seconds; halves or tenths for a record that is still short
      const double kBin_s = t_end >= 4.0 ? 1.0 : t_end >= 1.0 ? 0.5 : 0.1;
      const auto mine = bin_means(h, kBin_s, t_end), ref = bin_means(hl, kBin_s, t_end);
      if (mine.empty()) continue;
      md += fmt::format(
          "{} ({} {}, {}) has reached t = {:.2f} s; beside {} (liggghts {}), in {} s bins of the "
          "model-scale resistance (-fx):\n\n| t [s] | {} liggghts [N] | {} {} [N] | {} / {} - 1 |\n"
          "|---|---|---|---|\n",
          r->ref, r->engine, r->model, r->base_case, h.t_s.back(), l.ref, l.model, kBin_s, l.ref, r->ref,
          r->engine, r->ref, l.ref);
      for (std::size_t b = 0; b < mine.size(); ++b) {
        const bool both = std::isfinite(mine[b]) && std::isfinite(ref[b]) && ref[b] != 0.0;
        md += fmt::format("| {:g}-{:g} | {} | {} | {} |\n", b * kBin_s, (b + 1) * kBin_s, num(ref[b], 3),
                          num(mine[b], 3),
                          both ? fmt::format("{:+.1f} %", 100.0 * (mine[b] / ref[b] - 1.0)) : "—");
      }
      md += "\n";
    } catch (const std::exception& e) {
      md += fmt::format("(the record of {} or {} is not readable: {})\n\n", r->ref, l.ref, e.what());
    }
  }
}

void section_engines(Study& s, std::string& md) {
  md += "## (d) Engines\n\n";
  std::vector<const Run*> runs;
  std::set<std::string> engines;
  for (const auto& row : s.rows) {
    if (row.group != "engine" && row.group != "paper") continue;
    const Run& r = s.run_of(row);
    if (std::find(runs.begin(), runs.end(), &r) != runs.end()) continue;
    runs.push_back(&r);
    if (r.ok) engines.insert(r.engine);
  }
  if (engines.size() < 2) {
    md += fmt::format("Only {} engine(s) with completed runs in groups `paper`/`engine` ({}); the engine table "
                      "needs at least two of LIGGGHTS, ODE, YADE.\n\n",
                      engines.size(), engines.empty() ? std::string("none") : *engines.begin());
  }
  bool failed = false;
  for (const Run* r : runs) failed = failed || !r->ok;
  if (engines.size() < 2 && !failed) return;
  std::sort(runs.begin(), runs.end(), [](const Run* a, const Run* b) {
    return std::tie(a->base_case, a->model, a->engine) < std::tie(b->base_case, b->model, b->engine);
  });
  // Each other engine's run against the LIGGGHTS run of the same case and fluid model (the main engine; the
  // first one listed when there are several): R / R_liggghts - 1, its CI from the two runs' relative CIs in
  // quadrature (independent runs).
  std::map<std::pair<std::string, std::string>, const Run*> liggghts_of;
  for (const Run* r : runs)
    if (r->ok && r->engine == "liggghts") liggghts_of.emplace(std::pair{r->base_case, r->model}, r);
  auto vs_liggghts = [&](const Run& r) -> std::string {
    if (r.engine == "liggghts") return "reference";
    const auto it = liggghts_of.find({r.base_case, r.model});
    if (it == liggghts_of.end() || it->second->mean_N == 0.0 || r.mean_N == 0.0) return "—";
    const Run& l = *it->second;
    const double ratio = r.mean_N / l.mean_N;
    const double rel_ci = std::hypot(r.ci_N / r.mean_N, l.ci_N / l.mean_N);
    return fmt::format("{:+.1f} % ± {:.1f} % ({})", 100.0 * (ratio - 1.0), 100.0 * std::abs(ratio) * rel_ci,
                       l.ref);
  };
  md +=
      "| run | case | fluid model | engine | R model [N] ± CI95 | R full [kN] ± CI95 | vs LIGGGHTS ± CI95 | "
      "wall time [s] | particle-steps/s | status |\n"
      "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Run* r : runs) {
    if (!r->ok) {
      md += fmt::format("| {} | {} | {} | {} | — | — | — | — | — | {} |\n", r->ref, r->base_case, r->model,
                        r->engine, status_cell(*r));
      continue;
    }
    md += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", r->ref, r->base_case, r->model,
                      r->engine, pm(r->mean_N, r->ci_N), pm(r->full_kN, r->full_ci_kN, 1), vs_liggghts(*r),
                      num(r->wall_s, 0), r->wall_s > 0 ? fmt::format("{:.3g}", r->psteps / r->wall_s) : "n/a",
                      status_cell(*r));
  }
  md += "\n";
  section_engines_so_far(runs, md);
}

void section_runs(Study& s, std::string& md) {
  md +=
      "## (e) Runs and the commands that produced them\n\n"
      "\"report files\": the folder holding the run's report.json and report.md, its force history, "
      "case.yaml "
      "and meta.json, from which this document was generated. For a complete run made by a study it is the "
      "copy kept in the repository (the study's own runs beside this document, the paper runs and the "
      "ensembles' summaries in docs/paper_runs); the command's `--out` folder, with the dumps and restarts, "
      "lives on the machine that ran it.\n\n"
      "| run | report files | case | engine | fluid model | status | command |\n"
      "|---|---|---|---|---|---|---|\n";
  for (const auto& k : s.order) {
    const Run& r = s.runs.at(k);
    md += fmt::format("| {} | `{}` | {} | {} | {} | {} | `{}` |\n", r.ref, show_path(r.run_dir), r.case_name, r.engine,
                      r.model, status_cell(r), md_escape(r.command));
  }
  md += "\n";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"brash-study-report: docs/study.md from a study manifest and the report.json of its runs"};
  std::string manifest, out = "docs/study.md", plot, figures, summary_path, title = "brash study", study_command;
  app.add_option("manifest", manifest, "study manifest (tab-separated, see the file header)")->required();
  app.add_option("--out", out, "markdown output")->capture_default_str();
  app.add_option("--plot", plot, "speed-sweep PNG (default: <out stem>_speed.png next to --out; 'none' = no plot)");
  app.add_option("--figures", figures,
                 "folder for the Fig. 4/5/6 analogs of section (a) (default: <out stem>_figs next to --out; "
                 "'none' = no figures; its previous content is replaced)");
  app.add_option("--summary-json", summary_path, "also write the fits and run statuses as JSON");
  app.add_option("--title", title, "document title")->capture_default_str();
  app.add_option("--study-command", study_command, "the command that ran the whole study (shown at the top)");
  std::string paper_case = "cases/jbc_ia_5kn/case.yaml";
  app.add_option("--paper-case", paper_case, "the paper case, whose published values (its references) the "
                 "document compares with")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    Study s;
    if (!fs::exists(paper_case))
      throw brash::InputError(fmt::format("--paper-case {}: no such file (run from the repository root or name the "
                                          "paper case's case.yaml)", paper_case));
    s.paper = brash::load_case(paper_case).references;
    for (auto& row : read_manifest(manifest)) (row.group == "paired" ? s.paired_rows : s.rows).push_back(row);
    for (const auto& row : s.paired_rows)
      s.paired.push_back(load_paired(row, static_cast<int>(s.paired.size()) + 1));
    build(s);
    fs::path out_p = out;
    if (out_p.has_parent_path()) fs::create_directories(out_p.parent_path());
    fs::path plot_p;
    if (plot != "none")
      plot_p = plot.empty() ? out_p.parent_path() / (out_p.stem().string() + "_speed.png") : fs::path(plot);
    json summary;
    std::string md = fmt::format("# {}\n\n", title);
    md += fmt::format("Generated by `brash-study-report` from the manifest `{}` and the report.json of every run it "
                      "lists; do not edit by hand{}.\n",
                      fs::path(manifest).filename().string(),
                      study_command.empty() ? "" : fmt::format(" (re-run: `{}`)", study_command));
    md += "Each number carries the id of its run (R1, R2, ...); section (e) lists the command of each run. CI95 = 95 % "
          "confidence interval of the windowed mean from block averaging (brash-post). \"reduced case\" = a small "
          "scene (cases/jbc_bench and variants), not the paper's 417k-sphere channel.\n\n";
    section_failures(s, md);
    section_paper(s, md);
    section_setup(s, md);
    section_gap(s, md);
    if (figures != "none")
      section_figures(s, md,
                      figures.empty() ? out_p.parent_path() / (out_p.stem().string() + "_figs") : fs::path(figures),
                      out_p.parent_path());
    section_speed(s, md, plot_p, summary);
    section_sensitivity(s, md);
    section_paired(s, md);
    section_engines(s, md);
    section_runs(s, md);
    {
      const fs::path tmp = out_p.string() + ".tmp";
      std::ofstream o(tmp);
      o << md;
      o.close();
      if (!o) throw std::runtime_error("cannot write " + tmp.string());
      fs::rename(tmp, out_p);
    }
    summary["runs"] = json::array();
    std::size_t failed = 0, running = 0;
    for (const auto& k : s.order) {
      const Run& r = s.runs.at(k);
      failed += r.ok || r.in_progress ? 0 : 1;
      running += r.in_progress ? 1 : 0;
      summary["runs"].push_back({{"ref", r.ref}, {"run_dir", r.run_dir.string()}, {"ok", r.ok},
                                 {"in_progress", r.in_progress}, {"problem", r.problem}});
    }
    summary["paired"] = json::array();
    for (const Paired& p : s.paired) {
      failed += p.ok ? 0 : 1;
      summary["paired"].push_back(
          {{"ref", p.ref}, {"summary", p.row->run_dir.string()}, {"ok", p.ok}, {"problem", p.problem}});
    }
    summary["failed"] = failed;
    summary["in_progress"] = running;
    if (!summary_path.empty()) std::ofstream(summary_path) << summary.dump(2) << "\n";
    fmt::print("brash-study-report: {} ({} run(s), {} failed or missing, {} in progress)\n", out_p.string(),
               s.order.size(), failed, running);
    return 0;
  } catch (const std::exception& e) {
    fmt::print(stderr, "brash-study-report: {}\n", e.what());
    return 2;
  }
}
