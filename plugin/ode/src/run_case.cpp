// brash-ode case runner (run_case.hpp).
#include "brash/ode/run_case.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <unordered_map>

#include "brash/case.hpp"
#include "brash/case_fluid.hpp"
#include "brash/error.hpp"
#include "brash/guard.hpp"
#include "brash/hull/flow.hpp"
#include "brash/hull/mesh.hpp"
#include "brash/hull/proximity.hpp"
#include "brash/ode/restart.hpp"
#include "brash/packing.hpp"
#include "brash/run_layout.hpp"
#include "brash/runner_setup.hpp"
#include "brash/stats/early_stop.hpp"

namespace brash::ode {
namespace fs = std::filesystem;

namespace {

// SIGINT / SIGTERM during the time-stepping loop: the loop ends after the step in progress and the run is
// left resumable at that step (restart file, hull_force.csv, meta status "stopped"), instead of losing the
// work since the last periodic restart file. The handler only records the signal.
volatile std::sig_atomic_t g_stop_signal = 0;
extern "C" void record_stop_signal(int sig) {
  g_stop_signal = sig;
}
// Installs the handlers for its lifetime and puts the previous ones back.
class StopSignals {
 public:
  StopSignals() {
    g_stop_signal = 0;
    struct sigaction sa {};
    sa.sa_handler = record_stop_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &old_int_);
    sigaction(SIGTERM, &sa, &old_term_);
  }
  ~StopSignals() {
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
  }
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;
  int received() const { return g_stop_signal; }

 private:
  struct sigaction old_int_ {
  }, old_term_{};
};

// A run-time guard stopped the run (guard::stop_message).
class GuardStop : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Line number (1-based) of each data row of a packing CSV (rows after '#' lines and the header).
std::vector<int> packing_lines(const fs::path& file) {
  std::ifstream in(file);
  std::vector<int> lines;
  std::string s;
  int ln = 0;
  bool header = false;
  while (std::getline(in, s)) {
    ++ln;
    if (s.empty() || s[0] == '#') continue;
    if (!header) {
      header = true;
      continue;
    }
    lines.push_back(ln);
  }
  return lines;
}

// Overlaps beyond tol (m) between spheres and through the side walls; InputError naming file and lines.
void check_packing(const std::vector<Sphere>& s, const fs::path& file, double tol, double half_width) {
  const auto lines = packing_lines(file);
  auto where = [&](std::size_t i) {
    return fmt::format("{}:{}", file.string(), i < lines.size() ? lines[i] : static_cast<int>(i) + 1);
  };
  double dmax = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto& p = s[i];
    if (!std::isfinite(p.x_m) || !std::isfinite(p.y_m) || !std::isfinite(p.z_m) || !std::isfinite(p.diameter_m) ||
        !(p.diameter_m > 0))
      throw InputError(fmt::format("{}: sphere {} has a non-finite position or a non-positive diameter", where(i), i + 1));
    if (std::abs(p.y_m) + 0.5 * p.diameter_m > half_width + tol)
      throw InputError(fmt::format("{}: sphere {} (y {:.6g} m, d {:.6g} m) pokes {:.3g} m through a side wall at |y| = {:.6g} m",
                                   where(i), i + 1, p.y_m, p.diameter_m,
                                   std::abs(p.y_m) + 0.5 * p.diameter_m - half_width, half_width));
    dmax = std::max(dmax, p.diameter_m);
  }
  // Uniform grid with cell = d_max: neighbours are in the 27 surrounding cells.
  auto key = [&](long a, long b, long c) { return (a * 73856093L) ^ (b * 19349663L) ^ (c * 83492791L); };
  std::unordered_multimap<long, std::size_t> grid;
  grid.reserve(s.size() * 2);
  auto cell = [&](double v) { return static_cast<long>(std::floor(v / dmax)); };
  for (std::size_t i = 0; i < s.size(); ++i) grid.emplace(key(cell(s[i].x_m), cell(s[i].y_m), cell(s[i].z_m)), i);
  std::vector<std::string> bad;
  std::size_t nbad = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const long cx = cell(s[i].x_m), cy = cell(s[i].y_m), cz = cell(s[i].z_m);
    for (long a = -1; a <= 1; ++a)
      for (long b = -1; b <= 1; ++b)
        for (long c = -1; c <= 1; ++c) {
          auto [lo, hi] = grid.equal_range(key(cx + a, cy + b, cz + c));
          for (auto it = lo; it != hi; ++it) {
            const std::size_t j = it->second;
            if (j <= i) continue;
            const double dx = s[i].x_m - s[j].x_m, dy = s[i].y_m - s[j].y_m, dz = s[i].z_m - s[j].z_m;
            const double overlap = 0.5 * (s[i].diameter_m + s[j].diameter_m) - std::sqrt(dx * dx + dy * dy + dz * dz);
            if (overlap > tol) {
              ++nbad;
              if (bad.size() < 5)
                bad.push_back(fmt::format("{} and line {}: spheres {} and {} overlap by {:.3g} m", where(i),
                                          j < lines.size() ? lines[j] : static_cast<int>(j) + 1, i + 1, j + 1, overlap));
            }
          }
        }
  }
  if (nbad) {
    std::string msg = fmt::format("{}: {} overlapping sphere pairs (tolerance {:.3g} m); an overlapping packing "
                                  "explodes in ODE. First ones:",
                                  file.string(), nbad, tol);
    for (const auto& b : bad) msg += "\n  " + b;
    throw InputError(msg);
  }
}

