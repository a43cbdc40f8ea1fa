// Run directories, their force records and their archived copies.
#include "brash/study/run_outputs.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "brash/error.hpp"
#include "brash/run/run_layout.hpp"

namespace fs = std::filesystem;

namespace brash::study {

namespace {

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t field_count(const std::string& line) { return static_cast<std::size_t>(std::ranges::count(line, ',')) + 1; }

void write_text(const fs::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
  if (!out) throw InputError(fmt::format("{}: cannot write", file.string()));
}

}  // namespace

bool report_complete(const fs::path& run_dir) {
  std::ifstream in(run_dir / "report.json");
  if (!in) return false;
  const nlohmann::json report = nlohmann::json::parse(in, nullptr, false);
  return report.is_object() && report.value("status", "") == "complete";
}

std::vector<std::string> complete_force_rows(const fs::path& hull_force_csv) {
  std::string text = read_text(hull_force_csv);
  if (!text.empty() && text.back() != '\n') {  // the last line is still being written
    const auto last_newline = text.rfind('\n');
    text.resize(last_newline == std::string::npos ? 0 : last_newline + 1);
  }
  std::vector<std::string> rows;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (rows.empty() || (!line.empty() && field_count(line) == field_count(rows.front()))) rows.push_back(line);
  }
  return rows;
}

std::size_t force_row_count(const fs::path& hull_force_csv) {
  const auto rows = complete_force_rows(hull_force_csv);
  return rows.empty() ? 0 : rows.size() - 1;
}

double model_time_reached(const fs::path& run_dir) {
  const auto rows = complete_force_rows(run_dir / "hull_force.csv");
  if (rows.size() > 1) return std::stod(rows.back().substr(0, rows.back().find(',')));
  std::istringstream raw(read_text(run_dir / "hull_force.raw"));
  std::string last;
  for (std::string line; std::getline(raw, line);)
    if (!line.empty() && line[0] != '#') last = line;
  std::istringstream fields(last);
  std::string step, time;
  fields >> step >> time;
  try {
    return time.empty() ? 0.0 : std::stod(time);
  } catch (const std::exception&) {
    return 0.0;
  }
}

fs::path relative_path(const fs::path& to, const fs::path& from) {
  return fs::absolute(to).lexically_normal().lexically_relative(fs::absolute(from).lexically_normal());
}

void copy_outputs(const fs::path& run_dir, const fs::path& dst, bool with_plots) {
  fs::path tmp = dst;
  tmp += ".tmp";
  fs::remove_all(tmp);
  fs::create_directories(tmp);
  std::vector<std::string> files{"meta.json", "case.yaml", "report.json", "report.md", "hull_force.csv",
                                 "force_history.csv", "blocking.csv"};
  if (with_plots) {
    files.emplace_back("force_history.png");
    std::vector<std::string> views;
    for (const auto& entry : fs::directory_iterator(run_dir)) {
      const std::string name = entry.path().filename().string();
      if (name.starts_with("ice_views_") && name.ends_with(".png")) views.push_back(name);
    }
    if (!views.empty()) files.push_back(*std::ranges::max_element(views));
  }
  for (const auto& f : files)
    if (fs::is_regular_file(run_dir / f)) fs::copy_file(run_dir / f, tmp / f);
  write_text(tmp / "source_run_dir.txt", relative_path(run_dir, dst).string() + "\n");
  fs::remove_all(dst);
  fs::rename(tmp, dst);
}

bool archive_complete_run(const fs::path& run_dir, const fs::path& archive_dir) {
  const fs::path dst = archive_dir / fs::absolute(run_dir).lexically_normal().filename();
  if (fs::is_regular_file(dst / "report.json") && read_text(dst / "report.json") == read_text(run_dir / "report.json"))
    return false;
  copy_outputs(run_dir, dst, true);
  return true;
}

bool archive_partial_run(const fs::path& run_dir, const fs::path& archive_dir) {
  const fs::path dst = archive_dir / fs::absolute(run_dir).lexically_normal().filename();
  if (force_row_count(run_dir / "hull_force.csv") <= force_row_count(dst / "hull_force.csv")) return false;
  copy_outputs(run_dir, dst, false);
  std::string rows;
  for (const auto& row : complete_force_rows(run_dir / "hull_force.csv")) rows += row + "\n";
  run::write_atomic(dst / "hull_force.csv", rows);
  return true;
}

fs::path paper_listed_dir(const fs::path& run_dir, const fs::path& archive_dir) {
  const fs::path archived = archive_dir / fs::absolute(run_dir).lexically_normal().filename();
  if (report_complete(archived)) return archived;
  if (!fs::exists(run_dir / "meta.json") && fs::exists(archived / "meta.json")) return archived;
  return run_dir;
}

bool held_elsewhere(const fs::path& run_dir) {
  if (!fs::exists(run_dir / ".lock")) return false;
  try {
    const run::RunDirLock lock(run_dir);
    return false;
  } catch (const InputError&) {
    return true;
  }
}

}  // namespace brash::study
