// Analysis of one run directory -> report.json / report.md content. Pure apart from reading the run.
#pragma once
#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <brash/fsicr_params.hpp>
#include <brash/post/force_history.hpp>
#include <brash/post/fsicr.hpp>
#include <brash/post/ice_around_hull.hpp>
#include <brash/post/particles.hpp>
#include <brash/post/post_case.hpp>
#include <brash/post/run_meta.hpp>
#include <brash/stats/blocking.hpp>

namespace brash::post {

struct WindowSelection {
  std::array<double, 2> requested_s{};
  std::array<double, 2> used_s{};
  std::size_t i0 = 0, i1 = 0;   // samples [i0, i1) of the history
  bool truncated = false;       // the record ends before the requested window end
  bool fallback = false;        // no sample inside the window: last half of the record used
};

// Samples with t in [t0, t1]. Record shorter than t1: truncated window. No sample >= t0: the last
// half of the record is used instead (fallback, flagged). Needs >= 2 samples (InputError otherwise).
WindowSelection select_window(std::span<const double> t_s, std::array<double, 2> window_s,
                              const std::filesystem::path& source);

struct FsicrSummary {
  std::string ice_class;
  FsicrParams params;                          // full scale, psi recomputed
  std::map<std::string, std::string> source;   // per parameter: measured | override | case | missing
  std::optional<FsicrResult> result;           // empty if a parameter is missing
  std::vector<std::string> warnings;
};

// Model-scale hull parameters (as measured on the STL) to full scale: lengths * lambda, areas * lambda^2.
FsicrParams to_full_scale(const FsicrParams& model, double lambda);

// Combines measured full-scale parameters (may be absent), the case's main dimensions and the case's
// fsicr: overrides, then evaluates R_CH. Pure.
FsicrSummary resolve_fsicr(const PostCase& c, const std::optional<FsicrParams>& measured_full_scale);

// Measures the case hull with brash_hull when it is built in; empty (with a note) otherwise.
std::optional<FsicrParams> measure_case_hull_full_scale(const PostCase& c, std::vector<std::string>& notes);

struct RunAnalysis {
  std::filesystem::path run_dir;
  RunMeta meta;
  PostCase case_;
  ForceHistory force;
  WindowSelection window;
  std::vector<RecordGap> gaps;  // stretches of the window with no record (record_gaps)
  stats::BlockingResult resistance;  // of -fx, model scale [N]
  stats::BlockingResult fx, fy, fz;  // force components of the ice on the hull [N]
  // Every force sample of the window is zero: the record holds contact forces only, so the hull touched no ice
  // there and there is no resistance to report (resistance and its full-scale value are not shown).
  bool met_no_ice = false;
  // The hull force split over the window (docs/physics.md "The hull force split"): the resistance (-fx) of each
  // part, in kSplitParts' order, as resistance is averaged; empty when the record has no split, and then
  // split_not_recorded says why (never shown as 0).
  std::vector<stats::BlockingResult> resistance_split;
  std::vector<bool> split_contact;  // per part: whether it touched ice in the window (else "no contact", not 0)
  std::string split_not_recorded;
  std::optional<stats::HalvesTrend> resistance_trend;  // the window's two halves (>= kMinTrendSamples samples)
  double resistance_full_kN = 0, resistance_full_ci95_kN = 0;
  FsicrSummary fsicr;
  std::optional<double> ratio_fsicr_to_sim;
  std::optional<PublishedReference> reference;  // the case's published values for this run's fluid model
  std::optional<BandCheck> band;   // set by brash-post's report when the case has a contact band and snapshots
  // The ice around the hull over the window (ice_around_hull.hpp), set by brash-post's report (add_ice_around_hull);
  // without it, ice_around_missing says why (the report shows that, never zeros).
  std::optional<IceAroundHull> ice_around;
  std::string ice_around_missing = "not analysed";
  std::vector<std::string> notes;  // everything a reader must know (truncation, fallbacks, ...)
};

// The parts of the hull force split, in the order of brash::run::kSplitColumns: report.json's keys.
inline constexpr std::array<const char*, 5> kSplitParts{"bow", "mid", "stern", "normal", "tangential"};

// Fewest window samples for the stationarity check, made on every window that has them: two per half, so that each
// half has a mean and a spread (stats::halves_trend).
inline constexpr std::size_t kMinTrendSamples = 4;

RunAnalysis analyze_run(const std::filesystem::path& run_dir);

// Sets a.ice_around from the snapshots of the window (the case's hull; the regions of meta.json's hull_split, else
// measured on the hull; FSICR's H_F and H_M of the report's FSICR section, else of the case's beam and ice class), or
// a.ice_around_missing: no snapshot in the window, no hull mesh. Defined where brash-post has the hull library
// (BRASH_POST_HAVE_ICE_AROUND_HULL).
void add_ice_around_hull(RunAnalysis& a, const std::vector<SnapshotEntry>& entries);

// The run's fluid model: meta.json's, else the case's.
std::string run_fluid_model(const RunAnalysis& a);

nlohmann::ordered_json report_json(const RunAnalysis& a);
std::string report_markdown(const RunAnalysis& a);

// Window-sample CSV: t_s,fx_N,fy_N,fz_N,resistance_N,in_window (for spreadsheets and plots).
std::string force_history_csv(const RunAnalysis& a);
// Blocking levels (for checking the plateau by eye).
std::string blocking_csv(const stats::BlockingResult& b);

}  // namespace brash::post
