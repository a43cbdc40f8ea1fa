// Writes the LIGGGHTS input script and data file of a case (the scene of docs/case_format.md:
// channel walls, kinematic hull with mesh/surface/stress, gravity, fix icefluid last).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "brash/case.hpp"
#include "brash/packing.hpp"

namespace brash::liggghts {

struct SceneOptions {
  double duration_s = 0;        // simulated time of this run
  long restart_every_steps = 0; // 0 = no periodic restart files
  int ranks = 1;
  std::string hull_file = "hull.stl";  // inside the run dir, in the STL's own frame (keel at z=0)
};

struct Box {
  double xlo, xhi, ylo, yhi, zlo, zhi;
};

// Domain that holds the channel, the ice and the hull over its whole path.
Box scene_box(const Case& c, double hull_x_min_m, double hull_x_max_m, double hull_z_min_m, double hull_z_max_m,
              double duration_s);

// "read_data" file: atom_style granular lines "id type diameter density x y z".
std::string data_file(const std::vector<Sphere>& spheres, const Box& box, double ice_density_kg_m3);

// The input script; outputs (relative to the run dir): hull_force.raw, particles/dump.*.txt, restart/.
std::string input_script(const Case& c, const Box& box, const SceneOptions& opt);

}  // namespace brash::liggghts
