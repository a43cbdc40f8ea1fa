// A paired-seed ensemble's summary (bench/rank_ensemble.sh, `brash-post paired-ensemble`): every packing seed s run
// as side A in DIR/s<s>-<name A> and as side B in DIR/s<s>-<name B>; the complete pairs' window-mean resistances
// give B's effect on A, (B - A) / A of the ensemble means, with its delta-method 95 % CI (brash/stats/paired.hpp,
// the project's one definition of a change's size). B is within TOL of A when that CI lies inside (-TOL, +TOL).
//
// Output: a markdown table of the pairs and the ensemble statement (text), and DIR/ensemble-<A>-vs-<B>.json with
// case, side_a, side_b (the side specs), pairs, mean_a_N, mean_b_N, effect_rel, effect_ci95_rel, effect_sd_rel,
// definition (in words), a_N and b_N (the pairs' means, so the statistics can be recomputed), wall_a_s, wall_b_s
// (summed meta.json wall_time_s; null when a run has none) and speedup (wall A / wall B), read by
// brash-study-report (`paired` rows, through read_ensemble_summary) and bench/pareto_plot.sh. With fewer than 2
// complete pairs there is no statement and no JSON.
#pragma once
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace brash::post {

struct EnsembleSide {
  std::string spec;      // as given to bench/rank_ensemble.sh: NP[:section.key=value,...], ode[@DT[@IT]]
  std::string run_name;  // run directories are DIR/s<seed>-<run_name>
  std::string label;     // as the table prints it ("2 ranks"); run_name when empty
};

struct EnsembleSpec {
  std::filesystem::path dir;
  std::size_t seeds = 0;  // seeds 1 .. seeds
  std::string case_name;
  EnsembleSide a, b;
  double tol = 0.01;      // relative tolerance the CI is tested against
};

// One seed: each side's window-mean resistance [N] when its report.json says "complete", and its wall time [s]
// (NaN without meta.json wall_time_s).
struct EnsemblePair {
  std::size_t seed = 0;
  std::optional<double> a_N, b_N;
  double wall_a_s = NAN, wall_b_s = NAN;
  bool complete() const { return a_N && b_N; }
};

std::vector<EnsemblePair> read_ensemble(const EnsembleSpec& spec);

struct EnsembleSummary {
  std::string text;                             // table and statement, as printed
  std::optional<nlohmann::ordered_json> json;   // none with fewer than 2 complete pairs
  std::filesystem::path json_path;              // DIR/ensemble-<A>-vs-<B>.json
};

EnsembleSummary summarize_ensemble(const EnsembleSpec& spec, const std::vector<EnsemblePair>& pairs);

// A summary as read back. The summaries written before effects were taken on side A (evidence/ensembles) hold
// diff_rel, ci95_rel: the mean of (B - A) / mean of the pair with its CI, and no per-pair values. Their effect on
// A is recomputed from their ensemble means (exact: the definition is a ratio of the means); their CI on A cannot
// be, so it is NaN and their own numbers are kept, named as such.
struct EnsembleEffect {
  int pairs = 0;
  double mean_a_N = NAN, mean_b_N = NAN;
  double effect_rel = NAN;        // (B - A) / A of the ensemble means
  double ci95_rel = NAN;          // its 95 % CI; NaN where the summary holds no per-pair values
  double pair_mean_diff_rel = NAN, pair_mean_ci95_rel = NAN;  // an old summary's (B - A) / mean of the pair +- CI
  bool has_ci() const { return std::isfinite(ci95_rel); }
  bool resolved() const { return has_ci() && std::abs(effect_rel) > ci95_rel; }  // the CI excludes 0
};

// Throws nlohmann::json::exception when a field is missing or of the wrong type, std::invalid_argument when the
// per-pair lists do not make an ensemble (brash/stats/paired.hpp).
EnsembleEffect read_ensemble_summary(const nlohmann::json& summary);

// The summary's file name: ensemble-<A>-vs-<B>.json, or where that is longer than 200 bytes (a file name holds
// at most 255, and write_atomic adds a temporary suffix) its first 178 bytes, '-' and 16 hex digits of a hash of
// the whole name. brash-study finds a summary by its sides, not its name.
std::string ensemble_file_name(const std::string& run_name_a, const std::string& run_name_b);

}  // namespace brash::post
