// Running a planned study: each part runs (or, where the study only lists it, is looked up) and leaves a Listing,
// what the manifest says of its run id.
#pragma once
#include <filesystem>
#include <map>
#include <string>

#include "brash/study/plan.hpp"

namespace brash::study {

// The manifest's cells for one run id: its command, its exit code (or why it has none) and the folder it is listed
// from; has_report: that folder holds a report.json.
struct Listing {
  std::string command, exit_text;
  std::filesystem::path run_dir;
  bool has_report = false;
};
using Listings = std::map<std::string, Listing>;

// Progress and notes of a study, one line each on stderr ("brash-study: ...").
void say(const std::string& line);

// Resume: a run is kept when its report is complete and it was made by exactly this command (RUN/.study_cmd).
bool keeps_complete_run(const PlannedRun& r);

// The variants, one at a time (case folder derived once per study, then the engine; a kept run is not re-run).
void run_variants(const Plan& plan, const Settings& s, Listings& out);
// The speed sweep (bench/quick_speed_sweep.sh), then a listing per run it made.
void run_speed_sweep(const Study& study, const Plan& plan, const Settings& s, Listings& out);
// The ensembles: run or continued where the study runs them; listed from their summary once written (archived in
// <archive>/ensembles/<dir> and listed from there, also once the folder is gone).
void run_ensembles(const Plan& plan, const Settings& s, Listings& out);
// The paper runs: archived (complete, or the record so far), started or resumed where the study runs them and no
// other process holds one; listed once started.
void run_paper_runs(const Plan& plan, const Settings& s, Listings& out);

}  // namespace brash::study
