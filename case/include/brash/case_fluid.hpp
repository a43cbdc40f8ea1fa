// The case's fluid parameters: the one mapping from a case file (brash::Case: water.*, fluid.*) to the core's
// brash::core::FluidParams, used by every engine (ODE directly, LIGGGHTS through the arguments of fix icefluid,
// YADE through brash_yade.Fluid.from_case). fluid.hull_flow is not a FluidParams field: the engines that have
// the hull's flow build it from the hull mesh themselves.
#pragma once
#include "brash/case.hpp"
#include "brash/core/params.hpp"

namespace brash {

// model, treatment, drag law, C_D, Ca table from fluid.*; density, level, gravity and kinematic viscosity from
// water.*. apply_gravity stays false and the far-field flow zero: the engines add gravity themselves.
core::FluidParams fluid_params(const Case& c);

}  // namespace brash
