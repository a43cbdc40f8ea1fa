/* fix brash/guard: run-time guards that stop a run with a clear message instead of letting it go
   silently wrong (issue 10).

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

   Always: a non-finite (NaN/Inf) position, velocity or force component stops the run.
   Every stop is error->all naming the step, the atom id and the cause, e.g.
     ERROR: fix brash/guard: step 1200: atom 17: left the box: x = 2.31 > xhi = 2.2 (m)
   The fix is END_OF_STEP only (not POST_FORCE), so it may be defined anywhere, also before fix icefluid.
   It reads state and never changes it. Argument parsing: guard_args.h.
*/
#pragma once

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
};

}  // namespace brash::liggghts
