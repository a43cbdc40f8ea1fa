// brash-liggghts: the stock LIGGGHTS front end (same command-line options: -in, -var, -log, -screen,
// -echo, -partition, -suffix ...) with brash's styles registered. Runs under mpirun -np N.
#include <mpi.h>

#include <cstdio>
#include <cstring>

#include "fix_brash_exit.h"
#include "fix_brash_farfield.h"
#include "fix_brash_guard.h"
#include "fix_brash_hullsplit.h"
#include "fix_brash_window.h"
#include "fix_icefluid.h"
#include "input.h"
#include "lammps.h"
#include "register_style.h"

namespace {

using brash::liggghts::make_fix;

// brash's fix styles: registered with every LAMMPS object and listed by -h (doc pages: plugin/liggghts/doc/).
struct BrashFix {
  const char* style;
  brash::liggghts::FixCreatorFn creator;
};
constexpr BrashFix kBrashFixes[] = {
    {"icefluid", &make_fix<brash::liggghts::FixIceFluid>},
    {"brash/farfield", &make_fix<brash::liggghts::FixBrashFarfield>},
    {"brash/guard", &make_fix<brash::liggghts::FixBrashGuard>},
    {"brash/exit", &make_fix<brash::liggghts::FixBrashExit>},
    {"brash/window", &make_fix<brash::liggghts::FixBrashWindow>},
    {"brash/hullsplit", &make_fix<brash::liggghts::FixBrashHullSplit>},
};

bool asks_for_help(int argc, char** argv) {
  for (int i = 1; i < argc; i++)
    if (std::strcmp(argv[i], "-h") == 0 || std::strcmp(argv[i], "-help") == 0) return true;
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  // Line-buffered screen: error->one ends in MPI_Abort without flushing, which would swallow the
  // ERROR message (and everything before it) whenever stdout is a pipe or a file.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  MPI_Init(&argc, &argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  for (int i = 1; i < argc; i++) {
    if (std::strcmp(argv[i], "--version") == 0 || std::strcmp(argv[i], "-V") == 0) {
      std::printf("brash-liggghts (LIGGGHTS 3.8.0 library + fix icefluid)\n");
      MPI_Finalize();
      return 0;
    }
  }
  // LIGGGHTS' -h prints its styles and exits inside the LAMMPS constructor, before brash's are registered: list
  // them first.
  if (asks_for_help(argc, argv) && rank == 0) {
    std::printf("brash fix styles (added to LIGGGHTS'):\n");
    for (const auto& f : kBrashFixes) std::printf("  %s", f.style);
    std::printf("\n\n");
  }
  auto* lmp = new LAMMPS_NS::LAMMPS(argc, argv, MPI_COMM_WORLD);
  for (const auto& f : kBrashFixes) brash::liggghts::register_fix_creator(lmp, f.style, f.creator);
  lmp->input->file();
  delete lmp;
  MPI_Finalize();
  return 0;
}
