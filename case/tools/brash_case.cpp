// brash-case new NAME [--speed ... --scale ... --width ... ...]: makes a new case folder
// <cases-dir>/NAME/case.yaml from a template case (default: the quick case; --template jbc_ia_5kn: the paper case)
// with the given values replaced, then validates it with the loader (the folder is removed again if it is invalid).
// brash-case new NAME --hull FILE --draft T: the same around the user's own hull (docs/own_hull.md): the mesh is
// checked and measured with the hull library (closed, outward, units, frame, hydrostatics, FSICR parameters),
// refused with the reason when it fails, copied into the case folder as STL, and the hull keys are filled in.
// brash-case derive BASE --set key=value ... --out DIR: DIR/case.yaml, a variant of BASE through the case library
// (brash::write_derived_case: keys set, paths and packing as brash/case_derive.hpp says, checked by the loader).
// brash-case get CASE KEY: prints a key's value in the resolved case (every default filled in).
// brash-case keys [--markdown | --page FILE]: the case file's keys with their defaults, accepted values and meaning
// (brash/case_keys.hpp); --page rewrites the key table of a Markdown page (docs/case_format.md) in place.
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <regex>
#include <sstream>
#include <utility>

#include "brash/case.hpp"
#include "brash/case_derive.hpp"
#include "brash/case_keys.hpp"
#include "brash/error.hpp"
#include "brash/hull/hydrostatics.hpp"
#include "brash/hull/mesh.hpp"
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

// Measured hull values go in with 6 significant digits: an STL holds float32 vertices, so a 0.6 m beam reads
// 0.600000023842, and the digits past the sixth are the file's rounding, not the hull.
std::string measured(double v) { return text(std::stod(fmt::format("{:.6g}", v))); }

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

// ---- the user's own hull (--hull) ------------------------------------------------------------------------------

std::string lower_extension(const fs::path& file) {
  std::string e = file.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  return e;
}

struct OwnHull {
  fs::path source;              // as given on the command line
  fs::path stl;                 // the STL that goes into the case folder (source, or a converted temporary)
  bool converted = false;       // written from another format
  std::string case_file_name;   // its name in the case folder
  brash::hull::MeshCheck check;
  brash::hull::Hydrostatics hydro;
  brash::hull::FsicrDetail fsicr;
  double lpp_m = 0, draft_m = 0, beam_m = 0;
  bool lpp_from_waterline = false;  // no --lpp: Lpp is the waterline length
  double x_max_m = 0;           // the bow's most forward point, hull frame
};

// Why a closed-surface check failed, in words.
std::string topology_problem(const brash::hull::MeshCheck& c) {
  std::vector<std::string> why;
  if (!c.closed)
    why.push_back(fmt::format("the hull is not closed ({} boundary edges: holes or a missing deck/transom; a hull must be "
                              "a watertight surface for buoyancy, hydrostatics and the penetration guard)",
                              c.boundary_edges));
  if (!c.manifold) why.push_back(fmt::format("{} non-manifold edges (shared by three or more faces)", c.nonmanifold_edges));
  if (!c.oriented)
    why.push_back(fmt::format("faces are not consistently oriented ({} edges run the same way in two faces)",
                              c.misoriented_edges));
  else if (c.closed && !c.outward)
    why.push_back(fmt::format("faces point inward (enclosed volume {:.6g} m^3): flip the face order", c.signed_volume_m3));
  if (c.degenerate_faces > 0) why.push_back(fmt::format("{} degenerate faces (zero area)", c.degenerate_faces));
  return fmt::format("{}", fmt::join(why, "; "));
}

