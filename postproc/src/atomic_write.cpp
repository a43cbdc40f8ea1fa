// Atomic file output (temp file in the same folder + rename).
#include <brash/post/atomic_write.hpp>

#include <fstream>
#include <stdexcept>
#include <unistd.h>

namespace brash::post {

std::filesystem::path temp_path_for(const std::filesystem::path& path) {
  // pid in the name: two brash-post processes on one run do not clobber each other's temp files.
  return path.parent_path() / ("." + path.filename().string() + ".tmp" + std::to_string(::getpid()));
}

void write_file_atomic(const std::filesystem::path& path, std::string_view content) {
  const auto tmp = temp_path_for(path);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write " + tmp.string());
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) throw std::runtime_error("write failed: " + tmp.string());
  }
  std::filesystem::rename(tmp, path);
}

}  // namespace brash::post
