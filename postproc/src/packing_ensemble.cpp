// Packing-ensemble summary (packing_ensemble.hpp): the runs from their report.json and case.yaml, the statistics
// from brash/stats/paired.hpp.
#include <brash/post/packing_ensemble.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include <fmt/format.h>

#include <brash/case.hpp>
#include <brash/case_derive.hpp>
#include <brash/error.hpp>
#include <brash/stats/paired.hpp>
#include <brash/stats/student_t.hpp>

namespace brash::post {
namespace {

namespace fs = std::filesystem;
using J = nlohmann::json;
using O = nlohmann::ordered_json;  // what is written keeps its keys' order

// The keys a packing varies: the seed, the packing file it is written to, and the case's name.
bool packing_key(const std::string& key) {
  return key == "name" || key == "ice.seed" || key == "ice.packing_file";
}

std::optional<std::string> file_bytes(const fs::path& p) {
  std::error_code ec;
  if (!fs::is_regular_file(p, ec)) return std::nullopt;
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Run folders copied or made in another checkout resolve one hull file to another path: the same bytes are the
// same hull.
bool same_hull(const Case& a, const Case& b) {
  if (a.hull.file == b.hull.file) return true;
  const auto x = file_bytes(a.hull.file), y = file_bytes(b.hull.file);
  return x && y && *x == *y;
}

// The keys in which run b's case differs from run a's beyond the packing.
std::vector<std::string> keys_beyond_packing(const Case& a, const Case& b) {
  std::vector<std::string> keys;
  for (const auto& k : differing_case_keys(a, b))
    if (!packing_key(k) && !(k == "hull.file" && same_hull(a, b))) keys.push_back(k);
  return keys;
}

// A number of report.json at a JSON pointer; InputError naming the file and the key where there is none.
double number_at(const J& j, const char* pointer, const fs::path& file) {
  const J::json_pointer p(pointer);
  if (!j.contains(p) || !j.at(p).is_number())
    throw InputError(fmt::format("{}: no number at {} (a report of this brash-post: run brash-post {} again)",
                                 file.string(), pointer, file.parent_path().string()));
  return j.at(p).get<double>();
}

PackingRun read_run(const fs::path& dir, const Case& c) {
  const fs::path file = dir / "report.json";
  if (!fs::exists(file))
    throw InputError(fmt::format("{}: no report.json (run brash-post {} first)", dir.string(), dir.string()));
  std::ifstream in(file);
  const J j = J::parse(in, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded() || !j.is_object()) throw InputError(file.string() + ": not a JSON object");
  PackingRun r;
  r.dir = dir;
  r.name = fs::weakly_canonical(fs::absolute(dir)).filename().string();
  r.case_name = c.name;
  r.seed = c.ice.seed;
  r.window_s = {number_at(j, "/window_s/0", file), number_at(j, "/window_s/1", file)};
  r.requested_window_s = {c.run.window_s[0], c.run.window_s[1]};
  if (j.value("met_no_ice", false))
    throw InputError(fmt::format("{}: the hull met no ice in the run's window [{}, {}] s: it has no resistance",
                                 file.string(), r.window_s[0], r.window_s[1]));
  r.mean_N = number_at(j, "/resistance_model_N/mean", file);
  r.ci95_N = number_at(j, "/resistance_model_N/ci95", file);
  r.full_kN = number_at(j, "/resistance_full_kN", file);
  r.full_ci95_kN = number_at(j, "/resistance_full_ci95_kN", file);
  const J::json_pointer drifts("/resistance_model_N/window_halves/drifts");
  if (j.contains(drifts) && j.at(drifts).is_boolean()) r.halves_drift = j.at(drifts).get<bool>();
  const J::json_pointer rch("/fsicr/R_CH_kN");
  if (j.contains(rch) && j.at(rch).is_number()) r.R_CH_kN = j.at(rch).get<double>();
  return r;
}

// The run's case as it was asked for: an early stop rewrites the resolved case's duration and window to the stop
// (meta.json early_stop keeps what was asked), and runs of one ensemble may stop at different times.
Case read_case(const fs::path& dir) {
  const fs::path file = dir / "case.yaml";
  if (!fs::exists(file)) throw InputError(fmt::format("{}: no case.yaml (not a run folder)", dir.string()));
  Case c = load_case(file);
  const J meta = J::parse(std::ifstream(dir / "meta.json"), nullptr, /*allow_exceptions=*/false);
  const J::json_pointer duration("/early_stop/requested_duration_s"), window("/early_stop/requested_window_s");
  if (meta.is_object() && meta.contains(duration) && meta.at(duration).is_number() && meta.contains(window) &&
      meta.at(window).is_array() && meta.at(window).size() == 2) {
    c.run.duration_s = meta.at(duration).get<double>();
    c.run.window_s = {meta.at(window)[0].get<double>(), meta.at(window)[1].get<double>()};
  }
  return c;
}

bool same_window(const std::array<double, 2>& a, const std::array<double, 2>& b) {
  const auto near = [](double x, double y) { return std::abs(x - y) <= 1e-9 * std::max(1.0, std::abs(x)); };
  return near(a[0], b[0]) && near(a[1], b[1]);
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

// A case name as part of a file name: characters other than letters, digits, '.', '_' and '-' become '_'.
std::string file_safe(const std::string& name) {
  std::string s = name;
  for (char& ch : s)
    if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == '.' || ch == '_' || ch == '-')) ch = '_';
  return s.empty() ? "case" : s;
}

std::string drift_text(const std::optional<bool>& d) {
  if (!d) return "-";
  return *d ? "drifts" : "agree";
}

constexpr const char* kDefinition =
    "mean of the runs' window-mean resistances; 95 % CI between packings: Student t on n - 1 degrees of freedom "
    "of the run means, t sd / sqrt(n); each run's own CI: block averaging of its record (report.json)";

}  // namespace

std::vector<PackingRun> read_packing_runs(const std::vector<fs::path>& run_dirs) {
  if (run_dirs.size() < 2)
    throw InputError(fmt::format("packing-ensemble: {} run folder(s) given{}; at least 2 are needed",
                                 run_dirs.size(), run_dirs.empty() ? "" : " (" + run_dirs.front().string() + ")"));
  std::vector<PackingRun> runs;
  std::optional<Case> first;
  std::map<std::uint64_t, fs::path> by_seed;
  for (const auto& dir : run_dirs) {
    const Case c = read_case(dir);
    if (first) {
      if (const auto keys = keys_beyond_packing(*first, c); !keys.empty())
        throw InputError(fmt::format("{}/case.yaml differs from {}/case.yaml in {}: the runs of a packing ensemble "
                                     "differ only in ice.seed (and ice.packing_file, name)",
                                     dir.string(), run_dirs.front().string(), join(keys)));
    } else {
      first = c;
    }
    if (const auto [it, fresh] = by_seed.emplace(c.ice.seed, dir); !fresh)
      throw InputError(fmt::format("{} and {} have the same ice.seed {}: one packing twice", it->second.string(),
                                   dir.string(), c.ice.seed));
    runs.push_back(read_run(dir, c));
    // the window asked for (an early stop may end each run's at its own time: the rule that stopped it is the
    // same); different windows asked for are different ensembles
    const auto &a = runs.front().requested_window_s, &b = runs.back().requested_window_s;
    if (!same_window(a, b))
      throw InputError(fmt::format("{}: window [{}, {}] s asked for, but {} has [{}, {}] s: the means are over "
                                   "different windows",
                                   dir.string(), b[0], b[1], run_dirs.front().string(), a[0], a[1]));
  }
  return runs;
}

PackingEnsembleSummary summarize_packing_ensemble(const std::vector<PackingRun>& runs, const fs::path& out) {
  if (runs.size() < 2) throw InputError("packing-ensemble: at least 2 runs are needed");
  PackingEnsembleSummary s;
  const auto& f = runs.front();
  s.json_path = out.empty() ? fs::absolute(f.dir).lexically_normal().parent_path() /
                                  fmt::format("packing-ensemble-{}.json", file_safe(f.case_name))
                            : out;
  std::vector<double> model, full, within;
  int drifting = 0;
  auto& t = s.text;
  t += fmt::format("== {}: {} packings, mean resistance over the window [{}, {}] s\n", f.case_name, runs.size(),
                   f.window_s[0], f.window_s[1]);
  t += "| run | ice.seed | window [s] | model [N] | full scale [kN] | window halves |\n|---|---|---|---|---|---|\n";
  O rows = O::array();
  for (const auto& r : runs) {
    model.push_back(r.mean_N);
    full.push_back(r.full_kN);
    within.push_back(r.ci95_N);
    drifting += r.halves_drift.value_or(false) ? 1 : 0;
    t += fmt::format("| {} | {} | [{}, {}] | {:.3f} ± {:.3f} | {:.1f} ± {:.1f} | {} |\n", r.name, r.seed,
                     r.window_s[0], r.window_s[1], r.mean_N, r.ci95_N, r.full_kN, r.full_ci95_kN,
                     drift_text(r.halves_drift));
    rows.push_back({{"run", r.name}, {"dir", r.dir.string()}, {"seed", r.seed}, {"mean_N", r.mean_N},
                    {"ci95_N", r.ci95_N}, {"full_kN", r.full_kN}, {"full_ci95_kN", r.full_ci95_kN},
                    {"window_halves_drift", r.halves_drift ? O(*r.halves_drift) : O(nullptr)}});
  }
  const auto m = stats::mean_ci95(model), F = stats::mean_ci95(full), w = stats::mean_ci95(within);
  const double ratio_ci = m.ci95 / w.mean;
  t += fmt::format("| **ensemble mean** (n = {}) | | [{}, {}] | **{:.3f} ± {:.3f}** | **{:.1f} ± {:.1f}** | {} of {} "
                   "drift |\n",
                   m.n, f.window_s[0], f.window_s[1], m.mean, m.ci95, F.mean, F.ci95, drifting, runs.size());
  t += fmt::format("\nbetween packings: sd {:.3f} N ({:.1f} kN full scale), n = {}, 95 % CI = t_{{0.975,{}}} {:.3f} "
                   "x sd / sqrt(n)\n",
                   m.sd, F.sd, m.n, m.n - 1, stats::student_t975(m.n - 1));
  t += fmt::format("between-packing CI95 / mean within-run CI95 ({:.3f} N) = {:.2f}\n", w.mean, ratio_ci);
  O ratio = nullptr, ratio_range = nullptr;
  if (f.R_CH_kN) {
    const double rch = *f.R_CH_kN;
    ratio = rch / F.mean;
    t += fmt::format("FSICR R_CH {:.1f} kN; R_CH / R of the mean = {:.2f}", rch, rch / F.mean);
    if (F.lo() > 0) {
      ratio_range = {rch / F.hi(), rch / F.lo()};
      t += fmt::format(" ({:.2f} to {:.2f} over the mean's 95 % CI)", rch / F.hi(), rch / F.lo());
    }
    t += "\n";
    for (const auto& r : runs)
      if (!r.R_CH_kN || std::abs(*r.R_CH_kN - rch) > 1e-9 * std::abs(rch))
        t += fmt::format("note: {}'s report has another FSICR R_CH ({}): {}'s is used\n", r.name,
                         r.R_CH_kN ? fmt::format("{:.1f} kN", *r.R_CH_kN) : "none", f.name);
  } else {
    t += "FSICR R_CH: none in the first run's report\n";
  }
  s.json = O{
      {"case", f.case_name},
      {"definition", kDefinition},
      {"window_s", {f.window_s[0], f.window_s[1]}},
      {"n", m.n},
      {"dof", m.n - 1},
      {"t975", stats::student_t975(m.n - 1)},
      {"runs", rows},
      {"mean_N", m.mean},
      {"ci95_N", m.ci95},
      {"sd_N", m.sd},
      {"full_kN", F.mean},
      {"full_ci95_kN", F.ci95},
      {"sd_full_kN", F.sd},
      {"within_ci95_mean_N", w.mean},
      {"between_over_within_ci95", ratio_ci},
      {"window_halves_drifting", drifting},
      {"fsicr_R_CH_kN", f.R_CH_kN ? O(*f.R_CH_kN) : O(nullptr)},
      {"ratio_fsicr_to_mean", ratio},
      {"ratio_fsicr_to_mean_over_ci95", ratio_range}};
  return s;
}

}  // namespace brash::post
