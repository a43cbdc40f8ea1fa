// LIGGGHTS dump custom files as a run's snapshots (brash/post/native_dump.hpp).
#include <brash/post/native_dump.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include <brash/core/immersion.hpp>
#include <brash/error.hpp>
#include <brash/post/csv.hpp>

namespace fs = std::filesystem;

namespace brash::post {

namespace {

constexpr std::string_view kTimestep = "ITEM: TIMESTEP";

// The step of a dump file: the number on the line after "ITEM: TIMESTEP".
long long dump_step(const fs::path& file) {
  std::ifstream in(file);
  std::string first, second;
  std::getline(in, first);
  std::getline(in, second);
  const double step = parse_finite(second, file, 2, "TIMESTEP");
  if (step < 0 || step != std::floor(step))
    throw InputError(fmt::format("{}:2: TIMESTEP '{}' is not a non-negative integer", file.string(), second));
  return static_cast<long long>(step);
}

}  // namespace

bool is_native_dump(const fs::path& file) {
  std::ifstream in(file);
  std::string first;
  if (!std::getline(in, first)) return false;
  if (!first.empty() && first.back() == '\r') first.pop_back();
  return first == kTimestep;
}

std::vector<SnapshotEntry> native_dump_index(const fs::path& run_dir, const NativeDumpFrame& frame) {
  std::vector<SnapshotEntry> out;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(run_dir, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec)) {
    const auto name = it->path().filename().string();
    if (it.depth() == 0 && it->is_directory() &&
        (name == "particles" || name == "paraview" || name == "post" || name == "restart")) {
      it.disable_recursion_pending();  // brash's own outputs and restart files
      continue;
    }
    if (!it->is_regular_file() || !is_native_dump(it->path())) continue;
    SnapshotEntry e;
    e.file = it->path();
    e.step = dump_step(e.file);
    e.t_s = static_cast<double>(e.step) * frame.timestep_s;
    e.hull_x_m = frame.hull_start_x_m + frame.speed_m_s * e.t_s;
    e.native = true;
    e.water_level_m = frame.water_level_m;
    out.push_back(e);
  }
  std::sort(out.begin(), out.end(), [](const SnapshotEntry& a, const SnapshotEntry& b) { return a.step < b.step; });
  return out;
}

Snapshot read_native_dump(const fs::path& file, double water_level_m) {
  const std::string text = read_text_file(file);
  std::istringstream in(text);
  std::string line;
  std::size_t line_no = 0, expected = 0;
  std::map<std::string, std::size_t, std::less<>> column;
  bool atoms = false, counted = false, stepped = false;
  Snapshot s;
  const auto col = [&](std::string_view name) -> std::optional<std::size_t> {
    const auto it = column.find(name);
    return it == column.end() ? std::nullopt : std::optional(it->second);
  };
  std::optional<std::size_t> c_id, c_x, c_y, c_z, c_r, c_d, c_vx, c_vy, c_vz;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.rfind("ITEM:", 0) == 0) {
      atoms = false;
      if (line.rfind(kTimestep, 0) == 0) {
        if (stepped)
          throw InputError(fmt::format("{}:{}: a second TIMESTEP: one snapshot per file is read (a '*' in the dump's "
                                       "file name makes LIGGGHTS write one file per step)", file.string(), line_no));
        stepped = true;
      } else if (line.rfind("ITEM: NUMBER OF ATOMS", 0) == 0) {
        std::getline(in, line), ++line_no;
        expected = static_cast<std::size_t>(parse_finite(line, file, line_no, "NUMBER OF ATOMS"));
        counted = true;
      } else if (line.rfind("ITEM: ATOMS", 0) == 0) {
        const auto names = whitespace_fields(std::string_view(line).substr(11));
        for (std::size_t i = 0; i < names.size(); ++i) column.emplace(std::string(names[i]), i);
        c_id = col("id"), c_x = col("x"), c_y = col("y"), c_z = col("z"), c_r = col("radius"), c_d = col("diameter");
        c_vx = col("vx"), c_vy = col("vy"), c_vz = col("vz");
        for (const auto& [name, c] : {std::pair{"id", c_id}, std::pair{"x", c_x}, std::pair{"y", c_y}, std::pair{"z", c_z}})
          if (!c) throw InputError(fmt::format("{}:{}: ITEM: ATOMS has no column '{}' (brash-post needs id x y z "
                                               "radius: dump custom ... id x y z radius)", file.string(), line_no, name));
        if (!c_r && !c_d)
          throw InputError(fmt::format("{}:{}: ITEM: ATOMS has neither 'radius' nor 'diameter'", file.string(), line_no));
        atoms = true;
      }
      continue;
    }
    if (!atoms) continue;
    const auto f = whitespace_fields(line);
    if (f.empty()) continue;
    if (f.size() != column.size())
      throw InputError(fmt::format("{}:{}: {} values for the {} columns of ITEM: ATOMS", file.string(), line_no,
                                   f.size(), column.size()));
    const auto value = [&](const std::optional<std::size_t>& c, std::string_view name) {
      return c ? parse_finite(f[*c], file, line_no, name) : std::numeric_limits<double>::quiet_NaN();
    };
    const double id = value(c_id, "id");
    if (id != std::floor(id)) throw InputError(fmt::format("{}:{}: id '{}' is not an integer", file.string(), line_no, f[*c_id]));
    s.id.push_back(static_cast<std::int64_t>(id));
    s.x.push_back(value(c_x, "x")), s.y.push_back(value(c_y, "y")), s.z.push_back(value(c_z, "z"));
    const double r = c_r ? value(c_r, "radius") : 0.5 * value(c_d, "diameter");
    if (!(r > 0)) throw InputError(fmt::format("{}:{}: radius must be > 0", file.string(), line_no));
    s.radius.push_back(r);
    s.vx.push_back(value(c_vx, "vx")), s.vy.push_back(value(c_vy, "vy")), s.vz.push_back(value(c_vz, "vz"));
    s.submerged_fraction.push_back(core::immersion(r, s.z.back(), water_level_m).fraction);
    const double unknown = std::numeric_limits<double>::quiet_NaN();  // the dump does not hold fix icefluid's C_a
    s.ca_x.push_back(unknown), s.ca_y.push_back(unknown), s.ca_z.push_back(unknown);
  }
  if (!stepped || column.empty())
    throw InputError(fmt::format("{}: not a LIGGGHTS dump custom file (no ITEM: TIMESTEP or ITEM: ATOMS)", file.string()));
  if (counted && s.size() != expected)
    throw InputError(fmt::format("{}: {} atoms where NUMBER OF ATOMS says {} (a file still being written?)",
                                 file.string(), s.size(), expected));
  return s;
}

}  // namespace brash::post