std::string hms(double s) {
  if (!std::isfinite(s) || s < 0) return "--:--";
  const long t = std::lround(s);
  return t >= 3600 ? fmt::format("{}:{:02}:{:02}", t / 3600, (t / 60) % 60, t % 60) : fmt::format("{}:{:02}", t / 60, t % 60);
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Every option that shapes the run, stored in meta.json so that --resume rebuilds the same scene.
nlohmann::json options_json(const RunOptions& o) {
  const auto& st = o.stepper;
  const auto& k = o.skips;
  return {{"case_dir", fs::absolute(o.case_dir).lexically_normal().string()},
          {"duration_s", o.duration_s},
          {"model", o.model},
          {"treatment", o.treatment},
          {"dt_s", st.dt_s},
          {"iterations", st.iterations},
          {"erp", st.erp},
          {"cfm", st.cfm},
          {"contact_surface_layer_m", st.contact_surface_layer},
          {"max_contacts_per_pair", st.max_contacts_per_pair},
          {"angular_damping", st.angular_damping},
          {"broad_phase", to_string(st.broad_phase)},
          {"auto_disable", k.auto_disable},
          {"disable_linear_m_s", k.disable_linear_m_s},
          {"disable_angular_rad_s", k.disable_angular_rad_s},
          {"disable_steps", k.disable_steps},
          {"auto_disable_far_only", k.auto_disable_far_only},
          {"cull", k.cull},
          {"cull_ahead_m", k.cull_ahead_m},
          {"cull_behind_m", k.cull_behind_m},
          {"cull_side_m", k.cull_side_m},
          {"cull_every", k.cull_every},
          {"cull_geoms", k.cull_geoms},
          {"implicit", o.implicit_mode == ImplicitMode::EffectiveMass ? "effective_mass" : "scale_forces"},
          {"end_walls", o.end_walls},
          {"settle_s", o.settle_s},
          {"overlap_tolerance_over_d", o.overlap_tolerance_over_d},
          {"restart_every_s", o.restart_every_s}};
}

RunOptions options_from_meta(const fs::path& run_dir, const RunOptions& cli) {
  const fs::path mf = run_dir / "meta.json";
  if (!fs::exists(mf)) throw InputError(fmt::format("--resume {}: no meta.json there (not a run directory?)", run_dir.string()));
  nlohmann::json meta;
  try {
    meta = nlohmann::json::parse(read_text(mf));
  } catch (const std::exception& e) {
    throw InputError(fmt::format("{}: unreadable: {}", mf.string(), e.what()));
  }
  if (meta.value("engine", "") != "ode" || !meta.contains("ode_options"))
    throw InputError(fmt::format("{}: not a brash-ode run with restart support (no \"ode_options\")", mf.string()));
  const auto& j = meta["ode_options"];
  RunOptions o;
  try {
    o.case_dir = j.at("case_dir").get<std::string>();
    o.duration_s = j.at("duration_s");
    o.model = j.at("model");
    o.treatment = j.at("treatment");
    o.stepper.dt_s = j.at("dt_s");
    o.stepper.iterations = j.at("iterations");
    o.stepper.erp = j.at("erp");
    o.stepper.cfm = j.at("cfm");
    o.stepper.contact_surface_layer = j.at("contact_surface_layer_m");
    o.stepper.max_contacts_per_pair = j.at("max_contacts_per_pair");
    o.stepper.angular_damping = j.at("angular_damping");
    // Runs before the switch existed used sap; grid gives the same contacts (see world.hpp), so they go on with it.
    o.stepper.broad_phase = j.value("broad_phase", to_string(BroadPhase::Grid)) == to_string(BroadPhase::Sap) ? BroadPhase::Sap : BroadPhase::Grid;
    o.skips.auto_disable = j.at("auto_disable");
    o.skips.disable_linear_m_s = j.at("disable_linear_m_s");
    o.skips.disable_angular_rad_s = j.at("disable_angular_rad_s");
    o.skips.disable_steps = j.at("disable_steps");
    o.skips.auto_disable_far_only = j.at("auto_disable_far_only");
    o.skips.cull = j.at("cull");
    o.skips.cull_ahead_m = j.at("cull_ahead_m");
    o.skips.cull_behind_m = j.at("cull_behind_m");
    o.skips.cull_side_m = j.at("cull_side_m");
    o.skips.cull_every = j.at("cull_every");
    o.skips.cull_geoms = j.value("cull_geoms", true);  // runs before the switch existed: same contacts either way
    o.implicit_mode = j.at("implicit") == "scale_forces" ? ImplicitMode::ScaleForces : ImplicitMode::EffectiveMass;
    o.end_walls = j.at("end_walls");
    o.settle_s = j.at("settle_s");
    o.overlap_tolerance_over_d = j.at("overlap_tolerance_over_d");
    o.restart_every_s = j.at("restart_every_s");
  } catch (const nlohmann::json::exception& e) {
    throw InputError(fmt::format("{}: ode_options: {}", mf.string(), e.what()));
  }
  o.out_dir = run_dir;
  o.resume = true;
  o.progress = cli.progress;
  o.crash_after_step = cli.crash_after_step;
  o.stop_after_step = cli.stop_after_step;
  return o;
}

}  // namespace

