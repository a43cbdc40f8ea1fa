// brash-ode restart files (restart.hpp).
#include "brash/ode/restart.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "brash/core/fnv1a.hpp"
#include "brash/run/run_layout.hpp"

namespace brash::ode::restart {
namespace fs = std::filesystem;

namespace {
constexpr char kMagic[8] = {'B', 'R', 'A', 'S', 'H', 'O', 'D', 'E'};
constexpr char kEnd[4] = {'E', 'N', 'D', 'R'};
constexpr std::size_t kHead = 8 + 4 + 8, kTail = 8 + 4;

long step_of(const fs::path& p) {
  const std::string n = p.filename().string();
  if (n.rfind("restart_", 0) != 0 || p.extension() != ".bin") return -1;
  const std::string digits = n.substr(8, n.size() - 8 - 4);
  if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) return -1;
  return std::stol(digits);
}
}  // namespace


std::string seal(const std::string& payload) {
  Writer w;
  std::string out(kMagic, 8);
  w.put<std::uint32_t>(kVersion);
  w.put<std::uint64_t>(payload.size());
  out += w.bytes();
  out += payload;
  Writer t;
  t.put<std::uint64_t>(core::fnv1a(payload));
  out += t.bytes();
  out.append(kEnd, 4);
  return out;
}

std::string unseal(const std::string& b, const std::string& name, std::uint32_t* version_out) {
  if (b.size() < kHead + kTail || std::memcmp(b.data(), kMagic, 8) != 0)
    throw std::runtime_error(fmt::format("{}: not a brash-ode restart file or truncated ({} bytes)", name, b.size()));
  Reader r(b);
  r.get<std::uint64_t>();  // magic
  const auto version = r.get<std::uint32_t>();
  if (version < kOldestVersion || version > kVersion)
    throw std::runtime_error(fmt::format("{}: restart format version {} (this brash-ode reads {} to {})", name,
                                         version, kOldestVersion, kVersion));
  if (version_out) *version_out = version;
  const auto n = r.get<std::uint64_t>();
  if (b.size() != kHead + n + kTail)
    throw std::runtime_error(
        fmt::format("{}: truncated or padded: {} bytes, the header promises {}", name, b.size(), kHead + n + kTail));
  std::string payload = b.substr(kHead, n);
  std::uint64_t sum;
  std::memcpy(&sum, b.data() + kHead + n, 8);
  if (sum != core::fnv1a(payload) || std::memcmp(b.data() + kHead + n + 8, kEnd, 4) != 0)
    throw std::runtime_error(fmt::format("{}: checksum mismatch (corrupt file)", name));
  return payload;
}

std::vector<fs::path> list(const fs::path& dir) {
  std::vector<std::pair<long, fs::path>> v;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const long s = step_of(e.path());
    if (s >= 0 && e.is_regular_file()) v.emplace_back(s, e.path());
  }
  std::sort(v.begin(), v.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<fs::path> r;
  for (auto& [s, p] : v) r.push_back(p);
  return r;
}

fs::path write(const fs::path& dir, long step, const std::string& payload, int keep) {
  fs::create_directories(dir);
  const fs::path file = dir / fmt::format("restart_{:010d}.bin", step);
  run::write_atomic(file, seal(payload));
  const auto all = list(dir);
  for (std::size_t i = static_cast<std::size_t>(std::max(1, keep)); i < all.size(); ++i) {
    std::error_code ec;
    fs::remove(all[i], ec);
  }
  return file;
}

Found load_latest(const fs::path& dir) {
  Found f;
  for (const auto& p : list(dir)) {
    try {
      std::ifstream in(p, std::ios::binary);
      std::ostringstream ss;
      ss << in.rdbuf();
      f.payload = unseal(ss.str(), p.string(), &f.version);
      f.file = p;
      return f;
    } catch (const std::exception& e) {
      f.rejected.push_back(e.what());
    }
  }
  std::string msg = fmt::format("{}: no usable restart file", dir.string());
  for (const auto& r : f.rejected) msg += "\n  " + r;
  throw std::runtime_error(msg);
}

}  // namespace brash::ode::restart
