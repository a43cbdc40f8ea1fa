// PNG plots with gnuplot (pngcairo): each plot writes a data file and a script into a work folder,
// runs gnuplot as a subprocess (exit status checked) into a temp PNG and renames it into place.
#pragma once
#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <brash/post/particles.hpp>
#include <brash/post/report.hpp>

namespace brash::post {

// Runs `gnuplot script`; std::runtime_error with the log tail when gnuplot fails or is missing.
void run_gnuplot(const std::filesystem::path& script);

// Fig. 5 analog: fx, fy, fz of the ice on the hull vs time, averaging window shaded, mean marked.
std::filesystem::path plot_force_history(const RunAnalysis& a, const std::filesystem::path& out_dir,
                                         const std::filesystem::path& work_dir);

// Fig. 6 analog: full-scale resistance of the simulation (with CI) vs FSICR R_CH, paper values beside.
std::filesystem::path plot_resistance_bars(const RunAnalysis& a, const std::filesystem::path& out_dir,
                                           const std::filesystem::path& work_dir);

// The hull's waterline from its mesh (mesh frame: x forward, keel at z = 0, the water at z = draft_m) as a closed
// outline: the half-breadth at the waterline at 241 stations over the mesh's length, starboard aft to fore, port
// fore to aft. Empty when the mesh cannot be read (or brash-post is built without the hull library).
std::vector<std::array<double, 2>> hull_waterline(const std::filesystem::path& hull_file, double draft_m);

// Fig. 4 analog: top view (coloured by speed, topmost drawn last) and bottom view (coloured by
// submerged fraction, lowest drawn last) of the ice around the hull at one snapshot, with the hull's waterline
// (hull_waterline, placed at the snapshot's hull position) or, without one, its Lpp x B rectangle.
std::filesystem::path plot_ice_views(const Snapshot& s, const SnapshotEntry& e, const PostCase& c,
                                     const std::filesystem::path& out_dir, const std::filesystem::path& work_dir,
                                     const std::vector<std::array<double, 2>>& waterline = {});

// The ice around the hull (a.ice_around, which must be set): the brash thickness ahead of the stem against the
// distance ahead, with FSICR's H_F at model scale and the case's ice.thickness_m as lines, and beside the hull
// against the hull frame's x. ice_around_hull.png.
std::filesystem::path plot_ice_around_hull(const RunAnalysis& a, const std::filesystem::path& out_dir,
                                           const std::filesystem::path& work_dir);

struct CompareRow {
  std::string run, engine, fluid_model;
  double speed_m_s = 0;
  double duration_s = NAN;                      // the record's last sample (model time run)
  std::array<double, 2> window_s{NAN, NAN};     // the window averaged (after any shortening)
  double mean_N = NAN, ci95_N = NAN, full_kN = NAN, full_ci95_kN = NAN;  // NaN: the run's hull met no ice
  bool met_no_ice = false;
  double R_CH_kN = NAN, ratio = NAN;
  double reference_full_kN = NAN;  // the case's published resistance for this fluid model (NaN: none declared)
  bool complete = false;
};
CompareRow compare_row(const RunAnalysis& a);
std::string compare_markdown(const std::vector<CompareRow>& rows);
std::string compare_csv(const std::vector<CompareRow>& rows);
// Bar chart of the full-scale resistance per run (with CI) and FSICR R_CH.
std::filesystem::path plot_compare(const std::vector<CompareRow>& rows, const std::filesystem::path& out_dir,
                                   const std::filesystem::path& work_dir);

}  // namespace brash::post
