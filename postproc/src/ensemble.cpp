// Paired-seed ensemble summary (ensemble.hpp): reads the runs, the statistics come from brash/stats/paired.hpp.
#include <brash/post/ensemble.hpp>

#include <cmath>
#include <fstream>

#include <fmt/format.h>

#include <cstdint>

#include <brash/core/fnv1a.hpp>
#include <brash/stats/paired.hpp>

namespace brash::post {
namespace {

namespace fs = std::filesystem;

std::optional<nlohmann::json> read_json(const fs::path& p) {
  std::ifstream in(p);
  if (!in) return std::nullopt;
  const auto j = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) return std::nullopt;
  return j;
}

// The window-mean resistance of a complete run; none for a missing, unreadable or unfinished report.
std::optional<double> mean_N(const fs::path& run) {
  const auto r = read_json(run / "report.json");
  if (!r || !r->is_object() || r->value("status", std::string()) != "complete") return std::nullopt;
  const auto p = nlohmann::json::json_pointer("/resistance_model_N/mean");
  if (!r->contains(p) || !r->at(p).is_number()) return std::nullopt;
  return r->at(p).get<double>();
}

double wall_s(const fs::path& run) {
  const auto m = read_json(run / "meta.json");
  if (!m || !m->is_object() || !m->contains("wall_time_s") || !(*m)["wall_time_s"].is_number()) return NAN;
  return (*m)["wall_time_s"].get<double>();
}

// A mean of an incomplete pair's complete side, shortest round trip with a decimal point ("17.0", "17.25").
std::string bare(const std::optional<double>& v) {
  if (!v) return "-";
  std::string s = fmt::format("{}", *v);
  if (s.find_first_of(".eni") == std::string::npos) s += ".0";
  return s;
}

double sum_of(const std::vector<double>& x) {
  double s = 0;
  for (const double v : x) s += v;
  return s;
}

constexpr const char* kDefinition =
    "(B - A) / A of the ensemble means; 95 % CI by the delta method, Student t with pairs - 1 degrees of freedom";

fs::path run_dir(const EnsembleSpec& spec, std::size_t seed, const EnsembleSide& side) {
  return spec.dir / fmt::format("s{}-{}", seed, side.run_name);
}

}  // namespace

std::vector<EnsemblePair> read_ensemble(const EnsembleSpec& spec) {
  std::vector<EnsemblePair> pairs;
  for (std::size_t s = 1; s <= spec.seeds; ++s) {
    EnsemblePair p;
    p.seed = s;
    p.a_N = mean_N(run_dir(spec, s, spec.a));
    p.b_N = mean_N(run_dir(spec, s, spec.b));
    if (p.complete()) {
      p.wall_a_s = wall_s(run_dir(spec, s, spec.a));
      p.wall_b_s = wall_s(run_dir(spec, s, spec.b));
    }
    pairs.push_back(p);
  }
  return pairs;
}

EnsembleEffect read_ensemble_summary(const nlohmann::json& j) {
  EnsembleEffect e;
  e.pairs = j.at("pairs").get<int>();
  e.mean_a_N = j.at("mean_a_N").get<double>();
  e.mean_b_N = j.at("mean_b_N").get<double>();
  if (j.contains("a_N")) {  // the per-pair values: the statistics from them, by the one definition
    const auto a = j.at("a_N").get<std::vector<double>>(), b = j.at("b_N").get<std::vector<double>>();
    const auto p = stats::paired_effect(a, b);
    e.effect_rel = p.effect.mean;
    e.ci95_rel = p.effect.ci95;
    return e;
  }
  e.effect_rel = stats::relative_effect(e.mean_a_N, e.mean_b_N);
  e.pair_mean_diff_rel = j.at("diff_rel").get<double>();
  e.pair_mean_ci95_rel = j.at("ci95_rel").get<double>();
  return e;
}

std::string ensemble_file_name(const std::string& run_name_a, const std::string& run_name_b) {
  const std::string stem = fmt::format("ensemble-{}-vs-{}", run_name_a, run_name_b);
  constexpr std::size_t kMaxName = 200, kHashed = kMaxName - 22;  // "-" + 16 hex + ".json"
  if (stem.size() + 5 <= kMaxName) return stem + ".json";
  return fmt::format("{}-{:016x}.json", stem.substr(0, kHashed), core::fnv1a(stem));
}

