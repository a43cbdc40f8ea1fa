// How the study document writes numbers, paths and a run's state (brash-study-report).
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <brash/post/study_report/study.hpp>

namespace brash::post::study_report {

std::string num(double v, int prec = 2);  // "n/a" when not finite
std::string pm(double v, double ci, int prec = 2);  // "v ± ci"
std::string optnum(const std::optional<double>& v, int prec = 2);
std::string md_escape(const std::string& s);  // a table cell: '|' escaped
std::string join(const std::vector<std::string>& items, const std::string& separator);

// Run directories are shown relative to the working directory when they lie below it (repo-relative
// paths when the study is generated from the repository root). Lexically first: a run folder reached through
// a symbolic link below the working directory (runs -> /elsewhere/runs) is still shown as runs/...
std::string show_path(const std::filesystem::path& p);

// "paper case ..., window [...]" or "**reduced case** (...)": what a run's full-scale number stands for.
std::string scale_label(const Run& r);
// ok, the run's warnings, IN PROGRESS or FAILED/MISSING with the reason.
std::string status_cell(const Run& r);

// The paper's FSICR / simulation ratio for a fluid model: as stated where the case declares it, else derived
// from its two published numbers (the paper states no ratio for drag; brash::post::published_reference).
std::string paper_ratio_cell(const brash::ReferenceSpec& paper, const std::string& model);

// A paired ensemble's effect on side A in per cent with PREC decimals: "+8.82 % ± 0.81 %", or for a summary
// without per-pair values "+8.82 % (CI on A not recomputable; recorded on the pair mean: ± 0.81 %)".
std::string effect_cell(const EnsembleEffect& e, int prec = 2);

// The fluid model a paired ensemble's side runs ("fluid.model=X" among its edits), else "case default".
std::string side_model(const std::string& side);

}  // namespace brash::post::study_report
