// brash::Case: the case file (cases/<name>/case.yaml, schema in docs/case_format.md) as value types.
// load_case() reads and validates a case.yaml, fills every default and resolves paths to absolute ones;
// dump_case_yaml() writes the resolved case (a run directory's case.yaml), and
// load_case(file containing dump_case_yaml(c)) == c.
// SI units, named in each field; a field's initial value is its key's default (keys: case/src/case_key_table.cpp).
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "brash/far_field_options.hpp"
#include "brash/fluid_options.hpp"

namespace brash {

enum class IceClass { IA_super, IA, IB, IC };
enum class PackingMode { Volume, StrictTwoLayer };    // YAML: volume | strict_two_layer
// FluidModel, Treatment, DragLaw and their spelling: brash/fluid_options.hpp (shared with brash::core).
enum class CaTable { Table1, Text, Zero, Uniform };   // YAML: table1 | text | zero (Ca = 0) | uniform <Ca>

// fluid.ca_table: a named added-mass table, or "uniform <Ca>" (the same Ca >= 0 on every axis in every
// immersed state, for stability studies). Converts from the enum, so `spec = CaTable::Text` works.
struct CaTableSpec {
  CaTable table = CaTable::Table1;
  double uniform_ca = 0;  // used when table == Uniform
  CaTableSpec() = default;
  CaTableSpec(CaTable t) : table(t) {}  // NOLINT(google-explicit-constructor): a plain table is a spec
  static CaTableSpec uniform(double ca) {
    CaTableSpec s(CaTable::Uniform);
    s.uniform_ca = ca;
    return s;
  }
  bool operator==(const CaTableSpec&) const = default;
};

// The channel's ends at x = 0 and x = length: open (ice pushed past them leaves the scene, as in an open
// channel) or walls (as the end walls of an ice tank: the ice stays in the channel; the hull passes through them).
enum class ChannelEnds { Open, Walls };

// YAML spelling of each enum value (the inverse is done by the loader, with an error on unknown text).
std::string_view to_string(IceClass v);
std::string_view to_string(PackingMode v);
std::string_view to_string(CaTable v);
std::string_view to_string(ChannelEnds v);
// YAML spelling of an added-mass table: "table1" | "text" | "zero" | "uniform <Ca>" (shortest exact number);
// brash::core::parse_ca_table() and fix icefluid's `ca` keyword read the same text.
std::string to_string(const CaTableSpec& v);

// FSICR design ice thickness H_M of a Finnish-Swedish ice class: IA_super/IA 1.0, IB 0.8, IC 0.6 m.
double h_m_for_ice_class(IceClass c);

struct HullSpec {
  std::filesystem::path file;              // absolute (see resolve_hull_file)
  double draft_m = 0.4125;                 // STL keel at z=0, waterline at z=draft
  double lpp_m = 7.0;
  double beam_m = 1.125;
  double start_x_m = -7.2;                 // x of the aft perpendicular at t=0 (channel starts at x=0)
  std::optional<std::array<double, 2>> band_m;  // [below, above] the waterline; nullopt = full hull
  bool operator==(const HullSpec&) const = default;
};

struct ShipSpec {
  double speed_m_s = 0.482;
  double scale_lambda = 28.5;
  IceClass ice_class = IceClass::IA;
  bool operator==(const ShipSpec&) const = default;
};

struct ChannelSpec {
  double length_m = 21.0;                  // x in [0, length]
  double width_m = 2.25;                   // y in [-width/2, width/2]
  ChannelEnds ends = ChannelEnds::Open;
  bool operator==(const ChannelSpec&) const = default;
};

// ice.diameter_sd_m when the case does not give it: this fraction of the case's ice.diameter_mean_m.
inline constexpr double kDiameterSdOverMean = 0.05;

struct IceSpec {
  double thickness_m = 0.03515;
  double diameter_mean_m = 0.017578;
  double diameter_sd_m = kDiameterSdOverMean * diameter_mean_m;  // default: 5 % of the mean (of the case's mean)
  double diameter_truncation_sd = 3.0;
  double density_kg_m3 = 900.0;
  double porosity = 0.28;
  PackingMode packing_mode = PackingMode::Volume;
  std::uint64_t seed = 1;
  std::filesystem::path packing_file;      // absolute; default <case>/generated/packing.csv
  // Start from the packing settled first: floated with no ship and closed channel ends until the pieces' rms
  // speed is below settle_speed_m_s (brash-settle; cached beside the packing, brash/run/settle.hpp).
  bool settle = false;
  double settle_speed_m_s = 1.0e-3;
  bool operator==(const IceSpec&) const = default;
};

struct WaterSpec {
  double density_kg_m3 = kDefaultWaterDensity_kg_m3;  // the fluid defaults: brash/fluid_options.hpp
  double level_m = 0.0;
  double gravity_m_s2 = kDefaultGravity_m_s2;
  double kinematic_viscosity_m2_s = kDefaultKinematicViscosity_m2_s;
  bool operator==(const WaterSpec&) const = default;
};

struct FrictionSpec {
  double ice_ice = 1.35;
  double ice_hull = 0.1;
  double ice_wall = 1.35;
  bool operator==(const FrictionSpec&) const = default;
};

struct ContactSpec {
  double youngs_modulus_pa = 5.0e6;
  double poisson_ratio = 0.3;
  double restitution = 0.3;
  // Rolling resistance mu_r (dimensionless): a constant torque mu_r R_eff |F_n| against the contact's relative
  // rolling (docs/physics.md, "Rolling resistance"); 0 = none, the contact model without it.
  double rolling_friction = 0.0;
  bool operator==(const ContactSpec&) const = default;
};

struct FluidSpec {
  FluidModel model = FluidModel::Both;  // Eq. 1 + Eq. 2 (docs/physics.md)
  Treatment treatment = Treatment::Implicit;
  double drag_coefficient = kDefaultDragCoefficient;
  DragLaw drag_law = DragLaw::Constant;
  CaTableSpec ca_table;
  // U_flow of the drag: none = still water (the default); thin_ship = the water pushed ahead and aside by the
  // bow and following the stern (plugin/core hull_flow.hpp); panel = the double-body potential flow
  // (panel_flow.hpp); LIGGGHTS and ODE (brash/case_hull_flow.hpp)
  HullFlow hull_flow = HullFlow::None;
  // how that flow acts (fluid_options.hpp): full = drag + the water's acceleration from a table valid to the hull
  HullFlowCoupling hull_flow_coupling = HullFlowCoupling::Full;
  bool operator==(const FluidSpec&) const = default;
};

struct RunSpec {
  double duration_s = 40.0;
  double timestep_s = 5.0e-5;
  double output_interval_s = 0.01;
  double dump_interval_s = 1.0;
  std::array<double, 2> window_s = {15.0, 40.0};
  bool operator==(const RunSpec&) const = default;
};

// Speed-up switches (docs/performance.md). Every switch is off by default; with all of them off the
// scene is the brute-force one.
struct SpeedupSpec {
  bool farfield = false;                // idle far-field ice: not integrated, no contacts among idle pieces
  double farfield_ahead_m = 1.0;        // idle: more than this ahead of the bow
  double farfield_behind_m = 1.0;       // idle: more than this behind the stern
  // idle also beside the hull: more than this beyond the hull's half beam (the ice between the hull and the channel
  // walls; idle there once slower than the wake speed, as behind the stern); none: the whole width is in the window
  std::optional<double> farfield_beside_m;
  int farfield_every_steps = 100;       // membership update period [steps]
  double farfield_wake_force_weight = 1e-3;  // an idle piece wakes when the horizontal force on it exceeds this
                                        // fraction of the mean piece's weight (0 = the window alone: idle ice is
                                        // an immovable wall; docs/performance.md)
  double farfield_wake_speed_m_s = 0.005;  // with the wake: behind the stern (and at a run's start) a piece is idle
                                        // once slower than this
  WakeBy farfield_wake_by = WakeBy::Force;  // what wakes an idle piece: force (the force weight above),
                                        // neighbour_speed (a touching active piece faster than the wake speed) or
                                        // push_front (brash-ode: ahead of the bow the window's front follows the
                                        // push; beside the hull and behind the stern by force)
  double farfield_front_speed_m_s = 0.005;  // push_front: the front lies farfield_ahead_m ahead of the foremost
                                        // active piece moving ahead (along x) faster than this (docs/ode.md, "The
                                        // far field on ODE")
  bool moving_window = false;           // only the ice around the hull in the scene: the bed ahead held out until
                                        // the front reaches it, the ice far behind the stern removed
  double moving_window_ahead_m = 1.0;   // the front: this far ahead of the bow and of the foremost moving piece
  double moving_window_behind_m = 2.0;  // removed: more than this behind the stern
  bool symmetry_y = false;              // half channel y >= 0, frictionless wall at y = 0, forces x 2
  double neighbor_skin_d = 0.2;         // neighbour-list skin in mean sphere diameters
  double early_stop_rel_ci = 0;         // stop once the 95 % CI of the window mean is below this fraction of
                                        // the mean (checked from window start + 40 % of the window); 0 = off
  bool early_stop_trend_check = true;   // ... and only when the window's fitted slope is within its CI (no
                                        // drift; brash/stats/early_stop.hpp); false = on the CI alone, for
                                        // records known to be stationary
  bool operator==(const SpeedupSpec&) const = default;
};

// The far field with no wake rule: idle ice is an immovable wall to the pushed bed (biased high).
inline bool farfield_window_alone(const SpeedupSpec& s) {
  if (!s.farfield) return false;
  switch (s.farfield_wake_by) {  // as core::WakeRule::enabled
    case WakeBy::Force: return !(s.farfield_wake_force_weight > 0);
    case WakeBy::NeighbourSpeed: return !(s.farfield_wake_speed_m_s > 0);
    case WakeBy::PushFront: return !(s.farfield_front_speed_m_s > 0);
  }
  return true;
}

// Run-time guards (docs/stability.md, "Run-time guards"): what stops a run that is going wrong. The other
// guard limits (domain box, zmax, kinetic energy, dt vs contact stiffness) follow from the case itself.
struct GuardSpec {
  // Stop when a piece overlaps the (full, closed) hull by more than this fraction of its diameter;
  // 0.5 = its centre reached the hull surface; 0 = off.
  double max_hull_penetration_d = 0.5;
  int every_steps = 10;  // check every N steps
  bool operator==(const GuardSpec&) const = default;
};

// brash-ode's own numerics (docs/ode.md): its time step and solver, the broad phase, the order of its bodies,
// ODE's auto-disable and a settling before t = 0. The other engines ignore the section.
// ode.implicit: how the implicit added mass is realised in ODE (brash/ode/world.hpp): effective_mass (the body
// mass m + m_a,h) or scale_forces (the external forces scaled, contacts see m).
enum class OdeImplicit { EffectiveMass, ScaleForces };  // YAML: effective_mass | scale_forces
enum class OdeBroadPhase { Grid, Sap };                 // YAML: grid | sap
enum class OdeSphereOrder { Spatial, Packing };         // YAML: spatial | packing
std::string_view to_string(OdeImplicit v);
std::string_view to_string(OdeBroadPhase v);
std::string_view to_string(OdeSphereOrder v);

struct OdeSpec {
  double timestep_s = 5e-4;             // ODE's step (run.timestep_s is the soft-contact DEM step)
  int iterations = 8;                   // dWorldQuickStep iterations
  double erp = 0.2;                     // world ERP
  double cfm = 1e-5;                    // world CFM
  double surface_layer_m = 0.0;         // contact surface layer (a settled bed: at least its largest overlap)
  double angular_damping = 0.0;         // ODE's angular damping per step (fluid torque is neglected)
  OdeImplicit implicit = OdeImplicit::EffectiveMass;
  OdeBroadPhase broad_phase = OdeBroadPhase::Grid;
  OdeSphereOrder sphere_order = OdeSphereOrder::Spatial;
  bool idle_geoms_out = true;           // idle far-field pieces deep in the idle zone leave collision detection
  bool auto_disable = false;            // ODE's auto-disable of resting pieces outside the far field's window
  double auto_disable_linear_m_s = 0.005;
  double auto_disable_angular_rad_s = 0.5;
  int auto_disable_steps = 20;
  double settle_s = 0.0;                // the whole bed integrated this long before t = 0, the hull parked
  double settle_damping = 0.0;          // ODE's velocity damping per step over the settling's first half
  bool operator==(const OdeSpec&) const = default;
};

// Optional overrides of the FSICR hull parameters measured on the STL (full scale).
struct FsicrOverrides {
  std::optional<double> alpha_deg, phi1_deg, phi2_deg, psi_deg, L_par_m, L_bow_m, A_wf_m2;
  bool operator==(const FsicrOverrides&) const = default;
};

// Published values a case's results are compared with (docs/case_format.md, "references"). A case without
// the section declares none, and its report compares with nothing. Full scale; keyed by fluid-model name.
struct ReferenceSpec {
  std::string source;                                   // where the values are published
  std::map<std::string, double> resistance_full_kN;     // per fluid model: drag | added_mass | both
  std::optional<double> fsicr_R_CH_kN;                  // the source's FSICR channel resistance
  std::map<std::string, double> ratio_fsicr_to_sim;     // per fluid model, as the source states it
  bool declared() const { return !resistance_full_kN.empty() || fsicr_R_CH_kN || !ratio_fsicr_to_sim.empty(); }
  bool operator==(const ReferenceSpec&) const = default;
};

struct Case {
  std::string name;
  std::string description;
  HullSpec hull;
  ShipSpec ship;
  ChannelSpec channel;
  IceSpec ice;
  WaterSpec water;
  FrictionSpec friction;
  ContactSpec contact;
  FluidSpec fluid;
  RunSpec run;
  FsicrOverrides fsicr;
  SpeedupSpec speedups;
  GuardSpec guards;
  OdeSpec ode;
  ReferenceSpec references;
  bool operator==(const Case&) const = default;
};

// Contact time-step limit: smallest ice sphere radius (mean - truncation_sd * sd) / 2, its Rayleigh time
// T_R = pi r sqrt(rho_i / G) / (0.1631 nu + 0.8766), G = E / (2 (1 + nu)), and the largest accepted
// run.timestep_s / T_R (the loader rejects larger steps; docs/stability.md).
inline constexpr double kMaxTimestepOverRayleigh = 0.3;
double min_radius_m(const Case& c);
// Largest ice sphere radius, (mean + truncation_sd * sd) / 2. Inline: the guards use it without the case loader.
inline double max_radius_m(const Case& c) {
  return 0.5 * (c.ice.diameter_mean_m + c.ice.diameter_truncation_sd * c.ice.diameter_sd_m);
}
// Volume of a sphere of diameter d [m^3], pi d^3 / 6 (inline for the same reason as below).
inline double sphere_volume_m3(double diameter_m) {
  return std::numbers::pi / 6.0 * diameter_m * diameter_m * diameter_m;
}
// Rayleigh time of a Hertz contact: T_R = pi r sqrt(rho / G) / (0.1631 nu + 0.8766), G = E / (2 (1 + nu)).
// Inline: the guards (brash_guard) use it without linking the case loader.
inline double rayleigh_time_s(double radius_m, double density_kg_m3, double youngs_modulus_pa, double poisson_ratio) {
  const double shear_modulus_pa = youngs_modulus_pa / (2.0 * (1.0 + poisson_ratio));
  return std::numbers::pi * radius_m * std::sqrt(density_kg_m3 / shear_modulus_pa) / (0.1631 * poisson_ratio + 0.8766);
}
double rayleigh_time_s(const Case& c);

// Reads, validates and resolves a case file. Throws brash::InputError naming the file, the key
// (e.g. "ice.porosity") and the line where known, for: unreadable file, YAML syntax, unknown key,
// wrong type, NaN/inf, out-of-range value, unknown enum text, inconsistent values (including a
// run.timestep_s above kMaxTimestepOverRayleigh of the Rayleigh time).
// check_model_keys = false skips the checks that tie other keys to fluid.model (fluid.hull_flow needs the
// drag): for a runner that overrides the model and parses the result again with every check.
Case load_case(const std::filesystem::path& case_yaml, bool check_model_keys = true);

// Same, from YAML text; relative paths resolve against base_dir; `source` names it in messages.
Case parse_case(const std::string& yaml_text, const std::filesystem::path& base_dir,
                const std::string& source, bool check_model_keys = true);

// The resolved case as YAML (every key written, absolute paths, doubles in shortest round-trip form).
std::string dump_case_yaml(const Case& c);

// Where a relative hull file name is looked up, in order: the case folder, $BRASH_HULL_DIR,
// <data>/hull_meshes/ (brash/paths.hpp: <prefix>/share/brash or $BRASH_DATA_DIR). Absolute names are returned
// as they are.
std::vector<std::filesystem::path> hull_file_candidates(const std::filesystem::path& case_dir,
                                                        const std::filesystem::path& file);
// The first existing candidate; if none exists, <case_dir>/file (runners report it as missing).
std::filesystem::path resolve_hull_file(const std::filesystem::path& case_dir,
                                        const std::filesystem::path& file);

}  // namespace brash
