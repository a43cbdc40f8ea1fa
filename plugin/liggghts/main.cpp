// brash-liggghts: the stock LIGGGHTS front end (same command-line options: -in, -var, -log, -screen,
// -echo, -partition, -suffix ...) with brash's styles registered. Runs under mpirun -np N.
#include <mpi.h>

#include <cstdio>
#include <cstring>

#include "fix_brash_exit.h"
#include "fix_brash_farfield.h"
#include "fix_brash_guard.h"
#include "fix_brash_window.h"
#include "fix_icefluid.h"
#include "input.h"
#include "lammps.h"
#include "register_style.h"

int main(int argc, char** argv) {
  // Line-buffered screen: error->one ends in MPI_Abort without flushing, which would swallow the
  // ERROR message (and everything before it) whenever stdout is a pipe or a file.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  MPI_Init(&argc, &argv);
  for (int i = 1; i < argc; i++) {
    if (std::strcmp(argv[i], "--version") == 0 || std::strcmp(argv[i], "-V") == 0) {
      std::printf("brash-liggghts (LIGGGHTS 3.8.0 library + fix icefluid)\n");
      MPI_Finalize();
      return 0;
    }
  }
  auto* lmp = new LAMMPS_NS::LAMMPS(argc, argv, MPI_COMM_WORLD);
  brash::liggghts::register_fix_style<brash::liggghts::FixIceFluid>(lmp, "icefluid");
  brash::liggghts::register_fix_style<brash::liggghts::FixBrashFarfield>(lmp, "brash/farfield");
  brash::liggghts::register_fix_style<brash::liggghts::FixBrashGuard>(lmp, "brash/guard");
  brash::liggghts::register_fix_style<brash::liggghts::FixBrashExit>(lmp, "brash/exit");
  brash::liggghts::register_fix_style<brash::liggghts::FixBrashWindow>(lmp, "brash/window");
  lmp->input->file();
  delete lmp;
  MPI_Finalize();
  return 0;
}
