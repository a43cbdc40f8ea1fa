// Selections, fits and comparisons of the study's runs (analysis.hpp).
#include <algorithm>
#include <cmath>
#include <tuple>

#include <fmt/format.h>

#include <brash/post/report.hpp>
#include <brash/post/study_report/analysis.hpp>

namespace brash::post::study_report {

std::vector<const Row*> rows_of(const Study& s, const std::string& group) {
  std::vector<const Row*> rows;
  for (const auto& r : s.rows)
    if (r.group == group) rows.push_back(&r);
  return rows;
}

std::vector<const Run*> completed_runs(const Study& s, const std::string& group) {
  std::vector<const Run*> runs;
  for (const Row* row : rows_of(s, group)) {
    const Run& r = s.run_of(*row);
    if (r.ok && std::find(runs.begin(), runs.end(), &r) == runs.end()) runs.push_back(&r);
  }
  return runs;
}

bool any_paper_case(const std::vector<const Run*>& runs) {
  return std::any_of(runs.begin(), runs.end(), [](const Run* r) { return r->base_case == kPaperCase; });
}

std::vector<const Run*> started_paper_case_runs(const Study& s) {
  std::vector<const Run*> runs;
  for (const Row* row : rows_of(s, "paper")) {
    const Run& r = s.run_of(*row);
    if (row->base_case == kPaperCase && r.has_case_yaml && std::find(runs.begin(), runs.end(), &r) == runs.end())
      runs.push_back(&r);
  }
  return runs;
}

std::vector<std::string> sensitivity_groups(const Study& s) {
  std::vector<std::string> groups;
  for (const auto& r : s.rows)
    if (r.group != "paper" && r.group != "speed" && r.group != "engine" &&
        std::find(groups.begin(), groups.end(), r.group) == groups.end())
      groups.push_back(r.group);
  return groups;
}

std::pair<std::string, std::string> Baselines::key(const Run& r) const {
  return {r.engine, varies_model ? std::string() : r.model};
}

const Run* Baselines::of(const Run& r) const {
  const auto it = by_key.find(key(r));
  return it == by_key.end() ? nullptr : it->second;
}

Baselines baselines_of(const Study& s, const std::string& group) {
  Baselines b;
  for (const Row* r : rows_of(s, group))
    if (!r->param.empty()) b.param = r->param;
  b.varies_model = b.param == "fluid.model";
  for (const Row* r : rows_of(s, group))
    if (r->baseline && s.run_of(*r).ok) b.by_key[b.key(s.run_of(*r))] = &s.run_of(*r);
  return b;
}

double paper_full_kN(const brash::ReferenceSpec& paper, const std::string& model) {
  const auto r = published_reference(paper, model);
  return r && r->resistance_full_kN ? *r->resistance_full_kN : NAN;
}

std::vector<AddedMassVsDrag> added_mass_vs_drag(const Study& s) {
  std::map<std::pair<std::string, std::string>, std::map<std::string, const Run*>> by;
  for (const Row* row : rows_of(s, "paper")) {
    const Run& r = s.run_of(*row);
    if (r.ok) by[{r.engine, r.base_case}][r.model] = &r;
  }
  std::vector<AddedMassVsDrag> out;
  for (const auto& [key, runs] : by) {
    for (const char* added : {"added_mass", "both"}) {
      if (!runs.count(added) || !runs.count("drag")) continue;
      const Run& a = *runs.at(added);
      const Run& d = *runs.at("drag");
      const double diff = (a.mean_N - d.mean_N) / d.mean_N * 100.0;
      // first-order propagation of the two independent CIs into the ratio a/d
      const double ci = 100.0 * (a.mean_N / d.mean_N) * std::hypot(a.ci_N / a.mean_N, d.ci_N / d.mean_N);
      out.push_back({key.first, key.second, added, &a, &d, diff, ci});
    }
  }
  return out;
}

std::vector<GapToPaper> gaps_to_paper(const Study& s) {
  std::vector<GapToPaper> gaps;
  for (const Run* r : completed_runs(s, "paper")) {
    const double paper = paper_full_kN(s.paper, r->model);
    if (r->base_case != kPaperCase || !std::isfinite(paper)) continue;
    gaps.push_back({r, paper, 100.0 * (paper / r->full_kN - 1.0),
                    100.0 * paper * r->full_ci_kN / (r->full_kN * r->full_kN)});
  }
  return gaps;
}

bool CandidateChange::resolved() const { return !(std::abs(rel) < ci); }

std::vector<CandidateChange> candidate_changes(const Study& s) {
  std::vector<CandidateChange> out;
  for (const auto& g : sensitivity_groups(s)) {
    const Baselines base = baselines_of(s, g);
    for (const Row* row : rows_of(s, g)) {
      if (row->baseline) continue;
      const Run& r = s.run_of(*row);
      const Run* b = r.ok ? base.of(r) : nullptr;
      if (!b) continue;
      out.push_back({row, base.param.empty() ? g : base.param, &r, b, r.mean_N / b->mean_N - 1.0,
                     std::hypot(r.ci_N, b->ci_N) / b->mean_N});
    }
  }
  return out;
}

ChangeVsBaseline change_vs_baseline(const Run& run, const Run& baseline) {
  ChangeVsBaseline c;
  c.delta_N = run.mean_N - baseline.mean_N;
  c.delta_pct = c.delta_N / baseline.mean_N * 100.0;
  const double combined_ci = std::hypot(run.ci_N, baseline.ci_N);
  if (combined_ci > 0) c.delta_over_ci = c.delta_N / combined_ci;
  return c;
}

std::vector<SpeedFit> speed_fits(const Study& s) {
  std::map<std::pair<std::string, std::string>, std::vector<const Run*>> groups;
  for (const Run* r : completed_runs(s, "speed")) groups[{r->engine, r->model}].push_back(r);
  std::vector<SpeedFit> fits;
  for (const auto& [key, runs] : groups) {
    std::vector<double> speeds, means;
    for (const Run* r : runs)
      if (r->speed > 0 && r->mean_N > 0) speeds.push_back(r->speed), means.push_back(r->mean_N);
    SpeedFit f{brash::stats::fit_power_law(speeds, means), key.first, key.second, runs, {}, 0};
    f.laws = brash::stats::fit_speed_laws(speeds, means);
    f.best_law = brash::stats::best_speed_law(f.laws);
    fits.push_back(std::move(f));
  }
  return fits;
}

}  // namespace brash::post::study_report
