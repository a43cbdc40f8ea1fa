// Test helper: run brash-liggghts on an input script in a fresh directory (1 or N MPI ranks) and read
// whitespace-separated numeric output files back.
#pragma once
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace brash::test {

inline std::filesystem::path fresh_dir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("brash_lig_" + name + "_" + std::to_string(::getpid()));
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

inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace brash::test