// Checks the mesh as a hull in the case frame and measures it; throws brash::InputError with the reason when it
// is not fit for a case.
void check_and_measure(OwnHull& h, const brash::hull::Mesh& mesh, std::optional<double> lpp_m) {
  namespace hull = brash::hull;
  const double draft_m = h.draft_m;
  const auto refuse = [&](const std::string& why) {
    return brash::InputError(fmt::format("--hull {}: refused: {}", h.source.string(), why));
  };
  h.check = hull::check_mesh(mesh);
  if (!h.check.ok()) throw refuse(topology_problem(h.check));
  if (!(draft_m > 0)) throw refuse(fmt::format("--draft {} m is not positive", draft_m));
  if (lpp_m && !(*lpp_m > 0)) throw refuse(fmt::format("--lpp {} m is not positive", *lpp_m));
  if (const auto units = hull::unit_problems(mesh, draft_m, lpp_m.value_or(0.0)); !units.empty())
    throw refuse(fmt::format("{} (hull frame: metres, x forward, keel at z = 0, waterline at z = --draft)",
                             fmt::join(units, "; ")));
  const double y_lo = h.check.min_m.y(), y_hi = h.check.max_m.y();
  if (std::abs(y_lo + y_hi) > 0.01 * (y_hi - y_lo))
    throw refuse(fmt::format("the hull spans y = {:.6g} .. {:.6g} m, not centred on y = 0 (the channel's centreline): "
                             "move it so that its centre plane is y = 0", y_lo, y_hi));
  h.hydro = hull::hydrostatics(mesh, draft_m, lpp_m.value_or(0.0));
  if (!(h.hydro.volume_m3 > 0) || !(h.hydro.lwl_m > 0) || !(h.hydro.bwl_m > 0))
    throw refuse(fmt::format("no displaced volume below the waterline z = {} m", draft_m));
  h.lpp_m = lpp_m.value_or(h.hydro.lwl_m);
  h.lpp_from_waterline = !lpp_m;
  h.beam_m = h.hydro.bwl_m;
  h.x_max_m = h.check.max_m.x();
  try {
    h.fsicr = hull::measure_fsicr_detail(mesh, draft_m, h.lpp_m);
  } catch (const brash::InputError& e) {
    throw refuse(fmt::format("FSICR hull parameters cannot be measured ({})", e.what()));
  }
}

// Reads the hull (STL as is; OBJ and meshio formats converted to a temporary STL), checks and measures it.
OwnHull measure_own_hull(const fs::path& source, double draft_m, std::optional<double> lpp_m) {
  namespace hull = brash::hull;
  if (!fs::is_regular_file(source))
    throw brash::InputError(fmt::format("--hull {}: no such file", source.string()));
  OwnHull h;
  h.source = source;
  h.draft_m = draft_m;
  const std::string ext = lower_extension(source);
  hull::Mesh mesh;
  if (ext == ".stl") {
    mesh = hull::read_mesh(source);
    h.stl = source;
    h.case_file_name = source.filename().string();
  } else {
    // Any other format (hull::read_mesh: OBJ natively, the rest through meshio) goes into the case as a binary STL,
    // read back here so the checks see exactly what the engines will (float32 vertices, welded).
    mesh = hull::read_mesh(source);
    h.converted = true;
    h.case_file_name = source.stem().string() + ".stl";
    h.stl = fs::temp_directory_path() / fmt::format("brash_case_hull_{}.stl", ::getpid());
    hull::write_stl(h.stl, mesh);
    try {
      mesh = hull::read_mesh(h.stl);
      check_and_measure(h, mesh, lpp_m);
    } catch (...) {
      std::error_code ec;
      fs::remove(h.stl, ec);
      throw;
    }
    return h;
  }
  check_and_measure(h, mesh, lpp_m);
  return h;
}

