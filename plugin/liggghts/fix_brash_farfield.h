/* fix brash/farfield: idle far-field ice (docs/performance.md, switch speedups.farfield).

   fix ID group-ID brash/farfield every N ahead A behind B [beside H] hull_x0 X0 speed U bow_offset LB stern_offset LS
                                  [wake_force F [wake_speed V] | wake_neighbour_speed V] [active GROUP] [idle GROUP]

   Bow at x = X0 + LB + U t, stern at x = X0 + LS + U t (t = step * dt, the hull moving at U along +x from
   X0 at step 0, as fix move/mesh linear does). Every N steps, atoms of group-ID more than A ahead of the bow
   or more than B behind the stern are idle: removed from group `active` [active], added to group `idle`
   [idle], their velocity and angular velocity set to zero; the others are put back. Both groups must exist
   (e.g. `group active type 1`, `group idle subtract all all`). The scene integrates, and applies gravity and
   fluid forces to, group `active` only, and excludes idle-idle pairs with `neigh_modify exclude group idle
   idle`; active-idle contacts are still computed (an idle piece is an immovable neighbour until the ship
   comes within A of it). beside H (m): atoms with |y| > H (beside the hull, between it and the channel walls; the
   hull's centre line at y = 0) are outside the window too, and go idle as behind the stern; default: none.

   wake_force F (N), wake_speed V (m/s) (default 0 = off: the window alone). The window alone is not enough
   when the ship's push travels further than A through the ice (a packed bed pushed ahead of the bow: an idle
   wall A ahead of it jams the bed and raises the resistance, +19 % on cases/jbc_narrow). With wake_force, an idle
   piece wakes as soon as the horizontal force on it (from active neighbours and walls: idle pieces get no
   gravity or fluid force) exceeds F (END_OF_STEP, where f of a local atom is complete with newton off; its pairs
   with idle neighbours, excluded until then, are in the neighbour list from a build forced within 10 steps,
   one Allreduce per step tells every rank). Ahead of the bow a woken piece stays active (re-freezing slow pieces
   of a loaded bed would jam it again); behind the stern a piece goes idle once slower than V. At setup (new or
   resumed run) a piece outside the window is idle when slower than V.

   wake_neighbour_speed V (m/s): instead of the force, an idle piece touched by a piece faster than V (the pair
   style's neighbour list: active-idle pairs; an idle piece has v = 0) wakes at the next neighbour build, forced
   within 10 steps, which then lists its pairs with its idle neighbours; V is also the speed of the membership
   rule above. The force rule wakes a bed at rest through its resting contacts (an idle piece's idle-idle contacts
   are not computed, so one next to active pieces feels an unbalanced force); this rule leaves a resting bed idle
   and wakes the ice the push moves. The idle ice is then the ice the
   disturbance has not reached (tests/liggghts/test_farfield.cpp: a pushed chain moves as without the fix).
   The window, the wake test and the membership rule are brash::core's (brash/core/far_field.hpp), the same
   that brash-ode --cull applies; this fix adds the LIGGGHTS side (groups, masks, neighbour builds, ranks).

   Hooks: PRE_EXCHANGE, and END_OF_STEP (wake_force) or PRE_FORCE (wake_neighbour_speed: every local and ghost
   piece has its half-step velocity there). The mask bits are changed right before the
   exchange/borders of a neighbour-list build, so ghost copies carry the new bits and the same build applies the
   exclusion; a re-neighbour is forced every N steps (next_reneighbor). Not a POST_FORCE fix (fix icefluid stays last).
   Global vector (f_ID[1..2]): number of idle atoms, number of membership changes at the last update.
*/
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "brash/core/far_field.hpp"
#include "fix.h"
#include "fix_support.h"

namespace brash::liggghts {

class FixBrashFarfield : public LAMMPS_NS::Fix {
 public:
  FixBrashFarfield(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg);

  int setmask() override;
  void init() override;
  void setup_pre_exchange() override;
  void pre_exchange() override;
  void end_of_step() override;
  void pre_force(int vflag) override;
  double compute_vector(int i) override;

 private:
  void update_membership(bool setup);
  int wake_pushed_pieces();
  int mark_touched_by_fast_pieces();
  void wake_marked_pieces();
  void request_build(int any_local);
  brash::core::WakeRule wake_rule() const {
    return {wake_force_, wake_speed_, by_neighbour_ ? brash::WakeBy::NeighbourSpeed : brash::WakeBy::Force};
  }

  static constexpr int kWakeBuildSteps = 10;  // a woken piece meets its idle neighbours within this many steps
  LAMMPS_NS::bigint next_update_ = 0;

  int every_ = 100;
  double ahead_ = 1.0, behind_ = 1.0;
  double beside_half_width_m_ = std::numeric_limits<double>::infinity();  // |y| beyond this: beside the hull
  HullTrack track_;
  int active_bit_ = 0, idle_bit_ = 0;
  std::string active_name_ = "active", idle_name_ = "idle";
  bool have_ahead_ = false, have_behind_ = false;
  double wake_speed_ = 0;           // m/s; 0: no speed test
  double wake_force_ = 0;           // N; 0: idle pieces never wake by force
  bool have_wake_force_ = false;
  bool by_neighbour_ = false;       // wake_neighbour_speed: wake_speed_ is the speed that wakes
  std::vector<char> marked_;        // by local index: to wake at the next build (neighbour speed)
  double n_idle_ = 0, n_changed_ = 0;
};

}  // namespace brash::liggghts
