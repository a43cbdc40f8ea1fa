// Bridge to the hull tool (brash_hull): FSICR parameters measured on the case's STL, full scale.
// Built without brash_hull (BRASH_POST_HAVE_HULL undefined) it reports that the measurement is
// unavailable, and R_CH then needs the case's fsicr: overrides.
#include <brash/post/report.hpp>

#include <fmt/format.h>

namespace brash::post {

std::optional<FsicrParams> measure_case_hull_full_scale(const PostCase& c, std::vector<std::string>& notes) {
  (void)c;
  notes.push_back("FSICR hull parameters: hull measurement (brash_hull) not built in; using case dimensions and fsicr: overrides");
  return std::nullopt;
}

}  // namespace brash::post
