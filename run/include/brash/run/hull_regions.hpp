// The hull force split's regions of a case (brash/core/hull_split.hpp, docs/physics.md "The hull force split"):
// the parallel mid-body measured on the case's full hull at its draft (brash::hull::measure_fsicr_detail, the
// same measurement as FSICR's L_par and L_bow in brash-post), for the engines that record the split.
#pragma once
#include <filesystem>

#include <nlohmann/json.hpp>

#include "brash/case.hpp"
#include "brash/core/hull_split.hpp"
#include "brash/hull/mesh.hpp"

namespace brash::run {

// The parallel mid-body of `full_hull` (the case's whole hull, STL frame) at the case's draft. A hull whose
// waterline the measurement cannot read throws brash::InputError naming the case file and hull.file.
core::HullRegions measure_hull_regions(const hull::Mesh& full_hull, const Case& c,
                                       const std::filesystem::path& case_file);

// meta.json's "hull_split": the regions' bounds and the definitions, so that a report can name them.
nlohmann::json hull_split_meta(const core::HullRegions& r);

}  // namespace brash::run
