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
#include <map>
#include <sstream>
#include <vector>

#include "brash/error.hpp"
#include "brash/paths.hpp"
#include "case_key_table.hpp"

namespace fs = std::filesystem;

namespace brash {

// ---------------------------------------------------------------- enum spellings (case_key_table.hpp)
using case_keys::text_of;
std::string_view to_string(IceClass v) { return text_of(case_keys::kIceClass, v); }
std::string_view to_string(PackingMode v) { return text_of(case_keys::kPackingMode, v); }
std::string_view to_string(CaTable v) { return text_of(case_keys::kCaTable, v); }
std::string_view to_string(ChannelEnds v) { return text_of(case_keys::kChannelEnds, v); }
std::string_view to_string(OdeImplicit v) { return text_of(case_keys::kOdeImplicit, v); }
std::string_view to_string(OdeBroadPhase v) { return text_of(case_keys::kOdeBroadPhase, v); }
std::string_view to_string(OdeSphereOrder v) { return text_of(case_keys::kOdeSphereOrder, v); }
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
namespace case_keys {

void Reader::fail(const YAML::Node& n, const std::string& key, const std::string& msg) const {
  const YAML::Mark m = n.IsDefined() ? n.Mark() : YAML::Mark::null_mark();
  if (m.line >= 0) throw InputError(fmt::format("{}:{}:{}: key '{}': {}", source, m.line + 1, m.column + 1, key, msg));
  throw InputError(fmt::format("{}: key '{}': {}", source, key, msg));
}

// yaml-cpp keeps both of two equal keys and reads the first, so the second would be ignored without a word.
void Reader::check_map(const YAML::Node& n, const std::string& where, std::span<const std::string_view> known) const {
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

double Reader::to_double(const YAML::Node& v, const std::string& key) const {
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

double Reader::number(const YAML::Node& v, const std::string& key, bool (*ok)(double), std::string_view need) const {
  const double x = to_double(v, key);
  if (!ok(x)) fail(v, key, fmt::format("must be {}, got {}", need, x));
  return x;
}

std::string Reader::text(const YAML::Node& v, const std::string& key) const {
  if (!v.IsScalar()) fail(v, key, "expected a text value");
  return v.Scalar();
}

bool Reader::boolean(const YAML::Node& v, const std::string& key) const {
  if (!v.IsScalar()) fail(v, key, "expected true or false");
  try {
    return v.as<bool>();
  } catch (const YAML::Exception&) {
    fail(v, key, fmt::format("expected true or false, got '{}'", v.Scalar()));
  }
}

std::array<double, 2> Reader::pair(const YAML::Node& v, const std::string& key) const {
  if (!v.IsSequence() || v.size() != 2) fail(v, key, "expected a list of two numbers [a, b]");
  return {to_double(v[0], key + "[0]"), to_double(v[1], key + "[1]")};
}

std::uint64_t Reader::seed(const YAML::Node& v, const std::string& key) const {
  if (v.IsScalar() && !v.Scalar().empty() && v.Scalar()[0] != '-') {
    try {
      return v.as<std::uint64_t>();
    } catch (const YAML::Exception&) {
    }
  }
  fail(v, key, fmt::format("expected a non-negative integer, got '{}'", v.Scalar()));
}

// table1 | text | zero | "uniform <Ca>" with a finite Ca >= 0.
CaTableSpec Reader::ca_table(const YAML::Node& v, const std::string& key) const {
  if (!v.IsScalar()) fail(v, key, "expected a text value");
  const std::string& t = v.Scalar();
  if (t.rfind("uniform", 0) == 0) {
    const std::string rest = t.substr(7);
    char* end = nullptr;
    const double ca = rest.empty() || !std::isspace(static_cast<unsigned char>(rest[0]))
                          ? std::nan("")
                          : std::strtod(rest.c_str(), &end);
    if (std::isnan(ca) || end == rest.c_str() ||
        std::string_view(end).find_first_not_of(" \t") != std::string_view::npos || !std::isfinite(ca) || ca < 0)
      fail(v, key, fmt::format("expected 'uniform <Ca>' with a finite Ca >= 0, got '{}'", t));
    return CaTableSpec::uniform(ca);
  }
  try {
    return enumeration(v, key, kCaTable);
  } catch (const InputError& e) {
    throw InputError(std::string(e.what()) + " (uniform takes a value: 'uniform 2')");
  }
}

}  // namespace case_keys

namespace {

using case_keys::Reader;
using case_keys::SectionSpec;

std::vector<std::string_view> key_names(const SectionSpec& s) {
  std::vector<std::string_view> names;
  for (const auto& k : s.keys) names.push_back(k.name);
  return names;
}

// The top level's keys, then the sections.
std::vector<std::string_view> top_level_names() {
  std::vector<std::string_view> names;
  for (const auto& s : case_keys::sections())
    if (s.name.empty())
      names = key_names(s);
    else
      names.push_back(s.name);
  return names;
}

YAML::Node load_yaml(const std::string& yaml_text, const std::string& source) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::ParserException& e) {
    throw InputError(fmt::format("{}:{}:{}: YAML syntax error: {}", source, e.mark.line + 1, e.mark.column + 1, e.msg));
  }
  if (!root.IsDefined() || root.IsNull()) throw InputError(source + ": empty case file");
  return root;
}

// A section's mapping, checked against its keys; a section not given (or null) reads as an empty one.
YAML::Node section_node(const Reader& r, const YAML::Node& root, const SectionSpec& sec) {
  if (sec.name.empty()) return root;
  const YAML::Node s = root[std::string(sec.name)];
  if (!s.IsDefined() || s.IsNull()) return YAML::Node(YAML::NodeType::Map);
  r.check_map(s, std::string(sec.name), key_names(sec));
  return s;
}

// One section: its keys in table order (a key not given keeps its field's default, or takes the key's own), then
// its checks across keys.
void read_section(const Reader& r, const YAML::Node& root, const SectionSpec& sec, Case& c) {
  const YAML::Node s = section_node(r, root, sec);
  for (const auto& k : sec.keys) {
    const YAML::Node v = s[std::string(k.name)];
    if (v.IsDefined())
      k.read(k, r, v, sec.name.empty() ? std::string(k.name) : fmt::format("{}.{}", sec.name, k.name), c);
    else if (k.absent != nullptr)
      k.absent(k, r, c);
  }
  for (const auto& check : sec.checks) check.run(r, root, s, c);
}

}  // namespace

Case parse_case(const std::string& yaml_text, const fs::path& base_dir, const std::string& source,
                bool check_model_keys) {
  const Reader r{source, base_dir, check_model_keys};
  const YAML::Node root = load_yaml(yaml_text, source);
  r.check_map(root, "", top_level_names());
  Case c;
  for (const auto& sec : case_keys::sections()) read_section(r, root, sec, c);
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
namespace case_keys {

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

std::string yaml_number(double x) {
  std::string s = fmt::format("{}", x);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

}  // namespace case_keys

namespace {

// The lines of a section's keys (indent: 2 spaces in a section); a key whose value is a mapping (its value text
// starts with a line break) carries its lines.
std::string key_lines(const SectionSpec& sec, const Case& c) {
  std::string lines;
  for (const auto& k : sec.keys) {
    if (k.written != nullptr && !k.written(c)) continue;
    const std::string v = k.value(c);
    if (v.empty()) continue;  // an optional key not set
    lines += fmt::format("{}{}:{}{}\n", sec.name.empty() ? "" : "  ", k.name, v.starts_with('\n') ? "" : " ", v);
  }
  return lines;
}

}  // namespace

std::string dump_case_yaml(const Case& c) {
  std::string o = "# brash resolved case: every default filled in, paths absolute (docs/case_format.md)\n";
  for (const auto& sec : case_keys::sections()) {
    if (sec.written != nullptr && !sec.written(c)) continue;
    const std::string lines = key_lines(sec, c);
    if (sec.name.empty())
      o += lines;
    else
      o += lines.empty() ? fmt::format("{}: {{}}\n", sec.name) : fmt::format("{}:\n{}", sec.name, lines);
  }
  return o;
}

}  // namespace brash
