// A LIGGGHTS deck's own particle output, read as the run's snapshots when the folder has no particles/index.csv:
// `dump ID all custom N FILE id x y z radius [vx vy vz ...]` (radius, or diameter), one file per snapshot (a '*'
// in FILE: LIGGGHTS writes dump.<step>...). The files are found in the run folder and its sub-folders by their
// first line, "ITEM: TIMESTEP". Time t = step x the case's run.timestep_s; the hull's aft perpendicular at
// hull.start_x_m + ship.speed_m_s t; submerged_fraction from the sphere's immersion below water.level_m (what
// brash's own snapshots hold); ca and velocities that the dump does not give are NaN (nothing measured).
#pragma once
#include <filesystem>
#include <vector>

#include <brash/post/particles.hpp>

namespace brash::post {

struct NativeDumpFrame {  // case values that turn a dump's steps into the run's snapshots
  double timestep_s = 0, hull_start_x_m = 0, speed_m_s = 0, water_level_m = 0;
};

// Does the file start with "ITEM: TIMESTEP"?
bool is_native_dump(const std::filesystem::path& file);

// The native dump files under run_dir (particles/, paraview/, post/ and restart/ left out), as snapshot entries in
// step order (entry.native set). InputError naming the file for a dump without a TIMESTEP number.
std::vector<SnapshotEntry> native_dump_index(const std::filesystem::path& run_dir, const NativeDumpFrame& frame);

// One snapshot of a dump file; InputError naming the file and line for a missing column (id, x, y, z, radius or
// diameter), a number that does not parse, a count that differs from NUMBER OF ATOMS, or a second TIMESTEP.
Snapshot read_native_dump(const std::filesystem::path& file, double water_level_m);

}  // namespace brash::post
