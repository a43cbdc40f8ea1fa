// The wall time of each stage of a run made from its case (meta.json "stages", docs/case_format.md): the packing
// and its settled bed, the scene's set-up, the run itself and the report. The packing and the settled bed are made
// once per packing and cached: a run that finds them made records what making them cost (made_by_this_run: false),
// so the cost of a run from a new packing reads from any run's record.
#pragma once
#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>

namespace brash::run {

// What brash-pack recorded for the packing file: wall_time_s of <stem>.json beside it; nullopt when absent.
std::optional<double> packing_wall_s(const std::filesystem::path& packing_file);

// What brash-settle recorded in a settled bed's header (wall_s=...); nullopt for a bed made before it did.
std::optional<double> settled_bed_wall_s(const std::filesystem::path& settled_file);

// {"wall_s": seconds or null, "made_by_this_run": bool}
nlohmann::json made_input(std::optional<double> wall_s, bool made_by_this_run);

inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace brash::run
