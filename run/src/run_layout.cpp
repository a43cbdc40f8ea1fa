// Run directory helpers (see run_layout.hpp).
#include "brash/run/run_layout.hpp"

#include <chrono>
#include <fstream>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <fmt/chrono.h>
#include <fmt/format.h>

#include "brash/error.hpp"
#include "brash_git_commit.hpp"  // generated at build time (cmake/git_commit.cmake)

namespace brash::run {

std::filesystem::path temp_path_for(const std::filesystem::path& file) {
  return file.parent_path() / fmt::format(".{}.tmp{}", file.filename().string(), ::getpid());
}

void write_atomic(const std::filesystem::path& file, std::string_view content) {
  const auto tmp = temp_path_for(file);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) throw InputError(fmt::format("{}: cannot write (disk full or no permission?)", tmp.string()));
  }
  std::filesystem::rename(tmp, file);
}

std::filesystem::path make_run_dir(const std::filesystem::path& runs_root, const std::string& case_name,
                                   const std::string& engine, const std::string& fluid_model) {
  const auto now = std::chrono::system_clock::now();
  const std::string stamp = fmt::format("{:%Y%m%dT%H%M%S}", std::chrono::floor<std::chrono::seconds>(now));
  auto dir = runs_root / fmt::format("{}-{}-{}-{}", case_name, engine, fluid_model, stamp);
  for (int k = 2; std::filesystem::exists(dir); ++k)
    dir = runs_root / fmt::format("{}-{}-{}-{}-{}", case_name, engine, fluid_model, stamp, k);
  std::filesystem::create_directories(dir / "particles");
  std::filesystem::create_directories(dir / "restart");
  return dir;
}

void write_meta(const std::filesystem::path& run_dir, const nlohmann::json& meta) {
  write_atomic(run_dir / "meta.json", meta.dump(2) + "\n");
}

std::string git_commit() { return kGitCommit; }

RunDirLock::RunDirLock(const std::filesystem::path& run_dir) : file_(run_dir / ".lock") {
  const auto& file = file_;
  fd_ = ::open(file.c_str(), O_RDWR | O_CREAT, 0644);  // no O_CLOEXEC: the engine child keeps the lock too
  if (fd_ < 0) throw InputError(fmt::format("{}: cannot open the run lock", file.string()));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd_);
    fd_ = -1;
    throw InputError(fmt::format("{}: another process is running in this run directory (it holds {}); wait for "
                                 "it or stop it before resuming",
                                 run_dir.string(), file.filename().string()));
  }
}

// The lock file goes with the lock (a finished run folder holds only its results): removed while still held, so
// that a process opening it from now on opens a new file and takes its lock only after this one is released.
RunDirLock::~RunDirLock() {
  if (fd_ < 0) return;
  ::unlink(file_.c_str());
  ::close(fd_);
}

}  // namespace brash::run
