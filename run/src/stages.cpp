#include "brash/run/stages.hpp"

#include <cstdlib>
#include <fstream>
#include <regex>
#include <string>

namespace fs = std::filesystem;

namespace brash::run {

std::optional<double> packing_wall_s(const fs::path& packing_file) {
  const fs::path json = packing_file.parent_path() / (packing_file.stem().string() + ".json");
  const auto j = nlohmann::json::parse(std::ifstream(json), nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("wall_time_s") || !j["wall_time_s"].is_number())
    return std::nullopt;
  return j["wall_time_s"].get<double>();
}

std::optional<double> settled_bed_wall_s(const fs::path& settled_file) {
  std::ifstream in(settled_file);
  std::string header;
  std::getline(in, header);
  std::smatch m;
  if (!std::regex_search(header, m, std::regex(R"(^# brash-settle .* wall_s=([0-9.eE+-]+))"))) return std::nullopt;
  char* end = nullptr;
  const std::string text = m[1].str();
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return std::nullopt;
  return v;
}

nlohmann::json made_input(std::optional<double> wall_s, bool made_by_this_run) {
  return {{"wall_s", wall_s ? nlohmann::json(*wall_s) : nlohmann::json(nullptr)},
          {"made_by_this_run", made_by_this_run}};
}

}  // namespace brash::run
