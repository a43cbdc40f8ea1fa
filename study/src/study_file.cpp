// The study file reader: strict (every key known and given once, every reference defined), errors name the file,
// the line and the key.
#include "brash/study/study_file.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <initializer_list>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "brash/error.hpp"
#include "brash/fluid_options.hpp"

namespace fs = std::filesystem;

namespace brash::study {

std::string_view to_string(Engine e) {
  switch (e) {
    case Engine::Liggghts: return "liggghts";
    case Engine::Ode: return "ode";
    case Engine::Yade: return "yade";
  }
  return "?";
}

const CaseDef* Study::find_case(std::string_view name) const {
  const auto it = std::ranges::find(cases, name, &CaseDef::name);
  return it == cases.end() ? nullptr : &*it;
}

const CaseDef* Study::find_shared_case(std::string_view name) const {
  const auto it = std::ranges::find(shared_cases, name, &CaseDef::name);
  return it == shared_cases.end() ? nullptr : &*it;
}

namespace {

std::string join(std::initializer_list<std::string_view> words) {
  std::string s;
  for (auto w : words) s += (s.empty() ? "" : ", ") + std::string(w);
  return s;
}

// Reads nodes of one file; every error names the file, the node's line and the key.
struct Reader {
  std::string source;

  [[noreturn]] void fail(const YAML::Node& n, const std::string& key, const std::string& msg) const {
    const YAML::Mark m = n.IsDefined() ? n.Mark() : YAML::Mark::null_mark();
    if (m.line >= 0) throw InputError(fmt::format("{}:{}: key '{}': {}", source, m.line + 1, key, msg));
    throw InputError(fmt::format("{}: key '{}': {}", source, key, msg));
  }

  // A mapping whose keys are all in `known`, each given once (yaml-cpp would keep both of two equal keys).
  void check_map(const YAML::Node& n, const std::string& where, std::initializer_list<std::string_view> known) const {
    if (!n.IsMap()) fail(n, where, "expected a mapping");
    std::map<std::string, int> line_of;
    for (const auto& kv : n) {
      if (!kv.first.IsScalar()) fail(kv.first, where, "keys must be plain names");
      const std::string k = kv.first.Scalar();
      if (std::ranges::find(known, k) == known.end())
        fail(kv.first, where + "." + k, fmt::format("unknown key (known: {})", join(known)));
      if (const auto [at, fresh] = line_of.emplace(k, kv.first.Mark().line); !fresh)
        fail(kv.first, where + "." + k, fmt::format("given twice (first at line {})", at->second + 1));
    }
  }

  // Keys of a mapping the file names freely (case names, case keys), each given once.
  void check_unique_keys(const YAML::Node& n, const std::string& where) const {
    if (!n.IsMap()) fail(n, where, "expected a mapping");
    std::map<std::string, int> line_of;
    for (const auto& kv : n) {
      if (!kv.first.IsScalar()) fail(kv.first, where, "keys must be plain names");
      if (const auto [at, fresh] = line_of.emplace(kv.first.Scalar(), kv.first.Mark().line); !fresh)
        fail(kv.first, where + "." + kv.first.Scalar(), fmt::format("given twice (first at line {})", at->second + 1));
    }
  }

  YAML::Node required(const YAML::Node& map, const std::string& where, const char* key) const {
    const YAML::Node v = map[key];
    if (!v.IsDefined()) fail(map, where.empty() ? key : where + "." + key, "missing (required)");
    return v;
  }

  std::string text(const YAML::Node& v, const std::string& key) const {
    if (!v.IsScalar()) fail(v, key, "expected a single value");
    return v.Scalar();
  }

  // A name used in file and folder names and as a reference: letters, digits, '_', '-', '.'.
  std::string name(const YAML::Node& v, const std::string& key) const {
    const std::string s = text(v, key);
    static const std::regex pattern("[A-Za-z0-9_.-]+");
    if (!std::regex_match(s, pattern) || s == "." || s == "..")
      fail(v, key, fmt::format("'{}' is not a name (letters, digits, '_', '-', '.')", s));
    return s;
  }

  bool boolean(const YAML::Node& v, const std::string& key) const {
    const std::string s = text(v, key);
    if (s == "true") return true;
    if (s == "false") return false;
    fail(v, key, fmt::format("'{}' is not true or false", s));
  }

