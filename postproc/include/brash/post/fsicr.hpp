// FSICR channel resistance R_CH (Finnish-Swedish Ice Class Rules, "engine output" chapter).
// The formula is written out in fsicr.cpp (docs/fsicr_vs_paper.md checks it on the JBC). Every constant lives
// in FsicrConstants so a corrected rule text changes one place.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <brash/case.hpp>
#include <brash/fsicr_params.hpp>

namespace brash::post {

// The case schema's ice class; its name is brash::to_string(IceClass) and its H_M (1.0 m IA Super/IA,
// 0.8 m IB, 0.6 m IC) brash::h_m_for_ice_class.
using IceClass = brash::IceClass;

// "IA_super" (also "IAS", "IA Super"), "IA", "IB", "IC", any case (the command line's lenient spelling);
// InputError otherwise.
IceClass parse_ice_class(std::string_view text);

struct FsicrConstants {
  double C3 = 845.0;  // kg/(m^2 s^2)  [P]
  double C4 = 42.0;   // kg/(m^2 s^2)  [P]
  double C5 = 825.0;  // kg/s^2        [U]
  double Cmu_min = 0.45;
  double Cpsi_slope = 0.047, Cpsi_offset = 2.115, Cpsi_zero_below_psi_deg = 45.0;
  double HF_offset_m = 0.26;
  double LTB3_min = 5.0, LTB3_max = 20.0;  // clamp of (L T / B^2)^3
  // IA Super only (C1, C2; 0.1 m consolidated layer)  [U]
  double f1 = 23.0, f2 = 45.8, f3 = 14.7, f4 = 29.0;
  double g1 = 1530.0, g2 = 170.0, g3 = 400.0;
};

struct FsicrResult {
  double H_M_m = 0, H_F_m = 0;
  double psi_deg = 0, Cmu = 0, Cpsi = 0;
  double LTB3_raw = 0, LTB3_used = 0;  // (L T / B^2)^3 before and after clamping
  double C1_N = 0, C2_N = 0;
  // R_CH's terms: C1 + C2 + bow + mid-body + form = R_CH_N (the sum in that order, so it is exact)
  double bow_term_N = 0;      // C3 Cmu (H_F + H_M)^2 (B + Cpsi H_F): the bow pushing the brash
  double midbody_term_N = 0;  // C4 L_par H_F^2: friction along the parallel mid-body
  double form_term_N = 0;     // C5 (L T / B^2)^3 A_wf / L: the hull form
  double R_CH_N = 0;
};

// psi = atan(tan(phi2) / sin(alpha)) in degrees (90 when phi2 = 90).
double fsicr_psi_deg(double alpha_deg, double phi2_deg);

// R_CH and its intermediates. p.psi_deg is ignored: psi is recomputed from alpha and phi2 unless
// psi_override_deg is given (a case's fsicr.psi_deg). H_F_m: the brash thickness in front of the bow in place of
// the rule's 0.26 + (B H_M)^0.5 (a simulation's measured one, to see what the rule's H_F carries); none: the rule's.
FsicrResult fsicr_channel_resistance(const FsicrParams& p, IceClass ice_class,
                                     const FsicrConstants& k = {},
                                     std::optional<double> psi_override_deg = std::nullopt,
                                     std::optional<double> H_F_m = std::nullopt);

// Values no hull has, one text per problem naming the parameter(s) through `name` (an FsicrParams field such as
// "B_m" -> how the caller calls it, e.g. "--B"; default: the field name) and the value: non-finite values, lengths
// and areas <= 0 (L_par_m >= 0: a ship may have no parallel mid-body), angles outside (0, 90] deg, L_bow_m or
// L_par_m longer than L_m or both together longer than it, A_wf_m2 larger than the L_bow_m x B_m rectangle that
// holds it. The formula's result would be meaningless (a negative beam gives R_CH = nan): callers refuse them.
// Values inside these bounds but outside the rule's validity range are fsicr_validity_warnings.
std::vector<std::string> fsicr_impossible_values(
    const FsicrParams& p, const std::function<std::string(std::string_view field)>& name = {});

// Human-readable warnings for parameters outside the formula's validity range.
std::vector<std::string> fsicr_validity_warnings(const FsicrParams& p);

// Required propulsion power P = K_e (R_CH/1000)^1.5 / D_P in kW (reports only).
double fsicr_power_kW(double R_CH_N, double K_e, double propeller_diameter_m);

}  // namespace brash::post
