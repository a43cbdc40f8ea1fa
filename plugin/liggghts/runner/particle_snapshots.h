// LIGGGHTS' particle dumps -> the run layout's particle snapshots (docs/case_format.md, "particles/"):
// particles/particles_<step>.csv and particles/index.csv.
//
// With the moving window (speedups.moving_window, fix brash/window) the engine dumps only the pieces in the scene;
// every snapshot then holds every piece of the run's packing (packing.data, the packing or its settled bed) with
// a `state` column: 0 in the scene (as dumped), 1 held out (not yet in any snapshot: where the packing has it,
// at rest), 2 removed (in an earlier snapshot, gone since: behind the stern or through the channel's ends, where
// it was last seen, at rest). Without the window the snapshots are the dumps as they are (no state column).
// A dump with the hull wall's force on each piece (f_force_hullwall) gives the snapshot's last columns
// hull_fx_N,hull_fy_N,hull_fz_N: the piece's force on the hull (0 for a piece outside the scene).
#pragma once
#include <cstddef>
#include <filesystem>

#include "brash/case.hpp"

namespace brash::liggghts {

// A piece's state in a snapshot (the `state` column of a moving window's snapshots).
enum class PieceState { Scene = 0, HeldOut = 1, Removed = 2 };

// particles/dump.* -> particles/particles_<step>.csv (the dumps are removed), then particles/index.csv of every
// snapshot; the number of dumps converted. With the moving window the earlier snapshots of a resumed run (converted
// by its earlier attempts) give the last seen positions of the pieces removed since.
std::size_t convert_dumps(const std::filesystem::path& run_dir, const Case& c);

}  // namespace brash::liggghts
