/* fix brash/hullsplit: the hull force split (docs/physics.md "The hull force split", brash/core/hull_split.hpp):
   the x component of the force of the ice on a mesh wall, by hull region and by mechanism, from each contact.

   fix ID group-ID brash/hullsplit mesh MESH-ID hull_x0 X0 speed U par_aft XA par_fwd XF [scale S]

   MESH-ID is the hull's fix mesh/surface (or mesh/surface/stress), moved by fix move/mesh linear U 0 0 from
   x = X0 at step 0 (its STL frame: x = 0 at the aft perpendicular); its fix wall/gran must store each contact
   (keyword store_force_contact_stress yes), which gives, per piece and touched triangle, the contact force on
   the piece F and the vector d from the contact point to the piece's centre. Each contact of a piece of
   group-ID adds -F (the force on the hull) at the contact point x - d, whose hull-frame x is x - d - (X0 + U t),
   t = step * dt: to the bow (x > XF), mid-body (XA <= x <= XF) or stern (x < XA) part, and along d to the
   normal part, the rest to the tangential part. S (default 1) scales every part: 2 for the half hull of a
   symmetry plane, the whole ship's, as the deck's doubled f_hull.

   Global vector (f_ID[1..5], extensive, in N): fx of the bow, mid-body and stern parts, then of the normal and
   tangential parts; each set adds up to the mesh's own total fx to round-off. Summed over the ranks once per
   step, when first asked for (fix ave/time at END_OF_STEP: the contacts are those of this step's forces). At a
   run's set-up the vector is 0, as mesh/surface/stress's own total is there (no contact force summed yet).
*/
#pragma once

#include <string>

#include "brash/core/hull_split.hpp"
#include "fix.h"

namespace LAMMPS_NS {
class FixMeshSurface;
}

namespace brash::liggghts {

class FixBrashHullSplit : public LAMMPS_NS::Fix {
 public:
  FixBrashHullSplit(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg);

  int setmask() override;
  void init() override;
  double compute_vector(int i) override;

 private:
  void sum_contacts();

  std::string mesh_id_;
  LAMMPS_NS::FixMeshSurface* mesh_ = nullptr;
  core::HullRegions regions_;
  double x0_m_ = 0, speed_m_s_ = 0, scale_ = 1;
  core::HullSplit split_{};       // this step's, summed over the ranks
  LAMMPS_NS::bigint summed_at_ = -1;  // the step split_ belongs to
};

}  // namespace brash::liggghts
