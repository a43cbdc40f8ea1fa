// Adapter over case.yaml for the postprocessor (to be replaced by brash::load_case, see header).
#include <brash/post/post_case.hpp>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <brash/error.hpp>

namespace brash::post {
namespace {

struct Reader {
  std::filesystem::path file;

  [[noreturn]] void fail(const YAML::Node& n, std::string_view key, std::string_view what) const {
    const auto line = n.IsDefined() ? n.Mark().line + 1 : 0;
    throw InputError(line > 0 ? fmt::format("{}:{}: key '{}': {}", file.string(), line, key, what)
                              : fmt::format("{}: key '{}': {}", file.string(), key, what));
  }
  template <class T>
  T get(const YAML::Node& parent, std::string_view section, std::string_view key, const T* fallback) const {
    const std::string full = section.empty() ? std::string(key) : fmt::format("{}.{}", section, key);
    const YAML::Node sec = section.empty() ? parent : parent[std::string(section)];
    const YAML::Node n = sec.IsMap() ? sec[std::string(key)] : YAML::Node();
    if (!n.IsDefined() || n.IsNull()) {
      if (fallback) return *fallback;
      throw InputError(fmt::format("{}: missing key '{}'", file.string(), full));
    }
    try {
      return n.as<T>();
    } catch (const YAML::Exception&) {
      fail(n, full, "wrong type");
    }
  }
};

}  // namespace

PostCase read_post_case(const std::filesystem::path& case_yaml) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(case_yaml.string());
  } catch (const YAML::BadFile&) {
    throw InputError(fmt::format("{}: cannot open file", case_yaml.string()));
  } catch (const YAML::Exception& e) {
    throw InputError(fmt::format("{}:{}: {}", case_yaml.string(), e.mark.line + 1, e.msg));
  }
  const Reader r{case_yaml};
  PostCase c;
  c.file = case_yaml;
  const std::string empty;
  const double zero = 0;
  c.name = r.get<std::string>(root, "", "name", &empty);
  const auto hull = r.get<std::string>(root, "hull", "file", &empty);
  if (!hull.empty()) c.hull_file = case_yaml.parent_path() / hull;
  c.draft_m = r.get<double>(root, "hull", "draft_m", nullptr);
  c.lpp_m = r.get<double>(root, "hull", "lpp_m", nullptr);
  c.beam_m = r.get<double>(root, "hull", "beam_m", &zero);
  c.start_x_m = r.get<double>(root, "hull", "start_x_m", &zero);
  c.speed_m_s = r.get<double>(root, "ship", "speed_m_s", &zero);
  c.scale_lambda = r.get<double>(root, "ship", "scale_lambda", nullptr);
  const std::string ia = "IA";
  c.ice_class = r.get<std::string>(root, "ship", "ice_class", &ia);
  c.fluid_model = r.get<std::string>(root, "fluid", "model", &empty);
  c.duration_s = r.get<double>(root, "run", "duration_s", &zero);
  const std::vector<double> def{15.0, 40.0};
  const auto w = r.get<std::vector<double>>(root, "run", "window_s", &def);
  if (w.size() != 2 || !(w[1] > w[0])) r.fail(root["run"]["window_s"], "run.window_s", "expected [t0, t1] with t1 > t0");
  c.window_s = {w[0], w[1]};
  if (!(c.scale_lambda > 0)) r.fail(root["ship"]["scale_lambda"], "ship.scale_lambda", "must be > 0");

  if (const auto f = root["fsicr"]; f.IsDefined() && !f.IsNull()) {
    if (!f.IsMap()) r.fail(f, "fsicr", "expected a map");
    static const std::vector<std::string> kKeys{"L_m", "B_m", "T_m", "alpha_deg", "phi1_deg",
                                                "phi2_deg", "L_par_m", "L_bow_m", "A_wf_m2"};
    for (const auto& kv : f) {
      const auto key = kv.first.as<std::string>();
      if (std::find(kKeys.begin(), kKeys.end(), key) == kKeys.end())
        r.fail(kv.first, "fsicr." + key, "unknown key (expected one of L_m B_m T_m alpha_deg phi1_deg phi2_deg L_par_m L_bow_m A_wf_m2)");
      c.fsicr_overrides[key] = r.get<double>(f, "", key, nullptr);
    }
  }
  return c;
}

}  // namespace brash::post
