// Internals of brash-ode's case runner shared by its source files (run_case.cpp, run_options.cpp,
// packing_check.cpp).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "brash/case.hpp"
#include "brash/ode/run_case.hpp"
#include "brash/packing.hpp"

namespace brash::ode {

std::string read_text(const std::filesystem::path& p);

// Every option that shapes the run, stored in meta.json ("ode_options") so that --resume rebuilds the same scene.
nlohmann::json options_json(const RunOptions& o);

// The skips with --cull's wake rule in SI units: the case's unless given (brash/core/far_field.hpp).
Skips cull_skips(const RunOptions& o, const Case& c);

// Overlaps beyond tol (m) between spheres and through the side walls; InputError naming file and lines.
void check_packing(const std::vector<Sphere>& s, const std::filesystem::path& file, double tol, double half_width);

}  // namespace brash::ode
