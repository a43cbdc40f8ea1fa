// brash-case new NAME [--speed ... --scale ... --width ... ...]: makes a new case folder
// <cases-dir>/NAME/case.yaml from a template case (default: the paper case) with the given values
// replaced, then validates it with the loader (the folder is removed again if it is invalid).
// brash-case derive BASE --set key=value ... --out DIR: DIR/case.yaml, a variant of BASE through the case library
// (brash::write_derived_case: keys set, paths and packing as brash/case_derive.hpp says, checked by the loader).
// brash-case get CASE KEY: prints a key's value in the resolved case (every default filled in).
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <regex>

#include "brash/case.hpp"
#include "brash/case_derive.hpp"
#include "brash/error.hpp"
#include "brash/paths.hpp"

namespace fs = std::filesystem;

namespace {

// Numbers go in with 12 significant digits so derived values stay readable (0.00125, not
// 0.0012500000000000002).
std::string text(double v) {
  std::string s = fmt::format("{:.12g}", v);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

double number_at(const YAML::Node& n, const char* sec, const char* key, double fallback) {
  const YAML::Node v = n[sec][key];
  return v.IsDefined() && v.IsScalar() ? v.as<double>() : fallback;
}

YAML::Node flow_pair(double a, double b) {
  YAML::Node p(YAML::NodeType::Sequence);
  p.push_back(text(a));
  p.push_back(text(b));
  p.SetStyle(YAML::EmitterStyle::Flow);
  return p;
}

struct NewCaseOptions {
  std::string name, cases_dir = "cases", templ, description, fluid_model, treatment, ice_class, packing_mode;
  std::optional<double> speed, scale, length, width, thickness, diameter, diameter_sd, porosity, friction_ice,
      friction_hull, friction_wall, duration;
  std::vector<double> window, band;
  std::optional<std::uint64_t> seed;
  bool force = false;
};

int make_case(const NewCaseOptions& o) {
  if (!std::regex_match(o.name, std::regex("[A-Za-z0-9_.-]+")) || o.name == "." || o.name == "..")
    throw brash::InputError(fmt::format("case name '{}': use letters, digits, '_', '-', '.'", o.name));
  const fs::path templ = o.templ.empty() ? brash::paths::data_file("cases/jbc_ia_5kn/case.yaml", "the default template")
                                     : fs::path(o.templ);
  (void)brash::load_case(templ);  // the template itself must be valid
  YAML::Node n = YAML::LoadFile(templ.string());

  n["name"] = o.name;
  n["description"] = o.description.empty() ? fmt::format("made by brash-case from {}", templ.filename().string())
                                           : o.description;
  // New scale: hull dimensions and (unless given) speed follow Froude similarity from the template.
  if (o.scale) {
    const double old_lambda = number_at(n, "ship", "scale_lambda", 28.5);
    const double k = old_lambda / *o.scale;
    for (const char* key : {"draft_m", "lpp_m", "beam_m", "start_x_m"})
      if (n["hull"][key].IsDefined()) n["hull"][key] = text(n["hull"][key].as<double>() * k);
    n["ship"]["scale_lambda"] = text(*o.scale);
    if (!o.speed) n["ship"]["speed_m_s"] = text(number_at(n, "ship", "speed_m_s", 0.482) * std::sqrt(k));
    std::cerr << fmt::format("brash-case: note: hull dimensions scaled by {:.4g}; hull.file still names {} "
                             "-- generate the hull at 1:{} with the hull tool and point hull.file at it\n",
                             k, n["hull"]["file"].as<std::string>(), *o.scale);
  }
  if (o.speed) n["ship"]["speed_m_s"] = text(*o.speed);
  if (!o.band.empty()) n["hull"]["band_m"] = flow_pair(o.band.at(0), o.band.at(1));
  if (!o.ice_class.empty()) n["ship"]["ice_class"] = o.ice_class;
  if (o.length) n["channel"]["length_m"] = text(*o.length);
  if (o.width) n["channel"]["width_m"] = text(*o.width);
  if (o.thickness) n["ice"]["thickness_m"] = text(*o.thickness);
  if (o.diameter) {
    n["ice"]["diameter_mean_m"] = text(*o.diameter);
    if (!o.diameter_sd) n["ice"]["diameter_sd_m"] = text(0.05 * *o.diameter);
  }
  if (o.diameter_sd) n["ice"]["diameter_sd_m"] = text(*o.diameter_sd);
  if (o.porosity) n["ice"]["porosity"] = text(*o.porosity);
  if (!o.packing_mode.empty()) n["ice"]["packing_mode"] = o.packing_mode;
  if (o.seed) n["ice"]["seed"] = fmt::format("{}", *o.seed);
  n["ice"]["packing_file"] = "generated/packing.csv";
  if (o.friction_ice) {
    n["friction"]["ice_ice"] = text(*o.friction_ice);
    if (!o.friction_wall) n["friction"]["ice_wall"] = text(*o.friction_ice);  // walls are level ice
  }
  if (o.friction_wall) n["friction"]["ice_wall"] = text(*o.friction_wall);
  if (o.friction_hull) n["friction"]["ice_hull"] = text(*o.friction_hull);
  if (!o.fluid_model.empty()) n["fluid"]["model"] = o.fluid_model;
  if (!o.treatment.empty()) n["fluid"]["treatment"] = o.treatment;
  if (o.duration) {
    n["run"]["duration_s"] = text(*o.duration);
    const auto w = n["run"]["window_s"];
    if (o.window.empty() && (!w.IsDefined() || w[1].as<double>() > *o.duration))
      n["run"]["window_s"] = flow_pair(0.4 * *o.duration, *o.duration);  // the loader's default
  }
  if (!o.window.empty()) n["run"]["window_s"] = flow_pair(o.window.at(0), o.window.at(1));

  const fs::path dir = fs::path(o.cases_dir) / o.name;
  const fs::path file = dir / "case.yaml";
  if (fs::exists(file) && !o.force)
    throw brash::InputError(file.string() + ": exists already (use --force to overwrite)");
  const bool created = !fs::exists(dir);
  fs::create_directories(dir);
  YAML::Emitter e;
  e << n;
  {
    std::ofstream out(file);
    out << "# Made by brash-case from " << templ.string() << " (keys: docs/case_format.md).\n" << e.c_str() << "\n";
    if (!out) throw brash::InputError(file.string() + ": cannot write");
  }
  try {
    const brash::Case c = brash::load_case(file);
    std::cout << fmt::format("brash-case: wrote {} (speed {} m/s, channel {} x {} m, d {} m, fluid {})\n",
                             file.string(), c.ship.speed_m_s, c.channel.length_m, c.channel.width_m,
                             c.ice.diameter_mean_m, brash::to_string(c.fluid.model));
  } catch (...) {
    fs::remove(file);
    if (created) fs::remove_all(dir);
    throw;
  }
  return 0;
}

struct DeriveOptions {
  std::string base, out;
  std::vector<std::string> sets;
  bool force = false;
};

fs::path case_file_of(const std::string& arg) {
  return fs::is_directory(arg) ? fs::path(arg) / "case.yaml" : fs::path(arg);
}

int derive(const DeriveOptions& o) {
  brash::CaseOverrides overrides;
  for (const auto& s : o.sets) overrides.push_back(brash::parse_case_override(s));
  const fs::path base = case_file_of(o.base);
  const brash::Case c = brash::write_derived_case(base, overrides, o.out, o.force);
  const char* note = brash::same_packing_inputs(c, brash::load_case(base))
                         ? " (the base's)"
                         : " (its own ice: generated when a run starts, or by brash-pack)";
  std::cout << fmt::format("brash-case: wrote {} from {}; packing {}{}\n", (fs::path(o.out) / "case.yaml").string(),
                           base.string(), c.ice.packing_file.string(), note);
  return 0;
}

int get(const std::string& case_arg, const std::string& key) {
  const fs::path file = case_file_of(case_arg);
  const brash::Case c = brash::load_case(file);
  try {
    std::cout << brash::case_value(c, key) << "\n";
  } catch (const brash::InputError& e) {
    throw brash::InputError(file.string() + ": " + e.what());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"brash-case: make, derive and read case folders"};
  app.require_subcommand(1);
  NewCaseOptions o;
  CLI::App* nw = app.add_subcommand("new", "write <cases-dir>/NAME/case.yaml from a template with values replaced");
  nw->add_option("NAME", o.name, "case name (folder name)")->required();
  nw->add_option("--cases-dir", o.cases_dir, "folder holding the case folders")->capture_default_str();
  nw->add_option("--template", o.templ, "template case.yaml (default: the paper case cases/jbc_ia_5kn)");
  nw->add_option("--description", o.description, "free text");
  nw->add_option("--speed", o.speed, "ship speed [m/s] (model scale)");
  nw->add_option("--scale", o.scale, "scale lambda (hull dimensions and speed scaled from the template by Froude)");
  nw->add_option("--ice-class", o.ice_class, "IA_super | IA | IB | IC");
  nw->add_option("--length", o.length, "channel length [m]");
  nw->add_option("--width", o.width, "channel width [m]");
  nw->add_option("--thickness", o.thickness, "brash thickness [m]");
  nw->add_option("--diameter", o.diameter, "mean ice piece diameter [m] (sd defaults to 5 %)");
  nw->add_option("--diameter-sd", o.diameter_sd, "diameter standard deviation [m]");
  nw->add_option("--porosity", o.porosity, "brash porosity (0..1)");
  nw->add_option("--packing-mode", o.packing_mode, "volume | strict_two_layer");
  nw->add_option("--seed", o.seed, "packing seed");
  nw->add_option("--friction-ice", o.friction_ice, "ice-ice friction (also ice-wall unless --friction-wall)");
  nw->add_option("--friction-hull", o.friction_hull, "ice-hull friction");
  nw->add_option("--friction-wall", o.friction_wall, "ice-wall friction");
  nw->add_option("--fluid-model", o.fluid_model, "both (Eq. 1 + Eq. 2) | drag (Eq. 1) | added_mass (Eq. 2 alone); default: the template's");
  nw->add_option("--treatment", o.treatment, "implicit | explicit");
  nw->add_option("--duration", o.duration, "simulated time [s]");
  nw->add_option("--window", o.window, "averaging window START END [s]")->expected(2);
  nw->add_option("--band", o.band, "contact hull band BELOW ABOVE the waterline [m] (hull.band_m; deeper for faster "
                                   "ships: the bow pushes the ice deeper)")->expected(2);
  nw->add_flag("--force", o.force, "overwrite an existing case.yaml");

  DeriveOptions d;
  CLI::App* dv = app.add_subcommand("derive", "write DIR/case.yaml: BASE with keys set to new values (docs/case_format.md)");
  dv->add_option("BASE", d.base, "base case folder or case.yaml")->required();
  dv->add_option("--set", d.sets, "KEY=VALUE: a dotted case key and its YAML value (fluid.model=drag, "
                                  "run.window_s=[0.375,0.75]); an empty value removes the key; repeatable")
      ->allow_extra_args(false);
  dv->add_option("--out", d.out, "folder of the derived case (made when missing)")->required();
  dv->add_flag("--force", d.force, "overwrite an existing DIR/case.yaml");

  std::string get_case, get_key;
  CLI::App* gt = app.add_subcommand("get", "print a key's value in the resolved case (every default filled in)");
  gt->add_option("CASE", get_case, "case folder or case.yaml")->required();
  gt->add_option("KEY", get_key, "dotted case key, e.g. run.timestep_s")->required();
  CLI11_PARSE(app, argc, argv);
  try {
    if (*dv) return derive(d);
    if (*gt) return get(get_case, get_key);
    return make_case(o);
  } catch (const brash::InputError& e) {
    std::cerr << "brash-case: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "brash-case: error: " << e.what() << "\n";
    return 1;
  }
}
