// fix brash/exit: see fix_brash_exit.h.
#include "fix_brash_exit.h"

#include <fmt/format.h>
#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "atom.h"
#include "atom_vec.h"
#include "comm.h"
#include "error.h"
#include "fix_support.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace brash::liggghts {

FixBrashExit::FixBrashExit(LAMMPS* lmp, int narg, char** arg) : Fix(lmp, narg, arg) {
  bool have_lo = false, have_hi = false;
  for (int i = 3; i < narg; i += 2) {
    const std::string key = arg[i];
    if (i + 1 >= narg)
      error->all(FLERR, fmt::format("fix brash/exit: keyword {} needs a value", key).c_str());
    char* end = nullptr;
    const double v = std::strtod(arg[i + 1], &end);
    if (end == arg[i + 1] || *end != '\0')
      error->all(FLERR, fmt::format("fix brash/exit: {} {}: not a number", key, arg[i + 1]).c_str());
    if (key == "xlo")
      xlo_ = v, have_lo = true;
    else if (key == "xhi")
      xhi_ = v, have_hi = true;
    else
      error->all(FLERR, fmt::format("fix brash/exit: unknown keyword {} (expected xlo, xhi)", key).c_str());
  }
  if (!have_lo || !have_hi) error->all(FLERR, "fix brash/exit: needs xlo XLO xhi XHI");
  if (!(xlo_ < xhi_))
    error->all(FLERR, fmt::format("fix brash/exit: xlo {} must be below xhi {}", xlo_, xhi_).c_str());
  scalar_flag = 1;
  global_freq = 1;
  extscalar = 0;
  restart_global = 1;
}

int FixBrashExit::setmask() {
  return PRE_EXCHANGE;
}

void FixBrashExit::setup_pre_exchange() {
  expected_atoms_ = count_atoms();
}

long long FixBrashExit::count_atoms() const {
  long long mine = atom->nlocal, all = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_LONG_LONG, MPI_SUM, world);
  return all;
}

void FixBrashExit::post_run() {
  check_no_atom_lost();
}

void FixBrashExit::check_no_atom_lost() {
  const long long now = count_atoms();
  if (now != expected_atoms_)
    error->all(
        FLERR,
        fmt::format("fix brash/exit: step {}: {} atom(s) lost: they left the box elsewhere than through "
                    "the channel's ends (bad dynamics; fix brash/guard checks more often with a "
                    "smaller every)",
                    update->ntimestep, expected_atoms_ - now)
            .c_str());
}

void FixBrashExit::pre_exchange() {
  // Every atom must still be on some rank: LIGGGHTS drops an atom outside a fixed boundary at an exchange
  // (and re-counts natoms at thermo output under `thermo_modify lost ignore`, which the runner sets because
  // `lost error` counts against the run's initial number after a read_restart). So the count is kept here,
  // from the run's set-up on (and checked at its end too), and an atom gone elsewhere than through the ends
  // stops the run.
  check_no_atom_lost();
  const int removed = delete_local_atoms(atom, [&](int i) {
    const double x = atom->x[i][0];
    return (atom->mask[i] & groupbit) && (x < xlo_ || x > xhi_);
  });
  int removed_all = 0;
  MPI_Allreduce(&removed, &removed_all, 1, MPI_INT, MPI_SUM, world);
  if (removed_all == 0) return;
  recount_atoms(atom, world);
  removed_total_ += removed_all;
  expected_atoms_ -= removed_all;
  if (comm->me == 0) {
    const std::string msg = fmt::format(
        "fix brash/exit: step {}: {} piece(s) left the scene through the channel's ends (x < {:g} or x > "
        "{:g} m); "
        "{:.0f} in all\n",
        update->ntimestep, removed_all, xlo_, xhi_, removed_total_);
    if (screen) std::fputs(msg.c_str(), screen);
    if (logfile) std::fputs(msg.c_str(), logfile);
  }
}

double FixBrashExit::compute_scalar() {
  return removed_total_;
}

void FixBrashExit::write_restart(FILE* fp) {
  if (comm->me != 0) return;
  const int size = sizeof(double);
  std::fwrite(&size, sizeof(int), 1, fp);
  std::fwrite(&removed_total_, sizeof(double), 1, fp);
}

void FixBrashExit::restart(char* buf) {
  std::memcpy(&removed_total_, buf, sizeof(double));
}

}  // namespace brash::liggghts