  std::string number(const YAML::Node& v, const std::string& key, bool positive) const {
    const std::string s = text(v, key);
    std::size_t used = 0;
    double x = 0;
    try {
      x = std::stod(s, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != s.size() || s.empty()) fail(v, key, fmt::format("'{}' is not a number", s));
    if (positive && !(x > 0)) fail(v, key, fmt::format("'{}' must be > 0", s));
    return s;
  }

  int count(const YAML::Node& v, const std::string& key) const {
    const std::string s = text(v, key);
    if (s.empty() || s.size() > 6 || !std::ranges::all_of(s, [](char c) { return c >= '0' && c <= '9'; }) ||
        std::stoi(s) < 1)
      fail(v, key, fmt::format("'{}' is not a whole number >= 1", s));
    return std::stoi(s);
  }

  Engine engine(const YAML::Node& v, const std::string& key) const {
    const std::string s = text(v, key);
    for (Engine e : {Engine::Liggghts, Engine::Ode, Engine::Yade})
      if (s == to_string(e)) return e;
    fail(v, key, fmt::format("'{}' is not an engine (liggghts, ode, yade)", s));
  }

  std::string model(const YAML::Node& v, const std::string& key) const {
    const std::string s = text(v, key);
    for (FluidModel m : {FluidModel::Drag, FluidModel::AddedMass, FluidModel::Both})
      if (s == to_string(m)) return s;
    fail(v, key, fmt::format("'{}' is not a fluid model (drag, added_mass, both)", s));
  }

  std::vector<std::string> texts(const YAML::Node& v, const std::string& key) const {
    if (!v.IsSequence() || v.size() == 0) fail(v, key, "expected a non-empty list");
    std::vector<std::string> out;
    for (const auto& item : v) out.push_back(text(item, key));
    return out;
  }
};

// A case key's value as the derived case.yaml gets it: a scalar's text, a list of scalars in flow style.
std::string override_value(const Reader& r, const YAML::Node& v, const std::string& key) {
  if (v.IsScalar()) return v.Scalar();
  if (!v.IsSequence() || v.size() == 0) r.fail(v, key, "expected a value or a list of values");
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + r.text(v[i], key);
  return s + "]";
}

CaseDef read_case(const Reader& r, const std::string& name, const YAML::Node& n, const std::string& where) {
  r.check_map(n, where, {"base", "set"});
  CaseDef c{name, r.text(r.required(n, where, "base"), where + ".base"), {}};
  if (c.base.empty() || c.base.is_absolute())
    r.fail(n["base"], where + ".base", "expected a case.yaml path relative to the repository");
  if (const YAML::Node set = n["set"]; set.IsDefined()) {
    r.check_unique_keys(set, where + ".set");
    static const std::regex case_key("[a-z_]+\\.[a-z0-9_]+");
    for (const auto& kv : set) {
      const std::string key = kv.first.Scalar();
      if (!std::regex_match(key, case_key))
        r.fail(kv.first, where + ".set." + key, "a case key is written section.key (fluid.model)");
      c.overrides.push_back({key, override_value(r, kv.second, where + ".set." + key)});
    }
  }
  return c;
}

std::vector<CaseDef> read_cases(const Reader& r, const YAML::Node& n, const std::string& where) {
  std::vector<CaseDef> cases;
  if (!n.IsDefined()) return cases;
  r.check_unique_keys(n, where);
  for (const auto& kv : n) {
    const std::string name = r.name(kv.first, where);
    cases.push_back(read_case(r, name, kv.second, where + "." + name));
  }
  return cases;
}


// Each item of a list section, with its place in the file ("variants[3]") for messages.
template <typename Read>
void for_each_item(const Reader& r, const YAML::Node& list, const std::string& where, Read read) {
  if (!list.IsDefined()) return;
  if (!list.IsSequence()) r.fail(list, where, "expected a list");
  for (std::size_t i = 0; i < list.size(); ++i) read(list[i], fmt::format("{}[{}]", where, i));
}

Variant read_variant(const Reader& r, const YAML::Node& n, const std::string& where) {
  r.check_map(n, where, {"id", "case", "engine", "model"});
  return {r.name(r.required(n, where, "id"), where + ".id"), r.name(r.required(n, where, "case"), where + ".case"),
          r.engine(r.required(n, where, "engine"), where + ".engine"),
          r.model(r.required(n, where, "model"), where + ".model")};
}

SpeedSweep read_sweep(const Reader& r, const YAML::Node& n, const std::string& where) {
  r.check_map(n, where, {"speeds", "models", "base_case"});
  SpeedSweep s{r.texts(r.required(n, where, "speeds"), where + ".speeds"), {},
               r.name(r.required(n, where, "base_case"), where + ".base_case")};
  for (const auto& u : n["speeds"]) r.number(u, where + ".speeds", true);
  for (const auto& m : n["models"]) s.models.push_back(r.model(m, where + ".models"));
  if (s.models.empty()) r.fail(r.required(n, where, "models"), where + ".models", "expected a non-empty list");
  return s;
}

Ensemble read_ensemble(const Reader& r, const YAML::Node& n, const std::string& where) {
  r.check_map(n, where, {"id", "seeds", "side_a", "side_b", "case", "dir"});
  Ensemble e{r.name(r.required(n, where, "id"), where + ".id"), r.count(r.required(n, where, "seeds"), where + ".seeds"),
             r.text(r.required(n, where, "side_a"), where + ".side_a"),
             r.text(r.required(n, where, "side_b"), where + ".side_b"), "",
             r.name(r.required(n, where, "dir"), where + ".dir")};
  if (n["case"].IsDefined()) e.shared_case = r.name(n["case"], where + ".case");
  return e;
}

PaperRun read_paper_run(const Reader& r, const YAML::Node& n, const std::string& where) {
  r.check_map(n, where, {"id", "case", "engine", "model", "out", "restart_every_s", "dt_s"});
  PaperRun p;
  p.id = r.name(r.required(n, where, "id"), where + ".id");
  p.case_name = r.name(r.required(n, where, "case"), where + ".case");
  p.out = r.name(r.required(n, where, "out"), where + ".out");
  p.engine = r.engine(r.required(n, where, "engine"), where + ".engine");
  p.model = r.model(r.required(n, where, "model"), where + ".model");
  if (p.engine == Engine::Yade) r.fail(n["engine"], where + ".engine", "paper runs are liggghts or ode");
  if (n["restart_every_s"].IsDefined()) p.restart_every_s = r.number(n["restart_every_s"], where + ".restart_every_s", true);
  if (n["dt_s"].IsDefined()) {
    if (p.engine != Engine::Ode) r.fail(n["dt_s"], where + ".dt_s", "only an ode paper run takes a time step");
    p.dt_s = r.number(n["dt_s"], where + ".dt_s", true);
  }
  return p;
}

// A manifest item: `speed_sweep` (the sweep's rows), or a row of one run.
RowSpec read_row(const Reader& r, const YAML::Node& n, const std::string& where) {
  if (n.IsScalar()) {
    if (n.Scalar() != "speed_sweep") r.fail(n, where, fmt::format("'{}': a row is speed_sweep or a mapping", n.Scalar()));
    RowSpec sweep;
    sweep.sweep = true;
    return sweep;
  }
  r.check_map(n, where, {"run", "group", "label", "param", "value", "baseline", "base_case", "when_listed"});
  RowSpec row;
  row.run = r.name(r.required(n, where, "run"), where + ".run");
  row.group = r.name(r.required(n, where, "group"), where + ".group");
  row.label = r.text(r.required(n, where, "label"), where + ".label");
  row.base_case = r.name(r.required(n, where, "base_case"), where + ".base_case");
  if (n["param"].IsDefined()) row.param = r.text(n["param"], where + ".param");
  if (n["value"].IsDefined()) row.value = r.text(n["value"], where + ".value");
  if (n["baseline"].IsDefined()) row.baseline = r.boolean(n["baseline"], where + ".baseline");
  if (n["when_listed"].IsDefined()) row.when_listed = r.name(n["when_listed"], where + ".when_listed");
  for (const std::string* cell : {&row.label, &row.param, &row.value})
    if (cell->find_first_of("\t\n") != std::string::npos) r.fail(n, where, "a tab or line break in a manifest cell");
  return row;
}

// Study-wide checks: run ids unique, every reference defined; errors point at the item's line.
void check_references(const Reader& r, const Study& s, const YAML::Node& root) {
  std::set<std::string> ids;
  const auto add_id = [&](const std::string& id, const YAML::Node& at, const std::string& where) {
    if (!ids.insert(id).second) r.fail(at, where, fmt::format("run id '{}' given twice", id));
  };
  for (std::size_t i = 0; i < s.variants.size(); ++i) {
    const std::string where = fmt::format("variants[{}]", i);
    add_id(s.variants[i].id, root["variants"][i], where + ".id");
    if (!s.find_case(s.variants[i].case_name))
      r.fail(root["variants"][i], where + ".case", fmt::format("'{}' is not in cases", s.variants[i].case_name));
  }
  if (s.speed_sweep)
    for (const auto& u : s.speed_sweep->speeds)
      for (const auto& m : s.speed_sweep->models)
        add_id(fmt::format("quick_u{}_{}", u, m), root["speed_sweep"], "speed_sweep.speeds");
  for (std::size_t i = 0; i < s.ensembles.size(); ++i) {
    const std::string where = fmt::format("ensembles[{}]", i);
    add_id(s.ensembles[i].id, root["ensembles"][i], where + ".id");
    if (!s.ensembles[i].shared_case.empty() && !s.find_shared_case(s.ensembles[i].shared_case))
      r.fail(root["ensembles"][i], where + ".case", fmt::format("'{}' is not in shared_cases", s.ensembles[i].shared_case));
  }
  for (std::size_t i = 0; i < s.paper_runs.size(); ++i) {
    const std::string where = fmt::format("paper_runs[{}]", i);
    add_id(s.paper_runs[i].id, root["paper_runs"][i], where + ".id");
    if (!s.find_shared_case(s.paper_runs[i].case_name))
      r.fail(root["paper_runs"][i], where + ".case", fmt::format("'{}' is not in shared_cases", s.paper_runs[i].case_name));
  }
  for (std::size_t i = 0; i < s.manifest.size(); ++i) {
    const RowSpec& row = s.manifest[i];
    const std::string where = fmt::format("manifest[{}]", i);
    if (row.sweep && !s.speed_sweep) r.fail(root["manifest"][i], where, "speed_sweep rows without a speed_sweep section");
    for (const std::string* ref : {&row.run, &row.when_listed})
      if (!ref->empty() && !ids.contains(*ref))
        r.fail(root["manifest"][i], where, fmt::format("run '{}' is not defined", *ref));
  }
}

std::vector<Engine> read_engines(const Reader& r, const YAML::Node& n) {
  std::vector<Engine> engines;
  if (!n.IsSequence()) r.fail(n, "engines", "expected a list of engines");
  for (const auto& e : n) engines.push_back(r.engine(e, "engines"));
  return engines;
}

}  // namespace

Study parse_study(const std::string& yaml_text, const std::string& source) {
  const Reader r{source};
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::ParserException& e) {
    throw InputError(fmt::format("{}:{}: YAML syntax error: {}", source, e.mark.line + 1, e.msg));
  }
  if (!root.IsDefined() || root.IsNull()) throw InputError(source + ": empty study file");
  r.check_map(root, "study", {"study", "engines", "run_paper", "run_ensembles", "cases", "shared_cases", "variants",
                              "speed_sweep", "ensembles", "paper_runs", "manifest"});
  Study s;
  s.file = source;
  s.name = r.name(r.required(root, "", "study"), "study");
  s.engines = read_engines(r, r.required(root, "", "engines"));
  if (root["run_paper"].IsDefined()) s.run_paper = r.boolean(root["run_paper"], "run_paper");
  if (root["run_ensembles"].IsDefined()) s.run_ensembles = r.boolean(root["run_ensembles"], "run_ensembles");
  s.cases = read_cases(r, root["cases"], "cases");
  s.shared_cases = read_cases(r, root["shared_cases"], "shared_cases");
  for_each_item(r, root["variants"], "variants", [&](auto& n, auto w) { s.variants.push_back(read_variant(r, n, w)); });
  if (root["speed_sweep"].IsDefined()) s.speed_sweep = read_sweep(r, root["speed_sweep"], "speed_sweep");
  for_each_item(r, root["ensembles"], "ensembles", [&](auto& n, auto w) { s.ensembles.push_back(read_ensemble(r, n, w)); });
  for_each_item(r, root["paper_runs"], "paper_runs", [&](auto& n, auto w) { s.paper_runs.push_back(read_paper_run(r, n, w)); });
  for_each_item(r, r.required(root, "", "manifest"), "manifest", [&](auto& n, auto w) { s.manifest.push_back(read_row(r, n, w)); });
  check_references(r, s, root);
  return s;
}

Study load_study(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(fmt::format("{}: cannot open the study file", file.string()));
  std::stringstream text;
  text << in.rdbuf();
  return parse_study(text.str(), file.string());
}

}  // namespace brash::study
