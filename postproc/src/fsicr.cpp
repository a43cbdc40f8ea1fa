// FSICR channel resistance R_CH: the rule's formula, its constants and the validity tags (fsicr.hpp).
#include <brash/post/fsicr.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include <brash/error.hpp>

namespace brash::post {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

std::string normalized(std::string_view s) {
  std::string out;
  for (const char ch : s)
    if (std::isalnum(static_cast<unsigned char>(ch))) out += static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  return out;
}

}  // namespace

IceClass parse_ice_class(std::string_view text) {
  const auto n = normalized(text);
  if (n == "IASUPER" || n == "IAS") return IceClass::IA_super;
  if (n == "IA") return IceClass::IA;
  if (n == "IB") return IceClass::IB;
  if (n == "IC") return IceClass::IC;
  throw InputError(fmt::format("ice class '{}': expected IA_super, IA, IB or IC", text));
}

double fsicr_psi_deg(double alpha_deg, double phi2_deg) {
  // atan2 keeps phi2 = 90 deg (vertical bow, tan infinite) well defined: psi = 90.
  return std::atan2(std::sin(phi2_deg * kDeg), std::cos(phi2_deg * kDeg) * std::sin(alpha_deg * kDeg)) / kDeg;
}

FsicrResult fsicr_channel_resistance(const FsicrParams& p, IceClass ice_class, const FsicrConstants& k,
                                     std::optional<double> psi_override_deg, std::optional<double> H_F_m) {
  FsicrResult r;
  r.H_M_m = h_m_for_ice_class(ice_class);
  r.H_F_m = H_F_m ? *H_F_m : k.HF_offset_m + std::sqrt(r.H_M_m * p.B_m);
  r.psi_deg = psi_override_deg ? *psi_override_deg : fsicr_psi_deg(p.alpha_deg, p.phi2_deg);
  r.Cmu = std::max(k.Cmu_min, 0.15 * std::cos(p.phi2_deg * kDeg) + std::sin(r.psi_deg * kDeg) * std::sin(p.alpha_deg * kDeg));
  r.Cpsi = r.psi_deg <= k.Cpsi_zero_below_psi_deg ? 0.0 : k.Cpsi_slope * r.psi_deg - k.Cpsi_offset;
  r.LTB3_raw = std::pow(p.L_m * p.T_m / (p.B_m * p.B_m), 3);
  r.LTB3_used = std::clamp(r.LTB3_raw, k.LTB3_min, k.LTB3_max);
  if (ice_class == IceClass::IA_super) {
    const double B = p.B_m, L = p.L_m, T = p.T_m;
    r.C1_N = k.f1 * B * p.L_par_m / (2 * T / B + 1) +
             (1 + 0.021 * p.phi1_deg) * (k.f2 * B + k.f3 * p.L_bow_m + k.f4 * B * p.L_bow_m);
    r.C2_N = (1 + 0.063 * p.phi1_deg) * (k.g1 + k.g2 * B) + k.g3 * (1 + 1.2 * T / B) * B * B / std::sqrt(L);
  }
  const double hh = r.H_F_m + r.H_M_m;
  r.bow_term_N = k.C3 * r.Cmu * hh * hh * (p.B_m + r.Cpsi * r.H_F_m);
  r.midbody_term_N = k.C4 * p.L_par_m * r.H_F_m * r.H_F_m;
  r.form_term_N = k.C5 * r.LTB3_used * p.A_wf_m2 / p.L_m;
  r.R_CH_N = r.C1_N + r.C2_N + r.bow_term_N + r.midbody_term_N + r.form_term_N;
  return r;
}

