// The force of the ice on the hull (contacts only): hull_force.csv (header t_s,fx_N,fy_N,fz_N) or, in a run made
// from a user's own LIGGGHTS input, hull_force.raw as LIGGGHTS' fix ave/time writes it (docs/case_format.md).
#pragma once
#include <filesystem>
#include <vector>

namespace brash::post {

struct ForceHistory {
  std::vector<double> t_s, fx_N, fy_N, fz_N;
  // The hull force split (brash::run::kSplitColumns, in that order: fx of bow, mid-body, stern, normal,
  // tangential), one vector per part; empty when the record has none (then it is not recorded, never zero).
  std::vector<std::vector<double>> split_N;
  bool tail_dropped = false;  // an unterminated last record was ignored (run still being written)
};

// Strict reader (brash::run::read_hull_force_csv; further named columns allowed): bad numbers, wrong column
// count, NaN/inf, non-increasing time -> InputError naming file and line. `run_in_progress`: drop an
// unterminated last line instead of parsing it.
ForceHistory read_force_history(const std::filesystem::path& path, bool run_in_progress);

// A fix ave/time file: '#' comment lines, then rows "TimeStep t fx fy fz" (whitespace-separated; e.g.
// `fix hf all ave/time 100 1 100 v_t f_hull[1] f_hull[2] f_hull[3] file hull_force.raw`). Same checks as
// read_force_history, messages naming file and line.
ForceHistory read_ave_time_force_history(const std::filesystem::path& path, bool run_in_progress);

// The run directory's force record: hull_force.csv, else hull_force.raw; InputError naming both when neither exists.
std::filesystem::path force_record_file(const std::filesystem::path& run_dir);
// read_force_history or read_ave_time_force_history by the file's name (hull_force.raw: fix ave/time).
ForceHistory read_force_record(const std::filesystem::path& file, bool run_in_progress);

// A stretch of model time with no record: two consecutive rows further apart than kGapFactor x the record's
// median row interval (e.g. the rows of a lost attempt of a resumed run).
struct RecordGap {
  double from_s = 0, to_s = 0;  // the rows on either side
  double length_s() const { return to_s - from_s; }
};
inline constexpr double kGapFactor = 3.0;
// The gaps of t_s (increasing) overlapping [t0, t1]; none when it has fewer than 3 rows.
std::vector<RecordGap> record_gaps(const std::vector<double>& t_s, double t0, double t1);

}  // namespace brash::post
