// Running a planned command as a process (the study links no engine): output to a log file, `nice -n` when the
// command says so, its extra environment and folder.
#pragma once
#include <filesystem>
#include <vector>

#include "brash/study/plan.hpp"

namespace brash::study {

// Runs `c` and waits; stdout and stderr go to `log` (appended; an empty path: this process's own). Returns the exit status (128 + the signal when
// one ended it; 127 when it could not be started).
int run_process(const Command& c, const Settings& s, const std::filesystem::path& log);

// Runs the commands one after another while each succeeds (a shell's &&); returns the last exit status.
int run_steps(const std::vector<Command>& steps, const Settings& s, const std::filesystem::path& log);

}  // namespace brash::study
