// The case file's keys (see case_key_table.hpp): one entry per key, in file order, then the checks across keys of
// each section. A new key is one line here (and its field in brash/case.hpp); the loader, the resolved case,
// brash-case keys and docs/case_format.md follow from it.
#include "case_key_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <vector>

#include "brash/case_keys.hpp"
#include "brash/error.hpp"

namespace fs = std::filesystem;

namespace brash::case_keys {
namespace {

// The field of a key: field<&Case::ice, &IceSpec::seed>(c) is c.ice.seed.
template <auto... Path>
auto& field(Case& c) {
  return (c .* ... .* Path);
}
template <auto... Path>
const auto& field(const Case& c) {
  return (c .* ... .* Path);
}

bool positive(double x) { return x > 0; }
bool non_negative(double x) { return x >= 0; }
bool any_value(double) { return true; }
bool angle(double a) { return a > 0 && a <= 90; }
bool count(double n) { return n >= 1 && n <= 1e6 && n == std::floor(n); }
constexpr std::string_view kCountNeed = "an integer in [1, 1000000]";

std::string need_of(const KeySpec& k) { return std::string(k.need); }

// ---------------------------------------------------------------- kinds of key
template <auto... P>
constexpr KeySpec number(std::string_view name, bool (*ok)(double), std::string_view need, std::string_view doc,
                         bool (*written)(const Case&) = nullptr) {
  return {.name = name, .doc = doc, .need = need, .ok = ok,
          .read = [](const KeySpec& k, const Reader& r, const YAML::Node& v, const std::string& key, Case& c) {
            field<P...>(c) = r.number(v, key, k.ok, k.need);
          },
          .value = [](const Case& c) { return yaml_number(field<P...>(c)); }, .written = written, .values = need_of};
}

// A whole number, read as a number (so 2.5 gets the range's message).
template <auto... P>
constexpr KeySpec integer(std::string_view name, std::string_view doc) {
  return {.name = name, .doc = doc, .need = kCountNeed, .ok = count,
          .read = [](const KeySpec& k, const Reader& r, const YAML::Node& v, const std::string& key, Case& c) {
            field<P...>(c) = static_cast<int>(r.number(v, key, k.ok, k.need));
          },
          .value = [](const Case& c) { return fmt::format("{}", field<P...>(c)); }, .values = need_of};
}

// A number that may be left out (or null): no value.
template <auto... P>
constexpr KeySpec optional_number(std::string_view name, bool (*ok)(double), std::string_view need,
                                  std::string_view doc) {
  return {.name = name, .doc = doc, .need = need, .ok = ok,
          .read = [](const KeySpec& k, const Reader& r, const YAML::Node& v, const std::string& key, Case& c) {
            if (!v.IsNull()) field<P...>(c) = r.number(v, key, k.ok, k.need);
          },
          .value = [](const Case& c) {
            const auto& x = field<P...>(c);
            return x ? yaml_number(*x) : std::string();
          },
          .values = need_of};
}

template <auto... P>
constexpr KeySpec flag(std::string_view name, std::string_view doc, bool (*written)(const Case&) = nullptr) {
  return {.name = name, .doc = doc, .need = "true | false",
          .read = [](const KeySpec&, const Reader& r, const YAML::Node& v, const std::string& key, Case& c) {
            field<P...>(c) = r.boolean(v, key);
          },
          .value = [](const Case& c) { return std::string(field<P...>(c) ? "true" : "false"); }, .written = written,
          .values = need_of};
}

template <auto... P>
constexpr KeySpec text(std::string_view name, std::string_view doc) {
  return {.name = name, .doc = doc, .need = "text",
          .read = [](const KeySpec&, const Reader& r, const YAML::Node& v, const std::string& key, Case& c) {
            field<P...>(c) = r.text(v, key);
          },
          .value = [](const Case& c) { return yaml_quoted(field<P...>(c)); }, .values = need_of};
}

template <const auto& Table, auto... P>
constexpr KeySpec choice(std::string_view name, std::string_view doc, bool (*written)(const Case&) = nullptr) {
  return {.name = name, .doc = doc,
          .read = [](const KeySpec&, const Reader& r, const YAML::Node& v, const std::string& key, Case& c) {
            field<P...>(c) = r.enumeration(v, key, Table);
          },
          .value = [](const Case& c) { return std::string(text_of(Table, field<P...>(c))); }, .written = written,
          .values = [](const KeySpec&) { return choices(Table); }};
}

// A file name relative to the case folder, absolute in the resolved case; `default_text` when not given.
template <fs::path (*Resolve)(const fs::path& base_dir, const fs::path& file), auto... P>
constexpr KeySpec file(std::string_view name, std::string_view default_text, std::string_view doc) {
  return {.name = name, .doc = doc, .need = "a file name (relative: to the case folder)",
          .read = [](const KeySpec&, const Reader& r, const YAML::Node& v, const std::string& key, Case& c) {
            const std::string f = r.text(v, key);
            if (f.empty()) r.fail(v, key, "must not be empty");
            field<P...>(c) = Resolve(r.base_dir, f);
          },
          .absent = [](const KeySpec& k, const Reader& r, Case& c) {
            field<P...>(c) = Resolve(r.base_dir, fs::path(k.default_text));
          },
          .value = [](const Case& c) { return yaml_quoted(field<P...>(c).string()); }, .values = need_of,
          .default_text = default_text};
}

// Published values per fluid model: {drag | added_mass | both: value > 0}.
template <auto... P>
constexpr KeySpec per_model(std::string_view name, std::string_view doc) {
  return {.name = name, .doc = doc, .need = "> 0",
          .read = [](const KeySpec& k, const Reader& r, const YAML::Node& m, const std::string& key, Case& c) {
            if (m.IsNull()) return;
            std::vector<std::string_view> models;
            for (const auto& e : kFluidModel) models.push_back(e.text);
            r.check_map(m, key, models);
            for (const auto& kv : m) {
              const std::string model = kv.first.as<std::string>();
              field<P...>(c)[model] = r.number(m[model], key + "." + model, positive, k.need);
            }
          },
          .value = [](const Case& c) {
            std::string lines;
            for (const auto& [model, v] : field<P...>(c)) lines += fmt::format("\n    {}: {}", model, yaml_number(v));
            return lines;
          },
          .values = [](const KeySpec& k) { return fmt::format("{{{}: {}}}", choices(kFluidModel), k.need); }};
}

// ---------------------------------------------------------------- keys with a rule of their own
fs::path absolute_in(const fs::path& base_dir, const fs::path& file) {
  return fs::absolute(base_dir / file).lexically_normal();
}

std::string pair_text(const std::array<double, 2>& p) {
  return fmt::format("[{}, {}]", yaml_number(p[0]), yaml_number(p[1]));
}

const KeySpec kName{
    .name = "name", .doc = "the case's id (free text, not empty)", .need = "text",
    .read = [](const KeySpec&, const Reader& r, const YAML::Node& v, const std::string& key, Case& c) {
      c.name = r.text(v, key);
      if (c.name.empty()) r.fail(v, key, "must not be empty");
    },
    .absent = [](const KeySpec&, const Reader& r, Case&) {
      throw InputError(r.source + ": key 'name': missing (required)");
    },
    .value = [](const Case& c) { return yaml_quoted(c.name); }, .values = need_of, .default_text = "(required)"};

const KeySpec kBand{
    .name = "band_m",
    .doc = "[below, above] the waterline: the contact hull keeps only the triangles within it (a speed knob); below "
           "must exceed how deep the bow pushes the ice (brash-post reports the deepest piece, report.json "
           "\"contact_band\"); none = the full hull",
    .need = "[below, above], both >= 0",
    .read = [](const KeySpec&, const Reader& r, const YAML::Node& v, const std::string& key, Case& c) {
      if (v.IsNull()) return;
      c.hull.band_m = r.pair(v, key);
      if ((*c.hull.band_m)[0] < 0 || (*c.hull.band_m)[1] < 0)
        r.fail(v, key, "both distances (below, above the waterline) must be >= 0");
    },
    .value = [](const Case& c) { return c.hull.band_m ? pair_text(*c.hull.band_m) : std::string(); },
    .values = need_of};

const KeySpec kDiameterSd{
    .name = "diameter_sd_m", .doc = "standard deviation of the piece diameter [m]", .need = ">= 0",
    .ok = non_negative,
    .read = [](const KeySpec& k, const Reader& r, const YAML::Node& v, const std::string& key, Case& c) {
      c.ice.diameter_sd_m = r.number(v, key, k.ok, k.need);
    },
    .absent = [](const KeySpec&, const Reader&, Case& c) {
      c.ice.diameter_sd_m = kDiameterSdOverMean * c.ice.diameter_mean_m;
    },
    .value = [](const Case& c) { return yaml_number(c.ice.diameter_sd_m); }, .values = need_of,
    .default_text = "5 % of diameter_mean_m"};

const KeySpec kSeed{
    .name = "seed", .doc = "seed of the packing generator", .need = "an integer >= 0",
    .read = [](const KeySpec&, const Reader& r, const YAML::Node& v, const std::string& key, Case& c) {
      c.ice.seed = r.seed(v, key);
    },
    .value = [](const Case& c) { return fmt::format("{}", c.ice.seed); }, .values = need_of};

const KeySpec kCaTable{
    .name = "ca_table",
    .doc = "the added-mass coefficients: table1 (the paper's Table 1), text (Ca_z = 2 on reversal when submerged), "
           "zero (Ca = 0: buoyancy only) or uniform <Ca> (the same Ca on every axis in every immersed state; "
           "stability studies)",
    .need = "table1 | text | zero | uniform <Ca> (Ca >= 0)",
    .read = [](const KeySpec&, const Reader& r, const YAML::Node& v, const std::string& key, Case& c) {
      c.fluid.ca_table = r.ca_table(v, key);
    },
    .value = [](const Case& c) { return to_string(c.fluid.ca_table); }, .values = need_of};

const KeySpec kWindow{
    .name = "window_s", .doc = "averaging window of the resistance [s]", .need = "[start, end], 0 <= start < end <= "
                                                                            "duration_s",
    .read = [](const KeySpec&, const Reader& r, const YAML::Node& v, const std::string& key, Case& c) {
      c.run.window_s = r.pair(v, key);
    },
    .absent = [](const KeySpec&, const Reader&, Case& c) {
      if (c.run.window_s[1] > c.run.duration_s) c.run.window_s = {0.4 * c.run.duration_s, c.run.duration_s};
    },
    .value = [](const Case& c) { return pair_text(c.run.window_s); }, .values = need_of,
    .default_text = "[15.0, 40.0]; the last 60 % of a run shorter than 40 s"};

bool settles(const Case& c) { return c.ice.settle; }

// ---------------------------------------------------------------- the keys, in file order
const KeySpec kTop[] = {
    kName,
    text<&Case::description>("description", "free text"),
};

const KeySpec kHull[] = {
    file<resolve_hull_file, &Case::hull, &HullSpec::file>(
        "file", "jbc_panamax_model.stl",
        "the hull (STL, keel at z = 0, x forward); a relative name is looked up in the case folder, "
        "$BRASH_HULL_DIR, <data>/hull_meshes/ (\"Hull file lookup\" below)"),
    number<&Case::hull, &HullSpec::draft_m>("draft_m", positive, "> 0", "waterline height above the keel [m]"),
    number<&Case::hull, &HullSpec::lpp_m>("lpp_m", positive, "> 0", "length between perpendiculars [m]"),
    number<&Case::hull, &HullSpec::beam_m>("beam_m", positive, "> 0", "beam [m]"),
    number<&Case::hull, &HullSpec::start_x_m>("start_x_m", any_value, "finite",
                                              "x of the aft perpendicular at t = 0 (the channel starts at x = 0) [m]"),
    kBand,
};

const KeySpec kShip[] = {
    number<&Case::ship, &ShipSpec::speed_m_s>("speed_m_s", positive, "> 0", "ship speed, model scale [m/s]"),
    number<&Case::ship, &ShipSpec::scale_lambda>("scale_lambda", positive, "> 0", "scale 1:lambda of the model"),
    choice<kIceClass, &Case::ship, &ShipSpec::ice_class>(
        "ice_class", "Finnish-Swedish ice class (FSICR H_M 1.0 / 1.0 / 0.8 / 0.6 m)"),
};

const KeySpec kChannel[] = {
    number<&Case::channel, &ChannelSpec::length_m>("length_m", positive, "> 0", "the channel runs from x = 0 to x = "
                                                                                "length [m]"),
    number<&Case::channel, &ChannelSpec::width_m>("width_m", positive, "> 0", "side walls at y = +-width/2 [m]"),
    choice<kChannelEnds, &Case::channel, &ChannelSpec::ends>(
        "ends",
        "open: ice pushed past x = 0 or x = length leaves the scene; walls: end walls there, as in an ice tank (the "
        "hull passes through them); every engine",
        [](const Case& c) { return c.channel.ends != ChannelEnds::Open; }),
};

const KeySpec kIce[] = {
    number<&Case::ice, &IceSpec::thickness_m>("thickness_m", positive, "> 0",
                                              "brash thickness [m], at least diameter_mean_m (one layer of pieces)"),
    number<&Case::ice, &IceSpec::diameter_mean_m>("diameter_mean_m", positive, "> 0", "mean piece diameter [m]"),
    kDiameterSd,
    number<&Case::ice, &IceSpec::diameter_truncation_sd>("diameter_truncation_sd", non_negative, ">= 0",
                                                         "diameters are drawn within mean +- this many sd"),
    number<&Case::ice, &IceSpec::density_kg_m3>("density_kg_m3", positive, "> 0",
                                                "ice density [kg/m^3], below water.density_kg_m3"),
    number<&Case::ice, &IceSpec::porosity>("porosity", [](double p) { return p > 0 && p < 1; }, "in (0, 1)",
                                           "brash porosity"),
    choice<kPackingMode, &Case::ice, &IceSpec::packing_mode>(
        "packing_mode", "volume: place the ice volume (1 - porosity) x thickness per area, at its natural thickness; "
        "strict_two_layer: fill the slab [0, thickness] (thickness between d_max and 3 d_min)"),
    kSeed,
    file<absolute_in, &Case::ice, &IceSpec::packing_file>("packing_file", "generated/packing.csv",
                                                          "the packing (brash-pack writes it when missing)"),
    flag<&Case::ice, &IceSpec::settle>(
        "settle",
        "true: start from the settled bed, the packing floated with no ship and closed ends until its rms speed is "
        "below settle_speed_m_s (brash-settle, cached as generated/settled-<hash>.csv; LIGGGHTS and brash-ode)",
        settles),
    number<&Case::ice, &IceSpec::settle_speed_m_s>("settle_speed_m_s", positive, "> 0",
                                                   "rms speed below which the bed counts as settled [m/s]", settles),
};

const KeySpec kWater[] = {
    number<&Case::water, &WaterSpec::density_kg_m3>("density_kg_m3", positive, "> 0", "water density [kg/m^3]"),
    number<&Case::water, &WaterSpec::level_m>("level_m", any_value, "finite", "z of the water surface [m]"),
    number<&Case::water, &WaterSpec::gravity_m_s2>("gravity_m_s2", positive, "> 0", "gravity [m/s^2]"),
    number<&Case::water, &WaterSpec::kinematic_viscosity_m2_s>("kinematic_viscosity_m2_s", positive, "> 0",
                                                               "kinematic viscosity [m^2/s] (drag_law "
                                                               "schiller_naumann)"),
};

const KeySpec kFriction[] = {
    number<&Case::friction, &FrictionSpec::ice_ice>("ice_ice", non_negative, ">= 0", "ice-ice friction coefficient"),
    number<&Case::friction, &FrictionSpec::ice_hull>("ice_hull", non_negative, ">= 0",
                                                     "ice-hull friction coefficient"),
    number<&Case::friction, &FrictionSpec::ice_wall>("ice_wall", non_negative, ">= 0",
                                                     "ice-wall friction coefficient"),
};

const KeySpec kContact[] = {
    number<&Case::contact, &ContactSpec::youngs_modulus_pa>("youngs_modulus_pa", positive, "> 0",
                                                            "Young's modulus of the ice [Pa]"),
    number<&Case::contact, &ContactSpec::poisson_ratio>("poisson_ratio", [](double v) { return v > -1 && v < 0.5; },
                                                        "in (-1, 0.5)", "Poisson's ratio of the ice"),
    number<&Case::contact, &ContactSpec::restitution>("restitution", [](double e) { return e > 0 && e <= 1; },
                                                      "in (0, 1]", "coefficient of restitution"),
    number<&Case::contact, &ContactSpec::rolling_friction>(
        "rolling_friction", non_negative, ">= 0",
        "rolling resistance mu_r: a torque mu_r R_eff |F_n| against the relative rolling (constant "
        "directional torque, docs/physics.md); 0 = none; LIGGGHTS and ODE, not YADE",
        [](const Case& c) { return c.contact.rolling_friction != 0; }),
};

const KeySpec kFluid[] = {
    choice<kFluidModel, &Case::fluid, &FluidSpec::model>("model",
                                                         "drag (Eq. 1), added_mass (Eq. 2 alone) or both (Eq. 1 + "
                                                         "Eq. 2; docs/physics.md)"),
    choice<kTreatment, &Case::fluid, &FluidSpec::treatment>("treatment", "how the added mass is integrated"),
    number<&Case::fluid, &FluidSpec::drag_coefficient>("drag_coefficient", non_negative, ">= 0",
                                                       "C_D of drag_law constant"),
    choice<kDragLaw, &Case::fluid, &FluidSpec::drag_law>("drag_law", "C_D constant, or C_D(Re) of Schiller-Naumann"),
    kCaTable,
    choice<kHullFlow, &Case::fluid, &FluidSpec::hull_flow>(
        "hull_flow",
        "U_flow of the drag: none (still water), thin_ship (thin-ship sheet) or panel (double-body panel method, "
        "cached in generated/panel_flow.bin); LIGGGHTS and ODE, not YADE; not with model added_mass",
        [](const Case& c) { return c.fluid.hull_flow != HullFlow::None; }),
    choice<kHullFlowCoupling, &Case::fluid, &FluidSpec::hull_flow_coupling>(
        "hull_flow_coupling",
        "how fluid.hull_flow acts: full (the drag on the relative velocity and the water's acceleration, from a "
        "table valid up to the hull), drag (the drag alone, same table) or drag_regular_table (the drag alone, "
        "a regular table that samples inside the hull: the coupling of earlier versions)",
        [](const Case& c) { return c.fluid.hull_flow != HullFlow::None; }),
};

const KeySpec kRun[] = {
    number<&Case::run, &RunSpec::duration_s>("duration_s", positive, "> 0", "simulated time [s]"),
    number<&Case::run, &RunSpec::timestep_s>("timestep_s", positive, "> 0",
                                             "time step [s]; at most 30 % of the Rayleigh time of the smallest "
                                             "sphere (docs/stability.md)"),
    number<&Case::run, &RunSpec::output_interval_s>("output_interval_s", positive, "> 0",
                                                    "interval of the hull_force.csv rows [s]"),
    number<&Case::run, &RunSpec::dump_interval_s>("dump_interval_s", positive, "> 0",
                                                  "interval of the particle snapshots [s]"),
    kWindow,
};

constexpr std::string_view kAngle = "an angle in (0, 90] deg";
const KeySpec kFsicr[] = {
    optional_number<&Case::fsicr, &FsicrOverrides::alpha_deg>("alpha_deg", angle, kAngle,
                                                              "waterline angle at B/4 (else measured on the STL)"),
    optional_number<&Case::fsicr, &FsicrOverrides::phi1_deg>("phi1_deg", angle, kAngle,
                                                             "stem rake at the centreline (90: bulbous bow)"),
    optional_number<&Case::fsicr, &FsicrOverrides::phi2_deg>("phi2_deg", angle, kAngle,
                                                             "bow rake (buttock angle) at B/4"),
    optional_number<&Case::fsicr, &FsicrOverrides::psi_deg>("psi_deg", angle, kAngle,
                                                            "flare angle, atan(tan(phi2) / sin(alpha))"),
    optional_number<&Case::fsicr, &FsicrOverrides::L_par_m>("L_par_m", non_negative, ">= 0 (m, full scale)",
                                                            "parallel mid-body length at the waterline [m]"),
    optional_number<&Case::fsicr, &FsicrOverrides::L_bow_m>("L_bow_m", positive, "> 0 (m, full scale)",
                                                            "bow length at the waterline [m]"),
    optional_number<&Case::fsicr, &FsicrOverrides::A_wf_m2>("A_wf_m2", positive, "> 0 (m^2, full scale)",
                                                            "waterline area of the bow (the L_bow part) [m^2]"),
};

const KeySpec kSpeedups[] = {
    flag<&Case::speedups, &SpeedupSpec::farfield>(
        "farfield", "idle far-field ice (LIGGGHTS fix brash/farfield, brash-ode's cull): pieces outside the window "
                    "around the hull are not integrated and idle-idle pairs are not in the neighbour list"),
    number<&Case::speedups, &SpeedupSpec::farfield_ahead_m>("farfield_ahead_m", non_negative, ">= 0",
                                                            "idle: more than this ahead of the bow [m], >= 2 "
                                                            "diameters"),
    number<&Case::speedups, &SpeedupSpec::farfield_behind_m>("farfield_behind_m", non_negative, ">= 0",
                                                             "idle: more than this behind the stern [m]"),
    optional_number<&Case::speedups, &SpeedupSpec::farfield_beside_m>(
        "farfield_beside_m", non_negative, ">= 0 (m beyond the hull's half beam)",
        "idle also more than this beyond the hull's half beam, once slower than the wake speed; none: the whole "
        "width is in the window (docs/performance.md)"),
    integer<&Case::speedups, &SpeedupSpec::farfield_every_steps>("farfield_every_steps",
                                                                 "the window's membership is updated every N steps"),
    number<&Case::speedups, &SpeedupSpec::farfield_wake_force_weight>(
        "farfield_wake_force_weight", [](double f) { return f >= 0 && f <= 1; },
        "in [0, 1] (fraction of a piece's weight; 0 = the window alone)",
        "an idle piece wakes when the horizontal force on it exceeds this fraction of the mean piece's weight; 0 = "
        "the window alone (idle ice is an immovable wall)"),
    number<&Case::speedups, &SpeedupSpec::farfield_wake_speed_m_s>(
        "farfield_wake_speed_m_s", non_negative, ">= 0",
        "behind the stern (and at a run's start) a piece is idle once slower than this [m/s]"),
    choice<kWakeBy, &Case::speedups, &SpeedupSpec::farfield_wake_by>(
        "farfield_wake_by", "what wakes an idle piece: force (the weight fraction above), neighbour_speed (a touching "
                            "active piece faster than the wake speed; LIGGGHTS) or push_front (brash-ode: the "
                            "window's front follows the pushed ice; docs/ode.md)"),
    number<&Case::speedups, &SpeedupSpec::farfield_front_speed_m_s>(
        "farfield_front_speed_m_s", non_negative, ">= 0",
        "push_front: the speed along x that marks a piece as pushed [m/s]"),
    flag<&Case::speedups, &SpeedupSpec::moving_window>(
        "moving_window", "the moving window (LIGGGHTS fix brash/window): the bed ahead held out of the scene until "
                         "the front reaches it, the ice far behind the stern removed; needs ice.settle: true"),
    number<&Case::speedups, &SpeedupSpec::moving_window_ahead_m>(
        "moving_window_ahead_m", positive, "> 0",
        "the front: this far ahead of the bow and of the foremost moving piece [m], >= 2 diameters and >= "
        "farfield_ahead_m"),
    number<&Case::speedups, &SpeedupSpec::moving_window_behind_m>(
        "moving_window_behind_m", positive, "> 0", "pieces more than this behind the stern are removed [m]"),
    flag<&Case::speedups, &SpeedupSpec::symmetry_y>(
        "symmetry_y", "half channel y >= 0 with a frictionless wall at y = 0; hull fx, fz doubled, fy = 0"),
    number<&Case::speedups, &SpeedupSpec::neighbor_skin_d>(
        "neighbor_skin_d", [](double k) { return k > 0 && k <= 2; }, "in (0, 2]",
        "neighbour-list skin in mean ice diameters"),
    number<&Case::speedups, &SpeedupSpec::early_stop_rel_ci>(
        "early_stop_rel_ci", [](double f) { return f >= 0 && f < 1; }, "in [0, 1) (0 = off)",
        "stop once the 95 % CI of the window mean is below this fraction of it (checked from window start + 40 % of "
        "the window; LIGGGHTS and ODE); 0 = off"),
    flag<&Case::speedups, &SpeedupSpec::early_stop_trend_check>(
        "early_stop_trend_check",
        "... and only when the record shows no drift: the window's fitted slope within its 95 % CI (the full "
        "window's mean is then estimated along it); false = on the CI alone"),
};

const KeySpec kGuards[] = {
    number<&Case::guards, &GuardSpec::max_hull_penetration_d>(
        "max_hull_penetration_d", [](double f) { return f >= 0 && f <= 10; },
        "in [0, 10] (fraction of the piece diameter; 0 = off)",
        "stop when a piece overlaps the full closed hull by more than this fraction of its diameter (0.5 = its "
        "centre reached the hull surface); 0 = off"),
    integer<&Case::guards, &GuardSpec::every_steps>("every_steps", "check every N steps"),
};

const KeySpec kOde[] = {
    number<&Case::ode, &OdeSpec::timestep_s>("timestep_s", positive, "> 0",
                                             "brash-ode's time step [s] (run.timestep_s is the soft-contact step of "
                                             "LIGGGHTS and YADE; docs/ode.md)"),
    integer<&Case::ode, &OdeSpec::iterations>("iterations", "dWorldQuickStep iterations per step"),
    number<&Case::ode, &OdeSpec::erp>("erp", [](double e) { return e >= 0 && e <= 1; }, "in [0, 1]",
                                      "ODE's error reduction parameter (the share of a contact's depth corrected per "
                                      "step)"),
    number<&Case::ode, &OdeSpec::cfm>("cfm", non_negative, ">= 0", "ODE's constraint force mixing (contact give)"),
    number<&Case::ode, &OdeSpec::surface_layer_m>(
        "surface_layer_m", non_negative, ">= 0",
        "contact depth ODE leaves uncorrected [m]; a settled bed runs with at least its largest overlap"),
    number<&Case::ode, &OdeSpec::angular_damping>("angular_damping", [](double d) { return d >= 0 && d <= 1; },
                                                  "in [0, 1]",
                                                  "ODE's angular damping per step (the fluid's torque is neglected)"),
    choice<kOdeImplicit, &Case::ode, &OdeSpec::implicit>(
        "implicit", "fluid.treatment implicit on ODE: effective_mass (the body mass includes the added mass, "
                    "contacts see it) or scale_forces (the external forces scaled, contacts see the bare mass)"),
    choice<kOdeBroadPhase, &Case::ode, &OdeSpec::broad_phase>(
        "broad_phase", "grid (brash's, follows the active pieces) or sap (ODE's sweep and prune): the same "
                       "contacts, bit for bit"),
    choice<kOdeSphereOrder, &Case::ode, &OdeSpec::sphere_order>(
        "sphere_order", "order of the ODE bodies: spatial (cells of two mean diameters) or packing (the packing "
                        "file's; slower, the same physics)"),
    flag<&Case::ode, &OdeSpec::idle_geoms_out>(
        "idle_geoms_out", "idle far-field pieces deep in the idle zone leave collision detection (the same contacts, "
                          "faster); false keeps them in, for checking"),
    flag<&Case::ode, &OdeSpec::auto_disable>(
        "auto_disable", "ODE's auto-disable of resting pieces outside the far field's window (speedups.farfield_*)"),
    number<&Case::ode, &OdeSpec::auto_disable_linear_m_s>("auto_disable_linear_m_s", non_negative, ">= 0",
                                                          "auto-disable: at rest below this speed [m/s]"),
    number<&Case::ode, &OdeSpec::auto_disable_angular_rad_s>("auto_disable_angular_rad_s", non_negative, ">= 0",
                                                             "auto-disable: at rest below this spin [rad/s]"),
    integer<&Case::ode, &OdeSpec::auto_disable_steps>("auto_disable_steps",
                                                      "auto-disable: at rest for this many steps"),
    number<&Case::ode, &OdeSpec::settle_s>(
        "settle_s", non_negative, ">= 0",
        "the whole bed integrated this long before t = 0, the hull parked [s] (the far field begins after it)"),
    number<&Case::ode, &OdeSpec::settle_damping>(
        "settle_damping", [](double d) { return d >= 0 && d <= 0.5; }, "in [0, 0.5]",
        "ODE's velocity damping per step over the settling's first half (its second half is free)"),
};

const KeySpec kReferences[] = {
    text<&Case::references, &ReferenceSpec::source>("source", "where the values are published (required with any "
                                                              "value)"),
    per_model<&Case::references, &ReferenceSpec::resistance_full_kN>("resistance_full_kN",
                                                                     "full-scale resistance per fluid model [kN]"),
    optional_number<&Case::references, &ReferenceSpec::fsicr_R_CH_kN>("fsicr_R_CH_kN", positive, "> 0",
                                                                      "the source's FSICR channel resistance [kN]"),
    per_model<&Case::references, &ReferenceSpec::ratio_fsicr_to_sim>(
        "ratio_fsicr_to_sim", "R_CH / resistance as the source states it, per fluid model (else the report derives "
                              "it)"),
};

// ---------------------------------------------------------------- checks across keys
void sizes_positive(const Reader& r, const YAML::Node&, const YAML::Node& s, Case& c) {
  if (c.ice.diameter_mean_m - c.ice.diameter_truncation_sd * c.ice.diameter_sd_m <= 0)
    r.fail(s["diameter_sd_m"], "ice.diameter_sd_m",
           fmt::format("mean - truncation_sd * sd = {} - {} * {} must be > 0 (no zero-size spheres)",
                       c.ice.diameter_mean_m, c.ice.diameter_truncation_sd, c.ice.diameter_sd_m));
}

// The ice is a layer of pieces: one thinner than a piece cannot be built (the line is the thickness's, or the
// diameter's when the thickness is the default).
void one_piece_thick(const Reader& r, const YAML::Node&, const YAML::Node& s, Case& c) {
  if (c.ice.thickness_m >= c.ice.diameter_mean_m) return;
  const bool given = s["thickness_m"].IsDefined();
  r.fail(given ? s["thickness_m"] : s["diameter_mean_m"], "ice.thickness_m",
         fmt::format("{} m{} is thinner than one piece (ice.diameter_mean_m = {} m): the ice must be at least "
                     "one layer of pieces thick",
                     c.ice.thickness_m, given ? "" : " (the default)", c.ice.diameter_mean_m));
}

void ice_floats(const Reader& r, const YAML::Node& root, const YAML::Node&, Case& c) {
  if (c.ice.density_kg_m3 < c.water.density_kg_m3) return;
  const YAML::Node ice = root["ice"];  // the line of the ice's density where the case gives it
  r.fail(ice.IsDefined() && ice.IsMap() ? ice["density_kg_m3"] : YAML::Node(), "ice.density_kg_m3",
           fmt::format("ice ({} kg/m^3) must be lighter than water.density_kg_m3 ({}) to float", c.ice.density_kg_m3,
                       c.water.density_kg_m3));
}

void hull_flow_needs_drag(const Reader& r, const YAML::Node&, const YAML::Node& s, Case& c) {
  if (r.check_model_keys && c.fluid.hull_flow != HullFlow::None && c.fluid.model == FluidModel::AddedMass)
    r.fail(s["hull_flow"], "fluid.hull_flow",
           "the flow around the hull acts through the drag, and fluid.model added_mass has none: use drag or "
           "both, or hull_flow: none");
  if (c.fluid.hull_flow == HullFlow::None && c.fluid.hull_flow_coupling != HullFlowCoupling::Full)
    r.fail(s["hull_flow_coupling"], "fluid.hull_flow_coupling",
           "says how the hull's flow acts, and fluid.hull_flow is none: set a hull_flow, or drop this key");
}

void window_in_run(const Reader& r, const YAML::Node&, const YAML::Node& s, Case& c) {
  const auto [w0, w1] = c.run.window_s;
  if (!(w0 >= 0 && w0 < w1 && w1 <= c.run.duration_s))
    r.fail(s["window_s"], "run.window_s",
           fmt::format("window [{}, {}] s must satisfy 0 <= start < end <= run.duration_s = {}", w0, w1,
                       c.run.duration_s));
}

void step_within_output(const Reader& r, const YAML::Node&, const YAML::Node& s, Case& c) {
  if (c.run.timestep_s > c.run.output_interval_s)
    r.fail(s["timestep_s"], "run.timestep_s",
           fmt::format("timestep {} s is longer than run.output_interval_s {} s", c.run.timestep_s,
                       c.run.output_interval_s));
}

// Contact stability: the time step must resolve the Rayleigh time of the smallest sphere,
// T_R = pi r sqrt(rho / G) / (0.1631 nu + 0.8766), G = E / (2 (1 + nu)) (docs/stability.md).
void step_within_rayleigh(const Reader& r, const YAML::Node&, const YAML::Node& s, Case& c) {
  if (const double tr = rayleigh_time_s(c); c.run.timestep_s > kMaxTimestepOverRayleigh * tr)
    r.fail(s["timestep_s"], "run.timestep_s",
           fmt::format("timestep {} s is {:.0f} % of the Rayleigh time {:.3g} s of the smallest sphere (d = {:.4g} m, "
                       "contact.youngs_modulus_pa = {}, ice.density_kg_m3 = {}); contacts are unstable above {:.0f} %: "
                       "use <= {:.3g} s",
                       c.run.timestep_s, 100 * c.run.timestep_s / tr, tr, 2 * min_radius_m(c),
                       c.contact.youngs_modulus_pa, c.ice.density_kg_m3, 100 * kMaxTimestepOverRayleigh,
                       kMaxTimestepOverRayleigh * tr));
}

void output_within_run(const Reader& r, const YAML::Node&, const YAML::Node& s, Case& c) {
  if (c.run.output_interval_s > c.run.duration_s)
    r.fail(s["output_interval_s"], "run.output_interval_s",
           fmt::format("{} s is longer than run.duration_s {} s", c.run.output_interval_s, c.run.duration_s));
}

// The wake rule chosen must have a speed that wakes idle ice.
void wake_speeds_positive(const Reader& r, const YAML::Node&, const YAML::Node& s, Case& c) {
  const SpeedupSpec& u = c.speedups;
  if (u.farfield && u.farfield_wake_by == WakeBy::NeighbourSpeed && !(u.farfield_wake_speed_m_s > 0))
    r.fail(s["farfield_wake_speed_m_s"], "speedups.farfield_wake_speed_m_s",
           "must be > 0 with farfield_wake_by: neighbour_speed (it is the speed that wakes idle ice; for the "
           "window alone use farfield_wake_by: force with farfield_wake_force_weight: 0)");
  if (u.farfield && u.farfield_wake_by == WakeBy::PushFront && !(u.farfield_front_speed_m_s > 0))
    r.fail(s["farfield_front_speed_m_s"], "speedups.farfield_front_speed_m_s",
           "must be > 0 with farfield_wake_by: push_front (the window's front follows the pieces moving "
           "ahead faster than it)");
}

// Ice is disturbed up to a few diameters ahead of the bow; an idle zone that starts closer would stop pieces the
// bow is already pushing.
void farfield_clear_of_the_bow(const Reader& r, const YAML::Node&, const YAML::Node& s, Case& c) {
  if (c.speedups.farfield && c.speedups.farfield_ahead_m < 2 * c.ice.diameter_mean_m)
    r.fail(s["farfield_ahead_m"], "speedups.farfield_ahead_m",
           fmt::format("{} m is less than 2 ice diameters ({} m): the bow would push idle ice",
                       c.speedups.farfield_ahead_m, 2 * c.ice.diameter_mean_m));
}

// The moving window re-enters held-out pieces at rest, leads the moving ice, and holds out only the bed beyond the
// ice the scene integrates (the far field's window ahead).
void moving_window_fits(const Reader& r, const YAML::Node&, const YAML::Node& s, Case& c) {
  const SpeedupSpec& u = c.speedups;
  if (!u.moving_window) return;
  if (!c.ice.settle)
    r.fail(s["moving_window"], "speedups.moving_window",
           "needs ice.settle: true (a held-out piece re-enters the scene at rest, where it was: the settled bed is "
           "at rest, the packing is not)");
  if (!(u.farfield_wake_speed_m_s > 0))
    r.fail(s["farfield_wake_speed_m_s"], "speedups.farfield_wake_speed_m_s",
           "must be > 0 with moving_window: true (the window's front leads the ice moving faster than it)");
  const double least_ahead_m = std::max(2 * c.ice.diameter_mean_m, u.farfield ? u.farfield_ahead_m : 0.0);
  if (u.moving_window_ahead_m < least_ahead_m)
    r.fail(s["moving_window_ahead_m"], "speedups.moving_window_ahead_m",
           fmt::format("{} m is less than {} m (2 ice diameters and farfield_ahead_m): the bow would push "
                       "into the held-out bed",
                       u.moving_window_ahead_m, least_ahead_m));
}

void references_have_a_source(const Reader& r, const YAML::Node&, const YAML::Node& s, Case& c) {
  if (c.references.declared() && c.references.source.empty())
    r.fail(s, "references.source", "missing: name where the reference values are published");
}

const CrossCheck kIceChecks[] = {{"no zero-size spheres", sizes_positive},
                                 {"at least one piece thick", one_piece_thick}};
const CrossCheck kWaterChecks[] = {{"ice lighter than water", ice_floats}};
const CrossCheck kFluidChecks[] = {{"hull flow needs the drag", hull_flow_needs_drag}};
const CrossCheck kRunChecks[] = {{"window within the run", window_in_run},
                                 {"time step within the output interval", step_within_output},
                                 {"time step within the Rayleigh time", step_within_rayleigh},
                                 {"output interval within the run", output_within_run}};
const CrossCheck kSpeedupChecks[] = {{"wake speeds", wake_speeds_positive},
                                     {"far field clear of the bow", farfield_clear_of_the_bow},
                                     {"moving window", moving_window_fits}};
const CrossCheck kReferenceChecks[] = {{"a source for the values", references_have_a_source}};

}  // namespace

std::span<const SectionSpec> sections() {
  static const SectionSpec all[] = {
      {"", kTop, {}},
      {"hull", kHull, {}},
      {"ship", kShip, {}},
      {"channel", kChannel, {}},
      {"ice", kIce, kIceChecks},
      {"water", kWater, kWaterChecks},
      {"friction", kFriction, {}},
      {"contact", kContact, {}},
      {"fluid", kFluid, kFluidChecks},
      {"run", kRun, kRunChecks},
      {"fsicr", kFsicr, {}},
      {"speedups", kSpeedups, kSpeedupChecks},
      {"guards", kGuards, {}},
      {"ode", kOde, {}},
      {"references", kReferences, kReferenceChecks,
       [](const Case& c) { return c.references.declared() || !c.references.source.empty(); }},
  };
  return all;
}

}  // namespace brash::case_keys

