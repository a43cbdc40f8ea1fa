// libFuzzer: case.yaml text -> brash::parse_case. Only brash::InputError may escape.
#include <brash/case.hpp>
#include <brash/error.hpp>

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const brash::Case c = brash::parse_case(text, "/tmp/brash_fuzz_case", "fuzz/case.yaml");
    (void)brash::dump_case_yaml(c);  // a valid case must also write back
  } catch (const brash::InputError&) {
  }
  return 0;
}
