// brash-hull: generate the JBC hull STL, or check any hull mesh and print hydrostatics and FSICR
// parameters as JSON.
#include <brash/error.hpp>
#include <brash/hull/flow.hpp>
#include <brash/hull/hydrostatics.hpp>
#include <brash/hull/jbc.hpp>
#include <brash/hull/mesh.hpp>
#include <brash/hull/panel_flow.hpp>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <fstream>
#include <iostream>
#include <string_view>

namespace {

using namespace brash::hull;
using nlohmann::json;

json to_json(const MeshCheck& c) {
  return {{"closed", c.closed}, {"manifold", c.manifold}, {"oriented", c.oriented}, {"outward", c.outward},
          {"ok", c.ok()}, {"boundary_edges", c.boundary_edges}, {"nonmanifold_edges", c.nonmanifold_edges},
          {"misoriented_edges", c.misoriented_edges}, {"degenerate_faces", c.degenerate_faces},
          {"vertices", c.vertices}, {"faces", c.faces}, {"edges", c.edges},
          {"euler_characteristic", c.euler_characteristic}, {"enclosed_volume_m3", c.signed_volume_m3},
          {"area_m2", c.area_m2}, {"min_m", {c.min_m.x(), c.min_m.y(), c.min_m.z()}},
          {"max_m", {c.max_m.x(), c.max_m.y(), c.max_m.z()}}};
}

json to_json(const Hydrostatics& h) {
  return {{"volume_m3", h.volume_m3}, {"cb", h.cb}, {"lcb_x_m", h.lcb_x_m}, {"kb_m", h.kb_m},
          {"waterplane_area_m2", h.waterplane_area_m2}, {"lcf_x_m", h.lcf_x_m},
          {"wetted_surface_m2", h.wetted_surface_m2}, {"lwl_m", h.lwl_m}, {"bwl_m", h.bwl_m}};
}

json to_json(const FsicrDetail& d) {
  const auto& p = d.params;
  return {{"L_m", p.L_m}, {"B_m", p.B_m}, {"T_m", p.T_m}, {"alpha_deg", p.alpha_deg}, {"phi1_deg", p.phi1_deg},
          {"phi1_geometric_deg", d.phi1_geometric_deg}, {"bulbous_bow", d.bulbous_bow}, {"phi2_deg", p.phi2_deg},
          {"psi_deg", p.psi_deg}, {"L_par_m", p.L_par_m}, {"L_bow_m", p.L_bow_m}, {"A_wf_m2", p.A_wf_m2},
          {"x_b4_m", d.x_b4_m}, {"x_stem_m", d.x_stem_m}, {"x_par_aft_m", d.x_par_aft_m},
          {"x_par_fwd_m", d.x_par_fwd_m}};
}

int run_jbc(const std::filesystem::path& out, double lpp, double grid, const std::filesystem::path& data) {
  const Mesh m = make_jbc(load_jbc_data(data), {.lpp_m = lpp, .grid_factor = grid});
  const MeshCheck c = check_mesh(m);
  if (!c.ok()) throw std::runtime_error(fmt::format("generated JBC mesh failed its check: {}", to_json(c).dump()));
  write_stl(out, m);
  std::cerr << fmt::format("brash-hull: wrote {} ({} triangles, volume {:.5f} m^3)\n", out.string(), m.faces.size(),
                           c.signed_volume_m3);
  return 0;
}

int run_check(const std::filesystem::path& file, double draft, double lpp, const std::string& json_out) {
  const Mesh m = read_mesh(file);
  const MeshCheck c = check_mesh(m);
  json j{{"file", file.string()}, {"draft_m", draft}, {"check", to_json(c)},
         {"unit_problems", unit_problems(m, draft, lpp)}};
  const Hydrostatics h = hydrostatics(m, draft, lpp);
  j["hydrostatics"] = to_json(h);
  if (lpp <= 0) lpp = h.lwl_m;
  j["lpp_m"] = lpp;
  try {
    j["fsicr"] = to_json(measure_fsicr_detail(m, draft, lpp));
  } catch (const brash::InputError& e) {
    j["fsicr"] = {{"error", e.what()}};
  }
  const std::string text = j.dump(2);
  std::cout << text << "\n";
  if (!json_out.empty()) {
    std::ofstream(json_out) << text << "\n";
  }
  for (const auto& problem : unit_problems(m, draft, lpp))
    std::cerr << fmt::format("brash-hull: {}: {}\n", file.string(), problem);
  if (!c.closed)
    std::cerr << fmt::format("brash-hull: {}: mesh is not closed ({} boundary edges, {} non-manifold)\n",
                             file.string(), c.boundary_edges, c.nonmanifold_edges);
  if (c.closed && !c.outward)
    std::cerr << fmt::format("brash-hull: {}: faces are not consistently outward ({} misoriented edges, volume {} m^3)\n",
                             file.string(), c.misoriented_edges, c.signed_volume_m3);
  const bool good = c.ok() && j["unit_problems"].empty();
  if (!good) std::cerr << fmt::format("brash-hull: {}: mesh check or unit sanity failed (see JSON)\n", file.string());
  return good ? 0 : 2;
}

// The water's flow (still-water frame) along a line in the hull frame (z = 0 at the water level), as CSV: the
// panel flow evaluated directly, the thin-ship flow from its table (what the engines read).
int run_flow(const std::filesystem::path& file, double draft, double speed, const std::string& method,
             const std::vector<double>& line, int points, int max_panels, const std::string& out) {
  const Mesh m = read_mesh(file);
  if (line.size() != 6 || points < 2) throw brash::InputError("--line needs x0 y0 z0 x1 y1 z1 and --points >= 2");
  std::function<Eigen::Vector3d(const Eigen::Vector3d&)> field;
  brash::core::PanelSolution panel;
  brash::core::FlowTable table;
  if (method == "panel") {
    panel = panel_solution(m, draft, speed, {.max_panels = max_panels});
    field = [&](const Eigen::Vector3d& p) { return brash::core::panel_velocity(panel, p); };
  } else if (method == "thin_ship") {
    table = thin_ship_flow(m, draft, speed);
    field = [&](const Eigen::Vector3d& p) { return table.at(p); };
  } else {
    throw brash::InputError(fmt::format("--method {}: expected panel or thin_ship", method));
  }
  const Eigen::Vector3d a(line[0], line[1], line[2]), b(line[3], line[4], line[5]);
  std::ofstream file_out;
  if (!out.empty()) file_out.open(out);
  std::ostream& os = out.empty() ? std::cout : file_out;
  os << "s_m,x_m,y_m,z_m,ux_m_s,uy_m_s,uz_m_s,relative_speed_over_U\n";
  for (int k = 0; k < points; ++k) {
    const Eigen::Vector3d p = a + (b - a) * k / (points - 1.0), u = field(p);
    os << fmt::format("{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}\n", (p - a).norm(), p.x(), p.y(),
                      p.z(), u.x(), u.y(), u.z(), (u - Eigen::Vector3d(speed, 0, 0)).norm() / std::abs(speed));
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"brash-hull: JBC hull generator and hull mesh checker", "brash-hull"};
  app.require_subcommand(1);

  auto* jbc = app.add_subcommand("jbc", "write the JBC hull as a closed binary STL (x fwd from AP, keel z = 0)");
  std::filesystem::path out, data = default_jbc_data_dir();
  double lpp = JbcData::lpp_m, grid = 1.0;
  jbc->add_option("--out", out, "output STL")->required();
  jbc->add_option("--lpp", lpp, "length between perpendiculars in m (scales the 1:40 data; 7.0 = as is)");
  jbc->add_option("--grid-factor", grid, "multiplies every grid spacing (0.2 .. 5; smaller = finer)");
  jbc->add_option("--data", data, "folder with jbc_offsets_1to40.csv and jbc_profile_1to40.csv");

  auto* check = app.add_subcommand("check", "check a hull mesh; print check, hydrostatics, FSICR parameters as JSON");
  std::filesystem::path file;
  double draft = 0, check_lpp = 0;
  std::string json_out;
  check->add_option("file", file, "mesh (STL natively; OBJ, PLY, VTK ... through meshio)")->required();
  check->add_option("--draft", draft, "draft T in m (waterline z = T, keel at z = 0)")->required();
  check->add_option("--lpp", check_lpp, "length between perpendiculars in m (default: waterline length)");
  check->add_option("--json", json_out, "also write the JSON here");

  auto* flow = app.add_subcommand("flow", "the water's flow around the hull along a line, as CSV");
  std::string method = "panel", flow_out;
  double speed = 0;
  std::vector<double> line;
  int points = 101, max_panels = PanelFlowSettings{}.max_panels;
  flow->add_option("file", file, "hull mesh (keel at z = 0)")->required();
  flow->add_option("--draft", draft, "draft in m (the water level z = draft of the mesh)")->required();
  flow->add_option("--speed", speed, "ship speed along +x in m/s")->required();
  flow->add_option("--method", method, "panel | thin_ship");
  flow->add_option("--line", line, "x0 y0 z0 x1 y1 z1 in m, z = 0 at the water level")->expected(6)->required();
  flow->add_option("--points", points, "points along the line");
  flow->add_option("--max-panels", max_panels, "panel method: panels (unknowns)");
  flow->add_option("--out", flow_out, "CSV file (default: standard output)");

  // CLI11 only says "A subcommand is required" for a mistyped command: name it.
  if (argc > 1 && argv[1][0] != '-' && std::string_view(argv[1]) != "jbc" && std::string_view(argv[1]) != "check" &&
      std::string_view(argv[1]) != "flow") {
    std::cerr << "brash-hull: unknown command '" << argv[1] << "' (expected jbc | check | flow; see --help)\n";
    return 109;
  }
  CLI11_PARSE(app, argc, argv);
  try {
    if (jbc->parsed()) return run_jbc(out, lpp, grid, data);
    if (flow->parsed()) return run_flow(file, draft, speed, method, line, points, max_panels, flow_out);
    return run_check(file, draft, check_lpp, json_out);
  } catch (const std::exception& e) {
    std::cerr << "brash-hull: error: " << e.what() << "\n";
    return 1;
  }
}
