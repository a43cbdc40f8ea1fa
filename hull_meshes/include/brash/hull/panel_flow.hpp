// The water's flow around a hull from the double-body panel method (fluid.hull_flow: panel): the hull's
// wetted surface, cut at the waterline, grouped into panels and mirrored about the water level, solved by
// brash_core's source panel method (plugin/core panel_flow.hpp) and tabulated like the thin-ship flow
// (flow.hpp), so every engine reads the same FlowTable.
#pragma once
#include <brash/core/hull_flow.hpp>
#include <brash/core/panel_flow.hpp>
#include <brash/hull/flow.hpp>
#include <brash/hull/mesh.hpp>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace brash::hull {

// The mesh's triangles below the water level water_z_m, those crossing it cut there (a cut quadrilateral in
// two triangles), in the frame with the water level at z = 0; degenerate pieces dropped. Outward orientation
// kept.
std::vector<core::Triangle> wetted_triangles(const Mesh& mesh, double water_z_m);

// The triangles grouped into at most max_panels panels of one source density: the largest (by area, weighted
// up where its normals spread: finer panels at the stem and bilge) is split in two until there are max_panels, at the median of its longest extent, or by the direction of its
// normals where they differ by more than 45 degrees (the two sides of a sharp stem stay apart). Each triangle
// is a panel of its own when there are no more than max_panels. mirror_z is left false.
core::PanelBody group_panels(std::vector<core::Triangle> triangles, int max_panels);

struct PanelFlowSettings {
  int max_panels = 2000;                           // unknowns of the dense solve (~3 s at 2000)
  double far_factor = 5.0;                         // point source beyond this many panel diameters
  double table_spacing_fraction_of_draft = 0.125;  // as ThinShipSettings
  double margin_fraction_of_breadth = 1.0;         // as ThinShipSettings
  NearHullSettings near_hull{};                    // as ThinShipSettings
  TableWindow window{};                            // none: the whole table
};

// The double-body solution of `mesh` moving at ship_speed_m_s along x with the water at height water_z_m of
// the mesh's frame; positions in the mesh's frame shifted by water_z_m (z = 0 at the water level), the
// velocity the water's in the still-water frame. Throws brash::InputError when the water level is not between
// the keel and the top or nothing is under water.
core::PanelSolution panel_solution(const Mesh& mesh, double water_z_m, double ship_speed_m_s,
                                   const PanelFlowSettings& settings = {});

// Its table, on the box and spacing of thin_ship_flow's table for the same hull (flow.hpp), with the same
// treatment along the hull (nodes inside it never sampled, cells along it refined) and Du/Dt.
core::FlowTable panel_flow(const Mesh& mesh, double water_z_m, double ship_speed_m_s,
                           const PanelFlowSettings& settings = {});
// ... of a solution already at hand (panel_solution of the same mesh, water level and settings)
core::FlowTable panel_flow(const core::PanelSolution& solution, const Mesh& mesh, double water_z_m,
                           const PanelFlowSettings& settings = {});

// A flow table in a binary file headed by `key` (what it was computed from); read_flow_table returns nothing
// when the file is missing, unreadable or made for another key. Written atomically (a temporary, renamed).
void write_flow_table(const std::filesystem::path& file, const core::FlowTable& table,
                      const std::string& key);
std::optional<core::FlowTable> read_flow_table(const std::filesystem::path& file, const std::string& key);
// ... whatever its key (a table handed to an engine: fix icefluid's hull_flow FILE.bin)
std::optional<core::FlowTable> read_flow_table(const std::filesystem::path& file);

}  // namespace brash::hull
