// brash::ode::World: an ODE world of ice spheres, optional kinematic hull (trimesh) and fixed walls,
// stepped with dWorldQuickStep, with the per-sphere fluid forces of brash_core (buoyancy, drag, added mass).
//
// Per step (World::step):
//   1. fluid: for every awake, uncull'd sphere: out = core::evaluate(params, {r, m, x(n), v(n)}, state, dt)
//      (with a hull flow table, params' flow velocity is the table's at x(n) in the hull's frame);
//      the applied force is G = (-m g e_z + out.force_N) (.) out.scale (.) (M / m) and the body mass is M
//      (see "Implicit added mass in ODE" below; composed by brash/core/added_mass.hpp);
//      state = advance(state, v(n)).
//   2. collide: broad phase (our x-y grid, or ODE's sweep-and-prune), contact joints (dContactApprox1,
//      Coulomb mu per pair type, sphere body first; with Frictions::rolling also dContactRolling).
//   3. dWorldQuickStep (semi-implicit Euler: v(n+1) = v(n) + dt (G + F_contact) / M,
//      x(n+1) = x(n) + dt v(n+1)).
//   4. hull force = -sum fb.f1 over the hull contacts (feedback read after the step, before emptying
//      the group).
//
// Implicit added mass in ODE (the "treatment" of physics.md). The core asks for (m + m_a,i) a_i = F_i per
// axis, F = every force on the sphere. ODE only knows the contact forces inside its solver, and its
// translational mass is isotropic. We give the body the isotropic mass M = m + m_a,h (m_a,h = rho_w V_s (Ca_x
// + Ca_y)/2, the horizontal added mass, updated every step: core::isotropic_body_mass_kg) and apply
// G_i = F_ext,i * M / (m + m_a,i) (core::force_for_body_mass). Then
//   - external forces (gravity, buoyancy, drag) get exactly a_i = F_ext,i / (m + m_a,i) on every axis;
//   - contact forces get exactly 1/(m + m_a) on x and y (Table 1: Ca_x = Ca_y), and 1/M instead of
//     1/(m + m_a,z) on z (the solver sees the heavier horizontal inertia; Table 1 has Ca_z <= Ca_x except in
//     the paper's "text" variant). Nothing is lagged, so it is as stable as plain ODE for any Ca.
// The alternative ImplicitMode::ScaleForces keeps M = m and only scales the external forces (contacts then
// see the bare mass m: no added inertia in collisions). Both are exact for a sphere without contacts. The
// explicit treatment keeps M = m and adds the core's lagged F_a = -m_a (v(n) - v(n-1)) / dt.
#pragma once
#include <ode/ode.h>

#include <array>
#include <cstdint>
#include <deque>
#include <limits>
#include <string>
#include <vector>

#include "brash/core/far_field.hpp"
#include "brash/core/fluid.hpp"
#include "brash/core/hull_flow.hpp"
#include "brash/core/hull_split.hpp"

