// Case loader and writer (see brash/case.hpp and docs/case_format.md).
// The loader is strict on purpose: a typo in a key silently falling back to a default would make a
// run answer a different question, so unknown keys, wrong types and NaN are errors naming file,
// line and key.
#include "brash/case.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <numbers>
#include <sstream>

#include "brash/error.hpp"
#include "brash/paths.hpp"

namespace fs = std::filesystem;

namespace brash {

// ---------------------------------------------------------------- enum spellings
namespace {
template <class E>
struct EnumText {
  E value;
  std::string_view text;
};
constexpr EnumText<IceClass> kIceClass[] = {
    {IceClass::IA_super, "IA_super"}, {IceClass::IA, "IA"}, {IceClass::IB, "IB"}, {IceClass::IC, "IC"}};
constexpr EnumText<PackingMode> kPackingMode[] = {{PackingMode::Volume, "volume"},
                                                  {PackingMode::StrictTwoLayer, "strict_two_layer"}};
constexpr EnumText<FluidModel> kFluidModel[] = {
    {FluidModel::Drag, "drag"}, {FluidModel::AddedMass, "added_mass"}, {FluidModel::Both, "both"}};
constexpr EnumText<Treatment> kTreatment[] = {{Treatment::Implicit, "implicit"},
                                              {Treatment::Explicit, "explicit"}};
constexpr EnumText<DragLaw> kDragLaw[] = {{DragLaw::Constant, "constant"},
                                          {DragLaw::SchillerNaumann, "schiller_naumann"}};
constexpr EnumText<HullFlow> kHullFlow[] = {
    {HullFlow::None, "none"}, {HullFlow::ThinShip, "thin_ship"}, {HullFlow::Panel, "panel"}};
constexpr EnumText<ChannelEnds> kChannelEnds[] = {{ChannelEnds::Open, "open"}, {ChannelEnds::Walls, "walls"}};
constexpr EnumText<WakeBy> kWakeBy[] = {
    {WakeBy::Force, "force"},
    {WakeBy::NeighbourSpeed, "neighbour_speed"},
    {WakeBy::PushFront, "push_front"}};
constexpr EnumText<CaTable> kCaTable[] = {{CaTable::Table1, "table1"},
                                          {CaTable::Text, "text"},
                                          {CaTable::Zero, "zero"},
                                          {CaTable::Uniform, "uniform"}};

template <class E, std::size_t N>
std::string_view text_of(const EnumText<E> (&table)[N], E v) {
  for (const auto& e : table)
    if (e.value == v) return e.text;
  return "?";
}
}  // namespace

std::string_view to_string(IceClass v) { return text_of(kIceClass, v); }
std::string_view to_string(PackingMode v) { return text_of(kPackingMode, v); }
std::string_view to_string(CaTable v) { return text_of(kCaTable, v); }
std::string_view to_string(ChannelEnds v) { return text_of(kChannelEnds, v); }
std::string to_string(const CaTableSpec& v) {
  if (v.table == CaTable::Uniform) return fmt::format("uniform {}", v.uniform_ca);
  return std::string(to_string(v.table));
}

double h_m_for_ice_class(IceClass c) {
  switch (c) {
    case IceClass::IA_super:
    case IceClass::IA: return 1.0;
    case IceClass::IB: return 0.8;
    case IceClass::IC: return 0.6;
  }
  return 1.0;
}

// ---------------------------------------------------------------- hull file lookup
std::vector<fs::path> hull_file_candidates(const fs::path& case_dir, const fs::path& file) {
  if (file.is_absolute()) return {file};
  std::vector<fs::path> out{case_dir / file};
  if (const char* env = std::getenv("BRASH_HULL_DIR"); env != nullptr && *env != '\0')
    out.push_back(fs::path(env) / file);
  out.push_back(paths::data_dir() / "hull_meshes" / file);
  return out;
}

fs::path resolve_hull_file(const fs::path& case_dir, const fs::path& file) {
  for (const auto& p : hull_file_candidates(case_dir, file)) {
    std::error_code ec;
    if (fs::is_regular_file(p, ec)) return fs::absolute(p).lexically_normal();
  }
  return fs::absolute(case_dir / file).lexically_normal();
}

// ---------------------------------------------------------------- reading
namespace {

struct Reader {
  std::string source;  // file name for messages

  [[noreturn]] void fail(const YAML::Node& n, const std::string& key, const std::string& msg) const {
    const YAML::Mark m = n.IsDefined() ? n.Mark() : YAML::Mark::null_mark();
    if (m.line >= 0)
      throw InputError(fmt::format("{}:{}:{}: key '{}': {}", source, m.line + 1, m.column + 1, key, msg));
    throw InputError(fmt::format("{}: key '{}': {}", source, key, msg));
  }

