// A whole study: plan, run (or list) every part, the manifest, the copies of the runs beside the document, and the
// document itself (brash-study-report, a process).
#pragma once
#include <string>

#include "brash/study/plan.hpp"
#include "brash/study/study_file.hpp"

namespace brash::study {

// The engines among `wanted` whose executable is in s.bin; a note on stderr for each one left out. Throws
// brash::InputError naming the first missing tool every study needs (brash-pack, brash-post, brash-study-report,
// brash-liggghts-run).
std::vector<Engine> available_engines(const std::vector<Engine>& wanted, const Settings& s);

// The command that makes the document again, shown at its top: "STUDY=short make study", with the switches of the
// settings that differ from the study file (STUDY_YADE=1, STUDY_PAPER=1, STUDY_ENSEMBLES=1).
std::string rerun_command(const Study& study, const Settings& s);

// Runs the study and writes the document; returns brash-study-report's exit status.
int run_study(const Study& study, const Settings& s);

}  // namespace brash::study
