// libFuzzer: words of "fix ID group brash/guard ..." -> brash::liggghts::parse_guard_args (split on
// whitespace as LIGGGHTS does). Only brash::InputError may escape.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "guard_args.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  try {
    (void)brash::liggghts::parse_guard_args(words);
  } catch (const brash::InputError&) {
  }
  return 0;
}
