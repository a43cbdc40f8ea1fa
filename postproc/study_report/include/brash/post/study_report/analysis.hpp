// What the study's numbers say (brash-study-report): selections of runs, fits and comparisons, as pure
// functions of the loaded Study (study.hpp). The document's sections render these values.
#pragma once
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <brash/post/study_report/study.hpp>
#include <brash/stats/power_law.hpp>
#include <brash/stats/speed_law.hpp>

namespace brash::post::study_report {

// ---- selections -----------------------------------------------------------------------------------
std::vector<const Row*> rows_of(const Study& s, const std::string& group);  // in manifest order
// The completed runs of a manifest group, each once, in manifest order.
std::vector<const Run*> completed_runs(const Study& s, const std::string& group);
bool any_paper_case(const std::vector<const Run*>& runs);
// The paper case's runs of section (a) that have started (their run folder holds the resolved case.yaml),
// each once, in manifest order: what the set-up table and the history plot read, finished or not.
std::vector<const Run*> started_paper_case_runs(const Study& s);
// Sensitivity groups (every group but paper, speed and engine), in manifest order.
std::vector<std::string> sensitivity_groups(const Study& s);

// A sensitivity group's baseline for a run: the group's baseline row of the same engine and fluid model, or
// of the same engine alone when the group varies the fluid model itself. nullptr if there is none (or it
// failed).
struct Baselines {
  std::string param;  // the parameter the group varies (its rows' `param`; empty: none named)
  bool varies_model = false;
  std::map<std::pair<std::string, std::string>, const Run*> by_key;
  std::pair<std::string, std::string> key(const Run& r) const;
  const Run* of(const Run& r) const;
};
Baselines baselines_of(const Study& s, const std::string& group);

// ---- the paper ------------------------------------------------------------------------------------
// The paper's full-scale resistance for a fluid model, as the paper case declares it (NaN: none declared).
double paper_full_kN(const brash::ReferenceSpec& paper, const std::string& model);

// Our added-mass model against drag, same engine and base case: (R_added - R_drag) / R_drag in %, its CI by
// first-order propagation of the two independent CIs into the ratio.
struct AddedMassVsDrag {
  std::string engine, base_case, added_model;  // added_model: added_mass (Eq. 2 alone) or both (Eq. 2 + Eq. 1)
  const Run* added = nullptr;
  const Run* drag = nullptr;
  double difference_pct = 0, ci_pct = 0;
};
std::vector<AddedMassVsDrag> added_mass_vs_drag(const Study& s);

// How far a completed paper-case run is from the paper's number: the paper's value on ours, in %, and the
// part of that our CI95 alone explains.
struct GapToPaper {
  const Run* run = nullptr;
  double paper_kN = 0, gap_pct = 0, ci_pct = 0;
};
std::vector<GapToPaper> gaps_to_paper(const Study& s);

// A measured candidate for the gap: a sensitivity run's relative change on its baseline, with the CI95 of
// the two runs combined.
struct CandidateChange {
  const Row* row = nullptr;
  std::string param;  // the group's parameter, or the group's name when it names none
  const Run* run = nullptr;
  const Run* baseline = nullptr;
  double rel = 0, ci = 0;
  bool resolved() const;
};
std::vector<CandidateChange> candidate_changes(const Study& s);

// ---- sensitivities --------------------------------------------------------------------------------
// A run's change on its baseline: in N, in % of the baseline, and over the combined CI95 (unset when that is 0).
struct ChangeVsBaseline {
  double delta_N = 0, delta_pct = 0;
  std::optional<double> delta_over_ci;
};
ChangeVsBaseline change_vs_baseline(const Run& run, const Run& baseline);

// ---- speed sweep ----------------------------------------------------------------------------------
// R = a U^n per engine and fluid model (R in N at model scale, U in m/s): brash/stats/power_law.hpp; and the
// speed law in its three forms with the one AICc prefers (brash/stats/speed_law.hpp).
struct SpeedFit : brash::stats::PowerLawFit {
  std::string engine, model;
  std::vector<const Run*> runs;  // the group's completed runs, in manifest order
  std::vector<brash::stats::SpeedLawFit> laws;  // a U^n, a + b U^2, a + b U^n
  std::size_t best_law = 0;                     // index into laws; laws.size() when none has an AICc
};
std::vector<SpeedFit> speed_fits(const Study& s);  // by (engine, model)

// ---- engines --------------------------------------------------------------------------------------
// The runs of groups engine and paper, each once, sorted by (base case, fluid model, engine).
std::vector<const Run*> engine_runs(const Study& s);
std::set<std::string> engines_with_results(const Study& s);  // engines of the completed runs above
// A run against the LIGGGHTS run of the same case and fluid model (the first listed): R / R_liggghts - 1 in %
// and its CI from the two runs' relative CIs in quadrature (independent runs).
struct VsLiggghts {
  const Run* liggghts = nullptr;
  double rel_pct = 0, ci_pct = 0;
};
std::optional<VsLiggghts> vs_liggghts(const Run& r, const std::vector<const Run*>& sorted_runs);

// An unfinished run of another engine beside the complete LIGGGHTS run of the same case and fluid model, in
// whole bins of the model-scale resistance over the model time both records reach.
struct EngineSoFar {
  const Run* run = nullptr;
  const Run* liggghts = nullptr;
  std::string error;  // a record not readable: nothing else is set
  double t_reached_s = 0, bin_s = 0;
  std::vector<double> run_N, liggghts_N;  // bin means (NaN: no row in the bin)
};
std::vector<EngineSoFar> engines_so_far(const std::vector<const Run*>& sorted_runs);

// Mean resistance (-fx, model scale) in the whole bins [k w, (k + 1) w) that `h` covers up to `t_end_s`.
std::vector<double> bin_means(const ForceHistory& h, double w_s, double t_end_s);

// ---- the paper case's histories -------------------------------------------------------------------
struct PaperHistory {
  std::string title;                            // run, engine, fluid model (and how far a running one got)
  std::vector<std::pair<double, double>> t_kN;  // bin centre, bin mean of -fx at full scale (NaN: no row)
};
struct PaperHistories {
  std::vector<PaperHistory> lines;
  std::vector<std::pair<std::string, std::string>> unreadable;  // run ref, why its history could not be read
  std::array<double, 2> window{NAN, NAN};  // the window of the last run read
};
PaperHistories paper_histories(const Study& s, double bin_s);

}  // namespace brash::post::study_report