namespace brash::ode {

namespace restart {
class Writer;
class Reader;
}  // namespace restart

using core::Vec3;

enum class ImplicitMode { EffectiveMass, ScaleForces };

// Broad phase. Grid: a uniform x-y grid (cell = the largest sphere diameter) over the spheres still in collision
// detection, rebuilt every step, plus an AABB test of each of them against the hull and the walls; its cost
// follows the active spheres only. Sap: ODE's sweep-and-prune space (dSpaceCollide), which also walks every geom
// of the space each step (~18 % of a step on the paper scene, docs/ode.md). Both hand every pair whose AABBs
// overlap to the same narrow phase (dCollide) and the joints are created in a fixed order, so the run is the same
// to the last bit (test_restart: GridAndSapBroadPhasesGiveTheSameRun); Sap is kept for checking.
enum class BroadPhase { Grid, Sap };
// The option's words (--broad-phase, meta.json "broad_phase"): "grid" | "sap".
inline const char* to_string(BroadPhase b) { return b == BroadPhase::Sap ? "sap" : "grid"; }

struct StepperSettings {
  double dt_s = 5e-4;              // ode.md: 5e-4 recommended, 1e-3 cross-checked
  int iterations = 8;              // dWorldSetQuickStepNumIterations (ode.md: within 2 % of 20, no row shuffle)
  double erp = 0.2;                // world ERP
  double cfm = 1e-5;               // world CFM
  double contact_surface_layer = 0.0;
  int max_contacts_per_pair = 8;   // sphere-trimesh gives one contact per touched triangle (up to 6)
  double angular_damping = 0.0;    // dBodySetAngularDamping (fluid torque is neglected: default off)
  BroadPhase broad_phase = BroadPhase::Grid;
};

struct Frictions {
  double ice_ice = 1.35;
  double ice_hull = 0.1;
  double ice_wall = 1.35;
  // Rolling resistance mu_r (contact.rolling_friction), every pair type alike. 0: contacts without it, as
  // before it existed. Otherwise each contact gets ODE's rolling friction (dContactRolling) with
  // rho = mu_r R_eff: a torque of at most rho |F_n| about each tangent axis that stops the relative rolling
  // (R_eff = R_a R_b / (R_a + R_b) for two spheres, the sphere's R against the hull or a wall; world.cpp).
  double rolling = 0;
};

// Skips (each with a switch; effect measured in docs/ode.md).
struct Skips {
  bool auto_disable = false;            // ODE auto-disable of resting spheres
  double disable_linear_m_s = 0.005;
  double disable_angular_rad_s = 0.5;
  int disable_steps = 20;
  bool auto_disable_far_only = true;    // keep spheres within cull distance of the hull always awake
  // Cull: the far-field rule of brash/core/far_field.hpp (fix brash/farfield's in LIGGGHTS). Culled spheres are
  // frozen (static obstacles to the active ones; no fluid force, no contact among themselves).
  bool cull = false;
  double cull_ahead_m = 1.0;            // window: up to this ahead of the bow (hull max x)
  double cull_behind_m = 1.0;           // window: up to this behind the stern (hull min x)
  double cull_side_m = 1e9;             // window: up to |y| of the hull's half beam + this
  int cull_every = 20;                  // membership update every n steps
  // The wake rule: a culled sphere wakes when the horizontal force of the step's contacts on it exceeds
  // wake_force_N (read from the joints' feedback after the step), or (wake_by NeighbourSpeed) when an active
  // sphere in contact with it moved faster than wake_speed_m_s into the step (before it: the hard contact
  // with a culled sphere stops it within the step); with wake_by PushFront nothing wakes ahead of the bow:
  // the window's front follows the spheres moving ahead (+x) faster than front_speed_m_s
  // (core::push_front_x). At an update a sphere ahead of the bow keeps its state, one behind the stern,
  // beside the hull or at the first update is culled once no faster than wake_speed_m_s (ahead of the bow at
  // the first update, by push front, always). wake_force_N = 0: the window alone (the culled ice is an
  // immovable wall that jams the pushed bed, docs/performance.md). brash-ode sets both from the case's
  // speedups.farfield_wake_*.
  double wake_force_N = 0;
  double wake_speed_m_s = 0;
  WakeBy wake_by = WakeBy::Force;
  double front_speed_m_s = 0;  // by push front: the front follows the pieces moving ahead faster than this
  core::WakeRule wake_rule() const { return {wake_force_N, wake_speed_m_s, wake_by, front_speed_m_s}; }
  // Culled spheres more than 3 largest diameters inside the frozen zone also leave collision detection
  // (dGeomDisable): they can touch only other culled spheres, which give no contact, so the contacts and the
  // trajectory are the same (test_ode_restart: CullGeomsGiveTheSameRun), but the broad phase then costs the
  // active part of the scene only (paper scene: collide was 90 % of the step with every geom in it).
  bool cull_geoms = true;
};

struct Stats {
  double t_s = 0;
  long steps = 0;
  long particle_steps = 0;          // sum over steps of the number of stepped (awake, uncull'd) spheres
  double wall_fluid_s = 0, wall_collide_s = 0, wall_step_s = 0;
  std::size_t contacts_last = 0;
  std::size_t awake_last = 0;
  std::size_t geoms_out_max = 0;    // most culled spheres left out of collision detection at once (cull_geoms)
  long woken = 0;                   // culled spheres woken by the wake rule
  long woken_by_speed = 0;          // ... of which by a neighbour's speed
};

class World {
 public:
  World(const core::FluidParams& fluid, const StepperSettings& stepper, const Frictions& friction,
        const Skips& skips = {}, ImplicitMode mode = ImplicitMode::EffectiveMass);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  // Returns the sphere index.
  std::size_t add_sphere(const Vec3& position_m, double radius_m, double density_kg_m3,
                         const Vec3& velocity_m_s = Vec3::Zero());
  // A sphere's angular velocity at the start (a scene taken from another run).
  void set_angular_velocity(std::size_t i, const Vec3& omega_rad_s);
  // Axis-aligned fixed box (wall).
  void add_wall_box(const Vec3& centre_m, const Vec3& size_m);
  // Kinematic trimesh hull. vertices/triangles are copied (kept alive here); hull frame = body frame.
  void set_hull(std::vector<double> vertices_xyz, std::vector<dTriIndex> triangles, const Vec3& position_m,
                const Vec3& velocity_m_s);

