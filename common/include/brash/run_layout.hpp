// The run layout every engine writes (docs/case_format.md): run directory naming, atomic file
// writes and meta.json. Shared by brash-liggghts-run, brash-ode and the YADE runner.
#pragma once
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace brash::run {

// Writes `content` to `file` through a temporary file in the same folder and a rename, so a reader
// never sees a half-written file.
void write_atomic(const std::filesystem::path& file, const std::string& content);

// runs/<case>-<engine>-<model>-<UTC stamp>, created with particles/ and restart/ inside.
std::filesystem::path make_run_dir(const std::filesystem::path& runs_root, const std::string& case_name,
                                   const std::string& engine, const std::string& fluid_model);

// meta.json (atomic). Keys: engine, engine_version, fluid_model, treatment, dt_s, ranks, particles,
// wall_time_s, particle_steps, git_commit, status (running | complete | failed), reason.
void write_meta(const std::filesystem::path& run_dir, const nlohmann::json& meta);

// Commit of the source tree the binary was built from ("unknown" outside a git checkout).
std::string git_commit();

}  // namespace brash::run
