// brash-ode's case runner: the ODE adapter of the run driver (run_case.hpp).
#include "brash/ode/run_case.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numeric>
#include <optional>
#include <sstream>
#include <unordered_map>

#include "brash/case.hpp"
#include "brash/case_fluid.hpp"
#include "brash/case_hull_flow.hpp"
#include "brash/core/spatial_order.hpp"
#include "brash/error.hpp"
#include "brash/run/force_record.hpp"
#include "brash/run/guard.hpp"
#include "brash/run/hull_regions.hpp"
#include "brash/hull/flow.hpp"
#include "brash/hull/mesh.hpp"
#include "brash/hull/proximity.hpp"
#include "brash/ode/restart.hpp"
#include "brash/packing.hpp"
#include "brash/run/run_layout.hpp"
#include "brash/run/settle.hpp"
#include "ode_internal.hpp"

namespace brash::ode {
namespace fs = std::filesystem;

namespace {

// A run-time guard stopped the run (guard::stop_message).
class GuardStop : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace

struct OdeEngine::Scene {
  Case c;
  std::vector<Sphere> spheres;
  hull::Mesh contact_mesh;            // the hull the ice touches (the band when hull.band_m)
  guard::Limits limits;
  std::unique_ptr<hull::Proximity> hull_query;  // the full closed hull, for the penetration guard
  bool hull_closed = false;
  core::FlowTable hull_flow;          // fluid.hull_flow from the full hull
  StepperSettings stepper;            // the case's (stepper_settings), the surface layer raised for a settled bed
  bool surface_layer_from_bed = false;  // the contact surface layer is the settled bed's largest overlap
  Skips skips;                        // far_field_skips of the case
  ImplicitMode implicit = ImplicitMode::EffectiveMass;
  std::vector<Vec3> velocity_m_s;     // the pieces' starting velocities (--scene-from; empty: at rest)
  SceneFromDump dump;                 // --scene-from: the ids, angular velocities and counts (its pieces moved out)
  long first_step = 0;                // the step of the starting scene (--scene-time over the ODE step; 0)
  core::HullRegions hull_regions;     // the hull force split's, measured on the full hull
};

namespace {

// The piece of the packing that spheres[j] is (1-based): the dump's id, else the packing's order.
long piece_id(const OdeEngine::Scene& s, std::size_t j) {
  return s.dump.ids.empty() ? static_cast<long>(j) + 1 : s.dump.ids[j];
}

// A dump's pieces are the case's: each id one of its packing's pieces, once, with that piece's radius (to the
// dump's printed digits). InputError naming the file and the id.
void check_dump_is_of_case(const SceneFromDump& dump, const std::vector<Sphere>& packing, const fs::path& file) {
  std::vector<bool> seen(packing.size(), false);
  for (std::size_t j = 0; j < dump.ids.size(); ++j) {
    const long id = dump.ids[j];
    if (id < 1 || id > static_cast<long>(packing.size()))
      throw InputError(fmt::format("--scene-from {}: piece id {} is not one of the case's {} pieces (a snapshot of "
                                   "another case?)",
                                   file.string(), id, packing.size()));
    if (seen[std::size_t(id - 1)])
      throw InputError(fmt::format("--scene-from {}: piece id {} appears twice", file.string(), id));
    seen[std::size_t(id - 1)] = true;
    const double d_case = packing[std::size_t(id - 1)].diameter_m, d_dump = dump.spheres[j].diameter_m;
    if (std::abs(d_dump - d_case) > 1e-4 * d_case)
      throw InputError(fmt::format("--scene-from {}: piece {} has radius {} m, the case's packing {} m (a snapshot of "
                                   "another case?)",
                                   file.string(), id, 0.5 * d_dump, 0.5 * d_case));
  }
}

}  // namespace

OdeEngine::OdeEngine(RunOptions options) : options_(std::move(options)) {}
OdeEngine::~OdeEngine() = default;

nlohmann::json OdeEngine::meta() const {
  if (!scene_) return {{"resumes", nlohmann::json::array()}};
  const auto& st = scene_->stepper;
  const Skips& k = scene_->skips;
  nlohmann::json scene;
  if (!options_.scene_from.empty()) {
    const SceneFromDump& dump = scene_->dump;
    scene = {{"particles", scene_->spheres.size()},
             {"scene_from", options_.scene_from.string()},
             {"scene_time_s", options_.scene_time_s},
             {"scene_pieces", {{"in_scene", dump.in_scene}, {"held_out", dump.held_out}, {"removed", dump.removed}}}};
    if (options_.requested_window_s) scene["requested_window_s"] = *options_.requested_window_s;
  }
  nlohmann::json meta = {
      {"engine_version", fmt::format("brash-ode 0.1 + ODE {} (Debian libode, double, dWorldQuickStep)", "0.16.2")},
      {"implicit_realisation", to_string(scene_->c.ode.implicit)},
      {"dt_s", st.dt_s},
      {"restart_every_s", options_.restart_every_s},  // a resume keeps it (restart_every_of_run)
      {"ranks", 1},
      {"threads", 1},
      {"stepper", {{"quickstep_iterations", st.iterations}, {"erp", st.erp}, {"cfm", st.cfm},
                   {"contact_surface_layer_m", st.contact_surface_layer}, {"max_contacts_per_pair", st.max_contacts_per_pair},
                   {"angular_damping", st.angular_damping},
                   {"contact", scene_->c.contact.rolling_friction != 0 ? "dContactApprox1 | dContactRolling | "
                                                                         "dContactAxisDep"
                                                                       : "dContactApprox1"},
                   {"broad_phase", st.broad_phase == BroadPhase::Sap ? "ODE sweep and prune (xyz)" : "grid (brash)"}}},
      {"skips", {{"auto_disable", k.auto_disable}, {"auto_disable_far_only", k.auto_disable_far_only},
                 {"disable_linear_m_s", k.disable_linear_m_s}, {"disable_angular_rad_s", k.disable_angular_rad_s},
                 {"disable_steps", k.disable_steps}, {"cull", k.cull}, {"cull_ahead_m", k.cull_ahead_m},
                 {"cull_behind_m", k.cull_behind_m},
                 {"cull_side_m", k.cull_side_m}, {"cull_every_steps", k.cull_every},
                 {"cull_wake_force_N", k.wake_force_N}, {"cull_wake_speed_m_s", k.wake_speed_m_s},
                 {"cull_wake_by", std::string(to_string(k.wake_by))},
                 {"cull_front_speed_m_s", k.front_speed_m_s}}},
      {"hull_split", run::hull_split_meta(scene_->hull_regions)},
      {"resumes", nlohmann::json::array()}};
  if (scene.is_object()) meta.update(scene);
  return meta;
}

OdeEngine::WakeRefusal OdeEngine::wake_refusal(WakeBy by) const {
  if (by != WakeBy::NeighbourSpeed) return {};
  return {"on brash-ode's rigid contacts a pushed piece stops at the idle ice instead of moving into it, so the push "
          "never wakes it and the mean resistance is biased high (docs/ode.md, \"The far field on ODE\"); "
          "brash-ode idles the far field with the force rule",
          WakeBy::Force};
}

void OdeEngine::load(const Case& case_in, const fs::path& case_file, const std::vector<Sphere>& packing) {
  scene_ = std::make_unique<Scene>();
  Scene& s = *scene_;
  Case c = case_in;
  std::vector<Sphere> spheres = packing;
  const bool from_dump = !options_.scene_from.empty();
  if (from_dump) {  // another run's scene at scene_time_s: the run goes on from there (build_world places the hull)
    s.dump = read_scene_dump(options_.scene_from);
    check_dump_is_of_case(s.dump, packing, options_.scene_from);
    spheres = std::move(s.dump.spheres);
    s.velocity_m_s = std::move(s.dump.velocity_m_s);
    if (c.ode.settle_s > 0)
      throw InputError(fmt::format("ode.settle_s {} s settles the packing before t = 0, and --scene-from starts from "
                                   "a scene in motion: --set ode.settle_s=0",
                                   c.ode.settle_s));
    s.first_step = std::lround(options_.scene_time_s / c.ode.timestep_s);
    if (std::abs(double(s.first_step) * c.ode.timestep_s - options_.scene_time_s) > 1e-9 * std::max(1.0, options_.scene_time_s))
      throw InputError(fmt::format("--scene-time {} s is not a whole number of ODE steps (ode.timestep_s {} s)",
                                   options_.scene_time_s, c.ode.timestep_s));
  }
  const bool soft_bed = c.ice.settle || from_dump;
  const fs::path bed_file = from_dump ? options_.scene_from : c.ice.settle ? settled_packing_file(c) : c.ice.packing_file;
  if (spheres.empty()) throw InputError(bed_file.string() + ": no spheres");
  const double tolerance_over_d = soft_bed ? kSettledBedMaxOverlapOverD : kPackingMaxOverlapOverD;
  const double largest_overlap_m =
      check_packing(spheres, bed_file, tolerance_over_d * c.ice.diameter_mean_m, 0.5 * c.channel.width_m);
  // The settled bed lies as LIGGGHTS' soft contacts left it, its pieces overlapping by up to ~1 % d. ODE's
  // rigid contacts would push every overlap apart at ERP's pace, stirring the bed it is meant to start from at
  // rest; a contact surface layer as deep as the largest overlap lets them lie (ODE corrects only the depth
  // beyond the layer) and is itself a ~1 % d give of every contact.
  s.stepper = stepper_settings(c);
  s.skips = far_field_skips(c);
  s.implicit = implicit_mode(c);
  if (soft_bed) {
    double& layer_m = s.stepper.contact_surface_layer;
    layer_m = std::max(layer_m, largest_overlap_m);
    s.surface_layer_from_bed = layer_m == largest_overlap_m;  // (not a larger ode.surface_layer_m)
  }
  s.c = c;
  s.spheres = spheres;
  s.contact_mesh = hull::read_mesh(c.hull.file);
  hull::require_plausible_units(s.contact_mesh, c.hull.file, c.hull.draft_m, c.hull.lpp_m);
  s.hull_regions = run::measure_hull_regions(s.contact_mesh, c, case_file);  // the full hull (before a band)
  // Run-time guards (brash::guard, docs/stability.md): the limits of the LIGGGHTS scene box of the same case (from
  // the full hull's extents) and the hull penetration query on the full closed hull, even when the contact mesh
  // is a band (a piece slipping under the band ends up inside the full hull).
  const hull::MeshCheck full = hull::check_mesh(s.contact_mesh);
  s.limits = guard::limits_for_case(
      c, guard::domain_box(c, full.min_m.x(), full.max_m.x(), full.min_m.z(), full.max_m.z(), c.run.duration_s));
  s.hull_closed = full.closed;
  if (s.limits.max_hull_penetration_d && s.hull_closed) s.hull_query = std::make_unique<hull::Proximity>(s.contact_mesh);
  // The water's flow around the hull (fluid.hull_flow) from the full hull, as the LIGGGHTS runner builds it: the
  // STL's frame is the hull body's lowered by the draft, so the water level is at z = level + draft there.
  s.hull_flow = hull_flow_table(c, s.contact_mesh);
  if (c.hull.band_m)
    s.contact_mesh = hull::clip_band(s.contact_mesh, c.hull.draft_m - (*c.hull.band_m)[0], c.hull.draft_m + (*c.hull.band_m)[1]);
}

// The newest intact restart file is found when the run resumes (restart::load_latest, which falls back past a
// truncated one): one restart point when there is any file.
std::vector<std::string> OdeEngine::restarts(const fs::path& run_dir) const {
  if (restart::list(run_dir / "restart").empty()) return {};
  return {"restart/restart_<step>.bin (the newest intact)"};
}

run::ForceRecord OdeEngine::force_record(const fs::path& /*run_dir*/, double t_max_s) const {
  run::ForceRecord out;
  out.extra_columns = record_.extra_columns;
  const std::size_t n_extra = record_.extra_columns.size();
  for (std::size_t i = 0; i < record_.rows.size() && record_.rows[i].t_s <= t_max_s + 1e-9; ++i) {
    out.rows.push_back(record_.rows[i]);
    out.extra.insert(out.extra.end(), record_.extra.begin() + std::ptrdiff_t(i * n_extra),
                     record_.extra.begin() + std::ptrdiff_t((i + 1) * n_extra));
  }
  return out;
}

namespace {

// The progress line's note on the push front: where the window's front lies against the bow.
std::string front_note(const World& w) {
  if (!w.wake_rule().front_follows_push() || !std::isfinite(w.push_front_x())) return "";
  return fmt::format("  front {:+.2f} m from the bow", w.push_front_x() - w.bow_x());
}

// One attempt of an ODE run: the world, the stepping loop and the outputs it writes itself (log.txt, particles/,
// restart files, hull_force.csv before each restart file so that a resume finds the rows up to it).
class Stepping {
 public:
  Stepping(const RunOptions& o, const OdeEngine::Scene& s, const fs::path& run_dir, run::ForceRecord& record,
           run::Monitor& monitor)
      : o_(o), s_(s), c_(s.c), dt_(s.stepper.dt_s), run_dir_(run_dir), record_(record), monitor_(monitor) {}
  run::Attempt run(bool resume, RunSummary& summary);

