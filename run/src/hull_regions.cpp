// The hull force split's regions of a case (see hull_regions.hpp).
#include "brash/run/hull_regions.hpp"

#include <fmt/format.h>

#include "brash/error.hpp"
#include "brash/hull/hydrostatics.hpp"

namespace brash::run {

core::HullRegions measure_hull_regions(const hull::Mesh& full_hull, const Case& c,
                                       const std::filesystem::path& case_file) {
  try {
    const hull::FsicrDetail d = hull::measure_fsicr_detail(full_hull, c.hull.draft_m, c.hull.lpp_m);
    return {d.x_par_aft_m, d.x_par_fwd_m};
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: hull.file {}: the parallel mid-body (the hull force split's regions) could not "
                                 "be measured at hull.draft_m = {} m: {}",
                                 case_file.string(), c.hull.file.string(), c.hull.draft_m, e.what()));
  }
}

nlohmann::json hull_split_meta(const core::HullRegions& r) {
  return {{"x_par_aft_m", r.x_par_aft_m},
          {"x_par_fwd_m", r.x_par_fwd_m},
          {"frame", "hull STL frame (x = 0 at the aft perpendicular), the contact point's x"},
          {"regions", "bow: x > x_par_fwd_m; mid: x_par_aft_m <= x <= x_par_fwd_m; stern: x < x_par_aft_m"},
          {"mechanism", "normal: the contact force along the contact normal; tangential: the rest (friction)"}};
}

}  // namespace brash::run
