// brash-ode's settings from the case (run_case.hpp): the stepper, the implicit realisation and the far field; a
// particle dump as the starting scene (--scene-from); run directories from before the ode: case keys.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <unordered_map>

#include "brash/case.hpp"
#include "brash/case_derive.hpp"
#include "brash/core/far_field.hpp"
#include "brash/error.hpp"
#include "brash/run/driver.hpp"
#include "brash/run/run_layout.hpp"
#include "ode_internal.hpp"

namespace brash::ode {
namespace fs = std::filesystem;

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A particle dump (particles/*.csv of any engine's run: a header naming id,x,y,z,radius and optionally vx,vy,vz and
// omegax,omegay,omegaz): the pieces in the file's order with their velocities (zero without the columns). Of a
// moving window's snapshot (a state column) the pieces in its scene (state 0) and those held out ahead at their
// packing position (state 1, at rest); the removed ones (state 2) are left out. InputError naming file, line and
// column.
SceneFromDump read_scene_dump(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(fmt::format("--scene-from {}: cannot be read", file.string()));
  std::string line;
  int ln = 0;
  std::unordered_map<std::string, std::size_t> col;
  while (std::getline(in, line)) {
    ++ln;
    if (line.empty() || line[0] == '#') continue;
    std::stringstream ss(line);
    std::string name;
    for (std::size_t i = 0; std::getline(ss, name, ','); ++i) col[name] = i;
    break;
  }
  for (const char* need : {"x", "y", "z", "radius"})
    if (!col.count(need))
      throw InputError(fmt::format("{}:{}: no column \"{}\" in the header (a particle dump: id,x,y,z,radius,vx,vy,vz)",
                                   file.string(), ln, need));
  SceneFromDump out;
  out.has_velocity = col.count("vx") && col.count("vy") && col.count("vz");
  out.has_angular_velocity = col.count("omegax") && col.count("omegay") && col.count("omegaz");
  out.has_state = col.count("state") > 0;
  const auto vec = [&](const std::vector<double>& v, bool has, const char* x, const char* y, const char* z) {
    return has ? Vec3(v[col[x]], v[col[y]], v[col[z]]) : Vec3::Zero();
  };
  std::vector<double> v;
  while (std::getline(in, line)) {
    ++ln;
    if (line.empty() || line[0] == '#') continue;
    v.clear();
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) {
      char* end = nullptr;
      v.push_back(std::strtod(cell.c_str(), &end));
      if (end == cell.c_str() || !std::isfinite(v.back()))
        throw InputError(fmt::format("{}:{}: \"{}\" is not a finite number", file.string(), ln, cell));
    }
    if (v.size() < col.size()) throw InputError(fmt::format("{}:{}: {} values, the header names {}", file.string(), ln, v.size(), col.size()));
    if (out.has_state) {
      const double state = v[col["state"]];
      if (state != 0 && state != 1 && state != 2)
        throw InputError(fmt::format("{}:{}: state {} is not 0 (in the scene), 1 (held out) or 2 (removed)",
                                     file.string(), ln, state));
      if (state == 2) {
        ++out.removed;
        continue;
      }
      ++(state == 0 ? out.in_scene : out.held_out);
    }
    const double r = v[col["radius"]];
    if (!(r > 0)) throw InputError(fmt::format("{}:{}: radius {} is not > 0", file.string(), ln, r));
    out.spheres.push_back({v[col["x"]], v[col["y"]], v[col["z"]], 2 * r});
    out.ids.push_back(col.count("id") ? std::lround(v[col["id"]]) : long(out.spheres.size()));
    out.velocity_m_s.push_back(vec(v, out.has_velocity, "vx", "vy", "vz"));
    out.angular_velocity_rad_s.push_back(vec(v, out.has_angular_velocity, "omegax", "omegay", "omegaz"));
  }
  if (!out.has_state) out.in_scene = static_cast<long>(out.spheres.size());
  if (out.spheres.empty()) throw InputError(fmt::format("{}: no pieces", file.string()));
  return out;
}

StepperSettings stepper_settings(const Case& c) {
  const OdeSpec& o = c.ode;
  StepperSettings st;
  st.dt_s = o.timestep_s;
  st.iterations = o.iterations;
  st.erp = o.erp;
  st.cfm = o.cfm;
  st.contact_surface_layer = o.surface_layer_m;
  st.angular_damping = o.angular_damping;
  st.broad_phase = o.broad_phase == OdeBroadPhase::Sap ? BroadPhase::Sap : BroadPhase::Grid;
  return st;
}

ImplicitMode implicit_mode(const Case& c) {
  return c.ode.implicit == OdeImplicit::ScaleForces ? ImplicitMode::ScaleForces : ImplicitMode::EffectiveMass;
}

Skips far_field_skips(const Case& c) {
  const SpeedupSpec& sp = c.speedups;
  const OdeSpec& o = c.ode;
  Skips k;
  k.auto_disable = o.auto_disable;
  k.disable_linear_m_s = o.auto_disable_linear_m_s;
  k.disable_angular_rad_s = o.auto_disable_angular_rad_s;
  k.disable_steps = o.auto_disable_steps;
  k.cull = sp.farfield;
  k.cull_ahead_m = sp.farfield_ahead_m;
  k.cull_behind_m = sp.farfield_behind_m;
  k.cull_side_m = sp.farfield_beside_m.value_or(Skips{}.cull_side_m);
  // the membership period in model time (farfield_every_steps DEM steps) in ODE steps
  k.cull_every = std::max(1, static_cast<int>(std::lround(sp.farfield_every_steps * c.run.timestep_s / o.timestep_s)));
  k.wake_force_N = core::wake_force_N(sp.farfield_wake_force_weight, c.ice.diameter_mean_m, c.ice.density_kg_m3,
                                      c.water.gravity_m_s2);
  k.wake_speed_m_s = sp.farfield_wake_speed_m_s;
  k.wake_by = sp.farfield_wake_by;
  k.front_speed_m_s = sp.farfield_front_speed_m_s;
  k.cull_geoms = o.idle_geoms_out;
  return k;
}

namespace {

// The far field a run from before the ode: case keys ran with: its --cull* options (negative: not given) over its
// case's speedups.farfield_*, as that brash-ode merged them.
Skips far_field_before_case_keys(const nlohmann::json& j, const Case& c) {
  const SpeedupSpec& sp = c.speedups;
  const Skips defaults;
  Skips k;
  k.auto_disable = j.at("auto_disable");
  k.disable_linear_m_s = j.at("disable_linear_m_s");
  k.disable_angular_rad_s = j.at("disable_angular_rad_s");
  k.disable_steps = j.at("disable_steps");
  k.auto_disable_far_only = j.at("auto_disable_far_only");
  k.cull = j.at("cull").get<bool>() || sp.farfield;
  const auto pick = [&](const char* given, double from_case, double otherwise) {
    const double g = j.at(given);
    return g >= 0 ? g : sp.farfield ? from_case : otherwise;
  };
  k.cull_ahead_m = pick("cull_ahead_m", sp.farfield_ahead_m, defaults.cull_ahead_m);
  k.cull_behind_m = pick("cull_behind_m", sp.farfield_behind_m, defaults.cull_behind_m);
  k.cull_side_m = pick("cull_side_m", sp.farfield_beside_m.value_or(defaults.cull_side_m), defaults.cull_side_m);
  k.cull_every = sp.farfield ? std::max(1, static_cast<int>(std::lround(sp.farfield_every_steps * c.run.timestep_s /
                                                                         j.at("dt_s").get<double>())))
                             : j.at("cull_every").get<int>();
  const double weight = j.value("cull_wake_force_weight", 0.0);  // runs before the wake: the window alone
  k.wake_force_N = core::wake_force_N(weight >= 0 ? weight : sp.farfield_wake_force_weight, c.ice.diameter_mean_m,
                                      c.ice.density_kg_m3, c.water.gravity_m_s2);
  const double speed = j.value("cull_wake_speed_m_s", 0.0);
  k.wake_speed_m_s = speed >= 0 ? speed : sp.farfield_wake_speed_m_s;
  k.wake_by = sp.farfield_wake_by;
  k.front_speed_m_s = sp.farfield_front_speed_m_s;
  k.cull_geoms = j.value("cull_geoms", true);
  return k;
}

bool same_far_field(const Skips& a, const Skips& b) {
  // with neither culling nor auto-disable nothing is skipped, and the window's settings are used nowhere
  const bool a_off = !a.cull && !a.auto_disable, b_off = !b.cull && !b.auto_disable;
  if (a_off || b_off) return a_off == b_off;
  return a.auto_disable == b.auto_disable && a.disable_linear_m_s == b.disable_linear_m_s &&
         a.disable_angular_rad_s == b.disable_angular_rad_s && a.disable_steps == b.disable_steps &&
         a.auto_disable_far_only == b.auto_disable_far_only && a.cull == b.cull && a.cull_ahead_m == b.cull_ahead_m &&
         a.cull_behind_m == b.cull_behind_m && a.cull_side_m == b.cull_side_m && a.cull_every == b.cull_every &&
         a.wake_force_N == b.wake_force_N && a.wake_speed_m_s == b.wake_speed_m_s && a.wake_by == b.wake_by &&
         a.front_speed_m_s == b.front_speed_m_s && a.cull_geoms == b.cull_geoms;
}

std::string number_text(double x) { return fmt::format("{}", x); }

// The case keys that give a run from before the ode: section the settings of its "ode_options".
CaseOverrides case_keys_of(const nlohmann::json& j, const Case& c, const fs::path& meta_file) {
  const auto refuse = [&](const std::string& why) {
    throw InputError(fmt::format("{}: \"ode_options\": {}; the case keys cannot say that, so this brash-ode cannot "
                                 "resume the run as it was set up: resume it with the brash-ode that started it, or "
                                 "run its case again",
                                 meta_file.string(), why));
  };
  if (!j.value("scene_from", std::string()).empty()) refuse("a bench-ode run from another run's scene");
  if (j.at("max_contacts_per_pair").get<int>() != StepperSettings{}.max_contacts_per_pair)
    refuse("max_contacts_per_pair is not " + std::to_string(StepperSettings{}.max_contacts_per_pair));
  if (j.at("end_walls").get<bool>() && c.channel.ends != ChannelEnds::Walls)
    refuse("end walls, and its case.yaml has channel.ends: open");
  if (!j.at("auto_disable_far_only").get<bool>()) refuse("auto-disable everywhere (auto_disable_far_only false)");
  const double dt_s = j.at("dt_s");
  CaseOverrides set = {
      {"ode.timestep_s", number_text(dt_s)},
      {"ode.iterations", std::to_string(j.at("iterations").get<int>())},
      {"ode.erp", number_text(j.at("erp"))},
      {"ode.cfm", number_text(j.at("cfm"))},
      {"ode.surface_layer_m", number_text(j.at("contact_surface_layer_m"))},
      {"ode.angular_damping", number_text(j.at("angular_damping"))},
      {"ode.implicit", j.at("implicit").get<std::string>()},
      // runs before the switches existed used sap, the same contacts as grid, and the spatial order
      {"ode.broad_phase", j.value("broad_phase", "grid")},
      {"ode.sphere_order", j.value("sphere_order", "spatial")},
      {"ode.idle_geoms_out", j.value("cull_geoms", true) ? "true" : "false"},
      {"ode.auto_disable", j.at("auto_disable").get<bool>() ? "true" : "false"},
      {"ode.auto_disable_linear_m_s", number_text(j.at("disable_linear_m_s"))},
      {"ode.auto_disable_angular_rad_s", number_text(j.at("disable_angular_rad_s"))},
      {"ode.auto_disable_steps", std::to_string(j.at("disable_steps").get<int>())},
      {"ode.settle_s", number_text(j.at("settle_s"))},
      {"ode.settle_damping", number_text(j.value("settle_damping", 0.0))}};
  const Skips before = far_field_before_case_keys(j, c);
  if (!before.cull && !before.auto_disable) return set;  // the far field's keys act on nothing
  // the window, the wake and the membership period that run had, as the case's far field
  if (before.cull) set.emplace_back("speedups.farfield", "true");
  set.emplace_back("speedups.farfield_ahead_m", number_text(before.cull_ahead_m));
  set.emplace_back("speedups.farfield_behind_m", number_text(before.cull_behind_m));
  set.emplace_back("speedups.farfield_beside_m",
                   before.cull_side_m < Skips{}.cull_side_m ? number_text(before.cull_side_m) : "~");
  const double weight = j.value("cull_wake_force_weight", 0.0);
  if (weight >= 0) set.emplace_back("speedups.farfield_wake_force_weight", number_text(weight));
  set.emplace_back("speedups.farfield_wake_speed_m_s", number_text(before.wake_speed_m_s));
  if (!c.speedups.farfield)
    set.emplace_back("speedups.farfield_every_steps",
                     std::to_string(std::max(1L, std::lround(before.cull_every * dt_s / c.run.timestep_s))));
  return set;
}

}  // namespace

namespace {

// The snapshot's own model time where its folder's index.csv (particles/index.csv: step,t_s,file,...) lists it.
std::optional<double> indexed_time_s(const fs::path& file) {
  std::ifstream in(file.parent_path() / "index.csv");
  std::string line;
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::string step, t, name;
    if (std::getline(ss, step, ',') && std::getline(ss, t, ',') && std::getline(ss, name, ',') &&
        name == file.filename().string()) {
      char* end = nullptr;
      const double t_s = std::strtod(t.c_str(), &end);
      if (end != t.c_str()) return t_s;
    }
  }
  return std::nullopt;
}

}  // namespace

void take_scene_from(run::DriverOptions& d, RunOptions& o) {
  if (!d.resume_dir.empty()) {  // the scene the run started from
    const auto meta = nlohmann::json::parse(read_text(d.resume_dir / "meta.json"), nullptr, false);
    if (meta.is_object() && meta.value("scene_from", std::string()) != "") {
      o.scene_from = meta["scene_from"].get<std::string>();
      o.scene_time_s = meta.value("scene_time_s", 0.0);
      if (!fs::exists(o.scene_from))
        throw InputError(fmt::format("{}: the run started from the snapshot {} (\"scene_from\"), which is gone: a "
                                     "resume builds its scene from it again",
                                     (d.resume_dir / "meta.json").string(), o.scene_from.string()));
    }
    return;
  }
  if (o.scene_from.empty()) return;
  o.scene_from = fs::absolute(o.scene_from).lexically_normal();
  const double t0 = o.scene_time_s;
  if (const auto t = indexed_time_s(o.scene_from); t && std::abs(*t - t0) > 1e-6)
    throw InputError(fmt::format("--scene-time {} s: {} is the snapshot at t = {} s ({})", t0, o.scene_from.string(),
                                 *t, (o.scene_from.parent_path() / "index.csv").string()));
  const Case c = run::load_run_case(d, "[brash-ode]");
  const double t1 = c.run.duration_s;
  if (!(t1 > t0))
    throw InputError(fmt::format("{} is not after --scene-time {} s: a run from another run's scene goes on from "
                                 "--scene-time to --duration, the model time to reach",
                                 d.overrides.duration_s > 0 ? fmt::format("--duration {} s", t1)
                                                            : fmt::format("the case's run.duration_s {} s", t1),
                                 t0));
  const auto [w0, w1] = c.run.window_s;
  if (w1 <= t0)
    throw InputError(fmt::format("run.window_s [{}, {}] s ends before --scene-time {} s, where the run starts: set a "
                                 "window inside the run, e.g. --set run.window_s=[{}, {}]",
                                 w0, w1, t0, t0, t1));
  if (w0 < t0) {  // the run covers the window from its start on
    o.requested_window_s = {w0, w1};
    d.overrides.sets.emplace_back("run.window_s", fmt::format("[{}, {}]", t0, w1));
    fmt::print(stderr, "[brash-ode] run.window_s [{}, {}] s begins before --scene-time {} s: the run averages over "
                       "[{}, {}] s (its case.yaml)\n", w0, w1, t0, t0, w1);
  }
}

double restart_every_of_run(const fs::path& run_dir) {
  const auto meta = nlohmann::json::parse(read_text(run_dir / "meta.json"), nullptr, false);
  if (!meta.is_object()) return -1;
  const nlohmann::json& from = meta.contains("ode_options") ? meta["ode_options"] : meta;
  const auto it = from.find("restart_every_s");
  return it != from.end() && it->is_number() ? it->get<double>() : -1;
}

bool move_ode_options_into_case(const fs::path& run_dir) {
  const fs::path meta_file = run_dir / "meta.json", case_file = run_dir / "case.yaml";
  auto meta = nlohmann::json::parse(read_text(meta_file), nullptr, false);
  if (!meta.is_object() || !meta.contains("ode_options")) return false;
  run::RunDirLock lock(run_dir);  // not under a run still going
  const Case c = load_case(case_file);
  CaseOverrides set;
  try {
    set = case_keys_of(meta["ode_options"], c, meta_file);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(fmt::format("{}: \"ode_options\": {}", meta_file.string(), e.what()));
  }
  Case moved;
  try {
    moved = parse_case(derive_case(case_file, set), run_dir, case_file.string());
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: its \"ode_options\" as case keys: {}", meta_file.string(), e.what()));
  }
  if (!same_far_field(far_field_skips(moved), far_field_before_case_keys(meta["ode_options"], c)))
    throw InputError(fmt::format("{}: \"ode_options\": a far field the case keys cannot give to the step (its "
                                 "membership period or window); resume it with the brash-ode that started it, or run "
                                 "its case again",
                                 meta_file.string()));
  run::write_atomic(case_file, dump_case_yaml(moved));
  meta.erase("ode_options");
  run::write_meta(run_dir, meta);
  return true;
}

}  // namespace brash::ode
