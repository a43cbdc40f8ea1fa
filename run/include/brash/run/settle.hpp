// The settled bed (ice.settle): a case's packing floated and settled with no ship and closed channel ends until
// the pieces' rms speed is below ice.settle_speed_m_s, made once by brash-settle (LIGGGHTS, 1 rank: the same file
// for the same inputs) and cached beside the packing, keyed by the packing's bytes and every input of the
// settling. A run then starts from it instead of the packing (docs/performance.md, "The settled bed").
#pragma once
#include <filesystem>
#include <string>

#include "brash/case.hpp"

namespace brash {

// What the settling depends on besides the packing (one line per input, the settle line of the cached file).
std::string settle_inputs(const Case& c);

// The cached settled bed of c: <packing's folder>/settled-<16 hex digits>.csv, the digits a hash of the packing
// file's bytes and settle_inputs(c). Throws InputError when the packing cannot be read.
std::filesystem::path settled_packing_file(const Case& c);

}  // namespace brash

namespace brash::run {

// The packing a run starts from: c.ice.packing_file, or with ice.settle its settled bed, made by brash-settle
// (next to this executable) when it is not cached yet (made_now: by this call). Throws InputError when brash-settle
// fails.
struct StartingPacking {
  std::filesystem::path file;
  bool made_now = false;
};
StartingPacking starting_packing(const Case& c, const std::string& tag);

}  // namespace brash::run
