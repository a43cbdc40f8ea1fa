// Atomic file output: write a sibling temp file, then rename over the target, so a reader
// (ParaView, a compare run, CI) never sees a half-written report.
#pragma once
#include <filesystem>
#include <string_view>

namespace brash::post {

// Writes `content` to `path` atomically. Throws std::runtime_error on I/O failure.
void write_file_atomic(const std::filesystem::path& path, std::string_view content);

// The temp name used for `path` (same directory, so rename is atomic on POSIX).
std::filesystem::path temp_path_for(const std::filesystem::path& path);

}  // namespace brash::post
