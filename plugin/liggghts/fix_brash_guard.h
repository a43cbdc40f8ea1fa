/* fix brash/guard: run-time guards that stop a run with a clear message instead of letting it go
   silently wrong (docs/stability.md).

   fix ID group-ID brash/guard every N keyword value ...

   every N            check every N steps (required; at END_OF_STEP, after the final integration)
   keywords (optional; a guard is on only when its keyword is given, except NaN/Inf which is always on):
     box xlo xhi ylo yhi zlo zhi   atom centres must stay inside this box (m)
     zmax Z                        atom centres must stay below z = Z (pieces jumping out of the water)
     ke_max E                      kinetic energy per atom, 1/2 m v^2 + 1/2 I w^2, must stay <= E (J)
     youngs E                      contact time-step check at every run's setup: dt <= f T_R with the
     poisson NU  [0.3]               Rayleigh time T_R = pi r sqrt(rho/G) / (0.1631 nu + 0.8766),
     density RHO [each atom's]       G = E / (2 (1 + nu)), of the atom with the smallest T_R
     rmin R      [each atom's]       (or of rmin/density when given)
     max_dt_fraction F  [0.3]
     hull FILE x0 y0 z0 vx vy vz   hull penetration: FILE is the FULL closed hull (STL, read with
                                   brash::hull::read_mesh) in its own frame; the frame's origin is at
                                   (x0, y0, z0) at time 0 and moves at (vx, vy, vz) m/s: at step n it is
                                   at x0 + v n dt, like brash-liggghts-run's fix move/mesh (read_restart
                                   restores the step counter, so this holds after a resume). A band or
                                   half hull is refused (not closed: inside/outside is undefined).
     max_penetration F  [0.5]      stop when an atom overlaps the hull by more than F x its diameter
                                   (brash::hull::Proximity::penetration: r - d outside at distance
                                   d < r, r + d with the centre inside; 0.5 = centre on the surface)

   Always: a non-finite (NaN/Inf) position, velocity, angular velocity or force component stops the run.
   The per-atom checks are brash::guard::check_piece (run/include/brash/run/guard.hpp), the same function the
   ODE and YADE paths call; this fix adds the MPI reduction (lowest offending atom id over all ranks).
   The hull query only runs for atoms within their radius of the hull's bounding box.
   Every stop is error->all naming the step, the atom id and the cause, e.g.
     ERROR: fix brash/guard: step 1200: atom 17: left the box: x = 2.31 > xhi = 2.2 (m)
     ERROR: fix brash/guard: step 3400: atom 9: hull penetration: 0.0211 m = 60 % of its diameter 0.0352 m >
            max_hull_penetration_d 0.5 (centre inside the hull, 0.00349 m from its surface; hull frame ...)
   The fix is END_OF_STEP only (not POST_FORCE), so it may be defined anywhere, also before fix icefluid.
   It reads state and never changes it. Argument parsing: guard_args.h. Doc: doc/fix_brash_guard.txt.
*/
#pragma once

#include <memory>

#include "brash/run/guard.hpp"
#include "brash/hull/proximity.hpp"
#include "fix.h"
#include "guard_args.h"

namespace brash::liggghts {

class FixBrashGuard : public LAMMPS_NS::Fix {
 public:
  FixBrashGuard(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg);

  int setmask() override;
  void init() override;
  void setup(int vflag) override;
  void end_of_step() override;

  const GuardConfig& config() const { return cfg_; }

 private:
  void check_timestep();
  void check_atoms();

  GuardConfig cfg_;
  std::unique_ptr<brash::hull::Proximity> hull_;  // the hull check's query (null without 'hull')
};

}  // namespace brash::liggghts
