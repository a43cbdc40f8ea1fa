// Writes the LIGGGHTS input script and data file of a case (the scene of docs/case_format.md:
// channel walls, kinematic hull with mesh/surface/stress, gravity, fix icefluid last).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "brash/case.hpp"
#include "brash/core/hull_split.hpp"
#include "brash/hull/mesh.hpp"
#include "brash/packing.hpp"

namespace brash::liggghts {

struct SceneOptions {
  double duration_s = 0;        // simulated time of this run
  long restart_every_steps = 0; // 0 = no periodic restart files
  int ranks = 1;
  std::string restart_file;      // resume from this restart (relative to the run dir) instead of packing.data
  std::string hull_file = "hull.stl";  // inside the run dir, in the STL's own frame (keel at z=0)
  // The full closed hull for fix brash/guard's hull check (the contact hull may be a band or a half);
  // empty = no hull check.
  std::string guard_hull_file = "hull.stl";
  // fix icefluid hull_flow's file: the full hull (thin-ship flow built by the fix), in the same frame as
  // hull_file, or the flow table the runner computed (hull_flow.bin, brash::hull_flow_table).
  std::string flow_hull_file = "hull.stl";
  double hull_x_min_m = 0;      // x extent of the hull in the STL frame (stern, bow) for speedups.farfield
  double hull_x_max_m = 0;
  double hull_half_beam_m = 0;  // largest |y| of the hull, for speedups.farfield_beside_m
  // The hull force split's regions (fix brash/hullsplit, recorded in hull_force.raw after fx fy fz)
  core::HullRegions hull_regions;
};

struct Box {
  double xlo, xhi, ylo, yhi, zlo, zhi;
};

// Domain that holds the channel, the ice and the hull over its whole path.
Box scene_box(const Case& c, double hull_x_min_m, double hull_x_max_m, double hull_z_min_m, double hull_z_max_m,
              double duration_s);

// "read_data" file: atom_style granular lines "id type diameter density x y z". Material types: 1 ice,
// 2 hull, 3 channel walls, 4 symmetry plane (speedups.symmetry_y only).
std::string data_file(const std::vector<Sphere>& spheres, const Box& box, double ice_density_kg_m3,
                      int atom_types = 3);

// speedups.symmetry_y: the half y >= 0. Spheres whose centre is closer than their radius to y = 0 are dropped
// (a piece cannot straddle a symmetry plane), and the hull is clipped to y >= 0 (triangles crossing the plane
// are cut there; the result is an open mesh, which LIGGGHTS accepts).
std::vector<Sphere> half_channel_spheres(const std::vector<Sphere>& spheres);
hull::Mesh half_hull(const hull::Mesh& mesh);

// The granular model of every contact (pair gran, wall/gran): Hertz with tangential history, and with
// contact.rolling_friction > 0 LIGGGHTS' constant directional torque (rolling_friction cdt).
std::string granular_model(const Case& c);
// The material lines (fix property/global of types 1 ice, 2 hull, 3 walls, 4 the symmetry plane with
// symmetry_y) and the pair style of a case.
std::string contact_lines(const Case& c, bool symmetry_y);

// The input script; outputs (relative to the run dir): hull_force.raw, particles/dump.*.txt, restart/.
std::string input_script(const Case& c, const Box& box, const SceneOptions& opt);

// brash-settle's deck (brash/run/settle.hpp): the packing (packing.data) with gravity, the fluid forces (no hull's
// flow), the side walls and walls at both channel ends, no hull; run in chunks of chunk_steps until the pieces' rms
// speed is below ice.settle_speed_m_s or max_chunks have run; then prints "brash-settle: t T vrms V" and writes
// settled.dump (id x y z radius, sorted by id).
std::string settle_script(const Case& c, const Box& box, long chunk_steps, long max_chunks);

}  // namespace brash::liggghts