 private:
  void log(const std::string& line);
  double hull_start_x_m() const { return c_.hull.start_x_m + c_.ship.speed_m_s * double(s_.first_step) * dt_; }
  void build_world();
  void log_scene();
  void start_moving(bool resume);
  std::string settle_progress(long steps) const;
  void restore(run::Attempt& a);
  void save_restart(long step);
  void dump(long step);
  void flush();
  void check_guards(long step);
  void loop(run::Attempt& a);
  bool step(long k, run::Attempt& a);
  void conclude(run::Attempt& a, RunSummary& summary);

  const RunOptions& o_;
  const OdeEngine::Scene& s_;
  const Case& c_;
  const double dt_;
  fs::path run_dir_;
  run::ForceRecord& record_;  // the rows, with the hull force split's columns unless resumed from a record without
  run::Monitor& monitor_;
  std::unique_ptr<World> w_;
  std::vector<std::size_t> order_;  // world slot -> piece index in the packing (the spheres in a spatial order)
  std::string log_, index_ = "step,t_s,file,hull_x_m\n";
  // loop state that a restart file carries besides the world
  long k0_ = 0, win_n_ = 0, ps_settle_ = 0;
  Vec3 acc_ = Vec3::Zero();
  core::HullSplit acc_split_{};
  double win_sum_ = 0;
  Stats stats0_;
  long steps_ = 0, n_out_ = 1, n_dump_ = 1, n_restart_ = 0, n_check_ = 1, k_end_ = 0, ps_loop0_ = 0;
  std::chrono::steady_clock::time_point loop0_;
};

void Stepping::log(const std::string& line) {
  log_ += line + "\n";
  if (o_.progress) fmt::print(stderr, "[brash-ode] {}\n", line);
}

void Stepping::build_world() {
  const Frictions frictions{c_.friction.ice_ice, c_.friction.ice_hull, c_.friction.ice_wall,
                            c_.contact.rolling_friction};
  w_ = std::make_unique<World>(fluid_params(c_), s_.stepper, frictions, s_.skips, s_.implicit);
  // by default in a spatial order (cells of two mean diameters): ODE's bodies, and its contact rows, then sit
  // in memory as in space; ids in every output are the packing's (order_)
  std::vector<Vec3> centres;
  centres.reserve(s_.spheres.size());
  for (const auto& p : s_.spheres) centres.emplace_back(p.x_m, p.y_m, p.z_m);
  if (c_.ode.sphere_order == OdeSphereOrder::Spatial) {
    order_ = core::spatial_order(centres, 2 * c_.ice.diameter_mean_m);
  } else {
    order_.resize(centres.size());
    std::iota(order_.begin(), order_.end(), std::size_t{0});
  }
  const auto& omega = s_.dump.angular_velocity_rad_s;
  for (const std::size_t j : order_) {
    const std::size_t i = w_->add_sphere(centres[j], 0.5 * s_.spheres[j].diameter_m, c_.ice.density_kg_m3,
                                         s_.velocity_m_s.empty() ? Vec3::Zero() : s_.velocity_m_s[j]);
    if (!omega.empty()) w_->set_angular_velocity(i, omega[j]);
  }
  std::vector<double> verts;
  std::vector<dTriIndex> tris;
  double hx0 = 1e300, hx1 = -1e300, hz0 = 1e300;
  for (const auto& v : s_.contact_mesh.vertices) {
    verts.insert(verts.end(), {v.x(), v.y(), v.z() - c_.hull.draft_m});  // waterline at z = 0 in the body frame
    hx0 = std::min(hx0, v.x()), hx1 = std::max(hx1, v.x()), hz0 = std::min(hz0, v.z() - c_.hull.draft_m);
  }
  for (const auto& f : s_.contact_mesh.faces)
    for (int k : f) tris.push_back(static_cast<dTriIndex>(k));
  const double x_lo = std::min(0.0, c_.hull.start_x_m + hx0) - 0.5;
  const double x_hi = std::max(c_.channel.length_m, c_.hull.start_x_m + hx1 + c_.ship.speed_m_s * c_.run.duration_s) + 0.5;
  add_channel_walls(*w_, x_lo, x_hi, 0.5 * c_.channel.width_m, false, std::min(-1.0, hz0 - 0.1), 0.5);
  if (c_.channel.ends == ChannelEnds::Walls) {
    // End walls at the channel ends, spanning only the ice layer depth so the hull passes above/through freely
    // (hull-wall pairs never collide anyway).
    w_->add_wall_box(Vec3(-0.025, 0, -0.25), Vec3(0.05, c_.channel.width_m, 1.5));
    w_->add_wall_box(Vec3(c_.channel.length_m + 0.025, 0, -0.25), Vec3(0.05, c_.channel.width_m, 1.5));
  }
  // the hull where it is at the first step (--scene-from: where it was then in the other run)
  w_->set_hull(std::move(verts), std::move(tris), Vec3(hull_start_x_m(), 0, 0), Vec3::Zero());
  w_->set_hull_regions(s_.hull_regions);
}

void Stepping::log_scene() {
  const auto& st = s_.stepper;
  const auto& lim = s_.limits;
  log(fmt::format("{} spheres, {} hull triangles{}, channel {} x {} m, dt {} s, {} quickstep iterations, ERP {}, CFM {}",
                  s_.spheres.size(), s_.contact_mesh.faces.size(), c_.hull.band_m ? " (waterline band)" : "",
                  c_.channel.length_m, c_.channel.width_m, st.dt_s, st.iterations, st.erp, st.cfm));
  log(fmt::format("fluid model {} treatment {} (implicit realised as {}), ca_table {}, C_D {} ({})",
                  to_string(c_.fluid.model), to_string(c_.fluid.treatment),
                  to_string(c_.ode.implicit),
                  to_string(c_.fluid.ca_table), c_.fluid.drag_coefficient, to_string(c_.fluid.drag_law)));
  if (const Skips& k = s_.skips; k.cull) {
    const core::WakeRule wake = k.wake_rule();
    log(fmt::format("far field (speedups.farfield): idle beyond {} m ahead of the bow, {} m behind the stern{}; membership every {} "
                    "steps; {}",
                    k.cull_ahead_m, k.cull_behind_m,
                    k.cull_side_m < Skips{}.cull_side_m ? fmt::format(", {} m beyond the hull's half beam", k.cull_side_m) : "",
                    k.cull_every,
                    !wake.enabled()                       ? std::string("the window alone (no wake rule)")
                    : wake.by == WakeBy::NeighbourSpeed ? fmt::format("woken by a neighbour faster than {} m/s", wake.speed_m_s)
                    : wake.by == WakeBy::PushFront
                        ? fmt::format("the front {} m ahead of the foremost piece moving ahead faster than {} m/s; beside and "
                                      "behind woken by a horizontal force above {:.4g} N",
                                      k.cull_ahead_m, wake.front_speed_m_s, wake.force_N)
                        : fmt::format("woken by a horizontal force above {:.4g} N", wake.force_N)));
  }
  if (!o_.scene_from.empty()) {
    const SceneFromDump& d = s_.dump;
    log(fmt::format("scene from {} at t = {} s of its run: {} pieces, hull at x = {:.4g} m; {}",
                    o_.scene_from.string(), o_.scene_time_s, s_.spheres.size(), hull_start_x_m(),
                    d.has_state ? fmt::format("{} in its scene (state 0), {} held out at their packing position at "
                                              "rest (state 1), {} removed (state 2) left out",
                                              d.in_scene, d.held_out, d.removed)
                                : std::string("every piece (no state column)")));
    log(fmt::format("scene: {}{}", d.has_velocity ? "the snapshot's velocities" : "no velocities in the snapshot: at rest",
                    d.has_angular_velocity ? ", the snapshot's angular velocities"
                                           : ", no angular velocities in the snapshot: the pieces start without spin"));
  }
  if (s_.surface_layer_from_bed)
    log(fmt::format("{}: contact surface layer {:.3g} m ({:.2f} % d), its largest overlap, so that the "
                    "bed lies as it was left",
                    o_.scene_from.empty() ? "settled bed" : "scene", st.contact_surface_layer, 100 * st.contact_surface_layer / c_.ice.diameter_mean_m));
  log(fmt::format("run dir {}", run_dir_.string()));
  log(fmt::format("guards every {} steps: NaN/Inf; box x [{:.4g}, {:.4g}] y [{:.4g}, {:.4g}] z [{:.4g}, {:.4g}] m; "
                  "zmax {:.4g} m; ke_max {:.4g} J; hull penetration {}; pieces beyond the x range leave the scene; "
                  "(no dt check: ODE contacts are constraint joints, see docs/stability.md)",
                  c_.guards.every_steps, (*lim.box)[0], (*lim.box)[1], (*lim.box)[2], (*lim.box)[3], (*lim.box)[4],
                  (*lim.box)[5], *lim.z_max_m, *lim.ke_max_J,
                  s_.hull_query ? fmt::format("> {:g} d (full closed hull, {} triangles)", *lim.max_hull_penetration_d,
                                              s_.hull_query->triangles())
                                : std::string(s_.hull_closed ? "off (guards.max_hull_penetration_d = 0)"
                                                             : "off (hull not closed)")));
}

// Optional settling of the whole bed with the hull parked and every piece integrated (the far field begins after
// it; on resume the restart file holds the state after it), then the hull moves, with its flow.
void Stepping::start_moving(bool resume) {
  const OdeSpec& ode = c_.ode;
  const long settle_steps = std::lround(ode.settle_s / dt_);
  w_->begin_cull_at_step(settle_steps);
  const long report_every = std::max(1L, std::lround(0.05 / dt_));
  const long damped_steps = ode.settle_damping > 0 ? settle_steps / 2 : 0;
  if (!resume && damped_steps) w_->set_damping(ode.settle_damping, ode.settle_damping);
  for (long k = 0; !resume && k < settle_steps; ++k) {
    if (k == damped_steps && damped_steps) w_->set_damping(0, s_.stepper.angular_damping);
    w_->step();
    if ((k + 1) % report_every == 0 || k + 1 == settle_steps) log(settle_progress(k + 1));
  }
  w_->set_hull_velocity(Vec3(c_.ship.speed_m_s, 0, 0));
  if (!s_.hull_flow.empty()) {
    log(fmt::format("hull flow {}: {} table nodes, largest flow speed {:.4g} m/s (ship {} m/s)",
                    to_string(c_.fluid.hull_flow), s_.hull_flow.nodes().prod(), s_.hull_flow.max_speed_m_s(),
                    c_.ship.speed_m_s));
    core::FlowTable flow = s_.hull_flow;
    w_->set_hull_flow(std::move(flow));
  }
  ps_settle_ = w_->stats().particle_steps;
  stats0_ = w_->stats();
}

// How far the settling has come: the pieces the far field would still find moving (faster than its idle speed,
// speedups.farfield_wake_speed_m_s) and the rms speed.
std::string Stepping::settle_progress(long steps) const {
  const double idle_m_s = c_.speedups.farfield_wake_speed_m_s;
  std::size_t moving = 0;
  double sum_v2 = 0, max_v = 0;
  for (std::size_t i = 0; i < w_->size(); ++i) {
    const double v = w_->velocity(i).norm();
    moving += v > idle_m_s;
    sum_v2 += v * v;
    max_v = std::max(max_v, v);
  }
  return fmt::format("settling {:.3f} of {} s ({} steps): {} of {} pieces faster than {} m/s, rms speed {:.3g} m/s, "
                     "largest {:.3g} m/s",
                     double(steps) * dt_, c_.ode.settle_s, steps, moving, w_->size(), idle_m_s,
                     std::sqrt(sum_v2 / double(std::max<std::size_t>(1, w_->size()))), max_v);
}

// The newest intact restart file: the world and the loop state; the outputs keep only what was written up to it.
void Stepping::restore(run::Attempt& a) {
  const auto found = restart::load_latest(run_dir_ / "restart");
  for (const auto& rej : found.rejected) log("resume: skipped " + rej);
  restart::Reader r(found.payload);
  k0_ = r.get<long>();
  ps_settle_ = r.get<long>();
  stats0_.wall_fluid_s = r.get<double>();
  stats0_.wall_collide_s = r.get<double>();
  stats0_.wall_step_s = r.get<double>();
  acc_ = r.get_vec3();
  if (found.version >= 6)  // a version 5 file is from before the split: its record has no split columns either
    for (double& v : acc_split_) v = r.get<double>();
  win_sum_ = r.get<double>();
  win_n_ = r.get<long>();
  r.get<double>();  // the wall time up to the restart (meta.json keeps the run's)
  w_->load_state(r);
  if (w_->restore_inexact())
    log(fmt::format("resume: {} sphere quaternions restored within a few ulps, not bit for bit", w_->restore_inexact()));
  const double t_r = double(k0_) * dt_;
  auto& rows = record_.rows;
  const std::size_t before = rows.size();
  const auto kept = std::find_if(rows.begin(), rows.end(), [&](const run::ForceRow& row) { return row.t_s > t_r + 0.25 * dt_; });
  rows.erase(kept, rows.end());  // rows in time order
  record_.extra.resize(rows.size() * record_.extra_columns.size());
  const std::size_t dropped = before - rows.size();
  std::istringstream ix(read_text(run_dir_ / "particles" / "index.csv"));
  std::string line;
  std::getline(ix, line);
  while (std::getline(ix, line))
    if (!line.empty() && std::stol(line.substr(0, line.find(','))) <= k0_) index_ += line + "\n";
  const auto old = nlohmann::json::parse(read_text(run_dir_ / "meta.json"), nullptr, false);
  a.meta["resumes"] = old.is_object() && old.contains("resumes") ? old["resumes"] : nlohmann::json::array();
  a.meta["resumes"].push_back({{"from_file", found.file.filename().string()}, {"step", k0_}, {"t_s", t_r},
                               {"rejected", found.rejected}, {"hull_force_rows_dropped", dropped},
                               {"quaternions_inexact", w_->restore_inexact()}});
  log(fmt::format("resumed from {} at step {} (t = {} s): kept {} hull force rows, dropped {} later ones",
                  found.file.string(), k0_, t_r, rows.size(), dropped));
}

void Stepping::save_restart(long step) {
  restart::Writer rw;
  rw.put<long>(step);
  rw.put<long>(ps_settle_);
  rw.put<double>(stats0_.wall_fluid_s);
  rw.put<double>(stats0_.wall_collide_s);
  rw.put<double>(stats0_.wall_step_s);
  rw.put(acc_);
  for (const double v : acc_split_) rw.put<double>(v);
  rw.put<double>(win_sum_);
  rw.put<long>(win_n_);
  rw.put<double>(std::chrono::duration<double>(std::chrono::steady_clock::now() - loop0_).count());
  w_->reset_orientations();
  w_->save_state(rw);
  restart::write(run_dir_ / "restart", step, rw.bytes(), 2);
}

void Stepping::dump(long step) {
  std::string s = "id,x,y,z,radius,vx,vy,vz,submerged_fraction,ca_x,ca_y,ca_z,active\n";
  const World& w = *w_;
  for (std::size_t i = 0; i < w.size(); ++i) {
    const Vec3 x = w.position(i), v = w.velocity(i);
    if (!x.allFinite() || !v.allFinite())
      throw std::runtime_error(fmt::format("sphere {} has a non-finite position/velocity at t = {} s (step {})",
                                           piece_id(s_, order_[i]), double(step) * dt_, step));
    const auto im = core::immersion(w.radius(i), x.z(), c_.water.level_m);
    // idle far-field ice (--cull) and retired pieces: active 0, no Ca (no fluid force acts on them)
    const bool active = !w.culled(i) && !w.retired(i);
    const Vec3 ca = active ? w.fluid_output(i).ca : Vec3::Zero();
    s += fmt::format("{},{:.9g},{:.9g},{:.9g},{:.9g},{:.6g},{:.6g},{:.6g},{:.6g},{:.4g},{:.4g},{:.4g},{}\n",
                     piece_id(s_, order_[i]), x.x(), x.y(), x.z(), w.radius(i), v.x(), v.y(), v.z(), im.fraction, ca.x(),
                     ca.y(), ca.z(), active ? 1 : 0);
  }
  const std::string name = fmt::format("particles_{}.csv", step);
  run::write_atomic(run_dir_ / "particles" / name, s);
  index_ += fmt::format("{},{:.9g},{},{:.9g}\n", step, double(step) * dt_, name, w.hull_position().x());
  run::write_atomic(run_dir_ / "particles" / "index.csv", index_);
}

void Stepping::flush() {
  run::write_hull_force_csv(run_dir_ / "hull_force.csv", record_);
  run::write_atomic(run_dir_ / "log.txt", log_);
}

// The guards on every sphere (lowest id first); a stop is a GuardStop naming the step, the piece and the cause.
// A piece beyond the box's x-ends left through the channel's open ends (it can never reach the hull again): it is
// retired (World::retire, as LIGGGHTS' fix brash/exit removes it), not a guard stop. Leaving through the sides or
// the top stays a stop.
void Stepping::check_guards(long step) {
  World& w = *w_;
  const guard::HullNow hull_now{s_.hull_query.get(), w.hull_position() - Vec3(0, 0, c_.hull.draft_m)};
  const double exit_lo_m = (*s_.limits.box)[0], exit_hi_m = (*s_.limits.box)[1];
  std::size_t exits_now = 0;
  std::optional<std::pair<long, std::string>> stop;  // the lowest piece id with a guard stop, its cause
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (w.retired(i)) continue;
    guard::Piece p;
    p.x_m = w.position(i);
    if ((p.x_m.x() < exit_lo_m || p.x_m.x() > exit_hi_m) && p.x_m.allFinite() && w.velocity(i).allFinite()) {
      w.retire(i);
      ++exits_now;
      continue;
    }
    p.v_m_s = w.velocity(i);
    p.omega_rad_s = w.angular_velocity(i);
    p.radius_m = w.radius(i);
    p.mass_kg = w.mass(i);
    if (const auto cause = guard::check_piece(p, s_.limits, s_.hull_query ? &hull_now : nullptr))
      if (const long id = piece_id(s_, order_[i]); !stop || id < stop->first) stop.emplace(id, *cause);
  }
  if (stop) throw GuardStop(guard::stop_message(step, double(step) * dt_, stop->first, stop->second));
  if (exits_now)
    log(fmt::format("step {} (t = {:.4f} s): {} piece(s) left the scene through the channel's ends (x < {:.6g} or x > "
                    "{:.6g} m); {} in all",
                    step, double(step) * dt_, exits_now, exit_lo_m, exit_hi_m, w.retired_count()));
}

// Step k; false when the run ends here (a stop signal, the early stop).
bool Stepping::step(long k, run::Attempt& a) {
  World& w = *w_;
  w.step();
  if (k % c_.guards.every_steps == 0 || k == steps_) check_guards(k);
  const Vec3& f = w.hull_force();
  if (!f.allFinite()) throw std::runtime_error(fmt::format("non-finite hull force at t = {} s (step {})", double(k) * dt_, k));
  acc_ += f;
  const core::HullSplit& split = w.hull_split();
  for (std::size_t j = 0; j < split.size(); ++j) acc_split_[j] += split[j];
  const double t = double(k) * dt_;
  if (t >= c_.run.window_s[0] - 1e-12 && t <= c_.run.window_s[1] + 1e-12) win_sum_ += f.x(), ++win_n_;
  if (k % n_out_ == 0) {
    // the steps of this row: an output interval, or fewer in a run from a scene off the output grid
    const double n = double(std::min(n_out_, k - s_.first_step));
    const Vec3 m = acc_ / n;
    // the row as written (the early stop reads what a replay of hull_force.csv reads)
    record_.rows.push_back({t, run::as_recorded(m.x()), run::as_recorded(m.y()), run::as_recorded(m.z())});
    if (!record_.extra_columns.empty())  // the split's columns (advance: a record has all of them or none)
      for (const double v : acc_split_) record_.extra.push_back(run::as_recorded(v / n));
    acc_.setZero();
    acc_split_.fill(0);
  }
  a.t_last_s = t;
  a.particle_steps = double(w.stats().particle_steps - ps_loop0_);
  if (k % n_check_ == 0 &&
      monitor_.progress(
          t, a.particle_steps,
          fmt::format("Fx {:+.3f} N  awake {}  contacts {}{}{}", f.x(), w.stats().awake_last,
                      w.stats().contacts_last,
                      w.wake_rule().enabled()
                          ? fmt::format("  woken {} (by speed {})", w.stats().woken, w.stats().woken_by_speed)
                          : "",
                      front_note(w))) &&
      monitor_.stop_reason() == run::StopReason::EarlyStop) {
    log(fmt::format("early stop at t = {:.4f} s", t));
    dump(k);
    return false;
  }
  if (k % n_dump_ == 0 || k == steps_) dump(k), flush();
  if (n_restart_ && k % n_restart_ == 0 && k < steps_) flush(), save_restart(k);  // rows first: a resume drops later ones
  if (k == o_.crash_after_step) std::_Exit(137);
  if (o_.stop_after_step == k) std::raise(SIGTERM);  // testing: a stop request arriving during step k
  if (monitor_.stop_reason() == run::StopReason::Signal && k < steps_) {
    // resumable at this very step: the rows so far, then its restart file
    log(fmt::format("stopped by a signal at step {} (t = {:.4f} s)", k, t));
    flush();
    save_restart(k);
    return false;
  }
  return true;
}

void Stepping::loop(run::Attempt& a) {
  steps_ = std::lround(c_.run.duration_s / dt_);
  n_out_ = std::max(1L, std::lround(c_.run.output_interval_s / dt_));
  n_dump_ = std::max(1L, std::lround(c_.run.dump_interval_s / dt_));
  n_restart_ = o_.restart_every_s > 0 ? std::max(1L, std::lround(o_.restart_every_s / dt_)) : 0;
  n_check_ = std::max(1L, (steps_ - s_.first_step) / 200);  // the driver's check points: every 1/200 of the run, as LIGGGHTS' thermo
  loop0_ = std::chrono::steady_clock::now();
  ps_loop0_ = w_->stats().particle_steps;
  a.t_first_s = double(k0_) * dt_;
  k_end_ = steps_;
  for (long k = k0_ + 1; k <= steps_; ++k)
    if (!step(k, a)) {
      k_end_ = k;
      break;
    }
}

void Stepping::conclude(run::Attempt& a, RunSummary& summary) {
  const Stats& st = w_->stats();
  summary.loop_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - loop0_).count();
  summary.steps = k_end_;
  summary.dt_s = dt_;
  summary.simulated_s = double(k_end_ - k0_) * dt_;
  summary.stats = st;
  summary.particle_steps = st.particle_steps - ps_loop0_;
  summary.mean_fx_window_N = win_n_ ? win_sum_ / double(win_n_) : NAN;
  a.meta["steps_done"] = k_end_;
  a.meta["exits"] = w_->retired_count();
  a.meta["loop_time_s"] = summary.loop_time_s;
  // rates of this attempt's loop (a resumed run: the steps since its restart point)
  a.meta["particle_steps_per_s"] = double(summary.particle_steps) / summary.loop_time_s;
  a.meta["wall_s_per_simulated_s"] = summary.loop_time_s / summary.simulated_s;
  a.meta["phase_wall_s"] = {{"fluid", st.wall_fluid_s - stats0_.wall_fluid_s},
                            {"collide", st.wall_collide_s - stats0_.wall_collide_s},
                            {"quickstep", st.wall_step_s - stats0_.wall_step_s}};
  a.meta["mean_fx_window_N"] = summary.mean_fx_window_N;
  a.meta["cull_geoms_out_max"] = st.geoms_out_max;
  a.meta["cull_woken"] = {{"all", st.woken}, {"by_neighbour_speed", st.woken_by_speed}};
  if (monitor_.stop_reason() == run::StopReason::None)
    log(fmt::format("done: {} steps in {:.1f} s ({:.3g} particle-steps/s, {:.1f} s wall per simulated s); mean Fx over "
                    "[{}, {}] s = {:.4f} N",
                    k_end_ - k0_, summary.loop_time_s, a.meta["particle_steps_per_s"].get<double>(),
                    a.meta["wall_s_per_simulated_s"].get<double>(), c_.run.window_s[0], c_.run.window_s[1],
                    summary.mean_fx_window_N));
  flush();
}

run::Attempt Stepping::run(bool resume, RunSummary& summary) {
  run::Attempt a;
  if (resume) log_ = read_text(run_dir_ / "log.txt");
  try {
    build_world();
    log_scene();
    start_moving(resume);
    if (resume) restore(a);
    a.started = true;
    if (!resume) k0_ = s_.first_step, check_guards(k0_), dump(k0_);
    loop(a);
    conclude(a, summary);
  } catch (const std::exception& e) {
    // Outputs stay consistent: hull_force.csv holds the rows up to the stop, particles/ the snapshots written
    // before it; the driver marks meta.json failed with the reason (a guard stop: step, piece and cause).
    log(std::string("error: ") + e.what());
    flush();
    a.error = e.what();
    if (w_) a.meta["exits"] = w_->retired_count();
  }
  return a;
}

}  // namespace

