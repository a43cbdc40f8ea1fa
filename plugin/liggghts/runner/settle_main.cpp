// brash-settle CASE_FILE --out SETTLED_CSV: the case's packing floated and settled with LIGGGHTS on one rank (no
// ship, closed channel ends) until the pieces' rms speed is below ice.settle_speed_m_s, written as a packing file
// (id,x,y,z,diameter; ids kept). The run driver calls it for ice.settle (brash/run/settle.hpp) and caches the file.
#include <chrono>
#include <CLI/CLI.hpp>
#include <fmt/format.h>


#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "brash/case.hpp"
#include "brash/run/child_process.hpp"
#include "brash/error.hpp"
#include "brash/run/guard.hpp"
#include "brash/packing.hpp"
#include "brash/run/run_layout.hpp"
#include "brash/run/stages.hpp"
#include "brash/run/runner_setup.hpp"
#include "brash/run/settle.hpp"
#include "liggghts_input.h"

namespace fs = std::filesystem;
using namespace brash;

namespace {

// Runs the settling deck in `work`, its screen output into work/screen.txt, and reports each chunk's model time
// and rms speed on stderr (a paper-size bed takes tens of minutes). Returns LIGGGHTS' exit code and its output.
std::pair<int, std::string> run_settling(const fs::path& work, double target_m_s) {
  const run::ChildCommand command{work, "", run::shell_quote(run::executable_dir() / "brash-liggghts") +
                                                " -in in.lmp -log log.txt"};
  std::ofstream screen_file(work / "screen.txt");
  std::string screen;
  const std::string tag = "brash-settle progress: t ";
  const auto on_line = [&](const std::string& line) {
    screen += line;
    screen_file << line << std::flush;
    if (line.rfind(tag, 0) != 0) return false;
    double t = 0, vrms = 0;
    std::string word;
    std::istringstream in(line.substr(tag.size()));
    if (in >> t >> word >> vrms)
      std::cerr << fmt::format("[brash-settle] t = {:.2f} s, rms speed {:.3g} m/s (settled below {:g})\n", t, vrms,
                               target_m_s);
    return false;
  };
  const int code = run::run_child(command, {[](long /*pid*/) {}, on_line}).code;  // no driver: nothing to forward
  return {code, screen};
}

// "brash-settle: t 1.2 vrms 0.00093" from LIGGGHTS' screen output: {t, vrms}; throws if absent.
std::pair<double, double> settle_result(const std::string& screen, const fs::path& log) {
  const auto at = screen.rfind("brash-settle: t ");
  if (at == std::string::npos) throw InputError(log.string() + ": LIGGGHTS stopped before the bed settled");
  std::istringstream in(screen.substr(at + std::string("brash-settle: t ").size()));
  double t = NAN, v = NAN;
  std::string word;
  in >> t >> word >> v;
  if (!std::isfinite(t) || word != "vrms" || !std::isfinite(v))
    throw InputError(log.string() + ": unreadable result line of the settling");
  return {t, v};
}

// settled.dump (ITEM: ATOMS id x y z radius, sorted by id) as a packing file's rows
std::string packing_rows(const fs::path& dump) {
  std::ifstream in(dump);
  if (!in) throw InputError(dump.string() + ": no final dump of the settling");
  std::string line, out = "id,x,y,z,diameter\n";
  bool atoms = false;
  while (std::getline(in, line)) {
    if (line.rfind("ITEM: ATOMS", 0) == 0) {
      atoms = true;
      continue;
    }
    if (!atoms || line.empty()) continue;
    std::istringstream row(line);
    double id = 0, x = 0, y = 0, z = 0, r = 0;
    if (!(row >> id >> x >> y >> z >> r)) throw InputError(dump.string() + ": bad row '" + line + "'");
    out += fmt::format("{:.0f},{:.17g},{:.17g},{:.17g},{:.17g}\n", id, x, y, z, 2 * r);
  }
  return out;
}

int settle(const fs::path& case_file, const fs::path& out, double max_s) {
  const auto t0 = std::chrono::steady_clock::now();
  const Case c = load_case(case_file);
  const auto spheres = read_case_packing(c);
  // the scene's domain without a ship: the channel, its open-water margin and the water column
  Case still = c;
  still.hull.start_x_m = 0;
  still.hull.draft_m = 0;
  const auto d = guard::domain_box(still, 0, 0, 0, 0, 0);
  const liggghts::Box box{d[0], d[1], d[2], d[3], d[4], d[5]};
  const fs::path work = fs::path(out).replace_extension(".work");
  fs::remove_all(work);
  fs::create_directories(work);
  const long chunk_steps = std::max(1L, std::lround(0.05 / c.run.timestep_s));
  const long max_chunks = std::max(1L, std::lround(max_s / 0.05));
  run::write_atomic(work / "packing.data", liggghts::data_file(spheres, box, c.ice.density_kg_m3));
  run::write_atomic(work / "in.lmp", liggghts::settle_script(c, box, chunk_steps, max_chunks));
  std::cerr << fmt::format("[brash-settle] {} pieces, at most {} s of model time, until the rms speed < {} m/s\n",
                           spheres.size(), max_s, c.ice.settle_speed_m_s);
  const auto [rc, screen] = run_settling(work, c.ice.settle_speed_m_s);
  if (rc != 0)
    throw InputError(fmt::format("{}: LIGGGHTS failed (exit {}) while settling; its output: {}", case_file.string(), rc,
                                 (work / "screen.txt").string()));
  const auto [t_s, vrms] = settle_result(screen, work / "screen.txt");
  if (!(vrms < c.ice.settle_speed_m_s))
    throw InputError(fmt::format("{}: the bed did not settle within {} s: rms speed {:.3g} m/s >= ice.settle_speed_m_s "
                                 "= {} m/s (its log: {})",
                                 case_file.string(), max_s, vrms, c.ice.settle_speed_m_s, (work / "log.txt").string()));
  // wall_s: what making the bed cost, read by the runs that start from it (brash/run/stages.hpp)
  const std::string header = fmt::format("# brash-settle from={} t_s={:.6g} vrms_m_s={:.6g} wall_s={:.1f} {}\n",
                                         c.ice.packing_file.filename().string(), t_s, vrms, run::seconds_since(t0),
                                         settle_inputs(c));
  run::write_atomic(out, header + packing_rows(work / "settled.dump"));
  fs::remove_all(work);
  std::cerr << fmt::format("[brash-settle] settled at t = {:.3g} s (rms speed {:.3g} m/s): {}\n", t_s, vrms,
                           out.string());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"brash-settle: settle a case's packing (no ship, closed channel ends) into a packing file",
               "brash-settle"};
  fs::path case_file, out;
  double max_s = 20;
  app.add_option("case_file", case_file, "case.yaml (or its folder)")->required();
  app.add_option("--out", out, "the settled packing file to write")->required();
  app.add_option("--max-time", max_s, "model time allowed to settle [s]")->capture_default_str()->check(
      CLI::PositiveNumber);
  CLI11_PARSE(app, argc, argv);
  try {
    if (fs::is_directory(case_file)) case_file /= "case.yaml";
    return settle(case_file, out, max_s);
  } catch (const InputError& e) {
    std::cerr << "brash-settle: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "brash-settle: error: " << e.what() << "\n";
    return 1;
  }
}