void print_own_hull(const OwnHull& h, double lambda) {
  const auto& p = h.fsicr.params;
  std::cout << fmt::format(
      "brash-case: hull {}: closed, outward, {} faces; Lpp {:.4g} m{}, waterline beam {:.4g} m, draft {:.4g} m, "
      "displacement {:.4g} m^3, Cb {:.3f}\n",
      h.source.string(), h.check.faces, h.lpp_m, h.lpp_from_waterline ? " (waterline length)" : "", h.beam_m,
      h.draft_m, h.hydro.volume_m3, h.hydro.cb);
  std::cout << fmt::format(
      "brash-case: FSICR parameters (full scale, 1:{:g}): L {:.4g} m, B {:.4g} m, T {:.4g} m, alpha {:.1f} deg, "
      "phi1 {:.1f} deg{}, phi2 {:.1f} deg, psi {:.1f} deg, L_par {:.4g} m, L_bow {:.4g} m, A_wf {:.4g} m^2\n",
      lambda, p.L_m * lambda, p.B_m * lambda, p.T_m * lambda, p.alpha_deg, p.phi1_deg,
      h.fsicr.bulbous_bow ? " (bulbous bow)" : "", p.phi2_deg, p.psi_deg, p.L_par_m * lambda, p.L_bow_m * lambda,
      p.A_wf_m2 * lambda * lambda);
  for (const auto& [name, deg] : {std::pair{"alpha", p.alpha_deg}, std::pair{"phi1", p.phi1_deg},
                                   std::pair{"phi2", p.phi2_deg}, std::pair{"psi", p.psi_deg}})
    if (!(deg > 0 && deg <= 90))  // FSICR's angles lie in (0, 90]: outside, the measurement found no bow
      std::cerr << fmt::format("brash-case: warning: FSICR angle {} = {:.1f} deg is outside the valid range (0, 90] "
                               "deg: at the draft {:.4g} m the waterline does not cut a bow FSICR can take; reports "
                               "give no R_CH unless the case's fsicr: section sets {}_deg (docs/case_format.md)\n",
                               name, deg, h.draft_m, name);
  if (!(p.L_bow_m > 0) || !(p.A_wf_m2 > 0))
    std::cerr << fmt::format("brash-case: note: this hull has no bow the FSICR formula can take (L_bow {:.3g} m, A_wf "
                             "{:.3g} m^2): reports will give the resistance without FSICR R_CH unless the case's "
                             "fsicr: section sets L_bow_m and A_wf_m2 (docs/case_format.md)\n",
                             p.L_bow_m * lambda, p.A_wf_m2 * lambda * lambda);
}

// How far the template's bow stands outside the ice at t = 0, in its ship lengths (its hull's most forward point:
// the JBC's bulb is ahead of its FP); 1 % when the template's hull cannot be read or starts in the ice.
double bow_gap_over_lpp(const brash::Case& base) {
  double x_max = base.hull.lpp_m;
  try {
    x_max = brash::hull::check_mesh(brash::hull::read_mesh(base.hull.file)).max_m.x();
  } catch (const brash::InputError&) {
  }
  const double gap = -(base.hull.start_x_m + x_max) / base.hull.lpp_m;
  return gap > 0 ? gap : 0.01;
}

// The template's (or base's) published references describe another hull, speed, ice or fluid than the new case:
// they were left out (brash::keys_beyond_references).
void note_references_dropped(const fs::path& from, const std::vector<std::string>& keys) {
  std::cerr << fmt::format("brash-case: note: the published references of {} (references:) are not carried over: "
                           "they describe its hull, speed, ice and fluid, and {} changed (docs/case_format.md "
                           "\"references\")\n",
                           from.string(), fmt::join(keys, ", "));
}

// The template's ice at a new scale (k = old lambda / new lambda): thickness, piece size and its sd scaled by k, so
// the brash is as thick and its pieces as large at full scale as the template's; --thickness, --diameter and
// --diameter-sd, applied afterwards, still win. The time step follows the pieces (x k): the same fraction of the
// smallest piece's Rayleigh time, which is proportional to its size.
void scale_ice(YAML::Node& n, const brash::Case& base, double k, double lambda, bool note) {
  const brash::IceSpec& ice = base.ice;
  n["ice"]["thickness_m"] = text(ice.thickness_m * k);
  n["ice"]["diameter_mean_m"] = text(ice.diameter_mean_m * k);
  n["ice"]["diameter_sd_m"] = text(ice.diameter_sd_m * k);
  n["run"]["timestep_s"] = text(base.run.timestep_s * k);
  if (note)
    std::cerr << fmt::format("brash-case: note: the ice scaled by Froude like the hull (x {:.4g}): {:.4g} m "
                             "thick, pieces {:.4g} m (sd {:.4g} m), time step {:.4g} s; at full scale (1:{:g}) "
                             "{:.3g} m thick with {:.3g} m pieces, as the template's (--thickness, --diameter to "
                             "choose other ice)\n",
                             k, ice.thickness_m * k, ice.diameter_mean_m * k, ice.diameter_sd_m * k,
                             base.run.timestep_s * k, lambda, ice.thickness_m * k * lambda,
                             ice.diameter_mean_m * k * lambda);
}

// ---- brash-case new -----------------------------------------------------------------------------------------------