  // Every key of a mapping must be one of `known` and given once (yaml-cpp keeps both of two equal keys and
  // reads the first, so the second would be ignored without a word); a section that is not a mapping is an error.
  void check_map(const YAML::Node& n, const std::string& where,
                 std::initializer_list<std::string_view> known) const {
    if (!n.IsMap()) fail(n, where.empty() ? "<top>" : where, "expected a mapping of keys");
    std::map<std::string, int> first_line;  // key -> its line (0-based)
    for (const auto& kv : n) {
      // A list or mapping used as a key ("{[0.1, 0.1]}") has no text: yaml-cpp's as<string> would throw
      // its own exception (found by tests/fuzz/fuzz_case).
      if (!kv.first.IsScalar())
        fail(kv.first, where.empty() ? "<top>" : where, "keys must be plain names, got a list or mapping as a key");
      const std::string k = kv.first.as<std::string>();
      if (std::find(known.begin(), known.end(), k) == known.end()) {
        std::string list;
        for (auto s : known) list += (list.empty() ? "" : ", ") + std::string(s);
        fail(kv.first, where.empty() ? k : where + "." + k, "unknown key (known: " + list + ")");
      }
      if (const auto [at, fresh] = first_line.emplace(k, kv.first.Mark().line); !fresh)
        fail(kv.first, where.empty() ? k : where + "." + k,
             fmt::format("given twice (first at line {}); give each key once", at->second + 1));
    }
  }

  static std::string join(const std::string& where, std::string_view k) {
    return where.empty() ? std::string(k) : where + "." + std::string(k);
  }

  double to_double(const YAML::Node& v, const std::string& key) const {
    if (!v.IsScalar()) fail(v, key, "expected a number");
    double x = 0;
    try {
      x = v.as<double>();
    } catch (const YAML::Exception&) {
      fail(v, key, fmt::format("expected a number, got '{}'", v.Scalar()));
    }
    if (!std::isfinite(x)) fail(v, key, fmt::format("must be a finite number, got '{}'", v.Scalar()));
    return x;
  }

  // Reads a number if present (else keeps `out`) and checks it with `ok` (message `need`).
  void num(const YAML::Node& sec, const std::string& where, std::string_view k, double& out,
           const std::function<bool(double)>& ok, std::string_view need) const {
    const YAML::Node v = sec[std::string(k)];
    if (!v.IsDefined()) return;
    const std::string key = join(where, k);
    const double x = to_double(v, key);
    if (!ok(x)) fail(v, key, fmt::format("must be {}, got {}", need, x));
    out = x;
  }

  void opt_num(const YAML::Node& sec, const std::string& where, std::string_view k,
               std::optional<double>& out) const {
    const YAML::Node v = sec[std::string(k)];
    if (!v.IsDefined() || v.IsNull()) return;
    out = to_double(v, join(where, k));
  }

  void str(const YAML::Node& sec, const std::string& where, std::string_view k, std::string& out) const {
    const YAML::Node v = sec[std::string(k)];
    if (!v.IsDefined()) return;
    if (!v.IsScalar()) fail(v, join(where, k), "expected a text value");
    out = v.Scalar();
  }

  template <class E, std::size_t N>
  void enumeration(const YAML::Node& sec, const std::string& where, std::string_view k,
                   const EnumText<E> (&table)[N], E& out) const {
    const YAML::Node v = sec[std::string(k)];
    if (!v.IsDefined()) return;
    const std::string key = join(where, k);
    if (!v.IsScalar()) fail(v, key, "expected a text value");
    std::string list;
    for (const auto& e : table) {
      if (e.text == v.Scalar()) {
        out = e.value;
        return;
      }
      list += (list.empty() ? "" : " | ") + std::string(e.text);
    }
    fail(v, key, fmt::format("unknown value '{}' (one of: {})", v.Scalar(), list));
  }

  // fluid.ca_table: table1 | text | zero | "uniform <Ca>" with a finite Ca >= 0.
  void ca_table(const YAML::Node& sec, const std::string& where, CaTableSpec& out) const {
    const YAML::Node v = sec["ca_table"];
    if (!v.IsDefined()) return;
    const std::string key = join(where, "ca_table");
    if (!v.IsScalar()) fail(v, key, "expected a text value");
    const std::string& t = v.Scalar();
    if (t.rfind("uniform", 0) == 0) {
      const std::string rest = t.substr(7);
      char* end = nullptr;
      const double ca = rest.empty() || !std::isspace(static_cast<unsigned char>(rest[0]))
                            ? std::nan("")
                            : std::strtod(rest.c_str(), &end);
      if (std::isnan(ca) || end == rest.c_str() ||
          std::string_view(end).find_first_not_of(" \t") != std::string_view::npos || !std::isfinite(ca) ||
          ca < 0)
        fail(v, key, fmt::format("expected 'uniform <Ca>' with a finite Ca >= 0, got '{}'", t));
      out = CaTableSpec::uniform(ca);
      return;
    }
    CaTable named = CaTable::Table1;
    try {
      enumeration(sec, where, "ca_table", kCaTable, named);
    } catch (const InputError& e) {
      throw InputError(std::string(e.what()) + " (uniform takes a value: 'uniform 2')");
    }
    out = named;
  }

  void boolean(const YAML::Node& sec, const std::string& where, std::string_view k, bool& out) const {
    const YAML::Node v = sec[std::string(k)];
    if (!v.IsDefined()) return;
    const std::string key = join(where, k);
    if (!v.IsScalar()) fail(v, key, "expected true or false");
    try {
      out = v.as<bool>();
    } catch (const YAML::Exception&) {
      fail(v, key, fmt::format("expected true or false, got '{}'", v.Scalar()));
    }
  }

