// Numbers, paths and run states as the study document writes them (format.hpp).
#include <cmath>

#include <fmt/format.h>

#include <brash/post/report.hpp>
#include <brash/post/study_report/format.hpp>

namespace fs = std::filesystem;

namespace brash::post::study_report {

std::string num(double v, int prec) {
  if (!std::isfinite(v)) return "n/a";
  return fmt::format("{:.{}f}", v, prec);
}

std::string pm(double v, double ci, int prec) { return fmt::format("{} ± {}", num(v, prec), num(ci, prec)); }

std::string effect_cell(const EnsembleEffect& e, int prec) {
  const std::string effect = fmt::format("{:+.{}f} %", 100.0 * e.effect_rel, prec);
  if (e.has_ci()) return fmt::format("{} ± {:.{}f} %", effect, 100.0 * e.ci95_rel, prec);
  return fmt::format("{} (CI on A not recomputable; recorded on the pair mean: ± {:.{}f} %)", effect,
                     100.0 * e.pair_mean_ci95_rel, prec);
}

std::string optnum(const std::optional<double>& v, int prec) { return v ? num(*v, prec) : "n/a"; }

std::string md_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '|')
      o += "\\|";
    else
      o += c;
  }
  return o;
}

std::string join(const std::vector<std::string>& items, const std::string& separator) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : separator) + item;
  return out;
}

std::string show_path(const fs::path& p) {
  if (p.empty()) return "";
  const auto below = [](const fs::path& rel) { return !rel.empty() && *rel.begin() != ".."; };
  const fs::path lexical = fs::absolute(p).lexically_normal().lexically_relative(fs::current_path());
  if (below(lexical)) return lexical.string();
  std::error_code ec;
  const fs::path rel = fs::relative(p, fs::current_path(), ec);
  if (!ec && below(rel)) return rel.string();
  return p.string();
}

std::string scale_label(const Run& r) {
  const std::string window = fmt::format("window [{}, {}] s", num(r.window0), num(r.window1));
  if (r.base_case == kPaperCase) return fmt::format("paper case {}, {}", kPaperCase, window);
  return fmt::format("**reduced case** ({} based on {}; not the paper case), {}", r.case_name,
                     r.base_case.empty() ? std::string("?") : r.base_case, window);
}

std::string status_cell(const Run& r) {
  if (r.in_progress) return "**IN PROGRESS** (" + r.problem + ")";
  if (!r.ok) return "**FAILED/MISSING: " + r.problem + "**";
  return r.warnings.empty() ? "ok" : join(r.warnings, "; ");
}

std::string paper_ratio_cell(const brash::ReferenceSpec& paper, const std::string& model) {
  const auto r = published_reference(paper, model);
  if (!r || !r->ratio_fsicr_to_sim) return "n/a";
  if (r->ratio_stated) return fmt::format("{:.2f}", *r->ratio_fsicr_to_sim);
  return fmt::format("{:.2f} ({:.0f} / {:.0f})", *r->ratio_fsicr_to_sim, *r->fsicr_R_CH_kN, *r->resistance_full_kN);
}

std::string side_model(const std::string& side) {
  const auto at = side.find("fluid.model=");
  if (at == std::string::npos) return "case default";
  const auto from = at + std::string("fluid.model=").size();
  return side.substr(from, side.find(',', from) - from);
}

}  // namespace brash::post::study_report
