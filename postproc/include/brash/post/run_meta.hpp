// meta.json of a run (written by every engine runner; see docs/case_format.md).
#pragma once
#include <filesystem>
#include <optional>
#include <string>

namespace brash::post {

struct RunMeta {
  std::string engine = "unknown", engine_version, fluid_model, treatment, git_commit;
  std::string status = "unknown";  // running | complete | failed
  std::string reason;
  std::optional<double> dt_s, wall_time_s, particle_steps;
  std::optional<long long> ranks, particles;
  long long exits = 0;  // pieces that left through the channel's open ends (fix brash/exit, World::retire)
  bool culled_far_field = false;  // brash-ode --cull (skips.cull): spheres outside the window frozen, no wake rule
  bool in_progress() const { return status == "running"; }
};

// InputError (file + parser line/column) for invalid JSON or wrongly typed keys.
RunMeta read_run_meta(const std::filesystem::path& path);

}  // namespace brash::post