  void step();

  // Restart: the full dynamic state (per sphere: position, quaternion, linear and angular velocity, enabled,
  // culled and auto-disable flags, ODE mass, core::FluidState, last Ca; the hull position and velocity; ODE's
  // random seed, used by quickstep's constraint reordering; the step counters). load_state expects a world built
  // the same way (same spheres in the same order, same hull and walls) and throws std::runtime_error otherwise.
  // Not restored: ODE's auto-disable averaging buffers (with --auto-disable a resume is not bit-exact).
  void save_state(restart::Writer& w) const;
  void load_state(restart::Reader& r);
  // Every sphere's orientation to the identity. A sphere's orientation is not observable (its geometry and
  // inertia are isotropic), but ODE's step carries it and load_state cannot give an arbitrary one back bit for
  // bit: set before every restart file, in the uninterrupted run and the resumed one alike, a resume continues
  // bit for bit.
  void reset_orientations();
  // Spheres whose saved quaternion could not be given back bit for bit by the last load_state (see world.cpp).
  std::size_t restore_inexact() const { return restore_inexact_; }

  // Extra ODE velocity damping on every sphere (per-step scale factors, threshold 0), for preparing a bed
  // at rest (settling); set (0, angular_damping) back before the measured run. Not a physical force.
  void set_damping(double linear_per_step, double angular_per_step);

  std::size_t size() const { return spheres_.size(); }
  Vec3 position(std::size_t i) const;
  Vec3 velocity(std::size_t i) const;
  Vec3 angular_velocity(std::size_t i) const;
  double radius(std::size_t i) const { return spheres_[i].radius_m; }
  double mass(std::size_t i) const { return spheres_[i].mass_kg; }
  const core::FluidOutput& fluid_output(std::size_t i) const { return spheres_[i].last; }
  bool awake(std::size_t i) const;
  bool culled(std::size_t i) const { return spheres_[i].culled; }

  // Takes a sphere out of the scene for good (a piece that left through the channel's open ends and can never
  // reach the hull again): its body and geom are disabled and its velocities zeroed, so it is neither
  // stepped, nor given fluid forces, nor seen by the broad phase; it stays at its last position in the
  // particle files. Kept in restart files. The LIGGGHTS counterpart is fix brash/exit.
  void retire(std::size_t i);
  bool retired(std::size_t i) const { return spheres_[i].retired; }
  std::size_t retired_count() const;

