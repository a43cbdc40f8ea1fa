// The water's flow around the hull that a case asks for (fluid.hull_flow), for every engine that has one
// (LIGGGHTS through fix icefluid's table file, ODE in memory): one place that chooses the thin-ship sheet
// (hull_meshes flow.hpp) or the double-body panel flow (hull_meshes panel_flow.hpp).
#pragma once
#include <brash/case.hpp>
#include <brash/core/hull_flow.hpp>
#include <brash/hull/flow.hpp>
#include <brash/hull/mesh.hpp>
#include <filesystem>
#include <string>

namespace brash {

// The table of c.fluid.hull_flow for the full hull `mesh` (the case's STL frame: the water at z = level +
// draft), in the hull frame with z = 0 at the water level; empty for hull_flow: none. The panel flow (a few
// seconds to a minute) is cached in panel_flow_cache_file(c) and computed again when its key differs.
core::FlowTable hull_flow_table(const Case& c, const hull::Mesh& mesh);

// How the case's table treats the hull: fluid.hull_flow_coupling, and a clearance of half the smallest piece's
// radius (hull::NearHullSettings).
hull::NearHullSettings hull_flow_near_hull(const Case& c);

// <the packing file's folder>/panel_flow.bin: beside the packing (cases/<name>/generated/)
std::filesystem::path panel_flow_cache_file(const Case& c);

// What the panel flow's table is computed from: the mesh (a hash of its vertices and faces), the water level,
// the speed and the table's settings.
std::string panel_flow_key(const Case& c, const hull::Mesh& mesh);

}  // namespace brash
