// The few case.yaml values the postprocessor needs. This is an adapter: read_post_case() will be
// reimplemented on brash::load_case() (brash_case) once it exists; nothing else reads YAML.
#pragma once
#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

namespace brash::post {

struct PostCase {
  std::filesystem::path file;  // the case.yaml read
  std::string name;
  std::filesystem::path hull_file;  // resolved against the case file's folder
  double draft_m = 0, lpp_m = 0, beam_m = 0, start_x_m = 0;
  double speed_m_s = 0, scale_lambda = 1;
  std::string ice_class = "IA";
  std::string fluid_model;
  double duration_s = 0;
  std::array<double, 2> window_s{15.0, 40.0};
  // fsicr: overrides (full scale), keyed like FsicrParams fields: L_m, B_m, T_m, alpha_deg,
  // phi1_deg, phi2_deg, L_par_m, L_bow_m, A_wf_m2.
  std::map<std::string, double> fsicr_overrides;
};

PostCase read_post_case(const std::filesystem::path& case_yaml);

}  // namespace brash::post
