// Stability analysis of one finished, stopped or crashed run directory (docs/stability.md
// "Engine stability map"; `brash-post stability RUN_DIR`, bench/stability_engines.sh).
//
// From meta.json: how the run ended (complete / stopped by a run-time guard, which one, its message /
// crashed: an engine error or a run that never finished). From every particle snapshot (particles/index.csv):
//   - hull penetration: the largest overlap of a piece with the FULL closed hull (brash::hull::Proximity,
//     the guard's query), as a fraction of the piece's diameter; the hull's frame is at
//     (hull_x_m of the snapshot, 0, water level - draft) in the scene;
//   - sphere overlap: the largest r_i + r_j - |x_i - x_j| over all pairs (cell grid), as a fraction of the
//     pair's mean diameter r_i + r_j;
//   - escaped: pieces whose centre is beyond a side wall (|y| > channel width / 2);
//   - above water: pieces whose centre is more than `above_water_m` above the water level;
//   - mechanical energy of the ice E = sum over pieces of
//         1/2 sum_k (m + m_a,k) v_k^2  +  m g (z - L)  +  rho_w g I(h)
//     (m_a,k = rho_w V_sub ca_k: the water's added-mass kinetic energy; I(h) = integral of the submerged
//     volume over the depth: the buoyancy potential, zero for a piece clear of the water; h = submerged
//     height);
//   - work of the hull on the ice W(t) = integral of (-fx) U dt (hull_force.csv, trapezoids; the ship moves
//     only along x at the case speed U).
// Energy excess: the ship is the only source of energy, and drag, restitution and friction only remove it, so
// E(t) - E(0) <= W(t) for a physical run. energy_excess = max over snapshots of (E(t) - E(0) - W(t)), in
// units of E_ref = N 1/2 m_mean U^2 (every piece moving at the ship's speed); a value above
// `silent_energy_excess` means the integrator created energy.
//
// Verdict: "stable" (complete and none of the thresholds crossed), "guard" (stopped by a guard), "crashed"
// (an engine error or no end), or "silent" (complete, but hull penetration > silent_penetration_d, overlap >
// silent_overlap_d, escaped or above-water pieces, non-finite values, or energy excess >
// silent_energy_excess): a non-physical result that no guard stopped.
#pragma once
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace brash::post {

struct StabilityOptions {
  std::optional<double> above_water_m;  // default: 2 ice thicknesses of the case
  double silent_penetration_d = 0.5;    // the guards' default max_hull_penetration_d
  double silent_overlap_d = 0.5;
  double silent_energy_excess = 1.0;
};

struct StabilityResult {
  std::string status;   // complete | guard | crashed
  std::string guard;    // status guard: nan | box | zmax | kinetic_energy | hull | timestep
  std::string message;  // meta.json reason
  std::string verdict;  // stable | guard | crashed | silent
  std::vector<std::string> silent_reasons;
  std::string engine, treatment;
  std::optional<double> dt_s;
  std::size_t snapshots = 0, pieces = 0;
  double t_last_s = 0;  // time of the last snapshot read

  std::optional<double> max_hull_penetration_d;  // nullopt: no closed hull to test against
  std::int64_t max_penetration_piece = -1;
  double max_penetration_t_s = 0;
  double max_overlap_d = 0;
  std::int64_t max_overlap_pieces[2] = {-1, -1};
  double max_overlap_t_s = 0;
  std::size_t escaped_max = 0;          // largest count over the snapshots
  std::size_t above_water_max = 0;      // largest count over the snapshots
  double above_water_m = 0;             // threshold used
  double max_height_above_water_d = 0;  // highest centre above the water, in mean diameters
  std::size_t non_finite_snapshots = 0;

  double energy_first_J = 0, energy_last_J = 0;
  std::optional<double> work_hull_J;    // W at the last snapshot
  std::optional<double> energy_excess;  // max (E - E0 - W) / energy_ref_J
  double energy_ref_J = 0;
  std::vector<std::string> notes;
};

// Energy terms of one piece (exposed for the tests). depth-integrated submerged volume I(h) [m^4] of a sphere
// of radius r submerged to height h (h > 2r: fully submerged, deeper by h - 2r).
double submerged_volume_integral_m4(double radius_m, double submerged_height_m);

// Reads meta.json, case.yaml, particles/ and hull_force.csv of `run_dir`; throws brash::InputError only when
// case.yaml cannot be read (every other problem becomes a note or a silent reason).
StabilityResult analyze_stability(const std::filesystem::path& run_dir, const StabilityOptions& opt = {});

nlohmann::json stability_json(const StabilityResult& r);

// Which guard a stop message names (nan | box | zmax | kinetic_energy | hull | timestep), empty if none.
std::string guard_of_message(const std::string& reason);

}  // namespace brash::post
