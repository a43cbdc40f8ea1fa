/* fix brash/farfield: idle far-field ice (docs/performance.md, switch speedups.farfield).

   fix ID group-ID brash/farfield every N ahead A behind B hull_x0 X0 speed U bow_offset LB stern_offset LS
                                  [active GROUP] [idle GROUP]

   Bow at x = X0 + LB + U t, stern at x = X0 + LS + U t (t = step * dt, the hull moving at U along +x from
   X0 at step 0, as fix move/mesh linear does). Every N steps, atoms of group-ID more than A ahead of the bow
   or more than B behind the stern are idle: removed from group `active` [active], added to group `idle`
   [idle], their velocity and angular velocity set to zero; the others are put back. Both groups must exist
   (e.g. `group active type 1`, `group idle subtract all all`). The scene integrates, and applies gravity and
   fluid forces to, group `active` only, and excludes idle-idle pairs with `neigh_modify exclude group idle
   idle`; active-idle contacts are still computed (an idle piece is an immovable neighbour until the ship
   comes within A of it).

   Hooks: PRE_EXCHANGE. The mask bits are changed right before the exchange/borders of a neighbour-list
   build, so ghost copies carry the new bits and the same build applies the exclusion; a re-neighbour is
   forced every N steps (next_reneighbor). Not a POST_FORCE fix (fix icefluid stays last).
   Global vector (f_ID[1..2]): number of idle atoms, number of membership changes at the last update.
*/
#pragma once

#include <string>

#include "fix.h"

namespace brash::liggghts {

class FixBrashFarfield : public LAMMPS_NS::Fix {
 public:
  FixBrashFarfield(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg);

  int setmask() override;
  void init() override;
  void setup_pre_exchange() override;
  void pre_exchange() override;
  double compute_vector(int i) override;

 private:
  void update_membership();

  int every_ = 100;
  double ahead_ = 1.0, behind_ = 1.0, hull_x0_ = 0.0, speed_ = 0.0, bow_offset_ = 0.0, stern_offset_ = 0.0;
  int active_bit_ = 0, idle_bit_ = 0;
  std::string active_name_ = "active", idle_name_ = "idle";
  bool have_ahead_ = false, have_behind_ = false, have_x0_ = false, have_speed_ = false, have_bow_ = false,
       have_stern_ = false;
  double n_idle_ = 0, n_changed_ = 0;
};

}  // namespace brash::liggghts
