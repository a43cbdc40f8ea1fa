// meta.json of a run (written by every engine runner; see docs/case_format.md).
#pragma once
#include <array>
#include <filesystem>
#include <optional>
#include <string>

namespace brash::post {

// meta.json "early_stop" (LIGGGHTS runner, speedups.early_stop_rel_ci): where the run stopped and why.
struct EarlyStopMeta {
  double t_s = 0;                   // model time of the stop; the run's window and duration end here
  double requested_duration_s = 0;  // the case's run.duration_s
  double rel_ci_threshold = 0;      // the 95 % CI of the window mean fell below this fraction of it
  // runs since the slope test (brash/stats/early_stop.hpp); absent in older meta.json files
  std::string reason;               // why the rule held, e.g. "CI 0.36 % < 1.00 %, drift -0.40 %/window within ..."
  std::optional<double> estimate_N, estimate_ci95_N;  // the full window's mean as the rule estimated it, CI95
  std::optional<double> requested_window_end_s;       // the window's end the case asked for
};

// meta.json "early_stop_last_check": a run with the early stop on that went on to its end (or is still going):
// its last check and why the rule did not hold then.
struct EarlyStopCheckMeta {
  double t_s = 0;
  std::string reason;  // e.g. "drift -1.20 %/window > CI 0.90 %"
};

struct RunMeta {
  std::string engine = "unknown", engine_version, fluid_model, treatment, git_commit;
  std::string status = "unknown";  // running | complete | failed
  std::string reason;
  std::optional<double> dt_s, wall_time_s, particle_steps;
  std::optional<long long> ranks, particles;
  long long exits = 0;  // pieces that left through the channel's open ends (fix brash/exit, World::retire)
  bool culled_far_field = false;  // brash-ode --cull with the window alone (no wake force): spheres outside frozen
  std::optional<EarlyStopMeta> early_stop;
  std::optional<EarlyStopCheckMeta> early_stop_last_check;
  // meta.json "hull_split": the parallel mid-body bounding the hull force split's regions (x_par_aft_m,
  // x_par_fwd_m, hull frame), or the engine's words on why it records no split (YADE)
  std::optional<std::array<double, 2>> hull_split_par_m;
  std::string hull_split_not_recorded;
  bool in_progress() const { return status == "running"; }
};

// InputError (file + parser line/column) for invalid JSON or wrongly typed keys.
RunMeta read_run_meta(const std::filesystem::path& path);

}  // namespace brash::post
