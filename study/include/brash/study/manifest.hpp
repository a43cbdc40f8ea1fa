// The study manifest (<work>/manifest.tsv, read by brash-study-report): one row per manifest item of the study
// file whose run is listed, its run_dir relative to the work dir.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "brash/study/runner.hpp"
#include "brash/study/study_file.hpp"

namespace brash::study {

struct ManifestRow {
  std::string id, group, label, param, value;
  bool baseline = false;
  std::string base_case, exit_text;
  std::filesystem::path run_dir;  // absolute
  std::string command;
};

// The rows of the study file's manifest whose runs are listed (the speed sweep's item expanded to its runs).
std::vector<ManifestRow> manifest_rows(const Study& study, const Listings& listings);

// The study's own runs (rows listed from <work>/runs/<id>) with a complete report: their outputs copied to
// <doc dir>/<doc stem>_runs/<id> (made afresh: a copy of a run no row lists is dropped), and their rows listed
// from there. Returns the folder of the copies.
std::filesystem::path copy_study_runs(std::vector<ManifestRow>& rows, const Settings& s);

// The manifest's text: `title_comment` as a '#' line, the column names, one tab-separated line per row.
std::string manifest_text(const std::vector<ManifestRow>& rows, const Settings& s, const std::string& title_comment);

}  // namespace brash::study
