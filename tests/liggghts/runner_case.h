// Helpers of the brash-liggghts-run tests (test_resume.cpp, test_guard_runner.cpp): the narrowed quick case
// and the runner command. The test target defines BRASH_SOURCE_DIR, BRASH_BIN_DIR and BRASH_HULL_DIR.
#pragma once
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "liggghts_runner.h"

namespace brash::test {

// The quick case narrowed and shortened: the JBC stem starts 5 cm before a 0.8 m channel of ice, 1.3 m wide.
// Writes case_dir/case.yaml; `extra` is appended (e.g. a guards: section).
struct SmallCase {
  std::string duration_s = "0.6", window_s = "[0.0, 0.6]", output_interval_s = "0.01",
              dump_interval_s = "0.1";
  std::string fluid_model;  // empty: the case's (both)
  std::string extra;
};
inline void write_small_quick_case(const std::filesystem::path& case_dir, const SmallCase& k) {
  std::string yaml = read_text(std::filesystem::path(BRASH_SOURCE_DIR) / "cases/jbc_narrow/case.yaml");
  auto set = [&](const std::string& key, const std::string& value) {
    yaml = std::regex_replace(yaml, std::regex("\n  " + key + ":[^\n]*"), "\n  " + key + ": " + value);
  };
  set("length_m", "0.8");
  set("width_m", "1.3");
  set("start_x_m", "-7.05");
  set("duration_s", k.duration_s);
  set("window_s", k.window_s);
  set("output_interval_s", k.output_interval_s);
  set("dump_interval_s", k.dump_interval_s);
  if (!k.fluid_model.empty()) set("model", k.fluid_model);
  std::filesystem::create_directories(case_dir);
  std::ofstream(case_dir / "case.yaml") << yaml << k.extra;
}

// `brash-liggghts-run CASE --no-post --out OUT` with the build's hull folder.
inline std::string runner_command(const std::filesystem::path& case_dir, const std::filesystem::path& out) {
  return std::string("env BRASH_HULL_DIR='") + BRASH_HULL_DIR + "' '" + BRASH_BIN_DIR +
         "/brash-liggghts-run' '" + case_dir.string() + "' --no-post --out '" + out.string() + "'";
}

// Runs it with stdout and stderr into `log`; the exit status of std::system.
inline int run_runner(const std::filesystem::path& case_dir, const std::filesystem::path& out,
                      const std::filesystem::path& log) {
  return std::system((runner_command(case_dir, out) + " > '" + log.string() + "' 2>&1").c_str());
}

}  // namespace brash::test
