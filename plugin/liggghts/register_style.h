// Registers our fix styles with Debian's prebuilt LIGGGHTS, whose style table (Modify::fix_map) is
// private and filled from a header that is not installed. Names in an explicit template
// instantiation are not access-checked ([temp.spec.general]), which gives a standard-conforming
// pointer to that member. Must be called after the LAMMPS object exists and never after `clear`
// (which rebuilds Modify and drops our styles; brash-liggghts forbids `clear`).
#pragma once

#include <map>
#include <string>

#include "lammps.h"
#include "modify.h"

namespace brash::liggghts {

using FixCreatorFn = LAMMPS_NS::Fix* (*)(LAMMPS_NS::LAMMPS*, int, char**);
using FixMap = std::map<std::string, FixCreatorFn>;

// Adds `creator` under `style` to the private style table (register_style.cpp).
void register_fix_creator(LAMMPS_NS::LAMMPS* lmp, const std::string& style, FixCreatorFn creator);

template <typename T>
LAMMPS_NS::Fix* make_fix(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) {
  return new T(lmp, narg, arg);
}

template <typename T>
void register_fix_style(LAMMPS_NS::LAMMPS* lmp, const std::string& style) {
  register_fix_creator(lmp, style, &make_fix<T>);
}

}  // namespace brash::liggghts
