// Test helper: run brash-liggghts on an input script in a fresh directory (1 or N MPI ranks) and read
// whitespace-separated numeric output files back.
#pragma once
#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace brash::test {

inline std::filesystem::path fresh_dir(const std::string& name) {
  auto dir =
      std::filesystem::temp_directory_path() / ("brash_lig_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// Returns the exit status; the engine's screen output goes to dir/screen.txt.
inline int run_liggghts(const std::filesystem::path& dir, const std::string& input, int ranks = 1,
                        const std::string& input_name = "in.lmp") {
  std::ofstream(dir / input_name) << input;
  std::string cmd = "cd '" + dir.string() + "' && ";
  if (ranks > 1) cmd += "mpirun --allow-run-as-root --oversubscribe -np " + std::to_string(ranks) + " ";
  cmd += std::string("'") + BRASH_LIGGGHTS_EXE + "' -in " + input_name + " -log log_" + input_name +
         ".txt > screen_" + input_name + ".txt 2>&1";
  return std::system(cmd.c_str());
}

inline std::vector<std::vector<double>> read_table(const std::filesystem::path& file) {
  std::vector<std::vector<double>> rows;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ss(line);
    std::vector<double> row;
    double v;
    while (ss >> v) row.push_back(v);
    if (!row.empty()) rows.push_back(row);
  }
  return rows;
}

// The settings every granular test scene starts with (SI units, a closed box, per-atom map, no sorting so that
// atoms keep their order); the scene's region, box and atoms follow.
inline constexpr char kGranularPreamble[] =
    "atom_style granular\n"
    "atom_modify map array sort 0 0.0\n"
    "boundary f f f\n"
    "newton off\n"
    "communicate single vel yes\n"
    "units si\n";

// The preamble and a box x in [-0.1, x_hi], |y| < 0.5, |z| < 0.1 (one atom type); 2 ranks split it along x.
inline std::string box_along_x(double x_hi, int ranks) {
  return fmt::format("{}{}region reg block -0.1 {} -0.5 0.5 -0.1 0.1 units box\ncreate_box 1 reg\n", kGranularPreamble,
                     ranks > 1 ? "processors 2 1 1\n" : "", x_hi);
}

// Material and contact lines of a one-material (type 1) ice scene: Hertz with history, E 5 MPa,
// Poisson 0.3, restitution 0.3 and the given friction. Must follow create_box / read_restart.
inline std::string ice_contact_model(const std::string& friction) {
  return "fix m1 all property/global youngsModulus peratomtype 5.e6\n"
         "fix m2 all property/global poissonsRatio peratomtype 0.3\n"
         "fix m3 all property/global coefficientRestitution peratomtypepair 1 0.3\n"
         "fix m4 all property/global coefficientFriction peratomtypepair 1 " +
         friction +
         "\n"
         "pair_style gran model hertz tangential history\npair_coeff * *";
}

inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace brash::test
