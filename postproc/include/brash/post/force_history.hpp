// hull_force.csv: force of the ice on the hull (contacts only), header t_s,fx_N,fy_N,fz_N.
#pragma once
#include <filesystem>
#include <vector>

namespace brash::post {

struct ForceHistory {
  std::vector<double> t_s, fx_N, fy_N, fz_N;
  bool tail_dropped = false;  // an unterminated last record was ignored (run still being written)
};

// Strict reader: bad numbers, wrong column count, NaN/inf, non-increasing time -> InputError naming
// file and line. `run_in_progress`: drop an unterminated last line instead of parsing it.
ForceHistory read_force_history(const std::filesystem::path& path, bool run_in_progress);

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
