// brash-ode restart files, so long runs resume: RUN_DIR/restart/restart_<step>.bin, binary, written atomically
// (temporary file + rename), the last two kept.
//
// File = "BRASHODE" (8 bytes) | u32 version | u64 payload size | payload | u64 FNV-1a of the payload | "ENDR".
// A file with a wrong magic, size or checksum (a truncated or half-copied file) is rejected, and load_latest
// falls back to the previous one. Numbers are stored in the machine's native binary form (exact doubles; the
// file is for resuming on the same machine, not for exchange).
#pragma once
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "brash/core/fluid.hpp"

namespace brash::ode::restart {

// 2: per-sphere "retired" flag (World::retire); 3: spheres in a spatial order; 4: the push front (wake by
// push front); 5: the wake counts; 6: the hull force split's sums over the output interval. Version 5 files are
// read too (a run from before the split resumes without it).
constexpr std::uint32_t kVersion = 6;
constexpr std::uint32_t kOldestVersion = 5;

class Writer {
 public:
  template <class T>
  void put(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    buf_.append(reinterpret_cast<const char*>(&v), sizeof(T));
  }
  void put(const core::Vec3& v) {
    for (int k = 0; k < 3; ++k) put<double>(v[k]);
  }
  void put_string(const std::string& s) {
    put<std::uint64_t>(s.size());
    buf_ += s;
  }
  const std::string& bytes() const { return buf_; }

 private:
  std::string buf_;
};

class Reader {
 public:
  explicit Reader(const std::string& bytes) : s_(bytes) {}
  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    need(sizeof(T));
    T v;
    std::memcpy(&v, s_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  core::Vec3 get_vec3() {
    core::Vec3 v;
    for (int k = 0; k < 3; ++k) v[k] = get<double>();
    return v;
  }
  std::string get_string() {
    const auto n = get<std::uint64_t>();
    need(n);
    std::string r = s_.substr(pos_, n);
    pos_ += n;
    return r;
  }
  bool done() const { return pos_ == s_.size(); }

 private:
  void need(std::size_t n) const {
    if (n > s_.size() - pos_) throw std::runtime_error("restart payload ends early");
  }
  const std::string& s_;
  std::size_t pos_ = 0;
};

std::string seal(const std::string& payload);
// Returns the payload (and its format version in *version); throws std::runtime_error naming `name` and the defect.
std::string unseal(const std::string& file_bytes, const std::string& name, std::uint32_t* version = nullptr);

// Writes dir/restart_<step>.bin atomically, then deletes all but the newest `keep` restart files.
std::filesystem::path write(const std::filesystem::path& dir, long step, const std::string& payload, int keep = 2);

// Restart files in dir, newest (highest step) first.
std::vector<std::filesystem::path> list(const std::filesystem::path& dir);

struct Found {
  std::filesystem::path file;
  std::string payload;
  std::vector<std::string> rejected;  // "file: reason" for newer files that could not be used
  std::uint32_t version = kVersion;   // the file's format version (kOldestVersion .. kVersion)
};
// Newest restart file whose seal is intact; throws std::runtime_error if there is none.
Found load_latest(const std::filesystem::path& dir);

}  // namespace brash::ode::restart
