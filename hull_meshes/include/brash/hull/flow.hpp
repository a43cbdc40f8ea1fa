// The water's flow around a hull (fluid.hull_flow: thin_ship): the hull's half-breadths under water, measured
// on the mesh, made into brash_core's thin-ship source sheet and tabulated (plugin/core hull_flow.hpp). Every
// engine adapter that moves ice past a hull builds its table here, so the engines see the same field.
#pragma once
#include <brash/core/hull_flow.hpp>
#include <brash/hull/mesh.hpp>
#include <span>
#include <vector>

namespace brash::hull {

// Half-breadth max |y| of the mesh's section at height z_j (mesh frame) where it crosses x_i, 0 where the
// section does not reach x_i; z-major (out[j * nx + i]).
std::vector<double> half_breadths(const Mesh& mesh, std::span<const double> x_m, std::span<const double> z_m);

struct ThinShipSettings {
  int cells_along = 120;                           // sheet cells over the hull's length
  int cells_deep = 10;                             // sheet cells over the draft
  double table_spacing_fraction_of_draft = 0.125;  // table spacing = this x draft (also the core radius)
  double margin_fraction_of_breadth = 1.0;         // table box beyond the hull, in hull breadths
};

// The flow table of `mesh` with the water at height water_z_m of the mesh's frame, moving at ship_speed_m_s
// along x. The table's frame is the mesh's shifted by water_z_m: x, y as the mesh's, z = 0 at the water
// level. Throws brash::InputError when the water level is not between the mesh's keel and top or the hull has
// no breadth under water.
core::FlowTable thin_ship_flow(const Mesh& mesh, double water_z_m, double ship_speed_m_s,
                               const ThinShipSettings& settings = {});

}  // namespace brash::hull
