/* fix brash/exit: pieces that leave the scene through the channel's open ends are removed (a piece coasting
   out of the box would otherwise stop LIGGGHTS with 'ERROR: Lost atoms').

   fix ID group-ID brash/exit xlo XLO xhi XHI

   At every neighbour-list build (PRE_EXCHANGE, the hook LAMMPS' own atom deletion uses), atoms of group-ID
   with x < XLO or x > XHI (m) are deleted; the count is printed ("fix brash/exit: step N: K piece(s) left
   ...") and kept as the fix's global scalar (f_ID: pieces removed so far, kept across restarts). Why this is
   safe: the runner puts XLO and XHI inside the box guard's x range by one neighbour skin (a piece moves less
   than half a skin between builds, so it is removed before the guard or LIGGGHTS' lost-atom check see it),
   and the box's x-ends lie behind the stern's start and ahead of the bow's end position: a piece there moves
   away from a hull it can no longer reach. With the `added_mass` model (no drag, as in the paper) a piece
   knocked loose keeps its horizontal speed for ever, so such exits happen on long runs. y and z bounds stay
   guarded (an error). Deleting copies the last local atom over the removed one (AtomVec::copy, which carries
   every fix's per-atom arrays, like the exchange of atoms between ranks), then re-counts natoms and rebuilds
   the atom map.
*/
#pragma once

#include "fix.h"

namespace brash::liggghts {

class FixBrashExit : public LAMMPS_NS::Fix {
 public:
  FixBrashExit(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg);

  int setmask() override;
  void setup_pre_exchange() override;
  void pre_exchange() override;
  void post_run() override;
  double compute_scalar() override;
  // Another fix added (> 0) or removed (< 0) this many atoms on purpose (fix brash/window), at PRE_EXCHANGE.
  void expect_atoms(long long change) { expected_atoms_ += change; }
  void write_restart(FILE* fp) override;
  void restart(char* buf) override;

 private:
  double xlo_ = 0, xhi_ = 0;
  long long count_atoms() const;  // atoms on all ranks
  void check_no_atom_lost();
  double removed_total_ = 0;      // pieces removed since the run started (restart-safe)
  long long expected_atoms_ = 0;  // atoms there should be (set at each run's set-up, less those removed)
};

}  // namespace brash::liggghts
