// Shared runner set-up (see runner_setup.hpp).
#include "brash/run/runner_setup.hpp"

#include <algorithm>
#include <cstdlib>
#include <fmt/format.h>
#include <iostream>
#include <sys/wait.h>

#include "brash/case_derive.hpp"
#include "brash/error.hpp"
#include "brash/paths.hpp"

namespace fs = std::filesystem;

namespace brash::run {

fs::path executable_dir() { return paths::executable_dir(); }

std::string shell_quote(const fs::path& p) {
  std::string out = "'";
  for (char ch : p.string()) out += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return out + "'";
}

int run_shell(const std::string& command) {
  const int rc = std::system(command.c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : 128;
}

int run_postprocessor(const fs::path& run_dir, const std::string& tag) {
  const auto post = executable_dir() / "brash-post";
  if (!fs::exists(post)) {
    std::cerr << tag << " brash-post not built; skipping the report\n";
    return 0;
  }
  return run_shell(shell_quote(post) + " " + shell_quote(run_dir));
}

Case load_case_with_overrides(const fs::path& case_file, const CaseOverrides& o, const std::string& tag) {
  brash::CaseOverrides set;
  if (!o.model.empty()) set.emplace_back("fluid.model", o.model);
  if (!o.treatment.empty()) set.emplace_back("fluid.treatment", o.treatment);
  set.insert(set.end(), o.sets.begin(), o.sets.end());
  if (o.duration_s > 0) set.emplace_back("run.duration_s", fmt::format("{}", o.duration_s));
  if (set.empty()) return load_case(case_file);
  // through the case library, as `brash-case derive` (validated like a case file; a shorter run keeps its window
  // inside it by derive's rule, said here)
  try {
    Case c = parse_case(derive_case(case_file, set), fs::absolute(case_file).parent_path(),
                        case_file.string() + " (with command-line overrides)");
    if (o.duration_s > 0 && c.run.window_s != load_case(case_file, o.model.empty()).run.window_s)
      std::cerr << fmt::format("{} --duration {} s is shorter than the window: window set to [{}, {}] s\n", tag,
                               o.duration_s, c.run.window_s[0], c.run.window_s[1]);
    return c;
  } catch (const InputError& e) {
    throw InputError(fmt::format("{} (with command-line overrides)", e.what()));
  }
}

void prepare_case_inputs(const Case& c, const fs::path& case_file, const std::string& tag) {
  if (!fs::exists(c.ice.packing_file)) {
    std::cerr << tag << " generating the packing " << c.ice.packing_file << "\n";
    if (run_shell(shell_quote(executable_dir() / "brash-pack") + " " + shell_quote(case_file.parent_path())) != 0)
      throw InputError(case_file.string() + ": brash-pack failed to generate " + c.ice.packing_file.string());
  }
  if (!fs::exists(c.hull.file)) {
    const fs::path case_dir = fs::absolute(case_file).parent_path();
    const fs::path name = c.hull.file.lexically_relative(case_dir);
    const char* hull_dir = std::getenv("BRASH_HULL_DIR");
    throw InputError(fmt::format("{}: hull.file {} not found (searched: the case folder {}, $BRASH_HULL_DIR{}, {}); "
                                 "build the JBC hull with `make build`, or set BRASH_HULL_DIR or BRASH_DATA_DIR",
                                 case_file.string(), name.empty() ? c.hull.file.string() : name.string(),
                                 case_dir.string(), hull_dir && *hull_dir ? fmt::format(" ({})", hull_dir) : " (unset)",
                                 (paths::data_dir() / "hull_meshes").string()));
  }
}

}  // namespace brash::run
