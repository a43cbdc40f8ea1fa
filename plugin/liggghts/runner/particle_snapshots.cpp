#include "particle_snapshots.h"

#include <algorithm>
#include <array>
#include <fmt/format.h>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "brash/core/immersion.hpp"
#include "brash/error.hpp"
#include "brash/run/run_layout.hpp"

namespace fs = std::filesystem;

namespace brash::liggghts {

namespace {

// A dumped piece's columns after its id: x y z radius vx vy vz, then fix icefluid's submerged_fraction ca_x ca_y
// ca_z active (the dump command of liggghts_input.cpp), then the force of the piece on the hull (the hull wall's
// stored force on the piece, negated; 0 for a dump without it and for a piece at rest outside the scene)
using Columns = std::array<double, 15>;
constexpr std::size_t kDumped = 12;  // the columns every dump has
constexpr const char* kHeader = "id,x,y,z,radius,vx,vy,vz,submerged_fraction,ca_x,ca_y,ca_z,active";
// the dump's columns of the hull wall's force on each piece (fix hullwall ... store_force yes), and the snapshot's
constexpr const char* kDumpForce = "f_force_hullwall[1] f_force_hullwall[2] f_force_hullwall[3]";
constexpr const char* kForceHeader = ",hull_fx_N,hull_fy_N,hull_fz_N";

// particles/index.csv from every particles_<step>.csv in the folder, by step: the snapshots of all attempts
// of a resumed run (a resumed attempt rewrites those after its restart; the ones before it stay valid).
void write_snapshot_index(const fs::path& run_dir, const Case& c) {
  std::map<long, std::string> snapshots;
  const std::regex name_re(R"(particles_([0-9]+)\.csv)");
  std::smatch m;
  for (const auto& e : fs::directory_iterator(run_dir / "particles")) {
    const std::string name = e.path().filename().string();
    if (std::regex_match(name, m, name_re)) snapshots[std::stol(m[1])] = name;
  }
  std::string index = "step,t_s,file,hull_x_m\n";
  for (const auto& [step, name] : snapshots) {
    const double t = step * c.run.timestep_s;
    index += fmt::format("{},{:.9g},{},{:.9g}\n", step, t, name, c.hull.start_x_m + c.ship.speed_m_s * t);
  }
  run::write_atomic(run_dir / "particles" / "index.csv", index);
}

// One LIGGGHTS custom dump: its step (-1 without one), its pieces by id and whether it has the hull force columns
// (a dump of a deck from before them has not).
long read_dump(const fs::path& dump, std::map<long, Columns>& rows, bool& with_force) {
  std::ifstream in(dump);
  std::string line;
  long step = -1;
  bool atoms = false;
  with_force = false;
  while (std::getline(in, line)) {
    if (line.rfind("ITEM: TIMESTEP", 0) == 0) {
      std::getline(in, line);
      step = std::stol(line);
      continue;
    }
    if (line.rfind("ITEM:", 0) == 0) {
      atoms = line.rfind("ITEM: ATOMS", 0) == 0;
      if (atoms) with_force = line.find(kDumpForce) != std::string::npos;
      continue;
    }
    if (!atoms) continue;
    std::istringstream ss(line);
    long id;
    Columns v{};
    ss >> id;
    for (std::size_t k = 0; k < (with_force ? v.size() : kDumped); ++k) ss >> v[k];
    if (!ss) continue;
    for (std::size_t k = kDumped; k < v.size(); ++k) v[k] = -v[k];  // the wall's force on the piece -> on the hull
    rows[id] = v;
  }
  return step;
}

// A snapshot's row without its line end (the digits a snapshot has always had: positions and speeds to 9, fluid
// outputs to 6).
std::string row_text(long id, const Columns& v) {
  return fmt::format("{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.6g},{:.6g},{:.6g},{:.6g},{:.0f}", id, v[0],
                     v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10], v[11]);
}

// The hull force columns of a row (after active and state), with the dump's digits (6), and the line end.
std::string row_end(const Columns& v, bool with_force) {
  return with_force ? fmt::format(",{:.6g},{:.6g},{:.6g}\n", v[12] + 0.0, v[13] + 0.0, v[14] + 0.0) : "\n";
}

fs::path snapshot_file(const fs::path& run_dir, long step) {
  return run_dir / "particles" / fmt::format("particles_{:010d}.csv", step);
}

// One dump -> particles/particles_<step>.csv (sorted by id), the run without the moving window.
void convert_dump(const fs::path& dump, const fs::path& run_dir) {
  std::map<long, Columns> rows;
  bool with_force = false;
  const long step = read_dump(dump, rows, with_force);
  if (step < 0) return;
  std::string csv = std::string(kHeader) + (with_force ? kForceHeader : "") + "\n";
  for (const auto& [id, v] : rows) csv += row_text(id, v) + row_end(v, with_force);
  run::write_atomic(snapshot_file(run_dir, step), csv);
}

// The atoms of a scene's data file (liggghts_input.cpp's data_file: "id type diameter density x y z" after
// "Atoms"), as snapshot columns at rest: x y z radius, the submerged fraction below water_level_m, the rest 0.
std::map<long, Columns> read_data_file_atoms(const fs::path& file, double water_level_m) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string() + ": cannot read the scene's packing (the pieces of the moving window)");
  std::map<long, Columns> atoms;
  std::string line;
  bool in_atoms = false;
  while (std::getline(in, line)) {
    if (!in_atoms) {
      in_atoms = line.rfind("Atoms", 0) == 0;
      continue;
    }
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::istringstream ss(line);
    long id, type;
    double d, density, x, y, z;
    if (!(ss >> id >> type >> d >> density >> x >> y >> z))
      throw InputError(fmt::format("{}: '{}' is not an atom line 'id type diameter density x y z'", file.string(), line));
    atoms[id] = Columns{x, y, z, 0.5 * d, 0, 0, 0, core::immersion(0.5 * d, z, water_level_m).fraction};
  }
  if (atoms.empty()) throw InputError(file.string() + ": no atoms (an 'Atoms' section of 'id type diameter density x y z')");
  return atoms;
}

