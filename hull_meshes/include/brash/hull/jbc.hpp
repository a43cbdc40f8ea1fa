// JBC (JAPAN Bulk Carrier) hull generator: a closed, outward STL built from the 1:40 offsets table and
// centre-plane profile in hull_meshes/data/, scaled to any length. Data: NMRI, Tokyo 2015 CFD workshop.
#pragma once
#include <brash/hull/mesh.hpp>

#include <Eigen/Core>
#include <filesystem>
#include <utility>
#include <vector>

namespace brash::hull {

// The data as stored: model scale 1:40, metres, x from AP (bow +x), z from the baseline.
struct JbcData {
  static constexpr double lpp_m = 7.0, beam_m = 1.125, draft_m = 0.4125, depth_m = 0.625;
  std::vector<double> station_x_m;    // offsets stations, increasing
  std::vector<double> waterline_z_m;  // offsets waterlines, increasing
  Eigen::MatrixXd half_breadth_m;     // (station, waterline); 0 where there is no hull
  std::vector<double> profile_x_m;    // profile stations, increasing
  std::vector<std::vector<std::pair<double, double>>> profile_z_m;  // per station: [z_bottom, z_top] intervals
};

// Folder of the data files: <data>/hull_meshes/data (brash/paths.hpp; the repository's hull_meshes/data).
std::filesystem::path default_jbc_data_dir();

// Reads jbc_offsets_1to40.csv and jbc_profile_1to40.csv; throws brash::InputError naming the file.
JbcData load_jbc_data(const std::filesystem::path& dir = default_jbc_data_dir());

struct JbcOptions {
  double lpp_m = JbcData::lpp_m;  // geometric scaling: every length times lpp_m / 7.0
  double grid_factor = 1.0;       // multiplies every grid spacing (smaller = finer mesh)
};

// Builds the hull: half-breadth sheets y = +-Y(x, z) over an (x, z) grid clipped to the profile
// (marching squares, boundary points found by bisection), closed by strips from -Y to +Y along the
// profile boundary (flat bottom, transom, boss end, deck lid at z = depth). Y interpolates the offsets
// with monotone cubic (PCHIP) splines along x, then along z.
Mesh make_jbc(const JbcData& data, const JbcOptions& options = {});

}  // namespace brash::hull
