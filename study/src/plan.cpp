// Planning a study: case folders, engine commands, the bench scripts' commands, with their manifest text.
#include "brash/study/plan.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace fs = std::filesystem;

namespace brash::study {

std::string without_repo(std::string text, const Settings& s) {
  const std::string prefix = (s.repo / "").string();
  for (std::size_t at = text.find(prefix); at != std::string::npos; at = text.find(prefix, at))
    text.erase(at, prefix.size());
  return text;
}

namespace {

std::string quoted_if_needed(const std::string& word) {
  if (!word.empty() && word.find_first_of(" \t\"'[]{}*?$;&|<>()") == std::string::npos) return word;
  return "\"" + word + "\"";
}

std::string exe(const Settings& s, const char* name) { return (s.bin / name).string(); }

}  // namespace

std::string shell_text(const Command& c, const Settings& s) {
  std::string line;
  const auto add = [&line](const std::string& word) { line += (line.empty() ? "" : " ") + word; };
  for (const auto& [key, value] : c.env) add(key + "=" + quoted_if_needed(value));
  if (c.niced) add(fmt::format("nice -n {}", s.nice));
  for (const auto& word : c.argv) add(quoted_if_needed(word));
  return without_repo(line, s);
}

std::string shell_text(const std::vector<Command>& cs, const Settings& s) {
  std::string line;
  for (const auto& c : cs) line += (line.empty() ? "" : " && ") + shell_text(c, s);
  return line;
}

namespace {

CaseStep case_step(const CaseDef& def, const fs::path& cases_dir, const Settings& s) {
  CaseStep step{def.name, (s.repo / def.base).lexically_normal(), cases_dir / def.name, {{"name", def.name}}, ""};
  for (const auto& o : def.overrides) step.overrides.emplace_back(o.key, o.value);
  Command derive{{"brash-case", "derive", step.base.string()}, {}, false, {}};
  for (const auto& [key, value] : step.overrides) {
    derive.argv.push_back("--set");
    derive.argv.push_back(key + "=" + value);
  }
  for (const char* w : {"--out", step.dir.c_str(), "--force"}) derive.argv.emplace_back(w);
  step.text = shell_text(derive, s);
  return step;
}

// The engine's commands for a variant (study runs: no restart files).
std::vector<Command> engine_steps(Engine e, const fs::path& case_dir, const fs::path& out, const std::string& model,
                                  const Settings& s) {
  const std::string np = std::to_string(s.ranks);
  switch (e) {
    case Engine::Liggghts:
      return {{{exe(s, "brash-liggghts-run"), case_dir, "--np", np, "--out", out, "--model", model}, {}, true, {}}};
    case Engine::Ode:
      return {{{exe(s, "brash-ode"), case_dir, "--out", out, "--model", model, "--no-progress"}, {}, true, {}}};
    case Engine::Yade:
      return {{{exe(s, "brash-yade-run"), case_dir, "--out", out, "--model", model, "-j", np}, {}, true, {}}};
  }
  return {};
}

bool engine_runs(Engine e, const Settings& s) { return std::ranges::find(s.engines, e) != s.engines.end(); }

PlannedPaperRun plan_paper_run(const Study& study, const PaperRun& p, const Settings& s) {
  PlannedPaperRun r{&p, case_step(*study.find_shared_case(p.case_name), s.paper_dir / "cases", s), s.paper_dir / p.out,
                    {}, {}, ""};
  const std::string np = std::to_string(s.ranks), every = p.restart_every_s, out = r.out.string();
  if (p.engine == Engine::Liggghts) {
    r.start = {{{exe(s, "brash-liggghts-run"), r.case_step.dir, "--np", np, "--out", out, "--model", p.model,
                 "--restart-every", every}, {}, true, {}}};
    r.resume = {{{exe(s, "brash-liggghts-run"), "--resume", out, "--np", np, "--restart-every", every}, {}, true, {}}};
  } else {
    Command start{{exe(s, "brash-ode"), r.case_step.dir, "--out", out, "--model", p.model, "--restart-every", every},
                  {}, true, {}};
    if (!p.dt_s.empty()) start.argv.insert(start.argv.end(), {"--dt", p.dt_s});
    start.argv.emplace_back("--no-progress");
    r.start = {start};
    r.resume = {{{exe(s, "brash-ode"), "--resume", out, "--no-progress"}, {}, true, {}}};
  }
  r.command_text = fmt::format("{} && {} (resumed with: {} when interrupted)", r.case_step.text,
                               shell_text(r.start, s), shell_text(r.resume, s));
  return r;
}

PlannedEnsemble plan_ensemble(const Study& study, const Ensemble& e, const Settings& s) {
  PlannedEnsemble r{&e, s.paper_dir / e.dir, std::nullopt, {}, ""};
  r.command = Command{{"bash", (s.repo / "bench/rank_ensemble.sh").string(), std::to_string(e.seeds), r.dir.string()},
                      {{"BRASH_BIN", s.bin.string()}}, true, s.repo};
  if (!e.shared_case.empty()) {
    r.case_step = case_step(*study.find_shared_case(e.shared_case), s.paper_dir / "cases", s);
    r.command.env.emplace_back("CASE", r.case_step->dir.string());
  }
  r.command.env.insert(r.command.env.end(), {{"SIDE_A", e.side_a}, {"SIDE_B", e.side_b}, {"TOL_PCT", "2"}, {"JOBS", "1"}});
  r.command_text = shell_text(r.command, s);
  return r;
}

}  // namespace

Plan plan_study(const Study& study, const Settings& s) {
  Plan plan;
  for (const Variant& v : study.variants) {
    if (!engine_runs(v.engine, s)) {
      plan.left_out.push_back(fmt::format("{} ({} is not among this study's engines)", v.id, to_string(v.engine)));
      continue;
    }
    PlannedRun r{v.id, v.engine, v.model, case_step(*study.find_case(v.case_name), s.work / "cases", s),
                 s.work / "runs" / v.id, {}, ""};
    r.steps = engine_steps(v.engine, r.case_step.dir, r.out, v.model, s);
    r.command_text = r.case_step.text + " && " + shell_text(r.steps, s);
    plan.runs.push_back(std::move(r));
  }
  if (study.speed_sweep) {
    std::string speeds, models;
    for (const auto& u : study.speed_sweep->speeds) speeds += (speeds.empty() ? "" : " ") + u;
    for (const auto& m : study.speed_sweep->models) models += (models.empty() ? "" : " ") + m;
    plan.sweep.push_back({{"bash", (s.repo / "bench/quick_speed_sweep.sh").string(), (s.work / "runs").string()},
                          {{"SPEEDS", speeds}, {"MODELS", models}, {"BRASH_BIN", s.bin.string()}}, false, s.repo});
  }
  for (const Ensemble& e : study.ensembles) plan.ensembles.push_back(plan_ensemble(study, e, s));
  for (const PaperRun& p : study.paper_runs) plan.paper_runs.push_back(plan_paper_run(study, p, s));
  return plan;
}

}  // namespace brash::study
