// hull_force.csv of the run layout (docs/case_format.md).
#pragma once
#include <filesystem>
#include <vector>

#include "brash/run/engine.hpp"

namespace brash::run {

// "t_s,fx_N,fy_N,fz_N" and one row per ForceRow, written atomically; the number of rows.
std::size_t write_hull_force_csv(const std::filesystem::path& csv, const std::vector<ForceRow>& rows);

}  // namespace brash::run
