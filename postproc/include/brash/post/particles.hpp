// Particle snapshots of a run: particles/index.csv (step,t_s,file,hull_x_m) and
// particles/particles_<step>.csv (id,x,y,z,radius,vx,vy,vz,submerged_fraction,ca_x,ca_y,ca_z[,active[,state]]
// [,hull_fx_N,hull_fy_N,hull_fz_N]: active is 1 for an integrated piece, 0 for idle far-field ice; files without it
// (YADE) are read too; state, in the snapshots of a run with the moving window, is 0 for a piece in the scene, 1 for
// one held out ahead, 2 for one removed: every statistic reads the pieces in the scene only, the pictures every
// piece; hull_f*_N, where an engine writes them, the force of the piece on the hull at the snapshot).
#pragma once
#include <cstdint>
#include <filesystem>
#include <vector>

namespace brash::post {

struct SnapshotEntry {
  long long step = 0;
  double t_s = 0;
  std::filesystem::path file;  // absolute (particles dir / file)
  double hull_x_m = 0;         // x of the hull's aft perpendicular at t_s (channel frame)
  bool native = false;         // a LIGGGHTS dump custom file (brash/post/native_dump.hpp), not brash's CSV
  double water_level_m = 0;    // for a native dump: the level its submerged fractions are computed against
};

struct Snapshot {
  std::vector<std::int64_t> id;
  std::vector<double> x, y, z, radius, vx, vy, vz, submerged_fraction, ca_x, ca_y, ca_z;
  std::vector<std::uint8_t> active;  // 1 integrated, 0 idle; empty when the file has no active column
  std::vector<std::uint8_t> state;   // kScene, kHeldOut, kRemoved; empty when the file has no state column
  // the force of each piece on the hull [N]; empty when the file has no hull_f*_N columns (with_hull_force false)
  std::vector<double> hull_fx_N, hull_fy_N, hull_fz_N;
  bool with_hull_force = false;
  std::size_t size() const { return id.size(); }
  bool tail_dropped = false;
};

// Entries in file order. Missing index.csv: empty list. `run_in_progress` drops an unterminated
// last line. Entries whose snapshot file does not exist are kept (the caller decides).
std::vector<SnapshotEntry> read_snapshot_index(const std::filesystem::path& particles_dir, bool run_in_progress);

// The state column's codes (the moving window, speedups.moving_window): in the scene; held out (the bed ahead, not
// yet in the scene: where the packing has it, at rest); removed (gone behind the stern or through the channel's
// ends: where it was last seen, at rest).
inline constexpr std::uint8_t kScene = 0, kHeldOut = 1, kRemoved = 2;

// Which pieces a snapshot is read with: those in the scene (what every statistic uses: the snapshot as the engine
// had it), or every piece of the channel, those outside the scene too (the pictures).
enum class Pieces { Scene, All };

// Strict reader; InputError naming file and line.
Snapshot read_snapshot(const std::filesystem::path& file, bool run_in_progress, Pieces pieces = Pieces::Scene);
// The snapshot of an entry, brash's CSV or a native dump.
Snapshot read_snapshot(const SnapshotEntry& entry, bool run_in_progress, Pieces pieces = Pieces::Scene);

// Does the ice stay within the hull's contact band (hull.band_m)? Below the band's lower edge the contact hull has
// no triangles, so a piece pushed deeper beside the hull loses its hull contacts there (the guard only stops a run
// once a piece is half inside the closed hull). Over every snapshot: the deepest piece bottom below the waterline,
// and the most pieces at once whose bottom is below the band's edge.
struct BandCheck {
  double band_below_m = 0;           // hull.band_m[0]
  double deepest_bottom_m = 0;       // max over snapshots of (water level - (z - r)), 0 if no piece is submerged
  double deepest_t_s = 0;            // snapshot time of that piece
  std::size_t pieces_below_max = 0;  // most pieces at once with their bottom below the band's edge
  double pieces_below_t_s = 0;
  std::size_t snapshots = 0;         // snapshots read
  bool passed_under() const { return pieces_below_max > 0; }
};
// Snapshots whose file is missing are skipped.
BandCheck check_contact_band(const std::vector<SnapshotEntry>& entries, double band_below_m, double water_level_m,
                             bool run_in_progress);

// Indices of the entries nearest to each requested time (duplicates removed, order kept).
std::vector<std::size_t> nearest_snapshots(const std::vector<SnapshotEntry>& entries, const std::vector<double>& times_s);

}  // namespace brash::post
