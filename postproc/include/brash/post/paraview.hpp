// ParaView output through VTK's XML writers: particle and hull time series as .pvd collections.
// Files are VTK XML *unstructured grids* (.vtu, vtkXMLUnstructuredGridWriter; particles as vertex
// cells) rather than poly data (.vtp): ParaView reads both, but meshio 7 (Debian's python3-meshio)
// reads only .vtu, and the data must be readable by both.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <brash/post/particles.hpp>
#include <brash/post/post_case.hpp>

namespace brash::post {

// Hull surface in the hull frame (x forward, keel at z = 0) as flat arrays.
struct HullSurface {
  std::vector<double> xyz;     // 3 per vertex
  std::vector<long long> tri;  // 3 per triangle
};

// The case hull (via brash_hull), empty if unavailable (note added).
std::optional<HullSurface> load_case_hull(const PostCase& c, std::vector<std::string>& notes);

struct ParaviewOutput {
  std::filesystem::path particles_pvd, hull_pvd;  // hull_pvd empty if no hull
  std::size_t snapshots = 0;
};

// Writes <run>/paraview/particles_<step>.vtu (point fields radius, velocity[3], submerged_fraction,
// ca[3], id, and active where the snapshot has it), <run>/paraview/hull_<step>.vtu (hull moved to the channel frame: x + hull_x_m,
// z - draft + water level) and <run>/particles.pvd, <run>/hull.pvd. Every file is written atomically.
// Snapshots whose file is missing are skipped with a note.
ParaviewOutput write_paraview(const std::filesystem::path& run_dir, const std::vector<SnapshotEntry>& entries,
                              const std::optional<HullSurface>& hull, const PostCase& c, bool run_in_progress,
                              std::vector<std::string>& notes);

// <run>/hull.vtu: the case hull in its own frame with the window's cell data of the ice around it
// (ice_around_hull.hpp): contact_fraction, and contact_pressure_Pa where the snapshots carry the hull forces.
std::filesystem::path write_hull_contact_field(const std::filesystem::path& run_dir, const HullSurface& hull,
                                               const std::vector<double>& contact_fraction,
                                               const std::vector<double>& contact_pressure_Pa);

// The .pvd collection text (file names relative to the .pvd's folder).
std::string pvd_text(const std::vector<std::pair<double, std::string>>& time_and_file);

}  // namespace brash::post
