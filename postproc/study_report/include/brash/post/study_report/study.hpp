// The loaded study behind a study document (brash-study-report): the manifest's rows, one Run per run
// directory (its report.json and meta.json; for the runs of groups `paper` and `engine` also its resolved
// case.yaml and its force record), the paired-seed ensembles' summaries and the paper case's published values.
// Loading only: nothing here compares or interprets a number (analysis.hpp does).
//
// Manifest (tab-separated, one header line naming the columns, '#' lines are comments):
//   id  group  label  param  value  baseline  base_case  exit_code  run_dir  command
// required: group, run_dir, command; the others may be empty. One run may appear in several rows
// (e.g. the baseline run is the reference of every sensitivity group). run_dir is relative to the
// manifest's folder unless absolute.
// Groups: `paper` (table a), `speed` (table b, value = speed), `engine` (table d), `paired` (a paired-seed
// ensemble: run_dir is the summary JSON of bench/rank_ensemble.sh, param / value the change of its side B on
// its side A; table c and the gap's candidates), anything else is a sensitivity group (table c) whose rows
// with baseline = 1 are the reference.
#pragma once
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <brash/case.hpp>
#include <brash/post/ensemble.hpp>
#include <brash/post/force_history.hpp>

namespace brash::post::study_report {

// The paper's case (cases/jbc_ia_5kn): a run whose base_case it is reproduces the paper's scene.
inline constexpr const char* kPaperCase = "jbc_ia_5kn";

struct Row {  // one manifest row
  std::string id, group, label, param, value, base_case, command, exit_text;
  bool baseline = false;
  std::optional<int> exit_code;
  std::filesystem::path run_dir;
};

// The manifest's rows in file order; brash::InputError naming the file (and line) when it cannot be used.
std::vector<Row> read_manifest(const std::filesystem::path& path);

// P (absolute, or relative to BASE) joined lexically: brash-study writes logical paths (realpath -s), which may
// pass through a symlinked folder (runs/ -> elsewhere), where the file system's ".." would climb from the link's
// target instead.
std::filesystem::path join_logical(const std::filesystem::path& base, const std::filesystem::path& p);

struct Run {  // one run directory (several rows may share it)
  std::string ref;  // R1, R2, ... in order of first appearance
  std::filesystem::path run_dir;
  std::string command, base_case;
  std::optional<int> exit_code;
  std::string exit_text;
  bool ok = false;
  std::string problem;  // why the run is not usable (missing, failed, ...)
  bool in_progress = false;  // exit_code column "in progress: ..." (a long run resumed in pieces, not failed)
  std::vector<std::string> warnings;
  std::string engine = "?", model = "?", case_name = "?";
  double mean_N = 0, ci_N = 0, full_kN = 0, full_ci_kN = 0, speed = 0, lambda = 0;
  double window0 = 0, window1 = 0, t_last = 0, wall_s = 0, psteps = 0;
  std::optional<double> rch_kN, ratio;
  std::optional<double> lpp, beam, draft, alpha, phi2, awf;
  nlohmann::json meta = nlohmann::json::object();  // the run's meta.json (empty object when missing or unreadable)
  // Read for the runs of groups `paper` and `engine` only (the set-up table, the history plot and the engines'
  // binned comparison): whether the run folder holds its resolved case.yaml (the run has started) and its
  // hull_force.csv, the case and the force record (read as a run in progress unless the run is ok), each with
  // the reason it could not be read.
  bool has_case_yaml = false;
  bool has_force_record = false;
  std::optional<brash::Case> resolved_case;
  std::string case_error;
  std::optional<ForceHistory> history;
  std::string history_error;
};

// A run of the manifest: ROW (its first row) with its report.json and meta.json read.
Run load_run(const Row& row, std::string ref);

// A paired-seed ensemble's summary (bench/rank_ensemble.sh: OUT/ensemble-<A>-vs-<B>.json): every packing seed
// run as side A and as side B, B's effect (B - A) / A with its 95 % CI (brash::post::read_ensemble_summary; an
// old summary's CI on A is not recomputable).
struct Paired {
  std::string ref;  // P1, P2, ...
  Row row;
  bool ok = false;
  std::string problem;
  std::string side_a, side_b, case_name;
  int pairs = 0;
  EnsembleEffect effect;
  // the CI on A excludes 0; for an old summary without it, its recorded CI on the pair mean did
  bool resolved() const;
};

// The ensemble of a `paired` row (its run_dir is the summary JSON); INDEX numbers it P<INDEX>.
Paired load_paired(const Row& row, int index);

struct Study {
  std::vector<Row> rows;  // every row but group `paired`'s, in manifest order
  std::vector<Run> runs;  // one per run directory, in order of first appearance (R1, R2, ...)
  std::vector<std::size_t> run_index;  // rows[i] is a row of runs[run_index[i]]
  std::vector<Paired> paired;          // group `paired`, in manifest order (P1, P2, ...)
  brash::ReferenceSpec paper;          // the paper case's published values (its case.yaml's references)
  const Run& run_of(const Row& row) const;  // ROW must be one of `rows`
};

// The study of MANIFEST, compared with the references of PAPER_CASE (a case.yaml).
Study load_study(const std::filesystem::path& manifest, const std::filesystem::path& paper_case);

// The full run directory of a folder that holds a copy of a run's outputs (brash-study writes its path,
// relative to the copy itself, to source_run_dir.txt in the copy); empty for a run directory itself. Resolved
// against the copy, so the tool finds it from any working directory.
std::filesystem::path source_run_dir(const std::filesystem::path& run_dir);

}  // namespace brash::post::study_report
