// FNV-1a, 64 bit: a hash of bytes that is the same on every build and machine (std::hash is not), for the
// caches' keys (settled bed, panel flow), file names and brash-ode's restart checksum.
#pragma once
#include <cstdint>
#include <string_view>

namespace brash::core {

inline constexpr std::uint64_t kFnv1aOffset = 1469598103934665603ULL;

// The hash of `bytes`, continuing from `h` (chain calls to hash several pieces as one).
constexpr std::uint64_t fnv1a(std::string_view bytes, std::uint64_t h = kFnv1aOffset) {
  for (const unsigned char ch : bytes) h = (h ^ ch) * 1099511628211ULL;
  return h;
}

}  // namespace brash::core