std::vector<std::string> fsicr_impossible_values(const FsicrParams& p,
                                                 const std::function<std::string(std::string_view field)>& name) {
  std::vector<std::string> out;
  const auto called = [&](std::string_view field, double v) {
    return fmt::format("{} {:g}", name ? name(field) : std::string(field), v);
  };
  const auto positive = [&](std::string_view field, double v, std::string_view what, bool zero_ok = false) {
    if (std::isfinite(v) && (v > 0 || (zero_ok && v == 0))) return true;
    out.push_back(fmt::format("{}: {} must be a finite number {} 0", called(field, v), what, zero_ok ? ">=" : ">"));
    return false;
  };
  const auto angle = [&](std::string_view field, double v, std::string_view what) {
    if (!(std::isfinite(v) && v > 0 && v <= 90))
      out.push_back(fmt::format("{}: {} must be an angle in (0, 90] deg", called(field, v), what));
  };
  const bool L = positive("L_m", p.L_m, "the length between perpendiculars");
  const bool B = positive("B_m", p.B_m, "the breadth");
  positive("T_m", p.T_m, "the draught");
  angle("alpha_deg", p.alpha_deg, "the waterline angle");
  angle("phi1_deg", p.phi1_deg, "the stem rake");
  angle("phi2_deg", p.phi2_deg, "the bow rake");
  const bool par = positive("L_par_m", p.L_par_m, "the parallel mid-body length", true);
  const bool bow = positive("L_bow_m", p.L_bow_m, "the bow length");
  const bool awf = positive("A_wf_m2", p.A_wf_m2, "the bow's waterline area");
  if (L && bow && p.L_bow_m > p.L_m)
    out.push_back(fmt::format("{}: the bow is longer than the ship ({})", called("L_bow_m", p.L_bow_m), called("L_m", p.L_m)));
  if (L && par && p.L_par_m > p.L_m)
    out.push_back(fmt::format("{}: the parallel mid-body is longer than the ship ({})", called("L_par_m", p.L_par_m),
                              called("L_m", p.L_m)));
  else if (L && bow && par && p.L_bow_m <= p.L_m && p.L_bow_m + p.L_par_m > p.L_m)
    out.push_back(fmt::format("{} + {} = {:g}: the bow and the parallel mid-body are longer than the ship ({})",
                              called("L_bow_m", p.L_bow_m), called("L_par_m", p.L_par_m), p.L_bow_m + p.L_par_m,
                              called("L_m", p.L_m)));
  if (B && bow && awf && p.A_wf_m2 > p.L_bow_m * p.B_m)
    out.push_back(fmt::format("{}: the bow's waterline area is larger than the {} x {} = {:g} rectangle that holds it",
                              called("A_wf_m2", p.A_wf_m2), called("L_bow_m", p.L_bow_m), called("B_m", p.B_m),
                              p.L_bow_m * p.B_m));
  return out;
}

std::vector<std::string> fsicr_validity_warnings(const FsicrParams& p) {
  std::vector<std::string> w;
  const auto check = [&](std::string_view name, double v, double lo, double hi) {
    if (!(v >= lo && v <= hi)) w.push_back(fmt::format("{} = {:.4g} outside the FSICR validity range [{}, {}]", name, v, lo, hi));
  };
  check("alpha_deg", p.alpha_deg, 15, 55);
  check("phi1_deg", p.phi1_deg, 25, 90);
  check("phi2_deg", p.phi2_deg, 10, 90);
  check("L_m", p.L_m, 65, 250);
  check("B_m", p.B_m, 11, 40);
  check("T_m", p.T_m, 4, 15);
  if (p.L_m > 0) {
    check("L_bow/L", p.L_bow_m / p.L_m, 0.15, 0.40);
    check("L_par/L", p.L_par_m / p.L_m, 0.25, 0.75);
    if (p.B_m > 0) check("A_wf/(L B)", p.A_wf_m2 / (p.L_m * p.B_m), 0.09, 0.27);
  }
  return w;
}

double fsicr_power_kW(double R_CH_N, double K_e, double propeller_diameter_m) {
  return K_e * std::pow(R_CH_N / 1000.0, 1.5) / propeller_diameter_m;
}

}  // namespace brash::post
