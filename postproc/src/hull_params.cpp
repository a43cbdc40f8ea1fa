// Bridge to the hull tool (brash_hull): FSICR parameters measured on the case's STL, at full scale.
// Without brash_hull (BRASH_POST_HAVE_HULL undefined) the measurement is reported as unavailable and
// R_CH then needs the case's fsicr: overrides. A missing or bad hull file is a note, not an error:
// the resistance report is still worth writing.
#include <brash/post/report.hpp>

#include <fmt/format.h>

#include <brash/error.hpp>
#ifdef BRASH_POST_HAVE_HULL
#include <brash/hull/hydrostatics.hpp>
#include <brash/hull/mesh.hpp>
#endif

namespace brash::post {

std::optional<FsicrParams> measure_case_hull_full_scale(const PostCase& c, std::vector<std::string>& notes) {
#ifdef BRASH_POST_HAVE_HULL
  if (c.hull_file.empty()) {
    notes.push_back("FSICR hull parameters: the case names no hull file; using case dimensions and fsicr: overrides");
    return std::nullopt;
  }
  try {
    const auto mesh = brash::hull::read_mesh(c.hull_file);
    return to_full_scale(brash::hull::measure_fsicr(mesh, c.draft_m, c.lpp_m), c.scale_lambda);
  } catch (const std::exception& e) {
    notes.push_back(fmt::format("FSICR hull parameters not measured ({}); using case dimensions and fsicr: overrides", e.what()));
    return std::nullopt;
  }
#else
  (void)c;
  notes.push_back("FSICR hull parameters: hull measurement (brash_hull) not built in; using case dimensions and fsicr: overrides");
  return std::nullopt;
#endif
}

}  // namespace brash::post
