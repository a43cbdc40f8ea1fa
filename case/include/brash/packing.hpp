// Channel packing generator: a bed of ice spheres (normally distributed diameters) in the channel
// [0, L] x [-W/2, W/2], deposited geometrically and shifted vertically to floating equilibrium.
//
// Algorithm ("lowest of K drops, then roll into the pocket"): each new sphere is dropped at K random
// (x, y) positions onto the bed (floor z = 0 plus the spheres already placed); the lowest landing
// point is then improved by a pattern search on the landing height, which ends where the sphere
// rests in a pocket of the spheres below (or on the floor / against a wall). Spheres therefore never
// overlap (up to rounding) and the bed fills from the bottom up in irregular layers. A 2-D cell grid
// of columns (cell >= largest diameter) keeps every query local. Finally the whole bed is shifted in z
// so that the buoyancy of the submerged caps equals the total weight (water level from the case);
// individual spheres rest on each other, the engine's DEM settle does the rest.
//
// Modes: volume (default) places the ice volume (1 - porosity) L W thickness and reports the
// natural thickness; strict_two_layer fills the slab [0, thickness] (thickness between d_max and
// 3 d_min) until the requested volume is reached or no sphere fits any more, and reports the porosity.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "brash/case.hpp"

namespace brash {

struct Sphere {
  double x_m = 0, y_m = 0, z_m = 0, diameter_m = 0;
};

// Everything the generator needs, taken from a Case (packing_request) or set directly in tests.
struct PackingRequest {
  double length_m = 21.0, width_m = 2.25, thickness_m = 0.03515;
  double diameter_mean_m = 0.017578, diameter_sd_m = 0.00087890, truncation_sd = 3.0;
  double porosity = 0.28;
  double ice_density_kg_m3 = 900, water_density_kg_m3 = 1000, water_level_m = 0;
  PackingMode mode = PackingMode::Volume;
  std::uint64_t seed = 1;
  int drops_per_sphere = 8;  // K: random drop positions tried per sphere
  std::string source;        // case file name, for error messages
};

PackingRequest packing_request(const Case& c, const std::string& source);

struct PackingStats {
  std::string mode;
  std::uint64_t seed = 0;
  std::size_t count = 0;
  double requested_porosity = 0;
  double target_ice_volume_m3 = 0;       // (1 - porosity) L W thickness
  double ice_volume_m3 = 0;              // placed
  double ice_volume_per_area_m = 0;      // placed volume / (L W)
  double thickness_m = 0;                // volume: mean over 2 d columns of the highest sphere top - lowest bottom;
                                         // strict_two_layer: the slab thickness
  double porosity = 0;                   // 1 - ice volume / (L W thickness_m)
  double bulk_solid_fraction = 0;        // mean area fraction of horizontal sections in the bed's interior
  double equivalent_thickness_m = 0;     // ice volume per area / bulk solid fraction
  double bottom_z_m = 0, top_z_m = 0;    // lowest sphere bottom, highest sphere top (after the shift)
  double d_mean_m = 0, d_sd_m = 0, d_min_m = 0, d_max_m = 0;
  double max_overlap_over_d = 0;         // max (r_i + r_j - |c_i - c_j|) / d_mean over all pairs (<= 0: none)
  std::size_t overlapping_pairs = 0;     // pairs overlapping by more than overlap_tolerance_over_d
  double overlap_tolerance_over_d = 0;
  double max_wall_overlap_over_d = 0;    // how far a sphere pokes through a side or end wall (<= 0: none)
  double mean_contacts = 0;              // touching neighbours per sphere (gap < 1e-6 d)
  double buoyancy_N = 0, weight_N = 0;   // after the floating shift, water level from the request
  double float_shift_m = 0;              // z shift applied to the deposited bed
  double wall_time_s = 0;
};

struct Packing {
  std::vector<Sphere> spheres;
  PackingStats stats;
};

// Throws InputError (naming request.source and the case key) for requests that cannot be met.
void validate_packing_request(const PackingRequest& r);

// Deterministic for r.seed (own uniform and Box-Muller normal sampler on std::mt19937_64).
Packing generate_packing(const PackingRequest& r);

// Statistics of any bed (also used on a bed read back from a file). wall_time_s is left 0.
PackingStats measure_packing(const std::vector<Sphere>& s, const PackingRequest& r);

// Total buoyancy of the submerged caps and total weight [N] for water level r.water_level_m.
double total_buoyancy_N(const std::vector<Sphere>& s, const PackingRequest& r);
double total_weight_N(const std::vector<Sphere>& s, const PackingRequest& r);

// Files: CSV "id,x,y,z,diameter" (m) preceded by one '#' line with the stats; JSON with the stats.
// Both written atomically (temporary file + rename).
std::string packing_csv(const Packing& p);
void write_packing_csv(const std::filesystem::path& file, const Packing& p);
std::string packing_json(const PackingStats& s);
void write_packing_json(const std::filesystem::path& file, const PackingStats& s);
// Reads a packing CSV (skipping '#' lines and the header); InputError naming file and line on error
// (a value that is not a finite number, a diameter <= 0, an id given twice, overlapping pieces).
std::vector<Sphere> read_packing_csv(const std::filesystem::path& file);

// What a case's packing must hold besides: every piece inside the channel [0, L] x [-W/2, W/2] (a piece may poke
// through a wall or an end by this fraction of its diameter: brash-pack's 9-decimal rounding, <= 5e-10 m), no piece
// whose bottom is more than this many ice.diameter_mean_m above the water (brash-pack's beds at floating equilibrium:
// at most 0.22 d_mean in the repository's cases), none whose centre is more than this many ice.thickness_m below it
// (theirs: at most 1.3; the guards' domain reaches at least 6 thicknesses down, their zmax 5 up).
inline constexpr double kPackingChannelToleranceOverD = 1e-4;
inline constexpr double kPackingMaxBottomAboveWaterOverD = 1.0;
inline constexpr double kPackingMaxCentreBelowWaterOverThickness = 5.0;

// Largest overlap of two pieces a packing file may hold, as a fraction of the smaller diameter: a generated packing
// (< 1e-6 d; a DEM engine would start with a huge contact force at a larger one), and a settled bed (ice.settle,
// brash/run/settle.hpp), whose pieces rest in contact: Hertz overlaps under a piece's weight are ~0.8 % of d at the
// paper case's E / 16, 2 % at E / 64 (docs/performance.md, "Softer contacts").
inline constexpr double kPackingMaxOverlapOverD = 1e-4;
inline constexpr double kSettledBedMaxOverlapOverD = 0.05;

// Reads the case's packing (c.ice.packing_file) as read_packing_csv and checks every piece against the case as above:
// InputError naming the packing file, the line, the piece and the case key. Every engine runner reads its packing
// through this, before it makes the run directory.
std::vector<Sphere> read_case_packing(const Case& c, double max_overlap_over_d = kPackingMaxOverlapOverD);

}  // namespace brash
