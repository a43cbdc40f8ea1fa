// A packing ensemble's summary (`brash-post packing-ensemble RUN_DIR...`): runs of one case that differ only in
// the packing (ice.seed, hence ice.packing_file; the case's name may differ too), each post-processed (report.json).
// One run's CI (block averaging) holds the scatter of its own record only; another packing gives another mean. The
// ensemble's answer is the mean of the runs' window means with the between-packing 95 % CI, Student t on
// n - 1 degrees of freedom of the run means (brash/stats/paired.hpp mean_ci95), at model and full scale, beside
// each run's within-run CI; their ratio says how much of the packing's scatter one run's CI misses.
//
// Output: a markdown table (one row per run, then the ensemble's) with the statistics below it, and a JSON file
// (default: the first run's parent folder / packing-ensemble-<case name>.json) with case, definition, window_s, n,
// dof, t975, runs (run, dir, seed, mean_N, ci95_N, full_kN, full_ci95_kN, window_halves_drift), mean_N, ci95_N,
// sd_N, full_kN, full_ci95_kN, sd_full_kN, within_ci95_mean_N, between_over_within_ci95, window_halves_drifting
// (runs whose window halves drift), fsicr_R_CH_kN, ratio_fsicr_to_mean (R_CH / R of the full-scale mean) and
// ratio_fsicr_to_mean_over_ci95 (R_CH over the mean's CI ends; null where the CI reaches 0 or there is no R_CH).
#pragma once
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace brash::post {

// One run as its report.json and case.yaml give it.
struct PackingRun {
  std::filesystem::path dir;
  std::string name;                  // the run folder's name
  std::string case_name;             // case.yaml name
  std::uint64_t seed = 0;            // case.yaml ice.seed
  std::array<double, 2> window_s{};  // report.json window_s (the window used)
  std::array<double, 2> requested_window_s{};  // as asked for: before an early stop ended it (meta.json early_stop)
  double mean_N = 0, ci95_N = 0;     // report.json resistance_model_N mean, ci95 (block averaging)
  double full_kN = 0, full_ci95_kN = 0;
  std::optional<bool> halves_drift;  // resistance_model_N.window_halves.drifts; none where the report has none
  std::optional<double> R_CH_kN;     // fsicr.R_CH_kN
};

// Reads the runs and refuses (brash::InputError naming the run) fewer than 2 runs, a run without case.yaml or
// report.json or whose hull met no ice, runs whose resolved cases differ in any key but name, ice.seed and
// ice.packing_file (the keys listed; a hull file at another path with the same bytes counts as the same hull), two
// runs of one seed and runs with different windows.
std::vector<PackingRun> read_packing_runs(const std::vector<std::filesystem::path>& run_dirs);

struct PackingEnsembleSummary {
  std::string text;                  // table and statistics, as printed
  nlohmann::ordered_json json;
  std::filesystem::path json_path;   // `out` when given, else the default above
};

// The summary of runs read by read_packing_runs.
PackingEnsembleSummary summarize_packing_ensemble(const std::vector<PackingRun>& runs,
                                                  const std::filesystem::path& out = {});

}  // namespace brash::post
