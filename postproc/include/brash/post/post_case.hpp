// The few case.yaml values the postprocessor needs, read through brash::load_case (brash_case), so
// a run's case.yaml gets the same validation as everywhere else (InputError naming file, key, line).
#pragma once
#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include <brash/case.hpp>

namespace brash::post {

struct PostCase {
  std::filesystem::path file;  // the case.yaml read
  std::string name;
  std::filesystem::path hull_file;  // resolved against the case file's folder
  double draft_m = 0, lpp_m = 0, beam_m = 0, start_x_m = 0;
  double speed_m_s = 0, scale_lambda = 1;
  std::string ice_class = "IA";
  std::string fluid_model;
  double duration_s = 0, timestep_s = 0;
  double channel_width_m = 0, water_level_m = 0;
  // the brash as the case packs it (ice.thickness_m: its volume per area is (1 - porosity) thickness)
  double ice_thickness_m = 0, ice_porosity = 0, ice_diameter_mean_m = 0;
  bool symmetry_y = false;  // speedups.symmetry_y: the half channel y >= 0 only
  std::optional<std::array<double, 2>> band_m;  // contact hull: [below, above] the waterline; nullopt = full hull
  std::array<double, 2> window_s{15.0, 40.0};
  // fsicr: overrides (full scale), keyed like FsicrParams fields: alpha_deg, phi1_deg, phi2_deg,
  // L_par_m, L_bow_m, A_wf_m2.
  std::map<std::string, double> fsicr_overrides;
  std::optional<double> psi_override_deg;  // otherwise psi = atan(tan phi2 / sin alpha)
  bool farfield_window_alone = false;  // speedups.farfield with no wake: idle ice was an immovable wall (biased)
  brash::ReferenceSpec references;  // the published values the case declares (none: compared with nothing)
};

// The published values for one fluid model; empty when none is declared for it.
struct PublishedReference {
  std::string source, fluid_model;
  std::optional<double> resistance_full_kN, fsicr_R_CH_kN;
  std::optional<double> ratio_fsicr_to_sim;  // stated by the source, or its R_CH over its resistance
  bool ratio_stated = false;
};
std::optional<PublishedReference> published_reference(const brash::ReferenceSpec& refs, const std::string& fluid_model);

PostCase read_post_case(const std::filesystem::path& case_yaml);

}  // namespace brash::post
