// What every engine runner does before its engine starts: load the case with the command-line
// overrides (validated like any case key), make sure the packing exists (brash-pack, cached in the
// case folder) and that the hull file was found. Shared by brash-liggghts-run and brash-yade-run.
#pragma once
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "brash/case.hpp"

namespace brash::run {

struct CaseOverrides {
  std::string model;        // fluid.model, empty = keep
  std::string treatment;    // fluid.treatment, empty = keep
  double duration_s = -1;   // run.duration_s, <= 0 = keep; the window is pulled inside a shorter run
  // any other case keys, {dotted key, YAML value} as `brash-case derive --set KEY=VALUE` (--set, brash-ode's --dt)
  std::vector<std::pair<std::string, std::string>> sets;
};

// `tag` prefixes the notes printed on stderr (e.g. "[brash-liggghts]").
Case load_case_with_overrides(const std::filesystem::path& case_file, const CaseOverrides& o, const std::string& tag);

// Generates the packing with brash-pack (next to this executable) when the case's packing file is missing,
// and checks that the hull file exists. Throws InputError naming the case file.
void prepare_case_inputs(const Case& c, const std::filesystem::path& case_file, const std::string& tag);

// Runs brash-post (next to this executable) on a finished run; returns its exit status (0 with a note
// when brash-post is not built).
int run_postprocessor(const std::filesystem::path& run_dir, const std::string& tag);

std::filesystem::path executable_dir();                  // folder of the running executable
std::string shell_quote(const std::filesystem::path& p);  // '...' for /bin/sh
int run_shell(const std::string& command);                // exit status (128 if killed by a signal)

}  // namespace brash::run
