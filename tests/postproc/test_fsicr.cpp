// FSICR R_CH: worked values of the Finnish-Swedish Ice Class Rules' channel resistance formula (Traficom's
// ice class regulations) and every clamping rule.
#include <gtest/gtest.h>

#include <cmath>

#include <brash/error.hpp>
#include <brash/post/fsicr.hpp>

using namespace brash::post;

namespace {

// The paper's Panamax as in fsicr.md (IA, L_BOW 40 m, A_wf 900 m^2).
brash::FsicrParams panamax(double alpha, double phi2, double L_par) {
  brash::FsicrParams p;
  p.L_m = 199.11;
  p.B_m = 32;
  p.T_m = 11.733;
  p.alpha_deg = alpha;
  p.phi1_deg = 90;
  p.phi2_deg = phi2;
  p.L_par_m = L_par;
  p.L_bow_m = 40;
  p.A_wf_m2 = 900;
  return p;
}

}  // namespace

TEST(Fsicr, WorkedValue990kN) {
  const auto r = fsicr_channel_resistance(panamax(25, 60, 100), IceClass::IA);
  EXPECT_NEAR(r.H_F_m, 5.917, 0.0005);
  EXPECT_NEAR(r.LTB3_raw, 11.87, 0.005);
  EXPECT_EQ(r.LTB3_used, r.LTB3_raw);  // not clamped
  EXPECT_EQ(std::lround(r.R_CH_N / 1000), 990);
  EXPECT_EQ(r.C1_N, 0);
  EXPECT_EQ(r.C2_N, 0);
}

// The terms by hand for the 990 kN value: bow C3 Cmu (H_F + H_M)^2 (B + Cpsi H_F), mid-body C4 L_par H_F^2, form
// C5 (L T / B^2)^3 A_wf / L; they add up to R_CH exactly.
TEST(Fsicr, TermsAddUpToRch) {
  const auto p = panamax(25, 60, 100);
  const auto r = fsicr_channel_resistance(p, IceClass::IA);
  const double HF = 0.26 + std::sqrt(32.0), hh = HF + 1.0;
  const double psi = std::atan(std::tan(60 * M_PI / 180) / std::sin(25 * M_PI / 180));
  const double Cmu = 0.15 * std::cos(60 * M_PI / 180) + std::sin(psi) * std::sin(25 * M_PI / 180);
  const double Cpsi = 0.047 * psi * 180 / M_PI - 2.115;
  EXPECT_NEAR(r.bow_term_N, 845 * Cmu * hh * hh * (32 + Cpsi * HF), 1e-6);
  EXPECT_NEAR(r.midbody_term_N, 42 * 100 * HF * HF, 1e-6);
  EXPECT_NEAR(r.form_term_N, 825 * std::pow(199.11 * 11.733 / (32.0 * 32.0), 3) * 900 / 199.11, 1e-6);
  EXPECT_EQ(r.C1_N + r.C2_N + r.bow_term_N + r.midbody_term_N + r.form_term_N, r.R_CH_N);
  EXPECT_GT(r.bow_term_N, r.midbody_term_N);
}

// A measured H_F in place of the rule's: every term that holds H_F follows it (the form term does not).
TEST(Fsicr, MeasuredHfReplacesTheRulesInEveryTerm) {
  const auto p = panamax(25, 60, 100);
  const auto rule = fsicr_channel_resistance(p, IceClass::IA);
  const auto m = fsicr_channel_resistance(p, IceClass::IA, {}, std::nullopt, 1.3);
  EXPECT_EQ(m.H_F_m, 1.3);
  EXPECT_NEAR(m.bow_term_N, rule.bow_term_N * (2.3 * 2.3 * (32 + rule.Cpsi * 1.3)) /
                                ((rule.H_F_m + 1) * (rule.H_F_m + 1) * (32 + rule.Cpsi * rule.H_F_m)),
              1e-6);
  EXPECT_NEAR(m.midbody_term_N, 42 * 100 * 1.3 * 1.3, 1e-9);
  EXPECT_EQ(m.form_term_N, rule.form_term_N);
  EXPECT_EQ(m.bow_term_N + m.midbody_term_N + m.form_term_N, m.R_CH_N);
}

