// brash::guard: the run-time guards shared by every engine (docs/stability.md "Run-time guards").
// Pure functions on value types: an engine adapter (LIGGGHTS fix brash/guard, brash-ode, the YADE adapter)
// reads a piece's state, calls check_piece() and stops the run with stop_message() on the first cause.
//
//   non-finite   position, velocity, angular velocity or force component is NaN/Inf
//   box          centre outside the domain box (the LIGGGHTS scene box shrunk by d_mean / 4)
//   zmax         centre above z_max (jumped out of the water)
//   ke_max       1/2 m v^2 + 1/5 m r^2 w^2 above ke_max (runaway kinetic energy)
//   hull         overlap with the full closed hull (hull::Proximity::penetration) above
//                max_hull_penetration_d x the piece's diameter
// and, once per run, check_timestep(): dt above a fraction of the contact Rayleigh time.
#pragma once
#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "brash/case.hpp"
#include "brash/hull/proximity.hpp"

namespace brash::guard {

using Box = std::array<double, 6>;  // xlo xhi ylo yhi zlo zhi

// The domain of a case's scene: the channel, the ice, open water beyond the channel end for the ice the bow
// pushes ahead (the whole ship travel), and the hull over its whole path. hull_* are the extents of the FULL
// hull in its STL frame (keel z = 0, aft perpendicular x = 0). The LIGGGHTS runner's simulation box.
Box domain_box(const Case& c, double hull_x_min_m, double hull_x_max_m, double hull_z_min_m,
               double hull_z_max_m, double duration_s);

struct Limits {
  std::optional<Box> box;                        // centres must stay inside
  std::optional<double> z_max_m;                 // centres must stay below
  std::optional<double> ke_max_J;                // kinetic energy per piece (translation + rotation)
  std::optional<double> max_hull_penetration_d;  // overlap with the hull / the piece's diameter
};

// The limits a runner applies to a case (the same in every engine): box = domain shrunk by d_mean / 4;
// zmax = min(its top, water level + 5 ice thicknesses); ke_max = kinetic energy of the largest piece
// (d_mean + truncation_sd sd) at max(20 x ship speed, 5 m/s); hull = guards.max_hull_penetration_d (0 = off).
Limits limits_for_case(const Case& c, const Box& domain);

// Where the hull is now: the proximity query of the full closed hull in its own frame and the scene position
// of that frame's origin at the current step (the frame only translates).
struct HullNow {
  const hull::Proximity* proximity = nullptr;
  Eigen::Vector3d origin_m = Eigen::Vector3d::Zero();
};

struct Piece {
  Eigen::Vector3d x_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d v_m_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d omega_rad_s = Eigen::Vector3d::Zero();
  std::optional<Eigen::Vector3d> force_N;  // checked for NaN/Inf when the engine has it
  double radius_m = 0;
  double mass_kg = 0;
};

// The first guard the piece breaks (in the order of the list above), as a cause text such as
// "left the box: x = 2.31 > xhi = 2.2 (m)", or nullopt. `hull` may be null (no hull guard).
std::optional<std::string> check_piece(const Piece& p, const Limits& limits, const HullNow* hull = nullptr);

// Rayleigh time of a Hertz contact (case.hpp).
using brash::rayleigh_time_s;

// The contact time-step check for the smallest piece: cause text when dt > max_fraction T_R, else nullopt.
std::optional<std::string> check_timestep(double dt_s, double radius_m, double density_kg_m3,
                                          double youngs_modulus_pa, double poisson_ratio,
                                          double max_fraction);

// "guard: step N (t = T s): piece ID: CAUSE" (ids as the run's particle files number them, from 1).
std::string stop_message(long step, double t_s, long piece_id, std::string_view cause);

}  // namespace brash::guard
