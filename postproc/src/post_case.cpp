// The postprocessor's view of case.yaml, read through the project's one loader (brash::load_case).
#include <brash/post/post_case.hpp>

#include <brash/case.hpp>

namespace brash::post {

PostCase read_post_case(const std::filesystem::path& case_yaml) {
  const brash::Case c = brash::load_case(case_yaml);
  PostCase p;
  p.file = case_yaml;
  p.name = c.name;
  p.hull_file = c.hull.file;
  p.draft_m = c.hull.draft_m;
  p.lpp_m = c.hull.lpp_m;
  p.beam_m = c.hull.beam_m;
  p.start_x_m = c.hull.start_x_m;
  p.speed_m_s = c.ship.speed_m_s;
  p.scale_lambda = c.ship.scale_lambda;
  p.ice_class = std::string(brash::to_string(c.ship.ice_class));
  p.fluid_model = std::string(brash::to_string(c.fluid.model));
  p.duration_s = c.run.duration_s;
  p.timestep_s = c.run.timestep_s;
  p.window_s = c.run.window_s;
  p.channel_width_m = c.channel.width_m;
  p.water_level_m = c.water.level_m;
  p.band_m = c.hull.band_m;
  p.ice_thickness_m = c.ice.thickness_m;
  p.ice_porosity = c.ice.porosity;
  p.ice_diameter_mean_m = c.ice.diameter_mean_m;
  p.symmetry_y = c.speedups.symmetry_y;
  const auto put = [&](const char* key, const std::optional<double>& v) {
    if (v) p.fsicr_overrides[key] = *v;
  };
  put("alpha_deg", c.fsicr.alpha_deg);
  put("phi1_deg", c.fsicr.phi1_deg);
  put("phi2_deg", c.fsicr.phi2_deg);
  put("L_par_m", c.fsicr.L_par_m);
  put("L_bow_m", c.fsicr.L_bow_m);
  put("A_wf_m2", c.fsicr.A_wf_m2);
  p.psi_override_deg = c.fsicr.psi_deg;
  p.farfield_window_alone = farfield_window_alone(c.speedups);
  p.references = c.references;
  return p;
}

std::optional<PublishedReference> published_reference(const brash::ReferenceSpec& refs, const std::string& fluid_model) {
  const auto find = [&](const std::map<std::string, double>& m) -> std::optional<double> {
    const auto it = m.find(fluid_model);
    return it == m.end() ? std::nullopt : std::optional<double>(it->second);
  };
  PublishedReference r{refs.source, fluid_model, find(refs.resistance_full_kN), refs.fsicr_R_CH_kN,
                       find(refs.ratio_fsicr_to_sim), false};
  if (!r.resistance_full_kN && !r.fsicr_R_CH_kN && !r.ratio_fsicr_to_sim) return std::nullopt;
  r.ratio_stated = r.ratio_fsicr_to_sim.has_value();
  if (!r.ratio_stated && r.resistance_full_kN && r.fsicr_R_CH_kN)
    r.ratio_fsicr_to_sim = *r.fsicr_R_CH_kN / *r.resistance_full_kN;
  return r;
}

}  // namespace brash::post
