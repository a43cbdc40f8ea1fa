// meta.json reader.
#include <brash/post/run_meta.hpp>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <brash/error.hpp>
#include <brash/post/csv.hpp>

namespace brash::post {
namespace {

template <class T> struct Unwrap { using type = T; };
template <class T> struct Unwrap<std::optional<T>> { using type = T; };

template <class T>
void take(const nlohmann::json& j, const char* key, T& out, const std::filesystem::path& path) {
  if (!j.contains(key) || j[key].is_null()) return;
  try {
    out = j[key].get<typename Unwrap<T>::type>();
  } catch (const nlohmann::json::exception& e) {
    throw InputError(fmt::format("{}: key '{}': {}", path.string(), key, e.what()));
  }
}

}  // namespace

RunMeta read_run_meta(const std::filesystem::path& path) {
  const auto text = read_text_file(path);
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // e.what() carries "line L, column C" of the offending byte.
    throw InputError(fmt::format("{}: invalid JSON: {}", path.string(), e.what()));
  }
  if (!j.is_object()) throw InputError(fmt::format("{}:1: expected a JSON object", path.string()));
  RunMeta m;
  take(j, "engine", m.engine, path);
  take(j, "engine_version", m.engine_version, path);
  take(j, "fluid_model", m.fluid_model, path);
  take(j, "treatment", m.treatment, path);
  take(j, "git_commit", m.git_commit, path);
  take(j, "status", m.status, path);
  take(j, "reason", m.reason, path);
  take(j, "dt_s", m.dt_s, path);
  take(j, "wall_time_s", m.wall_time_s, path);
  take(j, "particle_steps", m.particle_steps, path);
  take(j, "ranks", m.ranks, path);
  take(j, "particles", m.particles, path);
  take(j, "exits", m.exits, path);
  if (j.contains("skips") && j["skips"].is_object()) {
    // brash-ode --cull with the window alone (a wake force of 0, or a run from before the wake rule)
    bool cull = false;
    double wake_force_N = 0;
    take(j["skips"], "cull", cull, path);
    take(j["skips"], "cull_wake_force_N", wake_force_N, path);
    m.culled_far_field = cull && !(wake_force_N > 0);
  }
  if (j.contains("early_stop") && j["early_stop"].is_object()) {
    EarlyStopMeta e;
    take(j["early_stop"], "t_s", e.t_s, path);
    take(j["early_stop"], "requested_duration_s", e.requested_duration_s, path);
    take(j["early_stop"], "rel_ci_threshold", e.rel_ci_threshold, path);
    take(j["early_stop"], "reason", e.reason, path);
    take(j["early_stop"], "estimate_N", e.estimate_N, path);
    take(j["early_stop"], "estimate_ci95_N", e.estimate_ci95_N, path);
    if (const auto w = j["early_stop"].value("requested_window_s", nlohmann::json());
        w.is_array() && w.size() == 2 && w[1].is_number())
      e.requested_window_end_s = w[1].get<double>();
    m.early_stop = e;
  }
  if (const auto& h = j.value("hull_split", nlohmann::json()); h.is_object()) {
    std::array<double, 2> par{};
    take(h, "x_par_aft_m", par[0], path);
    take(h, "x_par_fwd_m", par[1], path);
    m.hull_split_par_m = par;
  } else if (h.is_string()) {
    m.hull_split_not_recorded = h.get<std::string>();
  }
  if (j.contains("early_stop_last_check") && j["early_stop_last_check"].is_object()) {
    EarlyStopCheckMeta e;
    take(j["early_stop_last_check"], "t_s", e.t_s, path);
    take(j["early_stop_last_check"], "reason", e.reason, path);
    m.early_stop_last_check = e;
  }
  return m;
}

}  // namespace brash::post
