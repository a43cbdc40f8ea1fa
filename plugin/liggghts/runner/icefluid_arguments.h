// The arguments of `fix ID group icefluid ...` (plugin/liggghts/fix_icefluid.cpp parses them) for a set of
// core fluid parameters: the runner's in.lmp takes them from brash::fluid_params(case), the mapping every
// engine shares.
#pragma once
#include <string>

#include "brash/core/params.hpp"

namespace brash::liggghts {

// "model M treatment T cd C drag_law L nu V ca A water_level Z water_density R g G", then " flow X Y Z" when
// the far-field flow is not zero and " gravity yes" when the fix applies gravity itself. Doubles in 9
// significant digits; the Ca table by its name (core::ca_table_spelling: throws for a table without one).
std::string icefluid_arguments(const core::FluidParams& p);

}  // namespace brash::liggghts
