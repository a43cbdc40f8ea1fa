// The paper case's resistance histories at full scale, in bins (analysis.hpp).
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include <brash/post/study_report/analysis.hpp>

namespace brash::post::study_report {
namespace {

// Bin means of -fx over [0, last row], scaled by KN_PER_N; the last row closes the last bin.
std::vector<std::pair<double, double>> binned_kN(const ForceHistory& h, double bin_s, double kN_per_N) {
  const auto nbins = static_cast<std::size_t>(std::ceil(h.t_s.back() / bin_s));
  std::vector<double> sum(nbins + 1, 0.0);
  std::vector<int> n(nbins + 1, 0);
  for (std::size_t i = 0; i < h.t_s.size(); ++i) {
    const auto b = std::min(nbins, static_cast<std::size_t>(h.t_s[i] / bin_s));
    sum[b] -= h.fx_N[i];
    ++n[b];
  }
  std::vector<std::pair<double, double>> t_kN;
  for (std::size_t b = 0; b < nbins; ++b) t_kN.emplace_back((b + 0.5) * bin_s, n[b] ? sum[b] / n[b] * kN_per_N : NAN);
  return t_kN;
}

}  // namespace

PaperHistories paper_histories(const Study& s, double bin_s) {
  PaperHistories out;
  for (const Run* r : started_paper_case_runs(s)) {
    if (!r->has_force_record) continue;
    if (!r->resolved_case || !r->history) {
      out.unreadable.emplace_back(r->ref, r->resolved_case ? r->history_error : r->case_error);
      continue;
    }
    const brash::Case& c = *r->resolved_case;
    const ForceHistory& h = *r->history;
    if (h.t_s.empty()) continue;
    out.window = c.run.window_s;
    PaperHistory line;
    line.title = fmt::format("{} {} {}{}", r->ref, r->engine, brash::to_string(c.fluid.model),
                             r->ok ? "" : fmt::format(" (in progress, t = {:.1f} s)", h.t_s.back()));
    line.t_kN = binned_kN(h, bin_s, std::pow(c.ship.scale_lambda, 3) / 1000.0);
    out.lines.push_back(std::move(line));
  }
  return out;
}

}  // namespace brash::post::study_report