  std::array<double, 2> pair(const YAML::Node& v, const std::string& key) const {
    if (!v.IsSequence() || v.size() != 2) fail(v, key, "expected a list of two numbers [a, b]");
    return {to_double(v[0], key + "[0]"), to_double(v[1], key + "[1]")};
  }

  const YAML::Node section(const YAML::Node& root, std::string_view k,
                           std::initializer_list<std::string_view> known) const {
    YAML::Node s = root[std::string(k)];
    if (!s.IsDefined() || s.IsNull()) return YAML::Node(YAML::NodeType::Map);
    check_map(s, std::string(k), known);
    return s;
  }
};

const auto positive = [](double x) { return x > 0; };
const auto non_negative = [](double x) { return x >= 0; };
const auto any_value = [](double) { return true; };

}  // namespace

Case parse_case(const std::string& yaml_text, const fs::path& base_dir, const std::string& source,
                bool check_model_keys) {
  const Reader r{source};
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::ParserException& e) {
    throw InputError(fmt::format("{}:{}:{}: YAML syntax error: {}", source, e.mark.line + 1,
                                 e.mark.column + 1, e.msg));
  }
  if (!root.IsDefined() || root.IsNull()) throw InputError(source + ": empty case file");
  r.check_map(root, "", {"name", "description", "hull", "ship", "channel", "ice", "water", "friction",
                         "contact", "fluid", "run", "fsicr", "speedups", "guards", "references"});

  Case c;
  if (!root["name"].IsDefined()) throw InputError(source + ": key 'name': missing (required)");
  r.str(root, "", "name", c.name);
  if (c.name.empty()) r.fail(root["name"], "name", "must not be empty");
  r.str(root, "", "description", c.description);

