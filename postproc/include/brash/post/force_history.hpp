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

}  // namespace brash::post