struct NewCaseOptions {
  std::string name, cases_dir = "cases", templ, description, fluid_model, treatment, ice_class, packing_mode;
  std::string hull;
  std::optional<double> speed, scale, length, width, thickness, diameter, diameter_sd, porosity, friction_ice,
      friction_hull, friction_wall, duration, draft, lpp;
  std::vector<double> window, band;
  std::optional<std::uint64_t> seed;
  bool force = false;
};

// A case argument: its case.yaml, or the folder holding it.
fs::path case_file_of(const std::string& arg) {
  return fs::is_directory(arg) ? fs::path(arg) / "case.yaml" : fs::path(arg);
}

// --template: a case.yaml, its folder, or the name of a case of brash's data (cases/NAME: jbc_quick, jbc_ia_5kn);
// without it the quick case, small and fast (a new case is tried before it is made large).
fs::path template_file(const std::string& arg) {
  if (arg.empty()) return brash::paths::data_file("cases/jbc_quick/case.yaml", "the default template");
  std::error_code ec;
  if (fs::exists(arg, ec)) return case_file_of(arg);
  if (std::regex_match(arg, std::regex("[A-Za-z0-9_.-]+")))
    return brash::paths::data_file(fs::path("cases") / arg / "case.yaml", "--template " + arg + ":");
  throw brash::InputError("--template " + arg + ": no such case file or folder");
}