  {  // hull
    const auto s = r.section(root, "hull", {"file", "draft_m", "lpp_m", "beam_m", "start_x_m", "band_m"});
    std::string file = "jbc_panamax_model.stl";
    r.str(s, "hull", "file", file);
    if (file.empty()) r.fail(s["file"], "hull.file", "must not be empty");
    c.hull.file = resolve_hull_file(base_dir, file);
    r.num(s, "hull", "draft_m", c.hull.draft_m, positive, "> 0");
    r.num(s, "hull", "lpp_m", c.hull.lpp_m, positive, "> 0");
    r.num(s, "hull", "beam_m", c.hull.beam_m, positive, "> 0");
    r.num(s, "hull", "start_x_m", c.hull.start_x_m, any_value, "finite");
    if (const auto b = s["band_m"]; b.IsDefined() && !b.IsNull()) {
      c.hull.band_m = r.pair(b, "hull.band_m");
      if ((*c.hull.band_m)[0] < 0 || (*c.hull.band_m)[1] < 0)
        r.fail(b, "hull.band_m", "both distances (below, above the waterline) must be >= 0");
    }
  }
  {  // ship
    const auto s = r.section(root, "ship", {"speed_m_s", "scale_lambda", "ice_class"});
    r.num(s, "ship", "speed_m_s", c.ship.speed_m_s, positive, "> 0");
    r.num(s, "ship", "scale_lambda", c.ship.scale_lambda, positive, "> 0");
    r.enumeration(s, "ship", "ice_class", kIceClass, c.ship.ice_class);
  }
  {  // channel
    const auto s = r.section(root, "channel", {"length_m", "width_m", "ends"});
    r.num(s, "channel", "length_m", c.channel.length_m, positive, "> 0");
    r.num(s, "channel", "width_m", c.channel.width_m, positive, "> 0");
    r.enumeration(s, "channel", "ends", kChannelEnds, c.channel.ends);
  }
  {  // ice
    const auto s = r.section(root, "ice", {"thickness_m", "diameter_mean_m", "diameter_sd_m",
                                           "diameter_truncation_sd", "density_kg_m3", "porosity",
                                           "packing_mode", "seed", "packing_file", "settle",
                                           "settle_speed_m_s"});
    r.num(s, "ice", "thickness_m", c.ice.thickness_m, positive, "> 0");
    r.num(s, "ice", "diameter_mean_m", c.ice.diameter_mean_m, positive, "> 0");
    c.ice.diameter_sd_m = 0.05 * c.ice.diameter_mean_m;
    r.num(s, "ice", "diameter_sd_m", c.ice.diameter_sd_m, non_negative, ">= 0");
    r.num(s, "ice", "diameter_truncation_sd", c.ice.diameter_truncation_sd, non_negative, ">= 0");
    r.num(s, "ice", "density_kg_m3", c.ice.density_kg_m3, positive, "> 0");
    r.num(s, "ice", "porosity", c.ice.porosity, [](double p) { return p > 0 && p < 1; },
          "in (0, 1)");
    r.enumeration(s, "ice", "packing_mode", kPackingMode, c.ice.packing_mode);
    if (const auto v = s["seed"]; v.IsDefined()) {
      bool ok = v.IsScalar() && !v.Scalar().empty() && v.Scalar()[0] != '-';
      if (ok) {
        try {
          c.ice.seed = v.as<std::uint64_t>();
        } catch (const YAML::Exception&) {
          ok = false;
        }
      }
      if (!ok) r.fail(v, "ice.seed", fmt::format("expected a non-negative integer, got '{}'", v.Scalar()));
    }
    r.boolean(s, "ice", "settle", c.ice.settle);
    r.num(s, "ice", "settle_speed_m_s", c.ice.settle_speed_m_s, positive, "> 0");
    std::string pf = "generated/packing.csv";
    r.str(s, "ice", "packing_file", pf);
    if (pf.empty()) r.fail(s["packing_file"], "ice.packing_file", "must not be empty");
    c.ice.packing_file = fs::absolute(base_dir / pf).lexically_normal();
    if (c.ice.diameter_mean_m - c.ice.diameter_truncation_sd * c.ice.diameter_sd_m <= 0)
      r.fail(s["diameter_sd_m"], "ice.diameter_sd_m",
             fmt::format("mean - truncation_sd * sd = {} - {} * {} must be > 0 (no zero-size spheres)",
                         c.ice.diameter_mean_m, c.ice.diameter_truncation_sd, c.ice.diameter_sd_m));
    // The ice is a layer of pieces: one thinner than a piece cannot be built (the line is the thickness's, or the
    // diameter's when the thickness is the default).
    if (c.ice.thickness_m < c.ice.diameter_mean_m) {
      const bool given = s["thickness_m"].IsDefined();
      r.fail(given ? s["thickness_m"] : s["diameter_mean_m"], "ice.thickness_m",
             fmt::format("{} m{} is thinner than one piece (ice.diameter_mean_m = {} m): the ice must be at least "
                         "one layer of pieces thick",
                         c.ice.thickness_m, given ? "" : " (the default)", c.ice.diameter_mean_m));
    }
  }
  {  // water
    const auto s = r.section(root, "water",
                             {"density_kg_m3", "level_m", "gravity_m_s2", "kinematic_viscosity_m2_s"});
    r.num(s, "water", "density_kg_m3", c.water.density_kg_m3, positive, "> 0");
    r.num(s, "water", "level_m", c.water.level_m, any_value, "finite");
    r.num(s, "water", "gravity_m_s2", c.water.gravity_m_s2, positive, "> 0");
    r.num(s, "water", "kinematic_viscosity_m2_s", c.water.kinematic_viscosity_m2_s, positive, "> 0");
    if (c.ice.density_kg_m3 >= c.water.density_kg_m3)
      r.fail(root["ice"]["density_kg_m3"], "ice.density_kg_m3",
             fmt::format("ice ({} kg/m^3) must be lighter than water.density_kg_m3 ({}) to float",
                         c.ice.density_kg_m3, c.water.density_kg_m3));
  }
  {  // friction
    const auto s = r.section(root, "friction", {"ice_ice", "ice_hull", "ice_wall"});
    r.num(s, "friction", "ice_ice", c.friction.ice_ice, non_negative, ">= 0");
    r.num(s, "friction", "ice_hull", c.friction.ice_hull, non_negative, ">= 0");
    r.num(s, "friction", "ice_wall", c.friction.ice_wall, non_negative, ">= 0");
  }
  {  // contact
    const auto s = r.section(root, "contact", {"youngs_modulus_pa", "poisson_ratio", "restitution"});
    r.num(s, "contact", "youngs_modulus_pa", c.contact.youngs_modulus_pa, positive, "> 0");
    r.num(s, "contact", "poisson_ratio", c.contact.poisson_ratio,
          [](double v) { return v > -1 && v < 0.5; }, "in (-1, 0.5)");
    r.num(s, "contact", "restitution", c.contact.restitution,
          [](double e) { return e > 0 && e <= 1; }, "in (0, 1]");
  }
  {  // fluid
    const auto s = r.section(root, "fluid",
                             {"model", "treatment", "drag_coefficient", "drag_law", "ca_table", "hull_flow"});
    r.enumeration(s, "fluid", "model", kFluidModel, c.fluid.model);
    r.enumeration(s, "fluid", "treatment", kTreatment, c.fluid.treatment);
    r.num(s, "fluid", "drag_coefficient", c.fluid.drag_coefficient, non_negative, ">= 0");
    r.enumeration(s, "fluid", "drag_law", kDragLaw, c.fluid.drag_law);
    r.ca_table(s, "fluid", c.fluid.ca_table);
    r.enumeration(s, "fluid", "hull_flow", kHullFlow, c.fluid.hull_flow);
    if (check_model_keys && c.fluid.hull_flow != HullFlow::None && c.fluid.model == FluidModel::AddedMass)
      r.fail(
          s["hull_flow"], "fluid.hull_flow",
          "the flow around the hull acts through the drag, and fluid.model added_mass has none: use drag or "
          "both, or hull_flow: none");
  }
  {  // run
    const auto s = r.section(root, "run", {"duration_s", "timestep_s", "output_interval_s",
                                           "dump_interval_s", "window_s"});
    r.num(s, "run", "duration_s", c.run.duration_s, positive, "> 0");
    r.num(s, "run", "timestep_s", c.run.timestep_s, positive, "> 0");
    r.num(s, "run", "output_interval_s", c.run.output_interval_s, positive, "> 0");
    r.num(s, "run", "dump_interval_s", c.run.dump_interval_s, positive, "> 0");
    if (const auto w = s["window_s"]; w.IsDefined()) {
      c.run.window_s = r.pair(w, "run.window_s");
    } else if (c.run.window_s[1] > c.run.duration_s) {
      // Default window [15, 40] s does not fit a short run: average over its last 60 %.
      c.run.window_s = {0.4 * c.run.duration_s, c.run.duration_s};
    }
    const auto [w0, w1] = c.run.window_s;
    if (!(w0 >= 0 && w0 < w1 && w1 <= c.run.duration_s))
      r.fail(s["window_s"], "run.window_s",
             fmt::format("window [{}, {}] s must satisfy 0 <= start < end <= run.duration_s = {}", w0, w1,
                         c.run.duration_s));
    if (c.run.timestep_s > c.run.output_interval_s)
      r.fail(s["timestep_s"], "run.timestep_s",
             fmt::format("timestep {} s is longer than run.output_interval_s {} s", c.run.timestep_s,
                         c.run.output_interval_s));
    // Contact stability: the time step must resolve the Rayleigh time of the smallest sphere,
    // T_R = pi r sqrt(rho / G) / (0.1631 nu + 0.8766), G = E / (2 (1 + nu)) (docs/stability.md).
    if (const double tr = rayleigh_time_s(c); c.run.timestep_s > kMaxTimestepOverRayleigh * tr)
      r.fail(s["timestep_s"], "run.timestep_s",
             fmt::format("timestep {} s is {:.0f} % of the Rayleigh time {:.3g} s of the smallest sphere (d = {:.4g} m, "
                         "contact.youngs_modulus_pa = {}, ice.density_kg_m3 = {}); contacts are unstable above {:.0f} %: "
                         "use <= {:.3g} s",
                         c.run.timestep_s, 100 * c.run.timestep_s / tr, tr, 2 * min_radius_m(c),
                         c.contact.youngs_modulus_pa, c.ice.density_kg_m3, 100 * kMaxTimestepOverRayleigh,
                         kMaxTimestepOverRayleigh * tr));
    if (c.run.output_interval_s > c.run.duration_s)
      r.fail(s["output_interval_s"], "run.output_interval_s",
             fmt::format("{} s is longer than run.duration_s {} s", c.run.output_interval_s,
                         c.run.duration_s));
  }
  {  // fsicr
    const auto s = r.section(root, "fsicr",
                             {"alpha_deg", "phi1_deg", "phi2_deg", "psi_deg", "L_par_m", "L_bow_m", "A_wf_m2"});
    // values no hull has are errors here; values outside the rule's validity range are the report's warnings
    const auto bounded = [&](std::string_view k, std::optional<double>& out, auto ok, std::string_view need) {
      r.opt_num(s, "fsicr", k, out);
      if (out && !ok(*out)) r.fail(s[std::string(k)], "fsicr." + std::string(k), fmt::format("must be {}, got {}", need, *out));
    };
    const auto angle = [](double a) { return a > 0 && a <= 90; };
    bounded("alpha_deg", c.fsicr.alpha_deg, angle, "an angle in (0, 90] deg");
    bounded("phi1_deg", c.fsicr.phi1_deg, angle, "an angle in (0, 90] deg");
    bounded("phi2_deg", c.fsicr.phi2_deg, angle, "an angle in (0, 90] deg");
    bounded("psi_deg", c.fsicr.psi_deg, angle, "an angle in (0, 90] deg");
    bounded("L_par_m", c.fsicr.L_par_m, non_negative, ">= 0 (m, full scale)");
    bounded("L_bow_m", c.fsicr.L_bow_m, positive, "> 0 (m, full scale)");
    bounded("A_wf_m2", c.fsicr.A_wf_m2, positive, "> 0 (m^2, full scale)");
  }
  {  // speedups (docs/performance.md)
    const auto s = r.section(root, "speedups",
                             {"farfield", "farfield_ahead_m", "farfield_behind_m", "farfield_beside_m", "farfield_every_steps",
                              "farfield_wake_force_weight", "farfield_wake_speed_m_s", "farfield_wake_by", "farfield_front_speed_m_s", "moving_window",
                              "moving_window_ahead_m", "moving_window_behind_m", "symmetry_y", "neighbor_skin_d", "early_stop_rel_ci", "early_stop_trend_check"});
    r.boolean(s, "speedups", "farfield", c.speedups.farfield);
    r.num(s, "speedups", "farfield_ahead_m", c.speedups.farfield_ahead_m, non_negative, ">= 0");
    r.num(s, "speedups", "farfield_behind_m", c.speedups.farfield_behind_m, non_negative, ">= 0");
    r.opt_num(s, "speedups", "farfield_beside_m", c.speedups.farfield_beside_m);
    if (c.speedups.farfield_beside_m && !(*c.speedups.farfield_beside_m >= 0))
      r.fail(s["farfield_beside_m"], "speedups.farfield_beside_m",
             fmt::format("must be >= 0 (m beyond the hull's half beam), got {}", *c.speedups.farfield_beside_m));
    double every = c.speedups.farfield_every_steps;
    r.num(s, "speedups", "farfield_every_steps", every,
          [](double n) { return n >= 1 && n <= 1e6 && n == std::floor(n); }, "an integer in [1, 1000000]");
    c.speedups.farfield_every_steps = static_cast<int>(every);
    r.num(s, "speedups", "farfield_wake_force_weight", c.speedups.farfield_wake_force_weight,
          [](double f) { return f >= 0 && f <= 1; }, "in [0, 1] (fraction of a piece's weight; 0 = the window alone)");
    r.num(s, "speedups", "farfield_wake_speed_m_s", c.speedups.farfield_wake_speed_m_s, non_negative, ">= 0");
    r.enumeration(s, "speedups", "farfield_wake_by", kWakeBy, c.speedups.farfield_wake_by);
    if (c.speedups.farfield && c.speedups.farfield_wake_by == WakeBy::NeighbourSpeed &&
        !(c.speedups.farfield_wake_speed_m_s > 0))
      r.fail(s["farfield_wake_speed_m_s"], "speedups.farfield_wake_speed_m_s",
             "must be > 0 with farfield_wake_by: neighbour_speed (it is the speed that wakes idle ice; for the "
             "window alone use farfield_wake_by: force with farfield_wake_force_weight: 0)");
    r.num(s, "speedups", "farfield_front_speed_m_s", c.speedups.farfield_front_speed_m_s, non_negative, ">= 0");
    if (c.speedups.farfield && c.speedups.farfield_wake_by == WakeBy::PushFront &&
        !(c.speedups.farfield_front_speed_m_s > 0))
      r.fail(s["farfield_front_speed_m_s"], "speedups.farfield_front_speed_m_s",
             "must be > 0 with farfield_wake_by: push_front (the window's front follows the pieces moving "
             "ahead faster than it)");
    r.boolean(s, "speedups", "moving_window", c.speedups.moving_window);
    r.num(s, "speedups", "moving_window_ahead_m", c.speedups.moving_window_ahead_m, positive, "> 0");
    r.num(s, "speedups", "moving_window_behind_m", c.speedups.moving_window_behind_m, positive, "> 0");
    r.boolean(s, "speedups", "symmetry_y", c.speedups.symmetry_y);
    r.num(s, "speedups", "neighbor_skin_d", c.speedups.neighbor_skin_d,
          [](double k) { return k > 0 && k <= 2; }, "in (0, 2]");
    r.num(s, "speedups", "early_stop_rel_ci", c.speedups.early_stop_rel_ci,
          [](double f) { return f >= 0 && f < 1; }, "in [0, 1) (0 = off)");
    r.boolean(s, "speedups", "early_stop_trend_check", c.speedups.early_stop_trend_check);
    // Ice is disturbed up to a few diameters ahead of the bow; an idle zone that starts closer
    // would stop pieces the bow is already pushing.
    if (c.speedups.farfield && c.speedups.farfield_ahead_m < 2 * c.ice.diameter_mean_m)
      r.fail(s["farfield_ahead_m"], "speedups.farfield_ahead_m",
             fmt::format("{} m is less than 2 ice diameters ({} m): the bow would push idle ice",
                         c.speedups.farfield_ahead_m, 2 * c.ice.diameter_mean_m));
    // The held-out bed must lie beyond the ice the scene integrates (the far field's window ahead).
    const double least_ahead_m =
        std::max(2 * c.ice.diameter_mean_m, c.speedups.farfield ? c.speedups.farfield_ahead_m : 0.0);
    if (c.speedups.moving_window && !c.ice.settle)
      r.fail(s["moving_window"], "speedups.moving_window",
             "needs ice.settle: true (a held-out piece re-enters the scene at rest, where it was: the settled bed is "
             "at rest, the packing is not)");
    if (c.speedups.moving_window && !(c.speedups.farfield_wake_speed_m_s > 0))
      r.fail(s["farfield_wake_speed_m_s"], "speedups.farfield_wake_speed_m_s",
             "must be > 0 with moving_window: true (the window's front leads the ice moving faster than it)");
    if (c.speedups.moving_window && c.speedups.moving_window_ahead_m < least_ahead_m)
      r.fail(s["moving_window_ahead_m"], "speedups.moving_window_ahead_m",
             fmt::format("{} m is less than {} m (2 ice diameters and farfield_ahead_m): the bow would push "
                         "into the held-out bed",
                         c.speedups.moving_window_ahead_m, least_ahead_m));
  }
  {  // guards (docs/stability.md)
    const auto s = r.section(root, "guards", {"max_hull_penetration_d", "every_steps"});
    r.num(s, "guards", "max_hull_penetration_d", c.guards.max_hull_penetration_d,
          [](double f) { return f >= 0 && f <= 10; }, "in [0, 10] (fraction of the piece diameter; 0 = off)");
    double every = c.guards.every_steps;
    r.num(s, "guards", "every_steps", every, [](double n) { return n >= 1 && n <= 1e6 && n == std::floor(n); },
          "an integer in [1, 1000000]");
    c.guards.every_steps = static_cast<int>(every);
  }
  {  // references: published values the report compares with (none unless declared)
    const auto s = r.section(root, "references", {"source", "resistance_full_kN", "fsicr_R_CH_kN", "ratio_fsicr_to_sim"});
    r.str(s, "references", "source", c.references.source);
    const auto per_model = [&](std::string_view k, std::map<std::string, double>& out) {
      const YAML::Node m = s[std::string(k)];
      if (!m.IsDefined() || m.IsNull()) return;
      const std::string where = "references." + std::string(k);
      r.check_map(m, where, {"drag", "added_mass", "both"});
      for (const auto& kv : m) {
        const std::string model = kv.first.as<std::string>();
        r.num(m, where, model, out[model], positive, "> 0");
      }
    };
    per_model("resistance_full_kN", c.references.resistance_full_kN);
    per_model("ratio_fsicr_to_sim", c.references.ratio_fsicr_to_sim);
    if (const auto v = s["fsicr_R_CH_kN"]; v.IsDefined() && !v.IsNull()) {
      double kN = 0;
      r.num(s, "references", "fsicr_R_CH_kN", kN, positive, "> 0");
      c.references.fsicr_R_CH_kN = kN;
    }
    if (c.references.declared() && c.references.source.empty())
      r.fail(s, "references.source", "missing: name where the reference values are published");
  }
  return c;
}

