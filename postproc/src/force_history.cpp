// hull_force.csv reader.
#include <brash/post/force_history.hpp>

#include <algorithm>
#include <array>
#include <string_view>

#include <fmt/format.h>

#include <brash/error.hpp>
#include <brash/post/csv.hpp>

namespace brash::post {

ForceHistory read_force_history(const std::filesystem::path& path, bool run_in_progress) {
  static constexpr std::array<std::string_view, 4> kHeader{"t_s", "fx_N", "fy_N", "fz_N"};
  const auto text = read_text_file(path);
  ForceHistory h;
  const auto scan = scan_csv(path, text, kHeader, run_in_progress,
                             [&](std::size_t line, std::span<const std::string_view> f) {
    const double t = parse_finite(f[0], path, line, kHeader[0]);
    if (!h.t_s.empty() && !(t > h.t_s.back()))
      throw InputError(fmt::format("{}:{}: time {} s does not increase (previous {} s)", path.string(),
                                   line, t, h.t_s.back()));
    h.t_s.push_back(t);
    h.fx_N.push_back(parse_finite(f[1], path, line, kHeader[1]));
    h.fy_N.push_back(parse_finite(f[2], path, line, kHeader[2]));
    h.fz_N.push_back(parse_finite(f[3], path, line, kHeader[3]));
  });
  h.tail_dropped = scan.tail_dropped;
  return h;
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
