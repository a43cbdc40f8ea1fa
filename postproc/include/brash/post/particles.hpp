// Particle snapshots of a run: particles/index.csv (step,t_s,file,hull_x_m) and
// particles/particles_<step>.csv (id,x,y,z,radius,vx,vy,vz,submerged_fraction,ca_x,ca_y,ca_z).
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
};

struct Snapshot {
  std::vector<std::int64_t> id;
  std::vector<double> x, y, z, radius, vx, vy, vz, submerged_fraction, ca_x, ca_y, ca_z;
  std::size_t size() const { return id.size(); }
  bool tail_dropped = false;
};

// Entries in file order. Missing index.csv: empty list. `run_in_progress` drops an unterminated
// last line. Entries whose snapshot file does not exist are kept (the caller decides).
std::vector<SnapshotEntry> read_snapshot_index(const std::filesystem::path& particles_dir, bool run_in_progress);

// Strict reader; InputError naming file and line.
Snapshot read_snapshot(const std::filesystem::path& file, bool run_in_progress);

// Indices of the entries nearest to each requested time (duplicates removed, order kept).
std::vector<std::size_t> nearest_snapshots(const std::vector<SnapshotEntry>& entries, const std::vector<double>& times_s);

}  // namespace brash::post
