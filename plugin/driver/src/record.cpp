#include "record.hpp"

#include <fmt/format.h>

#include "brash/run_layout.hpp"

namespace brash::run {

std::size_t write_hull_force_csv(const std::filesystem::path& csv, const std::vector<ForceRow>& rows) {
  std::string out = "t_s,fx_N,fy_N,fz_N\n";
  for (const auto& r : rows) out += fmt::format("{:.9g},{:.9g},{:.9g},{:.9g}\n", r.t_s, r.fx_N, r.fy_N, r.fz_N);
  write_atomic(csv, out);
  return rows.size();
}

}  // namespace brash::run
