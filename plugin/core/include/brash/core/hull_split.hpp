// The hull force split (docs/physics.md, "The hull force split"), coded once for every engine that records it
// (LIGGGHTS' fix brash/hullsplit, brash-ode's World): the x component (the heading; resistance = -fx) of each
// contact force on the hull, booked by where the contact lies along the hull and by its mechanism.
//
//   - region: the contact point's x in the hull's own frame (the STL's: x = 0 at the aft perpendicular) against
//     the parallel mid-body measured on the hull (brash::hull::measure_fsicr_detail, x_par_aft_m..x_par_fwd_m at
//     the waterline): bow ahead of it (x > x_par_fwd_m), stern behind it (x < x_par_aft_m), mid-body between;
//   - mechanism: the contact force F split along the contact normal n (from the piece's centre through the
//     contact point, either sign): normal part (F.n) n / (n.n), tangential part F minus it (friction).
//
// Each set of parts adds up to the contact force, so summed over the contacts each adds up to the total.
// Scalar code, no allocation: it runs once per hull contact and step.
#pragma once
#include <array>
#include <cstddef>

namespace brash::core {

// The parts of the split, in the order of the record's columns (brash::run::kSplitColumns).
enum HullSplitPart : std::size_t { kSplitBow, kSplitMid, kSplitStern, kSplitNormal, kSplitTangential };
inline constexpr std::size_t kHullSplitParts = 5;
using HullSplit = std::array<double, kHullSplitParts>;

// The parallel mid-body in the hull's frame (x_par_aft_m <= x_par_fwd_m).
struct HullRegions {
  double x_par_aft_m = 0, x_par_fwd_m = 0;
};

// Which region part a contact at x (hull frame) belongs to.
constexpr HullSplitPart hull_region(const HullRegions& r, double x_hull_m) {
  return x_hull_m > r.x_par_fwd_m ? kSplitBow : (x_hull_m < r.x_par_aft_m ? kSplitStern : kSplitMid);
}

// Adds one contact's x parts to `split`: f = the contact force on the hull, n = the contact normal (any length;
// a zero normal books the whole force as normal), x_hull_m = the contact point's x in the hull's frame.
inline void add_contact_x(HullSplit& split, const HullRegions& r, double x_hull_m, const double f[3],
                          const double n[3]) {
  split[hull_region(r, x_hull_m)] += f[0];
  const double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  const double normal_x = nn > 0 ? (f[0] * n[0] + f[1] * n[1] + f[2] * n[2]) * n[0] / nn : f[0];
  split[kSplitNormal] += normal_x;
  split[kSplitTangential] += f[0] - normal_x;
}

}  // namespace brash::core
