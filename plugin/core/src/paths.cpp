// The run-time path rule (brash/paths.hpp).
#include "brash/paths.hpp"

#include <cstdlib>
#include <string_view>

#include "brash/error.hpp"

namespace fs = std::filesystem;

namespace brash::paths {
namespace {

const char* env(const char* name) {
  const char* v = std::getenv(name);
  return v != nullptr && *v != '\0' ? v : nullptr;
}

// <prefix> of the running executable: its folder's parent, or the nearest ancestor up to two more levels up
// that has share/brash (tests live in build/tests/<component>/); the parent when none has.
fs::path prefix() {
  const fs::path parent = executable_dir().parent_path();
  fs::path p = parent;
  for (int up = 0; up < 3 && !p.empty(); ++up, p = p.parent_path()) {
    std::error_code ec;
    if (fs::is_directory(p / "share" / "brash", ec)) return p;
    if (p == p.root_path()) break;
  }
  return parent;
}

}  // namespace

fs::path executable_dir() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::current_path() : self.parent_path();
}

fs::path data_dir() {
  if (const char* d = env("BRASH_DATA_DIR")) return fs::path(d);
  return prefix() / "share" / "brash";
}

std::string data_dir_description() {
  if (const char* d = env("BRASH_DATA_DIR")) return std::string("$BRASH_DATA_DIR (") + d + ")";
  return data_dir().string();
}

fs::path data_file(const fs::path& relative, const std::string& what) {
  const fs::path p = data_dir() / relative;
  std::error_code ec;
  if (fs::exists(p, ec)) return p;
  throw InputError(what + " " + relative.string() + " not found in the brash data folder " + data_dir_description() +
                   " (looked for " + p.string() + "; set BRASH_DATA_DIR to <prefix>/share/brash of an install or to "
                   "<build>/share/brash)");
}

fs::path yade_python_dir() {
  if (const char* d = env("BRASH_YADE_PYDIR")) return fs::path(d);
  return prefix() / "lib" / "brash" / "python";
}

}  // namespace brash::paths