  // The water's flow around the hull (fluid.hull_flow; brash::hull::thin_ship_flow): a table in the hull's
  // frame, x and y from the hull body's position, z = 0 at the water level (FluidParams::water_level_m). From
  // the next step on, each sphere's drag acts on its velocity relative to the table's flow at its centre, at
  // the hull's position at the start of the step (as fix icefluid's hull_flow), and the table's Du/Dt adds the
  // pressure-gradient force and the added mass on the relative acceleration (core flow_acceleration.hpp). Needs the hull (set_hull) and
  // a fluid model with drag (throws std::invalid_argument otherwise). Not in restart files: a resumed run
  // sets it again.
  void set_hull_flow(core::FlowTable table);
  bool has_hull_flow() const { return !hull_flow_.empty(); }

  // The far field (Skips::cull) from this step on: the steps before it integrate every sphere (brash-ode --settle
  // settles the whole bed, so that the ice the far field leaves idle lies as ODE's own contacts hold it); its
  // first membership update is at this step. Not in restart files: a resumed run sets it again.
  void begin_cull_at_step(long step) { cull_first_step_ = step; }
  bool culling() const { return skips_.cull && stats_.steps >= cull_first_step_; }

  void set_hull_velocity(const Vec3& v);
  bool has_hull() const { return hull_body_ != nullptr; }
  Vec3 hull_position() const;
  // Force of the ice on the hull during the last step (contacts only), and its number of contacts.
  const Vec3& hull_force() const { return hull_force_N_; }
  std::size_t hull_contacts() const { return hull_contacts_; }
  // The hull force split of the last step (brash/core/hull_split.hpp): hull_force().x() by region and by
  // mechanism, from each hull contact's force (its joint's feedback), point and normal. The regions are in the
  // hull's frame (the STL's: x = hull_position().x() + x_STL), set once with set_hull_regions.
  void set_hull_regions(const core::HullRegions& r) { hull_regions_ = r; }
  const core::HullSplit& hull_split() const { return hull_split_; }
  double bow_x() const { return hull_position().x() + hull_max_[0]; }    // the hull's foremost x now
  double stern_x() const { return hull_position().x() + hull_min_[0]; }  // the hull's aftmost x now
  double hull_half_beam() const { return std::max(std::abs(hull_min_[1]), std::abs(hull_max_[1])); }
  // By push front: the window's front (x; -infinity before the first membership update).
  double push_front_x() const { return push_front_x_m_; }

  const Stats& stats() const { return stats_; }
  core::WakeRule wake_rule() const;  // the cull's (none without the cull)
  const StepperSettings& stepper() const { return stepper_; }
  const core::FluidParams& fluid() const { return fluid_; }

 private:
  struct SphereRec {
    dBodyID body = nullptr;
    dGeomID geom = nullptr;
    double radius_m = 0, mass_kg = 0, inertia = 0;  // inertia: true 2/5 m r^2
    double ode_mass_kg = 0;                         // current M given to ODE
    core::FluidState state;
    core::FluidOutput last;
    bool culled = false;
    bool retired = false;  // retire()
    double push_x_N = 0, push_y_N = 0;  // wake rule: contact force on a culled sphere, summed over one step
  };
  double max_radius_m_ = 0;
  static void near_callback(void* data, dGeomID a, dGeomID b);
  void collide_pair(dGeomID a, dGeomID b);
  void collide_tagged(dGeomID a, std::size_t tag_a, dGeomID b, std::size_t tag_b);  // tags: see world.cpp
  void collide_grid();
  void create_joints();
  static constexpr std::size_t kPartnerWall = std::size_t(1) << 40, kPartnerHull = std::size_t(1) << 41;
  void apply_fluid();
  core::FarFieldWindow cull_window() const;
  void update_cull();
  void update_cull_geoms(const core::FarFieldWindow& window);
  void wake_pushed();
  static void freeze(SphereRec& s);
  static void thaw(SphereRec& s);
  void wake(SphereRec& s);  // thaw a culled sphere by the wake rule
  void set_ode_mass(SphereRec& s, double M);