EnsembleSummary summarize_ensemble(const EnsembleSpec& spec, const std::vector<EnsemblePair>& pairs) {
  EnsembleSummary out;
  out.json_path = spec.dir / ensemble_file_name(spec.a.run_name, spec.b.run_name);
  const std::string la = spec.a.label.empty() ? spec.a.run_name : spec.a.label;
  const std::string lb = spec.b.label.empty() ? spec.b.run_name : spec.b.label;
  auto& t = out.text;
  t += fmt::format("== {}, one packing seed per pair, mean resistance over its window, model scale\n", spec.case_name);
  t += fmt::format("| seed | A: {} [N] | B: {} [N] | (B - A) / A |\n|---|---|---|---|\n", la, lb);
  std::vector<double> a, b, wall_a, wall_b;
  for (const auto& p : pairs) {
    if (!p.complete()) {
      t += fmt::format("| {} | {} | {} | (incomplete) |\n", p.seed, bare(p.a_N), bare(p.b_N));
      continue;
    }
    a.push_back(*p.a_N);
    b.push_back(*p.b_N);
    wall_a.push_back(p.wall_a_s);
    wall_b.push_back(p.wall_b_s);
    t += fmt::format("| {} | {:.3f} | {:.3f} | {:+.2f} % |\n", p.seed, *p.a_N, *p.b_N,
                     100 * stats::relative_effect(*p.a_N, *p.b_N));
  }
  if (a.size() < 2) {
    t += "fewer than 2 complete pairs: no ensemble statement\n";
    return out;
  }
  const auto e = stats::paired_effect(a, b);
  const auto& d = e.effect;
  const double wa = sum_of(wall_a), wb = sum_of(wall_b);
  t += fmt::format("pairs: {}; ensemble mean A ({}) {:.3f} N, B ({}) {:.3f} N\n", d.n, la, e.mean_a, lb, e.mean_b);
  t += fmt::format("effect (B - A) / A of the means: {:+.2f} % +- {:.2f} % (95 % CI, delta method), sd of one "
                   "pair {:.2f} %\n",
                   100 * d.mean, 100 * d.ci95, 100 * d.sd);
  t += fmt::format("wall time: A {:.0f} s, B {:.0f} s in all; speed-up of B over A {:.2f}x\n", wa, wb, wa / wb);
  const auto finite_or_null = [](double v) { return std::isfinite(v) ? nlohmann::ordered_json(v) : nullptr; };
  out.json = nlohmann::ordered_json{{"case", spec.case_name}, {"side_a", spec.a.spec},     {"side_b", spec.b.spec},
                                    {"pairs", d.n},          {"mean_a_N", e.mean_a},       {"mean_b_N", e.mean_b},
                                    {"effect_rel", d.mean},  {"effect_ci95_rel", d.ci95},  {"effect_sd_rel", d.sd},
                                    {"definition", kDefinition}, {"a_N", a},               {"b_N", b},
                                    {"wall_a_s", finite_or_null(wa)}, {"wall_b_s", finite_or_null(wb)},
                                    {"speedup", finite_or_null(wa / wb)}};
  const std::string tol = fmt::format("{:g}", 100 * spec.tol);
  if (stats::within(d, spec.tol)) {
    t += fmt::format("WITHIN {} %: the 95 % CI [{:+.2f}, {:+.2f}] % lies inside [-{}, +{}] %\n", tol, 100 * d.lo(),
                     100 * d.hi(), tol, tol);
  } else {
    const auto need = stats::pairs_to_resolve(d, spec.tol);
    t += fmt::format("NOT SHOWN: the 95 % CI [{:+.2f}, {:+.2f}] % is not inside [-{}, +{}] %{}\n", 100 * d.lo(),
                     100 * d.hi(), tol, tol,
                     need ? fmt::format("; about {} pairs would resolve it at this scatter", *need) : "");
  }
  return out;
}

}  // namespace brash::post
