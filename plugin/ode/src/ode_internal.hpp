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

// Every option that shapes the run, stored in meta.json ("ode_options") so that --resume rebuilds the same scene.
nlohmann::json options_json(const RunOptions& o);

// The skips the run applies: --cull's window and wake rule in SI units, the case's far field (speedups.farfield_*)
// unless given on the command line (brash/core/far_field.hpp).
Skips cull_skips(const RunOptions& o, const Case& c);

// Another run's particle dump (RunOptions::scene_from): its pieces and their velocities, in the file's order.
struct SceneFromDump {
  std::vector<Sphere> spheres;
  std::vector<core::Vec3> velocity_m_s;
};
SceneFromDump read_scene_dump(const std::filesystem::path& file);

// Overlaps beyond tol (m) between spheres and through the side walls; InputError naming file and lines. Returns the
// largest overlap (m, 0 when none), of two spheres or of a sphere and a side wall.
double check_packing(const std::vector<Sphere>& s, const std::filesystem::path& file, double tol, double half_width);

}  // namespace brash::ode
