// The study manifest (study.hpp): a tab-separated table with a header line naming its columns.
#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

#include <fmt/format.h>

#include <brash/error.hpp>
#include <brash/post/study_report/study.hpp>

namespace fs = std::filesystem;

namespace brash::post::study_report {
namespace {

std::string trim(std::string s) {
  while (!s.empty() && (s.back() == '\r' || s.back() == ' ')) s.pop_back();
  std::size_t i = 0;
  while (i < s.size() && s[i] == ' ') ++i;
  return s.substr(i);
}

std::vector<std::string> split_tabs(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string f;
  while (std::getline(ss, f, '\t')) out.push_back(trim(f));
  if (!line.empty() && line.back() == '\t') out.emplace_back();
  return out;
}

// The exit_code column: an integer, or a text saying why nothing ran ("not run", "in progress: ...").
void read_exit_code(const std::string& cell, Row& row) {
  if (cell.empty()) return;
  std::size_t used = 0;
  try {
    row.exit_code = std::stoi(cell, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != cell.size()) {
    row.exit_code.reset();
    row.exit_text = cell;
  }
}

// One data line, its cells keyed by the header's column names.
Row read_row(std::map<std::string, std::string> m, const fs::path& base) {
  Row r;
  r.id = m["id"];
  r.group = m["group"];
  r.label = m["label"];
  r.param = m["param"];
  r.value = m["value"];
  r.base_case = m["base_case"];
  r.command = m["command"];
  r.baseline = m["baseline"] == "1" || m["baseline"] == "yes" || m["baseline"] == "true";
  read_exit_code(m["exit_code"], r);
  if (!m["run_dir"].empty()) r.run_dir = join_logical(base, fs::path(m["run_dir"]));
  return r;
}

}  // namespace

fs::path join_logical(const fs::path& base, const fs::path& p) {
  return (p.is_absolute() ? p : base / p).lexically_normal();
}

std::vector<Row> read_manifest(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: cannot open the manifest", path.string()));
  std::vector<std::string> header;
  std::vector<Row> rows;
  std::string line;
  int lineno = 0;  // for messages
  const fs::path base = fs::absolute(path).parent_path();
  while (std::getline(in, line)) {
    ++lineno;
    if (trim(line).empty() || line[0] == '#') continue;
    const auto cells = split_tabs(line);
    if (header.empty()) {
      header = cells;
      for (const char* need : {"group", "run_dir", "command"})
        if (std::find(header.begin(), header.end(), need) == header.end())
          throw InputError(fmt::format("{}: header lacks the column '{}'", path.string(), need));
      continue;
    }
    std::map<std::string, std::string> by_column;
    for (std::size_t i = 0; i < header.size(); ++i) by_column[header[i]] = i < cells.size() ? cells[i] : "";
    rows.push_back(read_row(std::move(by_column), base));
    if (rows.back().group.empty()) throw InputError(fmt::format("{}:{}: empty group", path.string(), lineno));
  }
  if (header.empty()) throw InputError(fmt::format("{}: empty manifest", path.string()));
  return rows;
}

}  // namespace brash::post::study_report