TEST(Fsicr, WorkedValue992kN) {
  const auto r = fsicr_channel_resistance(panamax(30, 45, 80), IceClass::IA);
  EXPECT_NEAR(r.H_F_m, 5.917, 0.0005);
  EXPECT_EQ(std::lround(r.R_CH_N / 1000), 992);
  EXPECT_NEAR(r.psi_deg, 63.435, 0.001);  // atan(1 / sin 30 deg) = atan(2)
}

TEST(Fsicr, IceClassSetsHM) {
  EXPECT_EQ(brash::h_m_for_ice_class(parse_ice_class("IA_super")), 1.0);
  EXPECT_EQ(brash::h_m_for_ice_class(parse_ice_class("IA")), 1.0);
  EXPECT_EQ(brash::h_m_for_ice_class(parse_ice_class("IB")), 0.8);
  EXPECT_EQ(brash::h_m_for_ice_class(parse_ice_class("ic")), 0.6);
  EXPECT_THROW(parse_ice_class("PC7"), brash::InputError);
  const auto r = fsicr_channel_resistance(panamax(25, 60, 100), IceClass::IB);
  EXPECT_NEAR(r.H_F_m, 0.26 + std::sqrt(0.8 * 32), 1e-12);
  EXPECT_LT(r.R_CH_N, 990e3);
}

TEST(Fsicr, CmuClampedAt045) {
  // alpha 15, phi2 20: 0.15 cos20 + sin(psi) sin15 = 0.141 + 0.2496 = 0.390 < 0.45
  const auto r = fsicr_channel_resistance(panamax(15, 20, 100), IceClass::IA);
  EXPECT_NEAR(r.psi_deg, std::atan(std::tan(20 * M_PI / 180) / std::sin(15 * M_PI / 180)) * 180 / M_PI, 1e-9);
  EXPECT_EQ(r.Cmu, 0.45);
  // Unclamped case: formula value.
  const auto u = fsicr_channel_resistance(panamax(30, 45, 80), IceClass::IA);
  EXPECT_NEAR(u.Cmu, 0.15 * std::cos(M_PI / 4) + std::sin(std::atan(2.0)) * 0.5, 1e-12);
}

TEST(Fsicr, CpsiZeroAtOrBelow45Deg) {
  // alpha 90 -> psi = phi2 exactly.
  auto below = fsicr_channel_resistance(panamax(90, 40, 100), IceClass::IA);
  EXPECT_NEAR(below.psi_deg, 40, 1e-9);
  EXPECT_EQ(below.Cpsi, 0);
  auto at = fsicr_channel_resistance(panamax(90, 45, 100), IceClass::IA);
  EXPECT_EQ(at.Cpsi, 0);
  auto above = fsicr_channel_resistance(panamax(90, 50, 100), IceClass::IA);
  EXPECT_NEAR(above.Cpsi, 0.047 * 50 - 2.115, 1e-9);  // 0.235
  // phi2 = 90 (vertical): psi = 90, Cpsi = 2.115
  EXPECT_NEAR(fsicr_psi_deg(25, 90), 90, 1e-9);
}

TEST(Fsicr, LTB2CubedClampedTo5And20) {
  auto p = panamax(25, 60, 100);
  p.T_m = 6;  // (199.11*6/1024)^3 = 1.59 -> 5
  const auto lo = fsicr_channel_resistance(p, IceClass::IA);
  EXPECT_NEAR(lo.LTB3_raw, std::pow(199.11 * 6 / 1024, 3), 1e-9);
  EXPECT_EQ(lo.LTB3_used, 5.0);
  p.T_m = 15;  // (199.11*15/1024)^3 = 24.9 -> 20
  const auto hi = fsicr_channel_resistance(p, IceClass::IA);
  EXPECT_GT(hi.LTB3_raw, 20);
  EXPECT_EQ(hi.LTB3_used, 20.0);
  // The term enters linearly: C5 * 20 * A_wf / L.
  const auto base = fsicr_channel_resistance(panamax(25, 60, 100), IceClass::IA);
  EXPECT_GT(hi.R_CH_N, base.R_CH_N);
}

