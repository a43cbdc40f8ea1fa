// libFuzzer: packing CSV bytes -> brash::read_packing_csv (through a scratch file). Only brash::InputError
// may escape.
#include <brash/error.hpp>
#include <brash/packing.hpp>

#include "fuzz_util.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = brash::fuzz::write_scratch("packing.csv", data, size);
  try {
    (void)brash::read_packing_csv(file);
  } catch (const brash::InputError&) {
  }
  return 0;
}