  core::FluidParams fluid_;
  core::FlowTable hull_flow_;  // empty: still water (or fluid_'s uniform flow)
  StepperSettings stepper_;
  Frictions friction_;
  Skips skips_;
  ImplicitMode mode_;
  dWorldID world_ = nullptr;
  dSpaceID space_ = nullptr;
  dJointGroupID contacts_ = nullptr;
  std::vector<SphereRec> spheres_;
  std::vector<dGeomID> walls_;
  dBodyID hull_body_ = nullptr;
  dGeomID hull_geom_ = nullptr;
  dTriMeshDataID hull_data_ = nullptr;
  std::vector<double> hull_vertices_;
  std::vector<dTriIndex> hull_triangles_;
  std::array<double, 3> hull_min_{0, 0, 0}, hull_max_{0, 0, 0};
  std::deque<dJointFeedback> hull_feedback_;
  // per hull joint, in hull_feedback_'s order: the contact point's x in the hull's frame and the contact normal
  struct HullContact {
    double x_hull_m;
    double normal[3];
  };
  std::vector<HullContact> hull_contact_;
  core::HullRegions hull_regions_;
  core::HullSplit hull_split_{};
  // Wake rule: the feedback of this step's joints between an active sphere and a culled one (by force), the
  // culled sphere of each and the active sphere's velocity before the step (by neighbour speed); after a wake,
  // the culled geoms near the woken spheres go back into collision detection.
  std::deque<dJointFeedback> idle_feedback_;
  std::vector<std::size_t> idle_fed_;
  std::vector<Vec3> idle_toucher_v_;
  bool cull_geoms_stale_ = false;
  // Wake by push front: the window's front (core::push_front_x; -infinity before the first update; in restarts)
  double push_front_x_m_ = -std::numeric_limits<double>::infinity();
  long cull_first_step_ = 0;  // begin_cull_at_step
  std::vector<dContact> contact_buf_;
  // Contacts of one step, created as joints in a fixed order (sphere index, partner) after the collision
  // pass, so the joint order does not depend on the broad phase's internal order (needed for exact restarts).
  static constexpr std::size_t kNoSphere = std::size_t(-1);
  struct PendingContact {
    std::size_t a = 0;       // sphere index
    std::size_t key = 0;     // partner: sphere index, or kPartnerWall + wall index, or kPartnerHull
    int slot = 0;            // contact number within the pair
    dBodyID ba = nullptr, bb = nullptr;
    bool hull = false;
    dContact c{};
    std::size_t idle = kNoSphere;  // the culled sphere of the pair, when the wake rule reads its force
  };
  std::vector<PendingContact> pending_;
  struct JointOrder {
    std::size_t a = 0, key = 0;
    int slot = 0;
    std::size_t index = 0;  // into pending_
  };
  std::vector<JointOrder> joint_order_;
  // Grid broad phase (collide_grid): the spheres whose geom is enabled (rebuilt when a geom is switched), and
  // per step their AABB data sorted by cell (counting sort: cell_start_[c] .. cell_start_[c + 1]).
  struct GridItem {
    double x = 0, y = 0, z = 0, r = 0;
    std::uint32_t sphere = 0;
    std::uint32_t cell = 0;
  };
  std::vector<std::uint32_t> broad_spheres_;
  bool broad_spheres_stale_ = true;
  std::vector<GridItem> grid_unsorted_, grid_items_;
  std::vector<std::uint32_t> cell_start_, cell_fill_;
  std::vector<std::array<dReal, 6>> wall_boxes_;  // AABB of walls_[w], taken once in add_wall_box
  Vec3 hull_force_N_ = Vec3::Zero();
  std::size_t hull_contacts_ = 0;
  std::size_t contacts_this_step_ = 0;
  Stats stats_;
  std::size_t restore_inexact_ = 0;
};

// dInitODE2 / dCloseODE once per process (RAII); also checks double precision.
class OdeLibrary {
 public:
  OdeLibrary();
  ~OdeLibrary();
};

}  // namespace brash::ode
