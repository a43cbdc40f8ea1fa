// The engines compared on the same case and fluid model (analysis.hpp).
#include <algorithm>
#include <cmath>
#include <tuple>

#include <brash/post/study_report/analysis.hpp>

namespace brash::post::study_report {

std::vector<const Run*> engine_runs(const Study& s) {
  std::vector<const Run*> runs;
  for (const auto& row : s.rows) {
    if (row.group != "engine" && row.group != "paper") continue;
    const Run& r = s.run_of(row);
    if (std::find(runs.begin(), runs.end(), &r) == runs.end()) runs.push_back(&r);
  }
  std::sort(runs.begin(), runs.end(), [](const Run* a, const Run* b) {
    return std::tie(a->base_case, a->model, a->engine) < std::tie(b->base_case, b->model, b->engine);
  });
  return runs;
}

std::set<std::string> engines_with_results(const Study& s) {
  std::set<std::string> engines;
  for (const auto& row : s.rows)
    if ((row.group == "engine" || row.group == "paper") && s.run_of(row).ok) engines.insert(s.run_of(row).engine);
  return engines;
}

namespace {

// The complete LIGGGHTS run of R's case and fluid model (the first listed), or nullptr.
const Run* liggghts_run_of(const Run& r, const std::vector<const Run*>& runs) {
  const auto it = std::find_if(runs.begin(), runs.end(), [&](const Run* l) {
    return l->ok && l->engine == "liggghts" && l->base_case == r.base_case && l->model == r.model;
  });
  return it == runs.end() ? nullptr : *it;
}

}  // namespace

std::optional<VsLiggghts> vs_liggghts(const Run& r, const std::vector<const Run*>& sorted_runs) {
  const Run* l = liggghts_run_of(r, sorted_runs);
  if (!l || l->mean_N == 0.0 || r.mean_N == 0.0) return std::nullopt;
  const double ratio = r.mean_N / l->mean_N;
  const double rel_ci = std::hypot(r.ci_N / r.mean_N, l->ci_N / l->mean_N);
  return VsLiggghts{l, 100.0 * (ratio - 1.0), 100.0 * std::abs(ratio) * rel_ci};
}

std::vector<double> bin_means(const ForceHistory& h, double w_s, double t_end_s) {
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

// An unfinished run of another engine (an ODE paper run takes tens of hours and is archived while it goes
// on) beside the complete LIGGGHTS run of the same case and fluid model with a force record, over the model
// time both have reached: the engine comparison on the scene itself for as far as it goes (the bow entering
// the ice, not the window).
std::vector<EngineSoFar> engines_so_far(const std::vector<const Run*>& sorted_runs) {
  std::vector<EngineSoFar> out;
  for (const Run* r : sorted_runs) {
    if (!r->in_progress || r->engine == "liggghts" || !r->has_force_record) continue;
    const auto lit = std::find_if(sorted_runs.begin(), sorted_runs.end(), [&](const Run* l) {
      return l->ok && l->engine == "liggghts" && l->base_case == r->base_case && l->model == r->model &&
             l->has_force_record;
    });
    if (lit == sorted_runs.end()) continue;
    EngineSoFar e;
    e.run = r;
    e.liggghts = *lit;
    if (!r->history || !e.liggghts->history) {
      e.error = !r->history ? r->history_error : e.liggghts->history_error;
      out.push_back(std::move(e));
      continue;
    }
    const ForceHistory &h = *r->history, &hl = *e.liggghts->history;
    if (h.t_s.empty() || hl.t_s.empty()) continue;
    e.t_reached_s = h.t_s.back();
    const double t_end = std::min(h.t_s.back(), hl.t_s.back());
    // whole seconds; halves or tenths for a record that is still short
    e.bin_s = t_end >= 4.0 ? 1.0 : t_end >= 1.0 ? 0.5 : 0.1;
    e.run_N = bin_means(h, e.bin_s, t_end);
    e.liggghts_N = bin_means(hl, e.bin_s, t_end);
    if (e.run_N.empty()) continue;
    out.push_back(std::move(e));
  }
  return out;
}

}  // namespace brash::post::study_report
