// Strict CSV scanning for run files; errors name file and line.
#include "brash/run/run_csv.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "brash/error.hpp"

namespace brash::run {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

void split_fields(std::string_view line, std::vector<std::string_view>& out) {
  out.clear();
  std::size_t start = 0;
  for (;;) {
    const auto comma = line.find(',', start);
    if (comma == std::string_view::npos) {
      out.push_back(trim(line.substr(start)));
      return;
    }
    out.push_back(trim(line.substr(start, comma - start)));
    start = comma + 1;
  }
}

std::string join(std::span<const std::string_view> cols) {
  std::string s;
  for (std::size_t i = 0; i < cols.size(); ++i) {  // piecewise: GCC 12 -O3 warns (falsely) on "," + std::string
    if (i > 0) s += ',';
    s.append(cols[i]);
  }
  return s;
}

}  // namespace

std::string read_text_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot open file", path.string()));
  std::ostringstream ss;
  ss << in.rdbuf();
  return std::move(ss).str();
}

CsvHeader read_csv_header(std::string_view text) {
  CsvHeader header;
  std::vector<std::string_view> fields;
  for (std::size_t pos = 0; pos < text.size();) {
    const auto nl = text.find('\n', pos);
    const auto line = text.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos);
    pos = nl == std::string_view::npos ? text.size() : nl + 1;
    ++header.line;
    if (trim(line).empty()) continue;
    split_fields(line, fields);
    header.fields.assign(fields.begin(), fields.end());
    return header;
  }
  return {};
}

CsvScan scan_csv(const std::filesystem::path& path, std::string_view text,
                 std::span<const std::string_view> header, bool drop_unterminated_tail,
                 const CsvRecordFn& on_record) {
  CsvScan scan;
  std::vector<std::string_view> fields;
  std::size_t pos = 0, line_no = 0;
  bool header_seen = false;
  while (pos < text.size()) {
    const auto nl = text.find('\n', pos);
    const bool terminated = nl != std::string_view::npos;
    const auto line = text.substr(pos, terminated ? nl - pos : std::string_view::npos);
    pos = terminated ? nl + 1 : text.size();
    ++line_no;
    if (!terminated && drop_unterminated_tail && header_seen) {
      scan.tail_dropped = !trim(line).empty();
      scan.tail_line = scan.tail_dropped ? line_no : 0;
      break;
    }
    if (trim(line).empty()) continue;
    split_fields(line, fields);
    if (!header_seen) {
      if (fields.size() != header.size() || !std::equal(fields.begin(), fields.end(), header.begin()))
        throw InputError(fmt::format("{}:{}: header is '{}', expected '{}'", path.string(), line_no,
                                     trim(line), join(header)));
      header_seen = true;
      continue;
    }
    if (fields.size() != header.size())
      throw InputError(fmt::format("{}:{}: {} fields, expected {} ({})", path.string(), line_no,
                                   fields.size(), header.size(), join(header)));
    on_record(line_no, fields);
    ++scan.records;
  }
  if (!header_seen) throw InputError(fmt::format("{}:1: empty file, expected header '{}'", path.string(), join(header)));
  return scan;
}

double parse_finite(std::string_view field, const std::filesystem::path& path, std::size_t line_no,
                    std::string_view column) {
  field = trim(field);
  double v = 0;
  const char* first = field.data();
  const char* last = first + field.size();
  if (!field.empty() && *first == '+') ++first;  // from_chars rejects a leading '+'
  const auto [ptr, ec] = std::from_chars(first, last, v);
  if (field.empty() || ec != std::errc{} || ptr != last)
    throw InputError(fmt::format("{}:{}: column '{}': '{}' is not a number", path.string(), line_no, column, field));
  if (!std::isfinite(v))
    throw InputError(fmt::format("{}:{}: column '{}': '{}' is not finite", path.string(), line_no, column, field));
  return v;
}

}  // namespace brash::run
