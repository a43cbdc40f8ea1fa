// The ice around the hull over the report's window (docs/outputs.md, "The ice around the hull"), from the particle
// snapshots in the window: the brash thickness ahead of the bow and beside the hull (the measured counterpart of
// FSICR's H_F), the share of the wetted hull the ice touches by region, how deep the ice goes along and under the
// hull, and per hull triangle the touched share and, where the snapshots carry each piece's force on the hull, the
// mean contact pressure.
//
// Frames: the snapshots' channel frame; the hull frame of the mesh (x from the aft perpendicular, keel at z = 0): a
// piece at channel (x, y, z) is at (x - hull_x_m, y, z - water_level_m + draft_m) in the hull frame.
//
// Thickness: the ice volume of the pieces whose centre lies in a patch, per patch area, over (1 - ice.porosity), the
// way the case packs its bed (ice.thickness_m is its volume per area over (1 - porosity)); so the undisturbed bed
// reads ice.thickness_m whatever the pieces' arrangement, and a patch where the ice piles up reads thicker.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <brash/post/particles.hpp>
#include <brash/post/post_case.hpp>

namespace brash::hull {
struct Mesh;
}

namespace brash::post {

// One patch of a thickness profile: from_m .. to_m along x (ahead: distance ahead of the stem; beside: hull frame
// x), the mean thickness over the window's snapshots [m].
struct ThicknessBand {
  double from_m = 0, to_m = 0, thickness_m = 0;
};

// A piece touches the hull when its centre is within its radius times (1 + kContactTolerance) of the hull's surface
// (or inside the closed hull): a snapshot catches a touching piece a little apart as often as overlapping it.
inline constexpr double kContactTolerance = 0.05;
// A touching piece is "on the bottom" when the triangle it touches faces down more than sideways: outward normal
// z below -cos 45 deg.
inline constexpr double kBottomNormalZ = -0.7071067811865476;

// The hull regions (bow, parallel mid-body, stern) by the contact's hull-frame x, as the hull force split's.
inline constexpr std::array<const char*, 3> kHullRegions{"bow", "mid", "stern"};

struct IceAroundHull {
  std::size_t snapshots = 0;  // snapshots of the window read
  std::array<double, 2> window_s{};
  // thickness profiles
  double band_m = 0;        // band length along x (a quarter of the beam)
  double strip_m = 0;       // the strip beside the hull: from the waterline's half-breadth outwards, this wide
  std::vector<ThicknessBand> ahead, beside;
  double ice_thickness_m = 0;  // the case's ice.thickness_m (the bed as packed)
  double H_F_measured_m = 0;   // ahead[0]: the brash in front of the bow, next to the stem
  std::optional<double> H_F_fsicr_model_m, H_M_model_m;  // FSICR's at model scale (/ lambda); none: not known
  // the regions' bounds: the parallel mid-body (hull frame x)
  std::array<double, 2> x_par_m{};
  // contact, per region (kHullRegions' order) and in all: the wetted area (below the waterline), the touched share
  // (sum of the touching pieces' cross sections pi r^2 over the wetted area, mean over the snapshots; a layer of
  // equal spheres in a square array against the hull touches pi / 4 of it)
  std::array<double, 3> wetted_area_m2{}, contact_fraction{};
  double wetted_area_all_m2 = 0, contact_fraction_all = 0;
  double touching_pieces_mean = 0;  // per snapshot
  double on_bottom_share = 0;       // of the touching pieces, those on the bottom (kBottomNormalZ)
  // depth: the deepest touching piece's bottom below the waterline, mean over the snapshots of each snapshot's and
  // the deepest of all; the pieces whose bottom is below the keel within the hull's plan (x over the hull's length,
  // |y| within the half beam), mean per snapshot, and the deepest such bottom below the keel
  double deepest_touching_mean_m = 0, deepest_touching_max_m = 0;
  double below_keel_pieces_mean = 0, below_keel_deepest_m = 0;
  double draft_m = 0;
  // per hull triangle (the mesh's faces): the touched share and, with the snapshots' hull forces, the mean contact
  // pressure [Pa] (each touching piece's force, its component along the triangle's inward normal, on the triangle
  // it touches, over the triangle's area and the number of snapshots)
  std::vector<double> triangle_contact_fraction;
  std::vector<double> triangle_pressure_Pa;  // empty without the snapshots' hull forces
  std::string pressure_missing;              // why there is no pressure field (empty when there is one)
  std::vector<std::string> notes;
};

// FSICR's brash in front of the bow and in the channel at full scale: H_F = 0.26 m + (B H_M)^0.5, H_M of the ice
// class (brash/post/fsicr.hpp); the report's FSICR result where there is one.
struct FsicrBrash {
  double H_F_m = 0, H_M_m = 0;
};

// The analysis over the window's snapshots (entries with t in window_s whose file exists). x_par_m: the parallel
// mid-body (meta.json's hull_split, else measured on the hull). The FSICR values are divided by the case's lambda.
// Throws InputError when no snapshot of the window can be read.
IceAroundHull analyze_ice_around_hull(const std::vector<SnapshotEntry>& entries, std::array<double, 2> window_s,
                                      const PostCase& c, const hull::Mesh& hull, std::array<double, 2> x_par_m,
                                      const std::optional<FsicrBrash>& fsicr_full_scale, bool run_in_progress);

}  // namespace brash::post