// The pieces in the scene of a snapshot converted before: its rows of state 0 (every row of one without the column).
void read_scene_rows(const fs::path& csv, std::map<long, Columns>& last_seen) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // the header
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) f.push_back(cell);
    if (f.size() < 13 || (f.size() > 13 && f[13] != "0")) continue;
    Columns v{};
    for (std::size_t k = 0; k < kDumped; ++k) v[k] = std::stod(f[k + 1]);
    last_seen[std::stol(f[0])] = v;
  }
}

// A piece outside the scene, at rest: its position, size and submerged fraction; no speed, no fluid force.
Columns at_rest(const Columns& v) { return Columns{v[0], v[1], v[2], v[3], 0, 0, 0, v[7]}; }

// The moving window's snapshots, in step order: the new dumps written with every piece of packing.data and its
// state; a snapshot converted before (an earlier attempt of a resumed run) is read for its pieces in the scene.
void convert_window_dumps(const std::vector<fs::path>& dumps, const fs::path& run_dir, const Case& c) {
  const auto packing = read_data_file_atoms(run_dir / "packing.data", c.water.level_m);
  std::map<long, fs::path> dump_of_step, converted;
  const std::regex csv_re(R"(particles_([0-9]+)\.csv)"), dump_re(R"(dump\.([0-9]+)\.txt)");
  std::smatch m;
  for (const auto& e : fs::directory_iterator(run_dir / "particles")) {
    const std::string name = e.path().filename().string();
    if (std::regex_match(name, m, csv_re)) converted[std::stol(m[1])] = e.path();
  }
  for (const auto& dump : dumps) {
    const std::string name = dump.filename().string();
    if (std::regex_match(name, m, dump_re)) dump_of_step[std::stol(m[1])] = dump;
  }
  std::map<long, bool> steps;  // step -> a new dump (else a snapshot converted before)
  for (const auto& [step, f] : converted) steps[step] = false;
  for (const auto& [step, f] : dump_of_step) steps[step] = true;
  std::map<long, Columns> last_seen;  // every piece in the scene of an earlier snapshot, as last seen there
  for (const auto& [step, is_dump] : steps) {
    if (!is_dump) {
      read_scene_rows(converted[step], last_seen);
      continue;
    }
    std::map<long, Columns> rows;
    bool with_force = false;
    const long dump_step = read_dump(dump_of_step[step], rows, with_force);
    if (dump_step < 0) continue;
    std::string csv = std::string(kHeader) + ",state" + (with_force ? kForceHeader : "") + "\n";
    // the state column, then the hull force (0 for a piece outside the scene: at rest, touching nothing)
    const auto state = [&](PieceState s, const Columns& v) {
      return fmt::format(",{}", static_cast<int>(s)) + row_end(v, with_force);
    };
    auto scene = rows.begin();
    for (const auto& [id, packed] : packing) {
      for (; scene != rows.end() && scene->first < id; ++scene)  // (a dumped id not in packing.data: kept)
        csv += row_text(scene->first, scene->second) + state(PieceState::Scene, scene->second);
      if (scene != rows.end() && scene->first == id) {
        csv += row_text(id, scene->second) + state(PieceState::Scene, scene->second);
        ++scene;
      } else if (const auto seen = last_seen.find(id); seen != last_seen.end()) {
        const Columns rest = at_rest(seen->second);
        csv += row_text(id, rest) + state(PieceState::Removed, rest);
      } else {
        csv += row_text(id, packed) + state(PieceState::HeldOut, packed);
      }
    }
    for (; scene != rows.end(); ++scene)
      csv += row_text(scene->first, scene->second) + state(PieceState::Scene, scene->second);
    run::write_atomic(snapshot_file(run_dir, dump_step), csv);
    for (const auto& [id, v] : rows) last_seen[id] = v;
  }
}

}  // namespace

std::size_t convert_dumps(const fs::path& run_dir, const Case& c) {
  std::vector<fs::path> dumps;
  for (const auto& e : fs::directory_iterator(run_dir / "particles"))
    if (e.path().filename().string().rfind("dump.", 0) == 0) dumps.push_back(e.path());
  std::sort(dumps.begin(), dumps.end());
  if (c.speedups.moving_window)
    convert_window_dumps(dumps, run_dir, c);
  else
    for (const auto& dump : dumps) convert_dump(dump, run_dir);
  for (const auto& dump : dumps) fs::remove(dump);
  write_snapshot_index(run_dir, c);
  return dumps.size();
}

}  // namespace brash::liggghts
