// Readers of the hull force record: hull_force.csv and a fix ave/time file (hull_force.raw).
#include <brash/post/force_history.hpp>

#include <algorithm>
#include <array>
#include <sstream>
#include <string_view>

#include <fmt/format.h>

#include <brash/error.hpp>
#include <brash/run/force_record.hpp>
#include <brash/post/csv.hpp>

namespace brash::post {

namespace {

// Appends one row; time must increase.
void append_row(ForceHistory& h, const std::filesystem::path& path, std::size_t line, const std::array<double, 4>& v) {
  if (!h.t_s.empty() && !(v[0] > h.t_s.back()))
    throw InputError(fmt::format("{}:{}: time {} s does not increase (previous {} s)", path.string(), line, v[0],
                                 h.t_s.back()));
  h.t_s.push_back(v[0]);
  h.fx_N.push_back(v[1]);
  h.fy_N.push_back(v[2]);
  h.fz_N.push_back(v[3]);
}

}  // namespace

ForceHistory read_force_history(const std::filesystem::path& path, bool run_in_progress) {
  const run::ForceRecord record = run::read_hull_force_csv(path, run_in_progress);
  ForceHistory h;
  for (auto* v : {&h.t_s, &h.fx_N, &h.fy_N, &h.fz_N}) v->reserve(record.rows.size());
  for (const auto& r : record.rows) {
    h.t_s.push_back(r.t_s);
    h.fx_N.push_back(r.fx_N);
    h.fy_N.push_back(r.fy_N);
    h.fz_N.push_back(r.fz_N);
  }
  if (record.has_split()) {
    h.split_N.assign(run::kSplitColumns.size(), {});
    for (std::size_t k = 0; k < run::kSplitColumns.size(); ++k) {
      const std::size_t column = record.split_column(k);
      h.split_N[k].reserve(record.rows.size());
      for (std::size_t i = 0; i < record.rows.size(); ++i) h.split_N[k].push_back(record.extra_value(i, column));
    }
  }
  h.tail_dropped = record.tail_dropped;
  return h;
}

ForceHistory read_ave_time_force_history(const std::filesystem::path& path, bool run_in_progress) {
  static constexpr std::array<std::string_view, 5> kColumns{"TimeStep", "t", "fx", "fy", "fz"};
  const auto text = read_text_file(path);
  ForceHistory h;
  std::istringstream in(text);
  std::string line;
  for (std::size_t no = 1; std::getline(in, line); ++no) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto fields = whitespace_fields(line);
    if (fields.empty() || fields[0][0] == '#') continue;
    if (run_in_progress && in.eof() && !text.empty() && text.back() != '\n') {
      h.tail_dropped = true;  // the engine is still writing this line
      break;
    }
    if (fields.size() != kColumns.size())
      throw InputError(fmt::format("{}:{}: expected {} columns (fix ave/time: TimeStep t fx fy fz), got {}",
                                   path.string(), no, kColumns.size(), fields.size()));
    std::array<double, 4> v{};
    for (std::size_t k = 1; k < kColumns.size(); ++k) v[k - 1] = parse_finite(fields[k], path, no, kColumns[k]);
    append_row(h, path, no, v);
  }
  return h;
}

std::filesystem::path force_record_file(const std::filesystem::path& run_dir) {
  for (const char* name : {"hull_force.csv", "hull_force.raw"})
    if (std::filesystem::exists(run_dir / name)) return run_dir / name;
  throw InputError(fmt::format("{}: no hull force record: hull_force.csv (header t_s,fx_N,fy_N,fz_N) or hull_force.raw "
                               "(LIGGGHTS fix ave/time: TimeStep t fx fy fz) is needed (docs/case_format.md)",
                               run_dir.string()));
}

ForceHistory read_force_record(const std::filesystem::path& file, bool run_in_progress) {
  return file.extension() == ".raw" ? read_ave_time_force_history(file, run_in_progress)
                                    : read_force_history(file, run_in_progress);
}

std::vector<RecordGap> record_gaps(const std::vector<double>& t_s, double t0, double t1) {
  std::vector<RecordGap> gaps;
  if (t_s.size() < 3) return gaps;
  std::vector<double> steps(t_s.size() - 1);
  for (std::size_t i = 1; i < t_s.size(); ++i) steps[i - 1] = t_s[i] - t_s[i - 1];
  auto mid = steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2);
  std::nth_element(steps.begin(), mid, steps.end());
  const double limit = kGapFactor * *mid;
  for (std::size_t i = 1; i < t_s.size(); ++i)
    if (t_s[i] - t_s[i - 1] > limit && t_s[i] > t0 && t_s[i - 1] < t1) gaps.push_back({t_s[i - 1], t_s[i]});
  return gaps;
}

}  // namespace brash::post
