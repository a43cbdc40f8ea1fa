// hull_force.csv: its one writer and its one reader (see force_record.hpp).
#include "brash/run/force_record.hpp"

#include <algorithm>
#include <charconv>
#include <iterator>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "brash/error.hpp"
#include "brash/run/run_csv.hpp"
#include "brash/run/run_layout.hpp"

namespace brash::run {
namespace {

// Every number of the record: 9 significant digits keep a double's forces and times to well below what a DEM
// run resolves, and the same value always prints the same.
void append_number(std::string& out, double v) { fmt::format_to(std::back_inserter(out), "{:.9g}", v); }

std::string expected_header() { return fmt::format("{}", fmt::join(kForceColumns, ",")); }

// Where each of the four columns and each further column sits in the file's header.
struct ColumnPlan {
  std::array<std::size_t, 4> required{};
  std::vector<std::size_t> extra;
};

ColumnPlan plan_columns(const std::filesystem::path& csv, const CsvHeader& header, ForceRecord& record) {
  const auto& names = header.fields;
  const auto fail = [&] {
    return InputError(fmt::format("{}:{}: header is '{}', expected '{}' (further named columns may follow)",
                                  csv.string(), header.line, fmt::join(names, ","), expected_header()));
  };
  ColumnPlan plan;
  for (std::size_t k = 0; k < kForceColumns.size(); ++k) {
    const auto at = std::find(names.begin(), names.end(), kForceColumns[k]);
    if (at == names.end()) throw fail();
    plan.required[k] = static_cast<std::size_t>(at - names.begin());
  }
  for (std::size_t j = 0; j < names.size(); ++j) {
    if (std::count(names.begin(), names.end(), names[j]) != 1 || names[j].empty()) throw fail();
    if (std::find(plan.required.begin(), plan.required.end(), j) != plan.required.end()) continue;
    plan.extra.push_back(j);
    record.extra_columns.push_back(names[j]);
  }
  return plan;
}

}  // namespace

std::size_t ForceRecord::split_column(std::size_t k) const {
  return static_cast<std::size_t>(std::find(extra_columns.begin(), extra_columns.end(), kSplitColumns.at(k)) -
                                  extra_columns.begin());
}

bool ForceRecord::has_split() const {
  for (std::size_t k = 0; k < kSplitColumns.size(); ++k)
    if (split_column(k) == extra_columns.size()) return false;
  return true;
}

void ForceRecord::set_split(const std::vector<double>& values) {
  const std::size_t n = kSplitColumns.size();
  if (!extra_columns.empty() || values.size() != rows.size() * n)
    throw std::logic_error(fmt::format("ForceRecord::set_split: {} values for {} rows and {} further columns",
                                       values.size(), rows.size(), extra_columns.size()));
  extra_columns.assign(kSplitColumns.begin(), kSplitColumns.end());
  extra = values;
}

std::string hull_force_csv_text(const ForceRecord& record) {
  std::string out = expected_header();
  for (const auto& name : record.extra_columns) {
    out += ',';
    out += name;
  }
  out += '\n';
  const std::size_t n_extra = record.extra_columns.size();
  for (std::size_t i = 0; i < record.rows.size(); ++i) {
    const ForceRow& r = record.rows[i];
    for (const double v : {r.t_s, r.fx_N, r.fy_N, r.fz_N}) {
      append_number(out, v);
      out += ',';
    }
    for (std::size_t k = 0; k < n_extra; ++k) {
      append_number(out, record.extra[i * n_extra + k]);
      out += ',';
    }
    out.back() = '\n';
  }
  return out;
}

std::size_t write_hull_force_csv(const std::filesystem::path& csv, const ForceRecord& record) {
  write_atomic(csv, hull_force_csv_text(record));
  return record.rows.size();
}

std::size_t write_hull_force_csv(const std::filesystem::path& csv, const std::vector<ForceRow>& rows) {
  ForceRecord record;
  record.rows = rows;
  return write_hull_force_csv(csv, record);
}

double as_recorded(double value) {
  std::string text;
  append_number(text, value);
  double v = value;
  (void)std::from_chars(text.data(), text.data() + text.size(), v);  // it parses: it was just printed
  return v;
}

ForceRecord read_hull_force_csv(const std::filesystem::path& csv, bool drop_unterminated_tail) {
  const std::string text = read_text_file(csv);
  const CsvHeader header = read_csv_header(text);
  if (header.fields.empty())
    throw InputError(fmt::format("{}:1: empty file, expected header '{}'", csv.string(), expected_header()));
  ForceRecord record;
  const ColumnPlan plan = plan_columns(csv, header, record);
  const std::vector<std::string_view> names(header.fields.begin(), header.fields.end());
  const CsvScan scan = scan_csv(csv, text, names, drop_unterminated_tail,
                                [&](std::size_t line, std::span<const std::string_view> f) {
    const auto number = [&](std::size_t column) { return parse_finite(f[column], csv, line, names[column]); };
    const auto& c = plan.required;
    const ForceRow row{number(c[0]), number(c[1]), number(c[2]), number(c[3])};
    if (!record.rows.empty() && !(row.t_s > record.rows.back().t_s))
      throw InputError(fmt::format("{}:{}: time {} s does not increase (previous {} s)", csv.string(), line, row.t_s,
                                   record.rows.back().t_s));
    record.rows.push_back(row);
    for (const std::size_t column : plan.extra) record.extra.push_back(number(column));
  });
  record.tail_dropped = scan.tail_dropped;
  return record;
}

}  // namespace brash::run
