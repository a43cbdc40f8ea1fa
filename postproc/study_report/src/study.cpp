// The study (study.hpp): the manifest's rows joined to their runs, the ensembles and the paper's values.
#include <map>
#include <set>

#include <fmt/format.h>

#include <brash/error.hpp>
#include <brash/post/study_report/study.hpp>

namespace fs = std::filesystem;

namespace brash::post::study_report {
namespace {

// One Run per run directory, in order of first appearance; rows without a run directory get one each.
void join_rows_to_runs(Study& s) {
  std::map<fs::path, std::size_t> index_of;
  int unnamed = 0;
  for (const auto& row : s.rows) {
    const fs::path key = row.run_dir.empty() ? fs::path(fmt::format("<no run dir #{}>", ++unnamed))
                                             : row.run_dir.lexically_normal();
    const auto it = index_of.find(key);
    if (it == index_of.end()) {
      index_of.emplace(key, s.runs.size());
      s.run_index.push_back(s.runs.size());
      s.runs.push_back(load_run(row, fmt::format("R{}", s.runs.size() + 1)));
      continue;
    }
    s.run_index.push_back(it->second);
    Run& run = s.runs[it->second];
    if (row.exit_code && *row.exit_code != 0 && run.ok) {  // a later attempt of the same run failed
      run.ok = false;
      run.problem = fmt::format("runner exited with code {}", *row.exit_code);
    }
  }
}

// The started run's resolved case.yaml and force record (a run in progress unless it is ok).
void read_case_and_record(Run& r) {
  r.has_case_yaml = !r.run_dir.empty() && fs::exists(r.run_dir / "case.yaml");
  r.has_force_record = !r.run_dir.empty() && fs::exists(r.run_dir / "hull_force.csv");
  if (r.has_case_yaml) {
    try {
      r.resolved_case = brash::load_case(r.run_dir / "case.yaml");
    } catch (const std::exception& e) {
      r.case_error = e.what();
    }
  }
  if (r.has_force_record) {
    try {
      r.history = read_force_history(r.run_dir / "hull_force.csv", !r.ok);
    } catch (const std::exception& e) {
      r.history_error = e.what();
    }
  }
}

}  // namespace

const Run& Study::run_of(const Row& row) const {
  const auto i = static_cast<std::size_t>(&row - rows.data());
  if (&row < rows.data() || i >= rows.size()) throw std::logic_error("Study::run_of: not a row of this study");
  return runs.at(run_index.at(i));
}

Study load_study(const fs::path& manifest, const fs::path& paper_case) {
  Study s;
  if (!fs::exists(paper_case))
    throw InputError(fmt::format("--paper-case {}: no such file (run from the repository root or name the "
                                 "paper case's case.yaml)",
                                 paper_case.string()));
  s.paper = brash::load_case(paper_case).references;
  for (auto& row : read_manifest(manifest)) {
    if (row.group == "paired")
      s.paired.push_back(load_paired(row, static_cast<int>(s.paired.size()) + 1));
    else
      s.rows.push_back(std::move(row));
  }
  join_rows_to_runs(s);
  // the set-up table, the history plot and the engines' binned comparison read groups paper and engine
  std::set<std::size_t> read;
  for (std::size_t i = 0; i < s.rows.size(); ++i)
    if ((s.rows[i].group == "paper" || s.rows[i].group == "engine") && read.insert(s.run_index[i]).second)
      read_case_and_record(s.runs[s.run_index[i]]);
  return s;
}

}  // namespace brash::post::study_report