TEST(Fsicr, IASuperAddsC1C2) {
  const auto p = panamax(25, 60, 100);
  const auto ia = fsicr_channel_resistance(p, IceClass::IA);
  const auto ias = fsicr_channel_resistance(p, IceClass::IA_super);
  const double B = 32, T = 11.733, L = 199.11;
  const double C1 = 23 * B * 100 / (2 * T / B + 1) + (1 + 0.021 * 90) * (45.8 * B + 14.7 * 40 + 29 * B * 40);
  const double C2 = (1 + 0.063 * 90) * (1530 + 170 * B) + 400 * (1 + 1.2 * T / B) * B * B / std::sqrt(L);
  EXPECT_NEAR(ias.C1_N, C1, 1e-6);
  EXPECT_NEAR(ias.C2_N, C2, 1e-6);
  EXPECT_NEAR(ias.R_CH_N - ia.R_CH_N, C1 + C2, 1e-6);
}

TEST(Fsicr, ValidityWarnings) {
  EXPECT_TRUE(fsicr_validity_warnings(panamax(25, 60, 100)).empty());
  auto p = panamax(10, 60, 100);  // alpha below 15
  p.L_m = 7.0;                     // model scale: L, B, T out of range
  p.B_m = 1.125;
  p.T_m = 0.4125;
  const auto w = fsicr_validity_warnings(p);
  EXPECT_GE(w.size(), 4u);
  EXPECT_NE(w.front().find("alpha_deg"), std::string::npos);
}

TEST(Fsicr, PowerFormula) {
  EXPECT_NEAR(fsicr_power_kW(1e6, 2.03, 7.0), 2.03 * std::pow(1000.0, 1.5) / 7.0, 1e-9);
}

// Geometry no hull has: each problem named by its parameter and value, through the caller's names.
TEST(Fsicr, ImpossibleValuesAreNamed) {
  EXPECT_TRUE(fsicr_impossible_values(panamax(25, 60, 100)).empty());
  auto p = panamax(25, 60, 0);  // no parallel mid-body: possible
  EXPECT_TRUE(fsicr_impossible_values(p).empty());
  const auto one = [](brash::FsicrParams q) {
    const auto m = fsicr_impossible_values(q);
    EXPECT_EQ(m.size(), 1u);
    return m.empty() ? std::string() : m.front();
  };
  p = panamax(25, 60, 100);
  p.B_m = -32;
  EXPECT_EQ(one(p), "B_m -32: the breadth must be a finite number > 0");
  p = panamax(25, 60, 100);
  p.T_m = std::nan("");
  EXPECT_EQ(one(p), "T_m nan: the draught must be a finite number > 0");
  p = panamax(95, 60, 100);
  EXPECT_EQ(one(p), "alpha_deg 95: the waterline angle must be an angle in (0, 90] deg");
  p = panamax(25, 0, 100);
  EXPECT_EQ(one(p), "phi2_deg 0: the bow rake must be an angle in (0, 90] deg");
  p = panamax(25, 60, 100);
  p.L_bow_m = 250;
  EXPECT_EQ(one(p), "L_bow_m 250: the bow is longer than the ship (L_m 199.11)");
  p = panamax(25, 60, 170);
  EXPECT_EQ(one(p), "L_bow_m 40 + L_par_m 170 = 210: the bow and the parallel mid-body are longer than the ship (L_m 199.11)");
  p = panamax(25, 60, 100);
  p.A_wf_m2 = 1300;  // > 40 x 32
  EXPECT_EQ(one(p), "A_wf_m2 1300: the bow's waterline area is larger than the L_bow_m 40 x B_m 32 = 1280 rectangle that holds it");
  // Every problem at once, in the caller's names.
  p = panamax(120, 60, -1);
  p.L_m = 0;
  const auto all = fsicr_impossible_values(p, [](std::string_view f) { return "<" + std::string(f) + ">"; });
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[0].rfind("<L_m> 0: ", 0), 0u) << all[0];
  EXPECT_EQ(all[1].rfind("<alpha_deg> 120: ", 0), 0u) << all[1];
  EXPECT_EQ(all[2].rfind("<L_par_m> -1: ", 0), 0u) << all[2];
  // Outside the validity range only: a warning, not impossible.
  p = panamax(10, 60, 100);
  EXPECT_TRUE(fsicr_impossible_values(p).empty());
  EXPECT_FALSE(fsicr_validity_warnings(p).empty());
}