RunResult run_case(const RunOptions& cli_options) {
  const RunOptions o = cli_options.resume ? options_from_meta(cli_options.out_dir, cli_options) : cli_options;
  using clock = std::chrono::steady_clock;
  const auto t_start = clock::now();
  const fs::path case_file = fs::is_directory(o.case_dir) ? o.case_dir / "case.yaml" : o.case_dir;
  const Case c = run::load_case_with_overrides(case_file, {o.model, o.treatment, o.duration_s}, "[brash-ode]");
  StepperSettings st = o.stepper;
  if (!(st.dt_s > 0) || !std::isfinite(st.dt_s)) throw InputError(fmt::format("--dt {}: must be > 0", st.dt_s));

  // Inputs: the packing is generated on first use (cached in the case folder); the hull must exist.
  run::prepare_case_inputs(c, case_file, "[brash-ode]");
  const auto spheres = read_case_packing(c);  // checked against the case before any output
  if (spheres.empty()) throw InputError(c.ice.packing_file.string() + ": no spheres");
  check_packing(spheres, c.ice.packing_file, o.overlap_tolerance_over_d * c.ice.diameter_mean_m,
                0.5 * c.channel.width_m);
  auto mesh = hull::read_mesh(c.hull.file);
  hull::require_plausible_units(mesh, c.hull.file, c.hull.draft_m, c.hull.lpp_m);
  // Run-time guards (brash::guard, docs/stability.md): the limits of the LIGGGHTS scene box of the same case
  // (from the full hull's extents) and the hull penetration query on the full closed hull, even when the
  // contact mesh is a band (a piece slipping under the band ends up inside the full hull).
  const hull::MeshCheck full = hull::check_mesh(mesh);  // extents and closedness of the full hull
  const guard::Limits limits = guard::limits_for_case(
      c, guard::domain_box(c, full.min_m.x(), full.max_m.x(), full.min_m.z(), full.max_m.z(), c.run.duration_s));
  std::unique_ptr<hull::Proximity> hull_query;
  const bool hull_closed = full.closed;
  if (limits.max_hull_penetration_d && hull_closed) hull_query = std::make_unique<hull::Proximity>(mesh);
  // The water's flow around the hull (fluid.hull_flow) from the full hull, as the LIGGGHTS runner builds it:
  // the STL's frame is the hull body's lowered by the draft (body frame: waterline at z = 0), so the water
  // level is at z = level + draft in the STL's frame.
  core::FlowTable hull_flow;
  if (c.fluid.hull_flow == HullFlow::ThinShip)
    hull_flow = hull::thin_ship_flow(mesh, c.water.level_m + c.hull.draft_m, c.ship.speed_m_s);
  if (c.hull.band_m) mesh = hull::clip_band(mesh, c.hull.draft_m - (*c.hull.band_m)[0], c.hull.draft_m + (*c.hull.band_m)[1]);
  std::vector<double> verts;
  std::vector<dTriIndex> tris;
  verts.reserve(mesh.vertices.size() * 3);
  for (const auto& v : mesh.vertices) {
    verts.push_back(v.x());
    verts.push_back(v.y());
    verts.push_back(v.z() - c.hull.draft_m);  // waterline at z = 0 in the body frame
  }
  for (const auto& f : mesh.faces)
    for (int k : f) tris.push_back(static_cast<dTriIndex>(k));

  // Run directory.
  const fs::path run_dir =
      o.out_dir.empty() ? run::make_run_dir(o.runs_root, c.name, "ode", std::string(to_string(c.fluid.model))) : o.out_dir;
  fs::create_directories(run_dir / "particles");
  fs::create_directories(run_dir / "restart");
  const run::RunDirLock run_lock(run_dir);  // a second brash-ode in the same run directory is refused
  if (!o.resume) run::write_atomic(run_dir / "case.yaml", dump_case_yaml(c));
  std::string log = o.resume ? read_text(run_dir / "log.txt") : std::string();
  auto logln = [&](const std::string& s) {
    log += s + "\n";
    if (!o.progress) return;
    fmt::print(stderr, "[brash-ode] {}\n", s);
  };
  if (o.skips.cull)  // docs/performance.md "The far field's error": measured on LIGGGHTS with the same rule
    logln("warning: --cull freezes the ice outside the window (no wake rule): the push of the bow cannot reach past "
          "it, which raised the mean resistance by +8 to +20 % in paired LIGGGHTS ensembles");

  const auto fluid = brash::fluid_params(c);
  nlohmann::json meta = {
      {"engine", "ode"},
      {"engine_version", fmt::format("brash-ode 0.1 + ODE {} (Debian libode, double, dWorldQuickStep)", "0.16.2")},
      {"fluid_model", to_string(c.fluid.model)},
      {"treatment", to_string(c.fluid.treatment)},
      {"implicit_realisation", o.implicit_mode == ImplicitMode::EffectiveMass ? "effective_mass" : "scale_forces"},
      {"dt_s", st.dt_s},
      {"ranks", 1},
      {"threads", 1},
      {"particles", spheres.size()},
      {"wall_time_s", 0.0},
      {"particle_steps", 0},
      {"git_commit", run::git_commit()},
      {"status", "running"},
      {"reason", ""},
      {"stepper", {{"quickstep_iterations", st.iterations}, {"erp", st.erp}, {"cfm", st.cfm},
                   {"contact_surface_layer_m", st.contact_surface_layer}, {"max_contacts_per_pair", st.max_contacts_per_pair},
                   {"angular_damping", st.angular_damping}, {"contact", "dContactApprox1"},
                   {"broad_phase", st.broad_phase == BroadPhase::Sap ? "ODE sweep and prune (xyz)" : "grid (brash)"}}},
      {"skips", {{"auto_disable", o.skips.auto_disable}, {"auto_disable_far_only", o.skips.auto_disable_far_only},
                 {"disable_linear_m_s", o.skips.disable_linear_m_s}, {"disable_angular_rad_s", o.skips.disable_angular_rad_s},
                 {"disable_steps", o.skips.disable_steps}, {"cull", o.skips.cull}, {"cull_ahead_m", o.skips.cull_ahead_m},
                 {"cull_behind_m", o.skips.cull_behind_m}}},
      {"end_walls", o.end_walls},
      {"settle_s", o.settle_s},
      {"ode_options", options_json(o)},
      {"resumes", nlohmann::json::array()}};
  if (o.resume) {
    const auto old = nlohmann::json::parse(read_text(run_dir / "meta.json"));
    if (old.value("status", "") == "complete") {
      if (o.progress) fmt::print(stderr, "[brash-ode] {}: already complete, nothing to resume\n", run_dir.string());
      RunResult r;
      r.run_dir = run_dir;
      r.particles = spheres.size();
      return r;
    }
    meta = old;
    meta["status"] = "running";
    meta["reason"] = "";
  }
  run::write_meta(run_dir, meta);

  RunResult res;
  res.run_dir = run_dir;
  res.particles = spheres.size();
  std::string csv = "t_s,fx_N,fy_N,fz_N\n";
  // (t [s], fx [N]) of csv's rows as written (the early stop's input: the same numbers a replay reads)
  std::vector<std::pair<double, double>> csv_t_fx;
  auto append_csv_row = [&](const std::string& row) {
    const auto c1 = row.find(','), c2 = row.find(',', c1 + 1);
    csv += row + "\n";
    csv_t_fx.emplace_back(std::stod(row.substr(0, c1)), std::stod(row.substr(c1 + 1, c2 - c1 - 1)));
  };
  std::string index = "step,t_s,file,hull_x_m\n";
  try {
    World w(fluid, st, Frictions{c.friction.ice_ice, c.friction.ice_hull, c.friction.ice_wall}, o.skips, o.implicit_mode);
    for (const auto& s : spheres) w.add_sphere(Vec3(s.x_m, s.y_m, s.z_m), 0.5 * s.diameter_m, c.ice.density_kg_m3);
    const double speed = c.ship.speed_m_s;
    const double duration = c.run.duration_s;
    double hx0 = 1e300, hx1 = -1e300, hz0 = 1e300;
    for (std::size_t i = 0; i < verts.size(); i += 3) {
      hx0 = std::min(hx0, verts[i]);
      hx1 = std::max(hx1, verts[i]);
      hz0 = std::min(hz0, verts[i + 2]);
    }
    const double x_lo = std::min(0.0, c.hull.start_x_m + hx0) - 0.5;
    const double x_hi = std::max(c.channel.length_m, c.hull.start_x_m + hx1 + speed * duration) + 0.5;
    add_channel_walls(w, x_lo, x_hi, 0.5 * c.channel.width_m, false, std::min(-1.0, hz0 - 0.1), 0.5);
    if (o.end_walls) {
      // End walls at the channel ends, spanning only the ice layer depth so the hull passes above/through freely
      // (hull-wall pairs never collide anyway).
      w.add_wall_box(Vec3(-0.025, 0, -0.25), Vec3(0.05, c.channel.width_m, 1.5));
      w.add_wall_box(Vec3(c.channel.length_m + 0.025, 0, -0.25), Vec3(0.05, c.channel.width_m, 1.5));
    }
    w.set_hull(std::move(verts), std::move(tris), Vec3(c.hull.start_x_m, 0, 0), Vec3::Zero());
    logln(fmt::format("{} spheres, {} hull triangles{}, channel {} x {} m, dt {} s, {} quickstep iterations, ERP {}, CFM {}",
                      spheres.size(), mesh.faces.size(), c.hull.band_m ? " (waterline band)" : "", c.channel.length_m,
                      c.channel.width_m, st.dt_s, st.iterations, st.erp, st.cfm));
    logln(fmt::format("fluid model {} treatment {} (implicit realised as {}), ca_table {}, C_D {} ({})",
                      to_string(c.fluid.model), to_string(c.fluid.treatment), meta["implicit_realisation"].get<std::string>(),
                      to_string(c.fluid.ca_table), c.fluid.drag_coefficient, to_string(c.fluid.drag_law)));
    logln(fmt::format("run dir {}", run_dir.string()));
    logln(
        fmt::format("guards every {} steps: NaN/Inf; box x [{:.4g}, {:.4g}] y [{:.4g}, {:.4g}] z [{:.4g}, "
                    "{:.4g}] m; zmax {:.4g} m; "
                    "ke_max {:.4g} J; hull penetration {}; pieces beyond the x range leave the scene; "
                    "(no dt check: ODE contacts are constraint joints, see docs/stability.md)",
                    c.guards.every_steps, (*limits.box)[0], (*limits.box)[1], (*limits.box)[2],
                    (*limits.box)[3], (*limits.box)[4], (*limits.box)[5], *limits.z_max_m, *limits.ke_max_J,
                    hull_query ? fmt::format("> {:g} d (full closed hull, {} triangles)",
                                             *limits.max_hull_penetration_d, hull_query->triangles())
                               : std::string(hull_closed ? "off (guards.max_hull_penetration_d = 0)"
                                                         : "off (hull not closed)")));

    // Optional settling with the hull parked (on resume the restart file holds the state after it).
    const long settle_steps = o.resume ? 0 : std::lround(o.settle_s / st.dt_s);
    for (long k = 0; k < settle_steps; ++k) w.step();
    if (settle_steps) logln(fmt::format("settled {} s ({} steps)", o.settle_s, settle_steps));
    w.set_hull_velocity(Vec3(speed, 0, 0));
    // the hull's flow from when it moves (a parked hull has none)
    if (!hull_flow.empty()) {
      logln(fmt::format("hull flow {}: {} table nodes, largest flow speed {:.4g} m/s (ship {} m/s)",
                        to_string(c.fluid.hull_flow), hull_flow.nodes().prod(), hull_flow.max_speed_m_s(),
                        speed));
      w.set_hull_flow(std::move(hull_flow));
    }
    long ps_settle = w.stats().particle_steps;
    auto stats0 = w.stats();
    // Loop state that a restart file carries besides the world.
    long k0 = 0;
    Vec3 acc = Vec3::Zero();
    double win_sum = 0, wall_before = 0;
    long win_n = 0;
    if (o.resume) {
      const auto found = restart::load_latest(run_dir / "restart");
      for (const auto& rej : found.rejected) logln("resume: skipped " + rej);
      restart::Reader r(found.payload);
      k0 = r.get<long>();
      ps_settle = r.get<long>();
      stats0.wall_fluid_s = r.get<double>();
      stats0.wall_collide_s = r.get<double>();
      stats0.wall_step_s = r.get<double>();
      acc = r.get_vec3();
      win_sum = r.get<double>();
      win_n = r.get<long>();
      wall_before = r.get<double>();
      w.load_state(r);
      if (w.restore_inexact())
        logln(fmt::format("resume: {} sphere quaternions restored within a few ulps, not bit for bit", w.restore_inexact()));
      const double t_r = double(k0) * st.dt_s;
      // Outputs: keep only what was written up to the restart point.
      std::istringstream in(read_text(run_dir / "hull_force.csv"));
      std::string line;
      long kept = 0, dropped = 0;
      std::getline(in, line);  // header
      while (std::getline(in, line)) {
        if (line.empty()) continue;
        if (std::stod(line.substr(0, line.find(','))) <= t_r + 0.25 * st.dt_s) {
          append_csv_row(line);
          ++kept;
        } else {
          ++dropped;
        }
      }
      std::istringstream ix(read_text(run_dir / "particles" / "index.csv"));
      std::getline(ix, line);
      while (std::getline(ix, line))
        if (!line.empty() && std::stol(line.substr(0, line.find(','))) <= k0) index += line + "\n";
      meta["resumes"].push_back({{"from_file", found.file.filename().string()}, {"step", k0}, {"t_s", t_r},
                                 {"rejected", found.rejected}, {"hull_force_rows_dropped", dropped},
                                 {"quaternions_inexact", w.restore_inexact()}});
      logln(fmt::format("resumed from {} at step {} (t = {} s): kept {} hull force rows, dropped {} later ones",
                        found.file.string(), k0, t_r, kept, dropped));
    }
    auto save_restart = [&](long step, double wall) {
      restart::Writer rw;
      rw.put<long>(step);
      rw.put<long>(ps_settle);
      rw.put<double>(stats0.wall_fluid_s);
      rw.put<double>(stats0.wall_collide_s);
      rw.put<double>(stats0.wall_step_s);
      rw.put(acc);
      rw.put<double>(win_sum);
      rw.put<long>(win_n);
      rw.put<double>(wall);
      w.save_state(rw);
      return restart::write(run_dir / "restart", step, rw.bytes(), 2);
    };

    const long steps = std::lround(duration / st.dt_s);
    const long n_out = std::max(1L, std::lround(c.run.output_interval_s / st.dt_s));
    const long n_dump = std::max(1L, std::lround(c.run.dump_interval_s / st.dt_s));
    const long n_restart = o.restart_every_s > 0 ? std::max(1L, std::lround(o.restart_every_s / st.dt_s)) : 0;
    const bool tty = isatty(2);
    // Early stop (speedups.early_stop_rel_ci; the rule of brash/stats/early_stop.hpp, checked as often as the
    // LIGGGHTS runner does: every 1/200 of the run) on the hull force rows written so far.
    const double es_rel = c.speedups.early_stop_rel_ci, es_t0 = c.run.window_s[0], es_t1 = c.run.window_s[1];
    const long n_check = std::max(1L, steps / 200);
    auto resistance_rows = [&](double t_now) {
      std::vector<double> r;
      for (const auto& [tr, fx] : csv_t_fx)
        if (tr >= es_t0 - 1e-12 && tr <= t_now + 1e-12) r.push_back(-fx);
      return r;
    };
    bool es_stopped = false;
    brash::stats::BlockingResult es_at;
    long k_end = steps;
    auto dump = [&](long step) {
      std::string s = "id,x,y,z,radius,vx,vy,vz,submerged_fraction,ca_x,ca_y,ca_z\n";
      for (std::size_t i = 0; i < w.size(); ++i) {
        const Vec3 x = w.position(i), v = w.velocity(i);
        if (!x.allFinite() || !v.allFinite())
          throw std::runtime_error(fmt::format("sphere {} has a non-finite position/velocity at t = {} s (step {})", i + 1,
                                               double(step) * st.dt_s, step));
        const auto im = core::immersion(w.radius(i), x.z(), c.water.level_m);
        const Vec3& ca = w.fluid_output(i).ca;
        s += fmt::format("{},{:.9g},{:.9g},{:.9g},{:.9g},{:.6g},{:.6g},{:.6g},{:.6g},{:.4g},{:.4g},{:.4g}\n", i + 1, x.x(), x.y(),
                         x.z(), w.radius(i), v.x(), v.y(), v.z(), im.fraction, ca.x(), ca.y(), ca.z());
      }
      const std::string name = fmt::format("particles_{}.csv", step);
      run::write_atomic(run_dir / "particles" / name, s);
      index += fmt::format("{},{:.9g},{},{:.9g}\n", step, double(step) * st.dt_s, name, w.hull_position().x());
      run::write_atomic(run_dir / "particles" / "index.csv", index);
    };
    auto flush = [&](long step, double wall) {  // wall: this process's time; wall_before adds earlier ones
      run::write_atomic(run_dir / "hull_force.csv", csv);
      run::write_atomic(run_dir / "log.txt", log);
      meta["wall_time_s"] = wall_before + wall;
      meta["particle_steps"] = w.stats().particle_steps - ps_settle;
      meta["steps_done"] = step;
      run::write_meta(run_dir, meta);
    };
    // The guards on every sphere (lowest id first); a stop is a GuardStop naming the step, the piece and the
    // cause. The hull's STL frame origin is the hull body's position lowered by the draft (body frame:
    // waterline z = 0).
    // A piece beyond the box's x-ends left through the channel's open ends (behind the stern's start or ahead
    // of the bow's end position: it can never reach the hull again; with added_mass alone nothing damps a
    // loose piece's horizontal speed): it is retired (World::retire, as LIGGGHTS' fix brash/exit removes it),
    // not a guard stop. Leaving through the sides or the top stays a stop.
    const double exit_lo_m = (*limits.box)[0], exit_hi_m = (*limits.box)[1];
    auto check_guards = [&](long step) {
      guard::HullNow hull_now{hull_query.get(), w.hull_position() - Vec3(0, 0, c.hull.draft_m)};
      std::size_t exits_now = 0;
      for (std::size_t i = 0; i < w.size(); ++i) {
        if (w.retired(i)) continue;
        guard::Piece p;
        p.x_m = w.position(i);
        if ((p.x_m.x() < exit_lo_m || p.x_m.x() > exit_hi_m) && p.x_m.allFinite() &&
            w.velocity(i).allFinite()) {
          w.retire(i);
          ++exits_now;
          continue;
        }
        p.v_m_s = w.velocity(i);
        p.omega_rad_s = w.angular_velocity(i);
        p.radius_m = w.radius(i);
        p.mass_kg = w.mass(i);
        if (const auto cause = guard::check_piece(p, limits, hull_query ? &hull_now : nullptr))
          throw GuardStop(
              guard::stop_message(step, double(step) * st.dt_s, static_cast<long>(i) + 1, *cause));
      }
      if (exits_now) {
        logln(fmt::format(
            "step {} (t = {:.4f} s): {} piece(s) left the scene through the channel's ends (x < {:.6g} "
            "or x > {:.6g} m); {} in all",
            step, double(step) * st.dt_s, exits_now, exit_lo_m, exit_hi_m, w.retired_count()));
        meta["exits"] = w.retired_count();
      }
    };
    if (!o.resume) {
      check_guards(0);
      dump(0);
    }
    const auto loop0 = clock::now();
    const long ps_loop0 = w.stats().particle_steps;
    auto last_print = loop0;
    const StopSignals stop_signals;
    int stop_signal = 0;
    for (long k = k0 + 1; k <= steps; ++k) {
      w.step();
      if (k % c.guards.every_steps == 0 || k == steps) check_guards(k);
      const Vec3& f = w.hull_force();
      if (!f.allFinite())
        throw std::runtime_error(fmt::format("non-finite hull force at t = {} s (step {})", double(k) * st.dt_s, k));
      acc += f;
      const double t = double(k) * st.dt_s;
      if (t >= c.run.window_s[0] - 1e-12 && t <= c.run.window_s[1] + 1e-12) {
        win_sum += f.x();
        ++win_n;
      }
      if (k % n_out == 0) {
        const Vec3 m = acc / double(n_out);
        append_csv_row(fmt::format("{:.6f},{:.9g},{:.9g},{:.9g}", t, m.x(), m.y(), m.z()));
        acc.setZero();
      }
      if (es_rel > 0 && k % n_check == 0 && k < steps &&
          t >= es_t0 + brash::stats::kEarlyStopFirstCheckFraction * (es_t1 - es_t0)) {
        const auto v = brash::stats::early_stop_verdict(resistance_rows(t), t, es_t0, es_t1, es_rel,
                                                        c.speedups.early_stop_trend_check);
        if (v.stop) {
          es_stopped = true, es_at = v.blocking, k_end = k;
          logln(fmt::format("early stop at t = {:.4f} s: window mean {:.4g} N, 95 % CI +-{:.3g} N ({:.2f} % < {:.2f} %)",
                            t, v.blocking.mean, v.blocking.ci95, 100 * v.blocking.ci95 / std::abs(v.blocking.mean),
                            100 * es_rel));
          dump(k);
          break;
        }
      }
      const auto now = clock::now();
      if (k % n_dump == 0 || k == steps) {
        dump(k);
        flush(k, std::chrono::duration<double>(now - t_start).count());
      }
      if (n_restart && k % n_restart == 0 && k < steps) {
        // hull_force.csv first (rows up to t), then the restart file: a resume drops rows after its restart time.
        flush(k, std::chrono::duration<double>(now - t_start).count());
        save_restart(k, wall_before + std::chrono::duration<double>(now - t_start).count());
      }
      if (k == o.crash_after_step) std::_Exit(137);
      if (o.stop_after_step == k) std::raise(SIGTERM);  // testing: a stop request arriving during step k
      if (stop_signals.received() != 0 && k < steps) {
        stop_signal = stop_signals.received();
        k_end = k;
        break;
      }
      if (o.progress && (std::chrono::duration<double>(now - last_print).count() > 1.0 || k == steps)) {
        last_print = now;
        const double el = std::chrono::duration<double>(now - loop0).count();
        const double eta = el / double(k - k0) * double(steps - k);
        const auto line = fmt::format("t = {:.3f} / {:.3f} s ({:3.0f}%)  elapsed {}  ETA {}  Fx {:+.3f} N  awake {}  contacts {}",
                                      t, duration, 100.0 * double(k) / double(steps), hms(el), hms(eta), f.x(),
                                      w.stats().awake_last, w.stats().contacts_last);
        if (tty) fmt::print(stderr, "\r[brash-ode] {}   ", line);
        else fmt::print(stderr, "[brash-ode] {}\n", line);
        log += line + "\n";
      }
    }
    if (o.progress && tty) fmt::print(stderr, "\n");
    const auto now = clock::now();
    res.loop_time_s = std::chrono::duration<double>(now - loop0).count();
    res.wall_time_s = wall_before + std::chrono::duration<double>(now - t_start).count();
    const double t_end = double(k_end) * st.dt_s;
    res.steps = k_end;
    res.simulated_s = t_end;
    res.stats = w.stats();
    res.particle_steps = w.stats().particle_steps - ps_settle;
    res.mean_fx_window_N = win_n ? win_sum / double(win_n) : NAN;
    if (stop_signal != 0) {
      // Resumable where it stopped: the rows so far, then the restart file of this step (a resume drops rows
      // after its restart time, so the order matters as for the periodic files).
      meta["status"] = "stopped";
      meta["reason"] =
          fmt::format("stopped by signal {} at step {} (t = {:.4f} s); resume with brash-ode --resume {}",
                      stop_signal == SIGINT ? "SIGINT" : "SIGTERM", k_end, t_end, run_dir.string());
      logln(meta["reason"].get<std::string>());
      flush(k_end, res.wall_time_s - wall_before);
      save_restart(k_end, res.wall_time_s);
      if (o.progress) fmt::print(stderr, "[brash-ode] {}\n", meta["reason"].get<std::string>());
      res.stopped_by_signal = stop_signal;
      return res;
    }
    meta["status"] = "complete";
    meta["loop_time_s"] = res.loop_time_s;
    // Rates from this process's loop only (a resumed run: the steps since the restart point).
    const double ps_this = double(w.stats().particle_steps - ps_loop0);
    meta["particle_steps_per_s"] = ps_this / res.loop_time_s;
    meta["wall_s_per_simulated_s"] = res.loop_time_s / (t_end - double(k0) * st.dt_s);
    if (es_stopped) {
      // The run ends at the stop: the resolved case says so (its window ends there), meta records why.
      brash::Case stopped = c;
      stopped.run.duration_s = t_end;
      stopped.run.window_s[1] = std::min(stopped.run.window_s[1], t_end);
      run::write_atomic(run_dir / "case.yaml", dump_case_yaml(stopped));
      meta["early_stop"] = {{"t_s", t_end},          {"requested_duration_s", duration},
                            {"rel_ci_threshold", es_rel}, {"mean_N", es_at.mean},
                            {"ci95_N", es_at.ci95}};
    }
    meta["phase_wall_s"] = {{"fluid", res.stats.wall_fluid_s - stats0.wall_fluid_s},
                            {"collide", res.stats.wall_collide_s - stats0.wall_collide_s},
                            {"quickstep", res.stats.wall_step_s - stats0.wall_step_s}};
    meta["mean_fx_window_N"] = res.mean_fx_window_N;
    meta["cull_geoms_out_max"] = res.stats.geoms_out_max;
    logln(fmt::format("done: {} steps in {:.1f} s ({:.3g} particle-steps/s, {:.1f} s wall per simulated s); "
                      "mean Fx over [{}, {}] s = {:.4f} N",
                      k_end - k0, res.loop_time_s, ps_this / res.loop_time_s,
                      res.loop_time_s / (t_end - double(k0) * st.dt_s),
                      c.run.window_s[0], c.run.window_s[1], res.mean_fx_window_N));
    flush(k_end, res.wall_time_s - wall_before);
  } catch (const std::exception& e) {
    // Outputs stay consistent: hull_force.csv holds the rows up to the stop, particles/ the snapshots written
    // before it, meta.json says failed with the reason (a guard stop: step, piece and cause).
    log += std::string("error: ") + e.what() + "\n";
    if (o.progress) fmt::print(stderr, "\n[brash-ode] stopped: {}\n", e.what());
    meta["status"] = "failed";
    meta["reason"] = e.what();
    meta["wall_time_s"] = std::chrono::duration<double>(clock::now() - t_start).count();
    run::write_atomic(run_dir / "hull_force.csv", csv);
    run::write_atomic(run_dir / "log.txt", log);
    run::write_meta(run_dir, meta);
    throw;
  }
  return res;
}

}  // namespace brash::ode
