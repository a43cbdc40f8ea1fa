// Reading the JBC offsets table and centre-plane profile (CSV, metres, model scale 1:40).
#include <brash/error.hpp>
#include <brash/hull/jbc.hpp>
#include <brash/paths.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace brash::hull {
namespace {

namespace fs = std::filesystem;

// Rows of a numeric CSV with a header line and exactly `cols` columns.
std::vector<std::vector<double>> read_csv(const fs::path& file, std::size_t cols) {
  std::ifstream in(file);
  if (!in) throw InputError(fmt::format("{}: cannot open the file", file.string()));
  std::string line;
  std::getline(in, line);  // header
  std::vector<std::vector<double>> rows;
  int line_no = 1;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::vector<double> row;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) {
      try {
        row.push_back(std::stod(cell));
      } catch (const std::exception&) {
        throw InputError(fmt::format("{}:{}: '{}' is not a number", file.string(), line_no, cell));
      }
      if (!std::isfinite(row.back())) throw InputError(fmt::format("{}:{}: value is not finite", file.string(), line_no));
    }
    if (row.size() != cols)
      throw InputError(fmt::format("{}:{}: {} columns, expected {}", file.string(), line_no, row.size(), cols));
    rows.push_back(std::move(row));
  }
  if (rows.empty()) throw InputError(fmt::format("{}: no data rows", file.string()));
  return rows;
}

}  // namespace

fs::path default_jbc_data_dir() { return paths::data_dir() / "hull_meshes" / "data"; }

JbcData load_jbc_data(const fs::path& dir) {
  if (std::error_code ec; !fs::is_directory(dir, ec))
    throw InputError(fmt::format("JBC data folder {} not found (brash's data folder: {}; set BRASH_DATA_DIR, or "
                                 "brash-hull jbc --data DIR)",
                                 dir.string(), paths::data_dir_description()));
  JbcData d;
  const fs::path offsets = dir / "jbc_offsets_1to40.csv";
  std::map<double, std::map<double, double>> table;  // x -> z -> Y
  for (const auto& r : read_csv(offsets, 3)) table[r[0]][r[1]] = r[2];
  for (const auto& [x, col] : table) {
    d.station_x_m.push_back(x);
    if (d.waterline_z_m.empty())
      for (const auto& [z, y] : col) d.waterline_z_m.push_back(z);
    if (col.size() != d.waterline_z_m.size())
      throw InputError(fmt::format("{}: station x = {} has {} waterlines, the first has {} (not a full grid)",
                                   offsets.string(), x, col.size(), d.waterline_z_m.size()));
  }
  d.half_breadth_m.resize(static_cast<Eigen::Index>(d.station_x_m.size()),
                          static_cast<Eigen::Index>(d.waterline_z_m.size()));
  Eigen::Index i = 0;
  for (const auto& [x, col] : table) {
    Eigen::Index k = 0;
    for (const auto& [z, y] : col) {
      if (z != d.waterline_z_m[static_cast<std::size_t>(k)])
        throw InputError(fmt::format("{}: station x = {} has waterline z = {} not on the grid", offsets.string(), x, z));
      if (y < 0) throw InputError(fmt::format("{}: negative half-breadth at x = {}, z = {}", offsets.string(), x, z));
      d.half_breadth_m(i, k++) = y;
    }
    ++i;
  }
  if (d.station_x_m.size() < 4 || d.waterline_z_m.size() < 4)
    throw InputError(fmt::format("{}: too few stations or waterlines", offsets.string()));

  const fs::path profile = dir / "jbc_profile_1to40.csv";
  for (const auto& r : read_csv(profile, 3)) {
    if (r[2] < r[1]) throw InputError(fmt::format("{}: z_top < z_bottom at x = {}", profile.string(), r[0]));
    if (d.profile_x_m.empty() || r[0] > d.profile_x_m.back()) {
      d.profile_x_m.push_back(r[0]);
      d.profile_z_m.emplace_back();
    } else if (r[0] < d.profile_x_m.back()) {
      throw InputError(fmt::format("{}: x = {} is not sorted", profile.string(), r[0]));
    }
    d.profile_z_m.back().emplace_back(r[1], r[2]);
  }
  return d;
}

}  // namespace brash::hull