double min_radius_m(const Case& c) {
  return 0.5 * (c.ice.diameter_mean_m - c.ice.diameter_truncation_sd * c.ice.diameter_sd_m);
}

double rayleigh_time_s(const Case& c) {
  return rayleigh_time_s(min_radius_m(c), c.ice.density_kg_m3, c.contact.youngs_modulus_pa, c.contact.poisson_ratio);
}

Case load_case(const fs::path& case_yaml, bool check_model_keys) {
  std::ifstream in(case_yaml);
  if (!in) throw InputError(case_yaml.string() + ": cannot open case file");
  std::stringstream ss;
  ss << in.rdbuf();
  const fs::path dir = fs::absolute(case_yaml).parent_path();
  return parse_case(ss.str(), dir, case_yaml.string(), check_model_keys);
}

// ---------------------------------------------------------------- writing
namespace {

// Double-quoted YAML string (always quoted so text like "no" or "1.0" stays text).
std::string yaml_quoted(std::string_view s) {
  std::string out = "\"";
  for (const char ch : s) {
    switch (ch) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      default:
        if (static_cast<unsigned char>(ch) < 0x20)
          out += fmt::format("\\x{:02x}", static_cast<unsigned char>(ch));
        else
          out += ch;
    }
  }
  return out + "\"";
}