namespace brash {

std::vector<CaseKeyInfo> case_key_reference() {
  const Case defaults;
  std::vector<CaseKeyInfo> out;
  for (const auto& sec : case_keys::sections())
    for (const auto& k : sec.keys) {
      std::string value = k.default_text.empty() ? k.value(defaults) : std::string(k.default_text);
      out.push_back({sec.name.empty() ? std::string(k.name) : fmt::format("{}.{}", sec.name, k.name),
                     value.empty() ? "none" : value, k.values(k), std::string(k.doc)});
    }
  return out;
}

std::string case_keys_markdown() {
  // A '|' would end the cell, and "<data>" would read as an HTML tag.
  const auto cell = [](const std::string& s) {
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i)
      if (s[i] == '|')
        out += "\\|";
      else if (s[i] == '<' && i + 1 < s.size() && std::isalpha(static_cast<unsigned char>(s[i + 1])))
        out += "&lt;";
      else
        out += s[i];
    return out;
  };
  std::string md = std::string(kCaseKeysBegin) + "\n\n| key | default | values | meaning |\n|---|---|---|---|\n";
  for (const auto& k : case_key_reference())
    md += fmt::format("| `{}` | {} | {} | {} |\n", k.key, cell(k.default_value), cell(k.values), cell(k.doc));
  return md + "\n" + kCaseKeysEnd + "\n";
}

}  // namespace brash
