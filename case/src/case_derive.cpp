// Case variants (see brash/case_derive.hpp): the base's YAML node tree with keys set, checked by the case loader.
#include "brash/case_derive.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <iterator>
#include <optional>
#include <set>
#include <tuple>
#include <utility>

#include <unistd.h>

#include "brash/error.hpp"
#include "brash/packing.hpp"

namespace fs = std::filesystem;

namespace brash {

namespace {

// "ice.seed" -> {"ice", "seed"}; every part must be a non-empty name.
std::vector<std::string> split_key(const std::string& key, const std::string& source) {
  std::vector<std::string> parts;
  std::size_t from = 0;
  while (true) {
    const std::size_t dot = key.find('.', from);
    parts.push_back(key.substr(from, dot == std::string::npos ? std::string::npos : dot - from));
    if (parts.back().empty())
      throw InputError(fmt::format("{}: key '{}': not a dotted case key (like fluid.model or run.window_s)", source, key));
    if (dot == std::string::npos) return parts;
    from = dot + 1;
  }
}

void check_each_key_once(const CaseOverrides& overrides, const std::string& source) {
  std::set<std::string> seen;
  for (const auto& [key, value] : overrides)
    if (!seen.insert(key).second)
      throw InputError(fmt::format("{}: key '{}': given twice among the overrides; give each key once", source, key));
}

// The value as YAML ("[0.375, 0.75]" a list, written back in flow style); a null value (empty, ~) removes the key.
YAML::Node parse_value(const std::string& key, const std::string& text, const std::string& source) {
  try {
    YAML::Node v = YAML::Load(text);
    if (v.IsSequence()) v.SetStyle(YAML::EmitterStyle::Flow);
    return v;
  } catch (const YAML::ParserException& e) {
    throw InputError(fmt::format("{}: key '{}': value '{}' is not YAML: {}", source, key, text, e.msg));
  }
}

// Sets (or, for a null value, removes) parts[i..] below the mapping `node`, making missing sections.
void set_at(YAML::Node node, const std::vector<std::string>& parts, std::size_t i, const YAML::Node& value,
            const std::string& key, const std::string& source) {
  const std::string& k = parts[i];
  if (i + 1 == parts.size()) {
    if (value.IsNull())
      node.remove(k);
    else
      node[k] = value;
    return;
  }
  if (!node[k].IsDefined() || node[k].IsNull()) {
    if (value.IsNull()) return;  // nothing to remove
    node[k] = YAML::Node(YAML::NodeType::Map);
  }
  if (!node[k].IsMap())
    throw InputError(fmt::format("{}: key '{}': '{}' is a value, not a section of keys", source, key, k));
  set_at(node[k], parts, i + 1, value, key, source);
}

bool given(const CaseOverrides& overrides, std::string_view key) {
  return std::any_of(overrides.begin(), overrides.end(), [&](const CaseOverride& o) { return o.first == key; });
}

// Whether files can be made at `file`: its nearest existing folder is writable (an installed case's folder is not).
bool can_write_at(const fs::path& file) {
  fs::path dir = file.parent_path();
  std::error_code ec;
  while (!dir.empty() && !fs::exists(dir, ec) && dir != dir.parent_path()) dir = dir.parent_path();
  return !dir.empty() && ::access(dir.c_str(), W_OK) == 0;
}

// A run made shorter than its base's averaging window (run.duration_s set, run.window_s not) keeps its window inside
// the run: [min(start, duration / 2), duration] (brash/case_derive.hpp, "Window"). A base without run.window_s
// needs nothing: the loader's default window follows the duration.
void keep_window_in_run(YAML::Node root, const Case& base, const CaseOverrides& overrides) {
  if (!given(overrides, "run.duration_s") || given(overrides, "run.window_s")) return;
  const YAML::Node run = std::as_const(root)["run"];
  if (!run.IsMap() || !run["window_s"].IsDefined() || !run["duration_s"].IsScalar()) return;
  double duration_s = 0;
  try {
    duration_s = run["duration_s"].as<double>();
  } catch (const YAML::Exception&) {
    return;  // not a number: the loader names the key
  }
  if (!(duration_s > 0) || duration_s >= base.run.window_s[1]) return;
  YAML::Node window(YAML::NodeType::Sequence);
  window.SetStyle(YAML::EmitterStyle::Flow);
  window.push_back(fmt::format("{}", std::min(base.run.window_s[0], 0.5 * duration_s)));  // shortest exact text
  window.push_back(fmt::format("{}", duration_s));
  root["run"]["window_s"] = window;
}

// The base's hull file and packing, seen from another folder (brash/case_derive.hpp, "Paths").
void fix_paths(YAML::Node root, const Case& base, const fs::path& base_dir, const CaseOverrides& overrides,
               const Case& derived) {
  if (!given(overrides, "hull.file")) {
    const YAML::Node hull = std::as_const(root)["hull"];  // a base without a hull section takes the defaults
    const YAML::Node file = hull.IsDefined() && hull.IsMap() ? std::as_const(hull)["file"] : YAML::Node();
    // without the key the loader's default applies, a bare file name (the one the resolved file carries)
    const fs::path name = file.IsDefined() && file.IsScalar() ? fs::path(file.Scalar()) : base.hull.file.filename();
    std::error_code ec;
    if (name.is_relative() && fs::is_regular_file(base_dir / name, ec)) root["hull"]["file"] = base.hull.file.string();
  }
  if (!given(overrides, "ice.packing_file"))
    root["ice"]["packing_file"] =
        same_packing_inputs(base, derived) && can_write_at(base.ice.packing_file) ? base.ice.packing_file.string()
                                                                                  : std::string("generated/packing.csv");
}

// Keys of how a run is computed, not of the hull, speed, ice or fluid it computes: a variant that changes only
// these still describes its base's published references (a key ending in '.' stands for its whole section).
constexpr std::array<std::string_view, 17> kKeysKeepingReferences{
    "name",          "description",          "run.",           "speedups.",       "guards.",      "ode.",
    "fsicr.",        "references.",          "contact.youngs_modulus_pa",         "fluid.model",
    "fluid.treatment", "hull.band_m",        "hull.start_x_m", "ice.seed",        "ice.settle",
    "ice.settle_speed_m_s", "ice.packing_file"};

bool keeps_references(std::string_view key) {
  return std::ranges::any_of(kKeysKeepingReferences,
                             [&](std::string_view k) { return k.ends_with('.') ? key.starts_with(k) : key == k; });
}

// The dotted keys under which two YAML mappings differ (a key on one side only counts), into `out`.
void differing_keys(const YAML::Node& a, const YAML::Node& b, const std::string& prefix, std::set<std::string>& out) {
  std::set<std::string> names;
  for (const YAML::Node* side : {&a, &b})
    if (side->IsMap())
      for (const auto& kv : *side) names.insert(kv.first.Scalar());
  for (const auto& name : names) {
    const YAML::Node x = a.IsMap() ? a[name] : YAML::Node(YAML::NodeType::Undefined);
    const YAML::Node y = b.IsMap() ? b[name] : YAML::Node(YAML::NodeType::Undefined);
    if (!x.IsDefined() || !y.IsDefined())  // (a key missing on one side is an invalid node there: ask nothing more)
      out.insert(prefix + name);
    else if (x.IsMap() && y.IsMap())
      differing_keys(x, y, prefix + name + ".", out);
    else if (YAML::Dump(x) != YAML::Dump(y))
      out.insert(prefix + name);
  }
}

bool sets_references(const CaseOverrides& overrides) {
  return std::ranges::any_of(overrides, [](const CaseOverride& o) {
    return o.first == "references" || o.first.starts_with("references.");
  });
}

std::string emit(const YAML::Node& root) {
  YAML::Emitter e;
  e << root;
  return std::string(e.c_str()) + "\n";
}

bool is_under(const fs::path& file, const fs::path& dir) {
  const fs::path rel = fs::absolute(file).lexically_normal().lexically_relative(fs::absolute(dir).lexically_normal());
  return !rel.empty() && *rel.begin() != "..";
}

std::string describe(const CaseOverrides& overrides) {
  std::string s;
  for (const auto& [key, value] : overrides) s += fmt::format("{}{}={}", s.empty() ? "" : ", ", key, value);
  std::replace(s.begin(), s.end(), '\n', ' ');
  return s.empty() ? "no overrides" : s;
}

}  // namespace

CaseOverride parse_case_override(std::string_view text) {
  const std::size_t eq = text.find('=');
  if (eq == std::string_view::npos || eq == 0)
    throw InputError(fmt::format("override '{}': expected key=value (like fluid.model=drag)", text));
  return {std::string(text.substr(0, eq)), std::string(text.substr(eq + 1))};
}

bool same_packing_inputs(const Case& a, const Case& b) {
  // every field of brash::PackingRequest but its `source` (a name for messages)
  const auto inputs = [](const Case& c) {
    const PackingRequest r = packing_request(c, "");
    return std::make_tuple(r.length_m, r.width_m, r.thickness_m, r.diameter_mean_m, r.diameter_sd_m, r.truncation_sd,
                           r.porosity, r.ice_density_kg_m3, r.water_density_kg_m3, r.water_level_m, r.mode, r.seed,
                           r.drops_per_sphere);
  };
  return inputs(a) == inputs(b);
}

std::vector<std::string> differing_case_keys(const Case& a, const Case& b) {
  std::set<std::string> changed;
  differing_keys(YAML::Load(dump_case_yaml(a)), YAML::Load(dump_case_yaml(b)), "", changed);
  return {changed.begin(), changed.end()};
}

std::vector<std::string> keys_beyond_references(const Case& base, const Case& variant) {
  std::vector<std::string> keys;
  std::ranges::copy_if(differing_case_keys(base, variant), std::back_inserter(keys),
                       [](const std::string& k) { return !keeps_references(k); });
  return keys;
}

std::string derive_case(const fs::path& base_case_file, const CaseOverrides& overrides) {
  // a new fluid.model may be what makes the base's other fluid keys valid (a hull-flow case run with drag): the
  // model checks wait for the derived case
  const bool model_overridden =
      std::ranges::any_of(overrides, [](const CaseOverride& o) { return o.first == "fluid.model"; });
  const Case base = load_case(base_case_file, !model_overridden);
  const std::string base_name = base_case_file.string();
  check_each_key_once(overrides, base_name);
  YAML::Node root = YAML::LoadFile(base_name);
  for (const auto& [key, value] : overrides)
    set_at(root, split_key(key, base_name), 0, parse_value(key, value, base_name), key, base_name);
  keep_window_in_run(root, base, overrides);
  const fs::path base_dir = fs::absolute(base_case_file).parent_path();
  // the derived file's first line; the loader's line numbers count it
  const std::string header = fmt::format("# Derived by brash-case from {} with: {} (keys: docs/case_format.md)\n",
                                         fs::absolute(base_case_file).lexically_normal().string(), describe(overrides));
  const std::string source = fmt::format("derived case ({} with {})", base_name, describe(overrides));
  const Case variant = parse_case(header + emit(root), base_dir, source);
  fix_paths(root, base, base_dir, overrides, variant);
  if (!sets_references(overrides) && !keys_beyond_references(base, variant).empty()) root.remove("references");
  const std::string text = header + emit(root);
  (void)parse_case(text, base_dir, source);
  return text;
}

Case write_derived_case(const fs::path& base_case_file, const CaseOverrides& overrides, const fs::path& out_dir,
                        bool overwrite) {
  const std::string text = derive_case(base_case_file, overrides);
  const fs::path file = out_dir / "case.yaml";
  std::optional<Case> before;  // the folder's earlier case, whose packing may be there
  if (fs::exists(file)) {
    if (!overwrite)
      throw InputError(file.string() + ": exists already; not overwritten (brash-case derive --force overwrites it)");
    try {
      before = load_case(file);
    } catch (const InputError&) {
    }
  }
  fs::create_directories(out_dir);
  const fs::path tmp = out_dir / "case.yaml.tmp";
  {
    std::ofstream out(tmp);
    out << text;
    if (!out) throw InputError(tmp.string() + ": cannot write");
  }
  fs::rename(tmp, file);
  const Case c = load_case(file);
  const fs::path pack = c.ice.packing_file;
  const bool still_valid = before && before->ice.packing_file == pack && same_packing_inputs(*before, c);
  if (is_under(pack, out_dir) && !still_valid) {
    fs::remove(pack);
    fs::remove(pack.parent_path() / (pack.stem().string() + ".json"));
  }
  return c;
}

std::string case_value(const Case& c, std::string_view dotted_key) {
  const std::string key(dotted_key);
  YAML::Node n = YAML::Load(dump_case_yaml(c));
  for (const auto& part : split_key(key, c.name)) {
    const YAML::Node next = n.IsMap() ? std::as_const(n)[part] : YAML::Node(YAML::NodeType::Undefined);
    if (!next.IsDefined())
      throw InputError(fmt::format("key '{}': not in the resolved case (an unknown key, or an optional key the case "
                                   "does not set)",
                                   key));
    n.reset(next);
  }
  if (n.IsMap()) throw InputError(fmt::format("key '{}': a section; name one of its keys", key));
  if (n.IsScalar()) return n.Scalar();
  YAML::Emitter e;
  e << YAML::Flow << n;
  return e.c_str();
}

}  // namespace brash