run::Attempt OdeEngine::advance(const fs::path& run_dir, const std::string& restart, run::Monitor& monitor) {
  const bool resume = !restart.empty();
  // the record so far (written whole before each restart file); the restart point decides which rows stay. A new
  // run records the hull force split; a resumed one only when its record so far has it (a run from before the
  // split goes on without it rather than with part of one).
  record_ = {};
  record_.extra_columns.assign(run::kSplitColumns.begin(), run::kSplitColumns.end());
  if (resume && fs::exists(run_dir / "hull_force.csv")) {
    record_ = run::read_hull_force_csv(run_dir / "hull_force.csv", /*drop_unterminated_tail=*/false);
    if (!std::equal(record_.extra_columns.begin(), record_.extra_columns.end(), run::kSplitColumns.begin(),
                    run::kSplitColumns.end()))
      record_.extra_columns.clear(), record_.extra.clear();
  }
  if (const Skips& k = scene_->skips; k.cull && !k.wake_rule().enabled())
    fmt::print(stderr, "[brash-ode] warning: the far field with no wake rule (the window alone): the push of the bow "
                       "cannot reach past the window and the mean resistance is biased high "
                       "(docs/performance.md, \"The idle far field\")\n");
  Stepping stepping(options_, *scene_, run_dir, record_, monitor);
  return stepping.run(resume, summary_);
}

}  // namespace brash::ode
