// The run layout every engine writes (docs/case_format.md): run directory naming, atomic file
// writes and meta.json. Shared by brash-liggghts-run, brash-ode and the YADE runner.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace brash::run {

// Writes `content` to `file` through a temporary file in the same folder and a rename, so a reader
// never sees a half-written file.
void write_atomic(const std::filesystem::path& file, std::string_view content);

// The temporary name write_atomic uses for `file` (hidden, same folder so the rename is atomic, with the
// pid so that two processes writing one run do not clobber each other). For writers that need a path
// (VTK, gnuplot): write there, then rename.
std::filesystem::path temp_path_for(const std::filesystem::path& file);

// runs/<case>-<engine>-<model>-<UTC stamp>, created with particles/ and restart/ inside.
std::filesystem::path make_run_dir(const std::filesystem::path& runs_root, const std::string& case_name,
                                   const std::string& engine, const std::string& fluid_model);

// meta.json (atomic). Keys: engine, engine_version, fluid_model, treatment, dt_s, ranks, particles,
// wall_time_s, particle_steps, git_commit, status (running | complete | failed), reason.
void write_meta(const std::filesystem::path& run_dir, const nlohmann::json& meta);

// Commit the binary was built from, recorded at build time ("unknown" when built outside a git checkout).
std::string git_commit();

// Exclusive lock on a run directory while a runner works in it (flock on RUN_DIR/.lock), so that a second
// runner (a --resume of a run still going, a study resuming it) cannot write the same files. The kernel releases
// it when every process holding it ends, kill -9 included; the descriptor is inherited by the engine a runner
// starts, so an engine left running by a killed runner still holds it. Throws brash::InputError naming the
// directory when another process holds it.
class RunDirLock {
 public:
  explicit RunDirLock(const std::filesystem::path& run_dir);
  ~RunDirLock();
  RunDirLock(const RunDirLock&) = delete;
  RunDirLock& operator=(const RunDirLock&) = delete;

 private:
  std::filesystem::path file_;
  int fd_ = -1;
};

}  // namespace brash::run
