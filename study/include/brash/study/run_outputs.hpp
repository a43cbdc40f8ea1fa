// A run directory as the study sees it: complete or not, how far its force record reached, and the copies of its
// small outputs (report, force history, case, meta; not the dumps and restarts) that keep it listed once the
// directory is gone (the paper runs' archive in evidence/, the study's runs beside the document).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace brash::study {

// RUN_DIR/report.json says "status": "complete" (a missing or unreadable report is not complete).
bool report_complete(const std::filesystem::path& run_dir);

// A hull_force.csv's header and complete rows: rows with the header's column count, without an unterminated last
// line (a row a runner is still writing). Empty when the file is missing.
std::vector<std::string> complete_force_rows(const std::filesystem::path& hull_force_csv);
// The number of complete data rows (0 when missing).
std::size_t force_row_count(const std::filesystem::path& hull_force_csv);
// The model time the run's force record has reached [s]: the last complete row of hull_force.csv, else the last
// record of hull_force.raw (0 when neither has one).
double model_time_reached(const std::filesystem::path& run_dir);

// `to` relative to the folder `from`, both made absolute without resolving links (a symlinked runs/ keeps its name).
std::filesystem::path relative_path(const std::filesystem::path& to, const std::filesystem::path& from);

// RUN_DIR's study outputs into a new folder DST (made as DST.tmp, then renamed over DST), with the newest
// ice_views_*.png and force_history.png when with_plots, and source_run_dir.txt naming RUN_DIR relative to DST.
void copy_outputs(const std::filesystem::path& run_dir, const std::filesystem::path& dst, bool with_plots);

// A complete run's outputs copied to ARCHIVE/<its name>, unless the copy there has the same report.json.
// Returns true when it copied.
bool archive_complete_run(const std::filesystem::path& run_dir, const std::filesystem::path& archive_dir);
// A started run's record so far (meta, case, the complete rows of hull_force.csv; no plots) copied to
// ARCHIVE/<its name> when it reaches further than the copy there. Returns true when it copied.
bool archive_partial_run(const std::filesystem::path& run_dir, const std::filesystem::path& archive_dir);

// The folder a paper run is listed from: its complete archive, else the run directory (going here, or not
// archived), else its partial archive (started on another machine and not finished).
std::filesystem::path paper_listed_dir(const std::filesystem::path& run_dir, const std::filesystem::path& archive_dir);

// Another process's runner works on RUN_DIR (it holds RUN_DIR/.lock).
bool held_elsewhere(const std::filesystem::path& run_dir);

}  // namespace brash::study
