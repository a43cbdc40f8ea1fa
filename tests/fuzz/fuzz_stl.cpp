// libFuzzer: STL bytes (binary or ASCII; the reader decides) -> brash::hull::read_mesh (through a scratch
// .stl file), then the mesh checks on what was read. Only brash::InputError may escape.
#include <brash/error.hpp>
#include <brash/hull/mesh.hpp>

#include "fuzz_util.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > (1u << 20)) return 0;  // the reader holds the file in memory; keep runs fast
  const auto file = brash::fuzz::write_scratch("hull.stl", data, size);
  try {
    const auto mesh = brash::hull::read_mesh(file);
    (void)brash::hull::check_mesh(mesh);
    (void)brash::hull::unit_problems(mesh, 0.4, 7.0);
  } catch (const brash::InputError&) {
  }
  return 0;
}