// Shortest text that reads back to the same double; always carries a '.' or exponent.
std::string num(double x) {
  std::string s = fmt::format("{}", x);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

}  // namespace

std::string dump_case_yaml(const Case& c) {
  std::string o;
  auto line = [&o](std::string_view indent, std::string_view key, const std::string& v) {
    o += fmt::format("{}{}: {}\n", indent, key, v);
  };
  auto pair = [](const std::array<double, 2>& p) { return fmt::format("[{}, {}]", num(p[0]), num(p[1])); };
  o += "# brash resolved case: every default filled in, paths absolute (docs/case_format.md)\n";
  line("", "name", yaml_quoted(c.name));
  line("", "description", yaml_quoted(c.description));
  o += "hull:\n";
  line("  ", "file", yaml_quoted(c.hull.file.string()));
  line("  ", "draft_m", num(c.hull.draft_m));
  line("  ", "lpp_m", num(c.hull.lpp_m));
  line("  ", "beam_m", num(c.hull.beam_m));
  line("  ", "start_x_m", num(c.hull.start_x_m));
  if (c.hull.band_m) line("  ", "band_m", pair(*c.hull.band_m));
  o += "ship:\n";
  line("  ", "speed_m_s", num(c.ship.speed_m_s));
  line("  ", "scale_lambda", num(c.ship.scale_lambda));
  line("  ", "ice_class", std::string(to_string(c.ship.ice_class)));
  o += "channel:\n";
  line("  ", "length_m", num(c.channel.length_m));
  line("  ", "width_m", num(c.channel.width_m));
  if (c.channel.ends != ChannelEnds::Open) line("  ", "ends", std::string(to_string(c.channel.ends)));
  o += "ice:\n";
  line("  ", "thickness_m", num(c.ice.thickness_m));
  line("  ", "diameter_mean_m", num(c.ice.diameter_mean_m));
  line("  ", "diameter_sd_m", num(c.ice.diameter_sd_m));
  line("  ", "diameter_truncation_sd", num(c.ice.diameter_truncation_sd));
  line("  ", "density_kg_m3", num(c.ice.density_kg_m3));
  line("  ", "porosity", num(c.ice.porosity));
  line("  ", "packing_mode", std::string(to_string(c.ice.packing_mode)));
  line("  ", "seed", fmt::format("{}", c.ice.seed));
  line("  ", "packing_file", yaml_quoted(c.ice.packing_file.string()));
  if (c.ice.settle) {
    line("  ", "settle", "true");
    line("  ", "settle_speed_m_s", num(c.ice.settle_speed_m_s));
  }
  o += "water:\n";
  line("  ", "density_kg_m3", num(c.water.density_kg_m3));
  line("  ", "level_m", num(c.water.level_m));
  line("  ", "gravity_m_s2", num(c.water.gravity_m_s2));
  line("  ", "kinematic_viscosity_m2_s", num(c.water.kinematic_viscosity_m2_s));
  o += "friction:\n";
  line("  ", "ice_ice", num(c.friction.ice_ice));
  line("  ", "ice_hull", num(c.friction.ice_hull));
  line("  ", "ice_wall", num(c.friction.ice_wall));
  o += "contact:\n";
  line("  ", "youngs_modulus_pa", num(c.contact.youngs_modulus_pa));
  line("  ", "poisson_ratio", num(c.contact.poisson_ratio));
  line("  ", "restitution", num(c.contact.restitution));
  o += "fluid:\n";
  line("  ", "model", std::string(to_string(c.fluid.model)));
  line("  ", "treatment", std::string(to_string(c.fluid.treatment)));
  line("  ", "drag_coefficient", num(c.fluid.drag_coefficient));
  line("  ", "drag_law", std::string(to_string(c.fluid.drag_law)));
  line("  ", "ca_table", to_string(c.fluid.ca_table));
  if (c.fluid.hull_flow != HullFlow::None) line("  ", "hull_flow", std::string(to_string(c.fluid.hull_flow)));
  o += "run:\n";
  line("  ", "duration_s", num(c.run.duration_s));
  line("  ", "timestep_s", num(c.run.timestep_s));
  line("  ", "output_interval_s", num(c.run.output_interval_s));
  line("  ", "dump_interval_s", num(c.run.dump_interval_s));
  line("  ", "window_s", pair(c.run.window_s));
  const std::pair<std::string_view, const std::optional<double>*> fs_keys[] = {
      {"alpha_deg", &c.fsicr.alpha_deg}, {"phi1_deg", &c.fsicr.phi1_deg}, {"phi2_deg", &c.fsicr.phi2_deg},
      {"psi_deg", &c.fsicr.psi_deg},     {"L_par_m", &c.fsicr.L_par_m},   {"L_bow_m", &c.fsicr.L_bow_m},
      {"A_wf_m2", &c.fsicr.A_wf_m2}};
  std::string fsicr;
  for (const auto& [k, v] : fs_keys)
    if (v->has_value()) fsicr += fmt::format("  {}: {}\n", k, num(**v));
  o += fsicr.empty() ? "fsicr: {}\n" : "fsicr:\n" + fsicr;
  o += "speedups:\n";
  line("  ", "farfield", c.speedups.farfield ? "true" : "false");
  line("  ", "farfield_ahead_m", num(c.speedups.farfield_ahead_m));
  line("  ", "farfield_behind_m", num(c.speedups.farfield_behind_m));
  if (c.speedups.farfield_beside_m) line("  ", "farfield_beside_m", num(*c.speedups.farfield_beside_m));
  line("  ", "farfield_every_steps", fmt::format("{}", c.speedups.farfield_every_steps));
  line("  ", "farfield_wake_force_weight", num(c.speedups.farfield_wake_force_weight));
  line("  ", "farfield_wake_speed_m_s", num(c.speedups.farfield_wake_speed_m_s));
  line("  ", "farfield_wake_by", std::string(to_string(c.speedups.farfield_wake_by)));
  line("  ", "farfield_front_speed_m_s", num(c.speedups.farfield_front_speed_m_s));
  line("  ", "moving_window", c.speedups.moving_window ? "true" : "false");
  line("  ", "moving_window_ahead_m", num(c.speedups.moving_window_ahead_m));
  line("  ", "moving_window_behind_m", num(c.speedups.moving_window_behind_m));
  line("  ", "symmetry_y", c.speedups.symmetry_y ? "true" : "false");
  line("  ", "neighbor_skin_d", num(c.speedups.neighbor_skin_d));
  line("  ", "early_stop_rel_ci", num(c.speedups.early_stop_rel_ci));
  line("  ", "early_stop_trend_check", c.speedups.early_stop_trend_check ? "true" : "false");
  o += "guards:\n";
  line("  ", "max_hull_penetration_d", num(c.guards.max_hull_penetration_d));
  line("  ", "every_steps", fmt::format("{}", c.guards.every_steps));
  if (const auto& ref = c.references; ref.declared() || !ref.source.empty()) {
    o += "references:\n";
    line("  ", "source", yaml_quoted(ref.source));
    const auto per_model = [&](std::string_view key, const std::map<std::string, double>& values) {
      if (values.empty()) return;
      o += fmt::format("  {}:\n", key);
      for (const auto& [model, v] : values) line("    ", model, num(v));
    };
    per_model("resistance_full_kN", ref.resistance_full_kN);
    if (ref.fsicr_R_CH_kN) line("  ", "fsicr_R_CH_kN", num(*ref.fsicr_R_CH_kN));
    per_model("ratio_fsicr_to_sim", ref.ratio_fsicr_to_sim);
  }
  return o;
}

}  // namespace brash
