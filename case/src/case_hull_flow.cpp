// fluid.hull_flow of a case: thin-ship or panel flow, the panel flow cached (case_hull_flow.hpp).
#include "brash/case_hull_flow.hpp"

#include <fmt/format.h>

#include <brash/core/fnv1a.hpp>
#include <brash/hull/flow.hpp>
#include <brash/hull/panel_flow.hpp>
#include <cstdint>
#include <cstring>
#include <iostream>

namespace brash {
namespace {

// FNV-1a over the mesh's bytes: any change of the hull changes the key
std::uint64_t mesh_hash(const hull::Mesh& mesh) {
  std::uint64_t h = core::kFnv1aOffset;
  auto add = [&](const void* p, std::size_t n) { h = core::fnv1a({static_cast<const char*>(p), n}, h); };
  for (const auto& v : mesh.vertices) add(v.data(), 3 * sizeof(double));
  for (const auto& f : mesh.faces) add(f.data(), 3 * sizeof(int));
  return h;
}

double water_z(const Case& c) {
  return c.water.level_m + c.hull.draft_m;
}

}  // namespace

// a piece's centre stays about its radius off the hull: closer, the panels' own near field is of no use
hull::NearHullSettings hull_flow_near_hull(const Case& c) {
  hull::NearHullSettings st;
  st.coupling = c.fluid.hull_flow_coupling;
  st.clearance_m = 0.5 * min_radius_m(c);
  return st;
}

std::filesystem::path panel_flow_cache_file(const Case& c) {
  return c.ice.packing_file.parent_path() / "panel_flow.bin";
}

std::string panel_flow_key(const Case& c, const hull::Mesh& mesh) {
  hull::PanelFlowSettings st;
  st.near_hull = hull_flow_near_hull(c);
  return fmt::format(
      "panel mesh {:016x} {} vertices {} faces; water_z {:.12g} m; speed {:.12g} m/s; max_panels {}; "
      "far_factor {:.6g}; spacing {:.6g} draft; margin {:.6g} breadth; along the hull: band {:.6g} draft, "
      "tolerance {:.6g} speed, factor {}, clearance {:.6g} m; coupling {}",
      mesh_hash(mesh), mesh.vertices.size(), mesh.faces.size(), water_z(c), c.ship.speed_m_s, st.max_panels,
      st.far_factor, st.table_spacing_fraction_of_draft, st.margin_fraction_of_breadth,
      st.near_hull.band_fraction_of_draft, st.near_hull.tolerance_fraction_of_speed, st.near_hull.max_factor, st.near_hull.clearance_m, to_string(st.near_hull.coupling));
}

core::FlowTable hull_flow_table(const Case& c, const hull::Mesh& mesh) {
  switch (c.fluid.hull_flow) {
    case HullFlow::None:
      return {};
    case HullFlow::ThinShip:
      return hull::thin_ship_flow(mesh, water_z(c), c.ship.speed_m_s, {.near_hull = hull_flow_near_hull(c)});
    case HullFlow::Panel:
      break;
  }
  const std::filesystem::path cache = panel_flow_cache_file(c);
  const std::string key = panel_flow_key(c, mesh);
  if (auto cached = hull::read_flow_table(cache, key)) return *cached;
  core::FlowTable t = hull::panel_flow(mesh, water_z(c), c.ship.speed_m_s, {.near_hull = hull_flow_near_hull(c)});
  try {
    std::filesystem::create_directories(cache.parent_path());
    hull::write_flow_table(cache, t, key);
  } catch (const std::exception& e) {  // a read-only case folder: the run goes on, computing it each time
    std::cerr << fmt::format("brash: note: cannot cache the panel flow in {}: {}\n", cache.string(),
                             e.what());
  }
  return t;
}

}  // namespace brash