int make_case(const NewCaseOptions& o) {
  if (!std::regex_match(o.name, std::regex("[A-Za-z0-9_.-]+")) || o.name == "." || o.name == "..")
    throw brash::InputError(fmt::format("case name '{}': use letters, digits, '_', '-', '.'", o.name));
  const fs::path templ = template_file(o.templ);
  const brash::Case base = brash::load_case(templ);  // the template itself must be valid
  YAML::Node n = YAML::LoadFile(templ.string());
  if (o.hull.empty() && (o.draft || o.lpp))
    throw brash::InputError("--draft and --lpp describe the hull given with --hull FILE (without it the template's hull "
                            "is used as it is)");
  if (!o.hull.empty() && !o.draft)
    throw brash::InputError(fmt::format("--hull {} needs --draft D: the waterline's height above the keel in m (a mesh "
                                        "does not say where its waterline is)", o.hull));
  // The user's hull: checked and measured before anything is written (a refused hull leaves no folder).
  std::optional<OwnHull> own;
  if (!o.hull.empty()) {
    try {
      own = measure_own_hull(o.hull, *o.draft, o.lpp);
    } catch (const brash::InputError& e) {  // the hull library's messages name the file; say which option it came from
      std::string what = std::regex_replace(e.what(), std::regex("\\s+\\)"), ")");  // meshio's trailing newline
      throw brash::InputError(what.starts_with("--hull") ? what : "--hull: refused: " + what);
    }
  }
  struct TempStl {  // a converted hull's temporary STL goes once it is copied (or the case is refused)
    fs::path file;
    ~TempStl() {
      std::error_code ec;
      if (!file.empty()) fs::remove(file, ec);
    }
  } temp_stl{own && own->converted ? own->stl : fs::path()};

  n["name"] = o.name;
  n["description"] = !o.description.empty() ? o.description
                     : own ? fmt::format("made by brash-case from {} with the hull {}", base.name,
                                         own->source.filename().string())
                           : fmt::format("made by brash-case from {}", base.name);
  // New scale: hull dimensions, the ice and (unless given) speed follow Froude similarity from the template (the
  // user's hull keeps its measured dimensions; the speed keeps the template's full-scale speed, the ice its
  // full-scale thickness and piece size, which FSICR's R_CH and the comparison with it assume).
  if (o.scale) {
    const double old_lambda = base.ship.scale_lambda;
    const double k = old_lambda / *o.scale;
    if (!own)
      for (const char* key : {"draft_m", "lpp_m", "beam_m", "start_x_m"})
        if (n["hull"][key].IsDefined()) n["hull"][key] = text(n["hull"][key].as<double>() * k);
    n["ship"]["scale_lambda"] = text(*o.scale);
    if (!o.speed) n["ship"]["speed_m_s"] = text(base.ship.speed_m_s * std::sqrt(k));
    scale_ice(n, base, k, *o.scale, !o.thickness && !o.diameter);
    if (!own)
      std::cerr << fmt::format("brash-case: note: hull dimensions scaled by {:.4g}; hull.file still names {} "
                               "-- generate the hull at 1:{} with the hull tool and point hull.file at it\n",
                               k, n["hull"]["file"].as<std::string>(), *o.scale);
  }
  if (own) {
    // Hull keys from the measurement; the channel follows the hull where not given: the template's width in beams,
    // its length in ship lengths, and the bow as far (in ship lengths) outside the ice at t = 0.
    n["hull"]["file"] = own->case_file_name;
    n["hull"]["draft_m"] = text(own->draft_m);
    n["hull"]["lpp_m"] = measured(own->lpp_m);
    n["hull"]["beam_m"] = measured(own->beam_m);
    n["hull"]["start_x_m"] = measured(-(own->x_max_m + bow_gap_over_lpp(base) * own->lpp_m));
    if (!o.width) {
      const double w = std::stod(measured(base.channel.width_m / base.hull.beam_m * own->beam_m));
      n["channel"]["width_m"] = text(w);
      std::cerr << fmt::format("brash-case: note: channel width {:.4g} m = {:.3g} beams, as in the template (--width to "
                               "change it)\n", w, base.channel.width_m / base.hull.beam_m);
    }
    if (!o.length) {
      const double l = std::stod(measured(base.channel.length_m / base.hull.lpp_m * own->lpp_m));
      n["channel"]["length_m"] = text(l);
      std::cerr << fmt::format("brash-case: note: channel length {:.4g} m = {:.3g} ship lengths, as in the template "
                               "(--length to change it)\n", l, base.channel.length_m / base.hull.lpp_m);
    }
    const double width = o.width ? *o.width : number_at(n, "channel", "width_m", base.channel.width_m);
    if (width <= own->beam_m)
      throw brash::InputError(fmt::format("channel.width_m {:.6g} m is not wider than the waterline beam {:.6g} m of "
                                          "--hull {} (--width)", width, own->beam_m, o.hull));
    if (width < 1.2 * own->beam_m)
      std::cerr << fmt::format("brash-case: note: the channel ({:.4g} m) is only {:.2f} beams wide: the ice has little "
                               "room beside the hull (FSICR channels are about 2 beams)\n", width, width / own->beam_m);
    if (!o.scale)
      std::cerr << fmt::format("brash-case: note: scale 1:{:g} from the template (--scale): full-scale results and the "
                               "FSICR comparison use it\n", base.ship.scale_lambda);
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
  fs::path hull_copy;  // the hull file this call put into the case folder
  if (own) {
    const fs::path dest = dir / own->case_file_name;
    const bool same = fs::exists(dest) && fs::equivalent(dest, own->stl);
    if (!same && fs::exists(dest) && !o.force)
      throw brash::InputError(dest.string() + ": exists already (use --force to overwrite)");
    fs::create_directories(dir);
    if (!same) {
      fs::copy_file(own->stl, dest, fs::copy_options::overwrite_existing);
      hull_copy = dest;
    }
  }
  fs::create_directories(dir);
  const auto write = [&] {
    YAML::Emitter e;
    e << n;
    std::ofstream out(file);
    out << "# Made by brash-case from " << templ.string() << " (keys: docs/case_format.md).\n" << e.c_str() << "\n";
    if (!out) throw brash::InputError(file.string() + ": cannot write");
  };
  try {
    write();
    brash::Case c = brash::load_case(file);
    if (const auto keys = brash::keys_beyond_references(base, c); base.references.declared() && !keys.empty()) {
      n.remove("references");
      write();
      c = brash::load_case(file);
      note_references_dropped(templ, keys);
    }
    if (own) print_own_hull(*own, c.ship.scale_lambda);
    std::cout << fmt::format("brash-case: wrote {} (speed {} m/s, channel {} x {} m, d {} m, fluid {}{})\n",
                             file.string(), c.ship.speed_m_s, c.channel.length_m, c.channel.width_m,
                             c.ice.diameter_mean_m, brash::to_string(c.fluid.model),
                             own ? fmt::format(", hull {}", own->case_file_name) : std::string());
  } catch (...) {
    fs::remove(file);
    if (!hull_copy.empty()) fs::remove(hull_copy);
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

int derive(const DeriveOptions& o) {
  brash::CaseOverrides overrides;
  for (const auto& s : o.sets) overrides.push_back(brash::parse_case_override(s));
  const fs::path base = case_file_of(o.base);
  const brash::Case c = brash::write_derived_case(base, overrides, o.out, o.force);
  const brash::Case base_case = brash::load_case(base);
  if (base_case.references.declared() && !c.references.declared())
    note_references_dropped(base, brash::keys_beyond_references(base_case, c));
  if (c.run.window_s != base_case.run.window_s && c.run.duration_s < base_case.run.window_s[1])
    std::cerr << fmt::format("brash-case: note: run.duration_s {} s is shorter than the base's window: run.window_s "
                             "set to [{}, {}] s (give run.window_s to choose another)\n",
                             c.run.duration_s, c.run.window_s[0], c.run.window_s[1]);
  const char* note = brash::same_packing_inputs(c, base_case)
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

struct KeysOptions {
  bool markdown = false;
  std::string page;
};

// Replaces the lines from the begin marker to the end marker of `page` with the key table.
void rewrite_key_table(const fs::path& page) {
  std::ifstream in(page);
  if (!in) throw brash::InputError(page.string() + ": cannot open");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  const std::size_t begin = text.find(brash::kCaseKeysBegin);
  const std::size_t end_marker = text.find(brash::kCaseKeysEnd, begin == std::string::npos ? 0 : begin);
  if (begin == std::string::npos || end_marker == std::string::npos)
    throw brash::InputError(fmt::format("{}: no key table (the lines '{}' ... '{}')", page.string(),
                                        brash::kCaseKeysBegin, brash::kCaseKeysEnd));
  const std::size_t end = text.find('\n', end_marker);
  const std::string rest = end == std::string::npos ? std::string() : text.substr(end + 1);
  std::ofstream out(page);
  out << text.substr(0, begin) << brash::case_keys_markdown() << rest;
  if (!out) throw brash::InputError(page.string() + ": cannot write");
}

int keys(const KeysOptions& o) {
  if (!o.page.empty()) {
    rewrite_key_table(o.page);
    return 0;
  }
  if (o.markdown) {
    std::cout << brash::case_keys_markdown();
    return 0;
  }
  for (const auto& k : brash::case_key_reference())
    std::cout << fmt::format("{} = {}  ({}): {}\n", k.key, k.default_value, k.values, k.doc);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"brash-case: make, derive and read case folders", "brash-case"};
  app.require_subcommand(1);
  NewCaseOptions o;
  CLI::App* nw = app.add_subcommand("new", "write <cases-dir>/NAME/case.yaml from a template with values replaced");
  nw->add_option("NAME", o.name, "case name (folder name)")->required();
  nw->add_option("--cases-dir", o.cases_dir, "folder holding the case folders")->capture_default_str();
  nw->add_option("--template", o.templ, "template: a case.yaml, its folder, or a case of brash's data by name (jbc_ia_5kn: the paper case); default: the quick case jbc_quick");
  nw->add_option("--description", o.description, "free text");
  nw->add_option("--speed", o.speed, "ship speed [m/s] (model scale)");
  nw->add_option("--scale", o.scale, "scale lambda (hull dimensions, speed and ice scaled from the template by "
                                   "Froude)");
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
  nw->add_option("--hull", o.hull, "your own hull: STL or OBJ (other formats through meshio), model scale, metres, "
                                 "x forward, keel at z = 0, centred on y = 0; checked, measured and copied into the "
                                 "case folder (docs/own_hull.md)");
  nw->add_option("--draft", o.draft, "with --hull: draft [m], the waterline's height above the keel");
  nw->add_option("--lpp", o.lpp, "with --hull: length between perpendiculars [m] (default: the waterline length)");
  nw->add_flag("--force", o.force, "overwrite an existing case.yaml (and hull file)");

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

  KeysOptions k;
  CLI::App* ks = app.add_subcommand("keys", "list the case file's keys: default, accepted values, meaning");
  ks->add_flag("--markdown", k.markdown, "as the Markdown table of docs/case_format.md, with its marker lines");
  ks->add_option("--page", k.page, "rewrite the key table (between the marker lines) of this Markdown page in place");
  CLI11_PARSE(app, argc, argv);
  try {
    if (*ks) return keys(k);
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
