// Manifest rows from the study file's items and the runs' listings; the study's runs copied beside the document.
#include "brash/study/manifest.hpp"

#include <fmt/format.h>

#include <set>

#include "brash/study/run_outputs.hpp"

namespace fs = std::filesystem;

namespace brash::study {

namespace {

ManifestRow row_of(const RowSpec& spec, const Listing& l) {
  return {spec.run, spec.group, spec.label, spec.param, spec.value, spec.baseline, spec.base_case,
          l.exit_text, l.run_dir, l.command};
}

// A cell's text on one line without tabs (a failure message may hold either).
std::string cell(std::string text) {
  for (char& c : text)
    if (c == '\t' || c == '\n' || c == '\r') c = ' ';
  return text;
}

bool listed(const RowSpec& spec, const Listings& listings) {
  const auto it = listings.find(spec.run);
  if (it == listings.end()) return false;
  return spec.when_listed.empty() || (listings.contains(spec.when_listed) && it->second.has_report);
}

}  // namespace

std::vector<ManifestRow> manifest_rows(const Study& study, const Listings& listings) {
  std::vector<ManifestRow> rows;
  for (const RowSpec& spec : study.manifest) {
    if (!spec.sweep) {
      if (listed(spec, listings)) rows.push_back(row_of(spec, listings.at(spec.run)));
      continue;
    }
    for (const auto& u : study.speed_sweep->speeds)
      for (const auto& m : study.speed_sweep->models) {
        RowSpec r;
        r.run = fmt::format("quick_u{}_{}", u, m);
        r.group = "speed";
        r.label = "U " + u;
        r.param = "speed_m_s";
        r.value = u;
        r.base_case = study.speed_sweep->base_case;
        if (listed(r, listings)) rows.push_back(row_of(r, listings.at(r.run)));
      }
  }
  return rows;
}

fs::path copy_study_runs(std::vector<ManifestRow>& rows, const Settings& s) {
  const fs::path copies = s.doc.parent_path() / (s.doc.stem().string() + "_runs");
  fs::path fresh = copies;
  fresh += ".new";
  fs::remove_all(fresh);
  fs::create_directories(fresh);
  const fs::path runs = (s.work / "runs").lexically_normal();
  std::set<fs::path> copied;
  for (const auto& row : rows) {
    const fs::path dir = row.run_dir.lexically_normal();
    if (dir.parent_path() != runs || copied.contains(dir) || !report_complete(dir)) continue;
    copy_outputs(dir, fresh / dir.filename(), false);
    copied.insert(dir);
  }
  fs::remove_all(copies);
  fs::rename(fresh, copies);
  for (auto& row : rows)
    if (copied.contains(row.run_dir.lexically_normal())) row.run_dir = copies / row.run_dir.filename();
  return copies;
}

std::string manifest_text(const std::vector<ManifestRow>& rows, const Settings& s, const std::string& title_comment) {
  std::string text = "# " + title_comment + "\n";
  text += "id\tgroup\tlabel\tparam\tvalue\tbaseline\tbase_case\texit_code\trun_dir\tcommand\n";
  for (const auto& r : rows)
    text += fmt::format("{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\n", r.id, r.group, r.label, r.param, r.value,
                        r.baseline ? 1 : 0, r.base_case, cell(r.exit_text),
                        relative_path(r.run_dir, s.work).string(), cell(r.command));
  return text;
}

}  // namespace brash::study
