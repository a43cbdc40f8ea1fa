// Internals of brash-ode's case runner shared by its source files (run_case.cpp, run_options.cpp,
// packing_check.cpp).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "brash/case.hpp"
#include "brash/core/params.hpp"
#include "brash/ode/run_case.hpp"
#include "brash/packing.hpp"

namespace brash::ode {

std::string read_text(const std::filesystem::path& p);

// Another run's particle dump (RunOptions::scene_from): its pieces in the file's order, with their ids (the file's
// id column; without one 1, 2, ... in the file's order), velocities and angular velocities (zero where the file has
// no such columns), and how many rows of each moving-window state it had.
struct SceneFromDump {
  std::vector<Sphere> spheres;
  std::vector<long> ids;
  std::vector<core::Vec3> velocity_m_s;
  std::vector<core::Vec3> angular_velocity_rad_s;
  bool has_velocity = false, has_angular_velocity = false, has_state = false;
  long in_scene = 0, held_out = 0, removed = 0;  // rows of state 0, 1 (kept) and 2 (left out)
};
SceneFromDump read_scene_dump(const std::filesystem::path& file);

// Overlaps beyond tol (m) between spheres and through the side walls; InputError naming file and lines. Returns the
// largest overlap (m, 0 when none), of two spheres or of a sphere and a side wall.
double check_packing(const std::vector<Sphere>& s, const std::filesystem::path& file, double tol, double half_width);

}  // namespace brash::ode
