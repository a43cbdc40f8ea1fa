/* fix brash/window: the moving window (docs/performance.md "The moving window", switch speedups.window). Only
   the ice around the hull is in the scene: the undisturbed bed ahead is held out until the front reaches it,
   the ice far behind the stern is removed, so the channel's length no longer sets the cost of a step.

   fix ID group-ID brash/window every N ahead A behind B hull_x0 X0 speed U bow_offset LB stern_offset LS
                                [moving_speed V]

   Bow at x = X0 + LB + U t, stern at x = X0 + LS + U t, as in fix brash/farfield. The front lies A (m) ahead
   of the bow and ahead of the foremost piece of group-ID faster than V (m/s, default 0.005: the push through
   the bed), and never recedes (brash::core::moving_window).
   - At a run's set-up, every atom of group-ID beyond the front is held out: its id, type, group mask,
   position, radius, mass and density are kept (the same list on every rank, sorted along x) and the atom is
   deleted. A held-out piece is at rest, where it was: this suits a settled bed (ice.settle), which is at
   rest.
   - Every N steps (a neighbour build is forced then), held-out pieces behind the front enter the scene at
   rest with their own id, type, groups and properties (each on the rank whose sub-domain holds it, fixes with
     per-atom data initialised as LIGGGHTS' own insertion does), and atoms of group-ID more than B behind the
     stern are deleted for good.
   The held-out list, the front and the counts are in the restart file (a resumed run holds out nothing
   again). Atoms are added and deleted at PRE_EXCHANGE, as fix brash/exit and LIGGGHTS' insertion do; fix
   brash/exit, if defined, is told of every change (it checks that no atom is lost otherwise). Define this fix
   after fix brash/farfield: the far field's marks are by local index and are used at the same build, before
   atoms move. Global vector (f_ID[1..3]): pieces held out now, pieces removed behind the stern so far, the
   front's x (m).
*/
#pragma once

#include <vector>

#include "brash/core/far_field.hpp"
#include "fix.h"
#include "fix_support.h"

namespace brash::liggghts {

class FixBrashExit;

class FixBrashWindow : public LAMMPS_NS::Fix {
 public:
  FixBrashWindow(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg);

  int setmask() override;
  void init() override;
  void setup_pre_exchange() override;
  void pre_exchange() override;
  double compute_vector(int i) override;
  void write_restart(FILE* fp) override;
  void restart(char* buf) override;

 private:
  // one held-out piece, as doubles (ids and masks are exact below 2^53): the restart file's and MPI's unit
  struct HeldPiece {
    double tag, type, mask, x, y, z, radius, rmass, density;
  };
  static constexpr int kDoublesPerPiece = sizeof(HeldPiece) / sizeof(double);

  brash::core::MovingWindow window_now(double t_s) const;  // at model time t; the front from all ranks
  void hold_out_beyond(double front_x_m);
  long long insert_before(double front_x_m);
  long long remove_behind(double x_m);
  void atoms_changed(long long added, long long deleted);  // on every rank, counts from all ranks

  int every_ = 100;
  double ahead_ = 1.0, behind_ = 2.0;
  HullTrack track_;
  double moving_speed_ = 0.005;
  bool have_ahead_ = false, have_behind_ = false;
  FixBrashExit* exit_ = nullptr;
  LAMMPS_NS::bigint next_update_ = 0;

  std::vector<HeldPiece> held_;  // sorted along x; [next_held_, end) are still held out
  std::size_t next_held_ = 0;
  double front_x_m_;              // -infinity before the first set-up
  double removed_ = 0;            // pieces removed behind the stern since the run started
  bool holding_started_ = false;  // the list is made (at the first set-up) or read from a restart file
};

}  // namespace brash::liggghts
