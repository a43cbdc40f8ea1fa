// The source panel method (panel_flow.hpp) against exact potential flows: a triangle's field against direct
// quadrature, a sphere and a prolate spheroid moving through still water against their closed forms,
// convergence with the panel count, no flux through the body, and the double body against the whole body.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "brash/core/panel_flow.hpp"
#include "brash/error.hpp"
#include "panel_meshes.hpp"

namespace {

using brash::core::PanelSolution;
using brash::core::Triangle;
using brash::core::Vec3;
namespace core = brash::core;
namespace test = brash::test;

constexpr double kU = 0.5;  // body speed along +x, m/s

// The flow of a unit-density triangle by brute force: 4^levels sub-triangles, each a point source.
Vec3 quadrature(const Triangle& t, const Vec3& p, int levels) {
  if (levels == 0) {
    const Vec3 c = core::triangle_centroid(t), d = p - c;
    return d * core::triangle_area(t) / (4 * std::numbers::pi * std::pow(d.norm(), 3));
  }
  const Vec3 a = (t.v[0] + t.v[1]) / 2, b = (t.v[1] + t.v[2]) / 2, c = (t.v[2] + t.v[0]) / 2;
  return quadrature({{t.v[0], a, c}}, p, levels - 1) + quadrature({{a, t.v[1], b}}, p, levels - 1) +
         quadrature({{c, b, t.v[2]}}, p, levels - 1) + quadrature({{a, b, c}}, p, levels - 1);
}

TEST(PanelFlow, TriangleFieldMatchesQuadrature) {
  const Triangle t{{Vec3(0.1, -0.2, 0.05), Vec3(1.3, 0.1, -0.1), Vec3(0.4, 0.9, 0.2)}};
  for (const Vec3& p : {Vec3(0.5, 0.3, 0.8), Vec3(0.5, 0.3, -0.4), Vec3(2.0, -1.0, 0.3), Vec3(-0.3, 0.2, 0.1),
                        Vec3(0.6, 0.2, 0.25)}) {
    const Vec3 exact = core::triangle_source_velocity(t, p), brute = quadrature(t, p, 7);
    EXPECT_LT((exact - brute).norm(), 2e-3 * brute.norm()) << p.transpose();
  }
}

TEST(PanelFlow, NormalVelocityOnTheTriangleIsHalfTheDensity) {
  const Triangle t{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}};
  const Vec3 c = core::triangle_centroid(t), n = core::triangle_normal(t);
  EXPECT_NEAR(n.dot(core::triangle_source_velocity(t, c)), 0.5, 1e-12);              // on it: fluid side
  EXPECT_NEAR(n.dot(core::triangle_source_velocity(t, c + 1e-9 * n)), 0.5, 1e-6);    // just above
  EXPECT_NEAR(n.dot(core::triangle_source_velocity(t, c - 1e-9 * n)), -0.5, 1e-6);   // just below
  EXPECT_NEAR(n.dot(core::triangle_source_velocity(t, Vec3(2, 2, 0))), 0.0, 1e-12);  // in its plane, outside
}

// uniform motion U e_x of a sphere of radius a: phi = -U a^3 x / (2 r^3) (Lamb, Hydrodynamics, §92)
Vec3 sphere_exact(const Vec3& p, double a) {
  const double r = p.norm();
  return kU * a * a * a / 2 * (3 * p.x() * p / std::pow(r, 5) - Vec3::UnitX() / std::pow(r, 3));
}

// Prolate spheroid x^2/a^2 + (y^2 + z^2)/b^2 = 1 moving at U e_x (Lamb, Hydrodynamics, 6th ed., §114-115: an
// ellipsoid in translation): phi = K x I(lambda), I(lambda) = int_lambda^inf dt / ((a^2 + t)^(3/2) (b^2 +
// t)), lambda the confocal coordinate of the point, K = -a b^2 U / (2 - alpha0), alpha0 = a b^2 I(0). With s
// = sqrt(a^2 + lambda) and c = sqrt(a^2 - b^2): I = (2 / c^2) (ln((s + c) / (s - c)) / (2 c) - 1 / s).
struct Spheroid {
  double a, b;
  double c() const { return std::sqrt(a * a - b * b); }
  double integral(double lambda) const {
    const double s = std::sqrt(a * a + lambda), cc = c();
    return 2 / (cc * cc) * (std::log((s + cc) / (s - cc)) / (2 * cc) - 1 / s);
  }
  double alpha0() const { return a * b * b * integral(0.0); }
  Vec3 velocity(const Vec3& p) const {
    const double x2 = p.x() * p.x(), rho2 = p.y() * p.y() + p.z() * p.z();
    const double pb = a * a + b * b - x2 - rho2, qc = a * a * b * b - x2 * b * b - rho2 * a * a;
    const double lambda = (-pb + std::sqrt(pb * pb - 4 * qc)) / 2;  // the larger root
    const double k = -a * b * b * kU / (2 - alpha0());
    const double ea = a * a + lambda, eb = b * b + lambda;
    const double d_integral = -1 / (std::pow(ea, 1.5) * eb);
    const Vec3 g(p.x() / ea, p.y() / eb, p.z() / eb);
    const double norm = x2 / (ea * ea) + rho2 / (eb * eb);
    const Vec3 grad_lambda = 2 * g / norm;
    return k * integral(lambda) * Vec3::UnitX() + k * p.x() * d_integral * grad_lambda;
  }
};

struct Errors {
  double surface = 0, near = 0, off = 0;  // largest |u - exact| / U
};

// At points above the triangles' centroids, on the exact surface (scale 1 from the body's centre), near it
// (1.05) and off it (1.1 and 2): `project` puts a direction onto the exact surface.
template <class Exact, class Project>
Errors errors(const PanelSolution& s, const Exact& exact, const Project& project) {
  Errors e;
  auto err = [&](const Vec3& p) { return (core::panel_velocity(s, p) - exact(p)).norm() / kU; };
  for (std::size_t k = 0; k < s.body.triangles.size(); k += 2) {
    const Vec3 p = project(core::triangle_centroid(s.body.triangles[k]));
    e.surface = std::max(e.surface, err(p));
    e.near = std::max(e.near, err(1.05 * p));
    if (k % 6 == 0) e.off = std::max({e.off, err(1.1 * p), err(2.0 * p)});
  }
  return e;
}

Errors sphere_errors(const PanelSolution& s, double a) {
  return errors(
      s, [&](const Vec3& p) { return sphere_exact(p, a); },
      [&](const Vec3& p) { return Vec3(a * p.normalized()); });
}

TEST(PanelFlow, SphereMatchesClosedForm) {
  const double a = 0.3;
  const PanelSolution s = core::solve_panel_flow(
      test::one_panel_each(test::scaled(test::icosphere(3), Vec3::Constant(a))), kU * Vec3::UnitX());
  ASSERT_EQ(s.body.panels(), 1280u);
  const Errors e = sphere_errors(s, a);
  RecordProperty("surface", std::to_string(e.surface));
  RecordProperty("near", std::to_string(e.near));
  RecordProperty("off", std::to_string(e.off));
  EXPECT_LT(e.near, 0.01);
  EXPECT_LT(e.off, 0.01);
  EXPECT_LT(e.surface, 0.03);  // flat panels: the first-order error is largest on the surface itself
  // relative to the body: stagnation ahead, U (1 + a^3 / (2 r^3)) past the equator
  const double r = 1.05 * a, ratio = std::pow(a / r, 3);
  EXPECT_NEAR(core::panel_velocity(s, Vec3(r, 0, 0)).x() - kU, (ratio - 1) * kU, 0.01 * kU);
  EXPECT_NEAR(core::panel_velocity(s, Vec3(0, 0, -r)).x() - kU, -(1 + ratio / 2) * kU, 0.01 * kU);
}

TEST(PanelFlow, ProlateSpheroidMatchesLamb) {
  const Spheroid sp{0.6, 0.2};
  // Lamb §115: alpha0 = 2 (1 - e^2) / e^3 (ln((1 + e) / (1 - e)) / 2 - e)
  const double ecc = sp.c() / sp.a;
  EXPECT_NEAR(sp.alpha0(),
              2 * (1 - ecc * ecc) / std::pow(ecc, 3) * (0.5 * std::log((1 + ecc) / (1 - ecc)) - ecc), 1e-12);
  const PanelSolution s = core::solve_panel_flow(
      test::one_panel_each(test::scaled(test::icosphere(3), Vec3(sp.a, sp.b, sp.b))), kU * Vec3::UnitX());
  // onto the spheroid along the ray from its centre
  auto project = [&](const Vec3& p) {
    return Vec3(p / std::sqrt(std::pow(p.x() / sp.a, 2) + (p.y() * p.y() + p.z() * p.z()) / (sp.b * sp.b)));
  };
  const Errors e = errors(
      s, [&](const Vec3& p) { return sp.velocity(p); }, project);
  RecordProperty("surface", std::to_string(e.surface));
  RecordProperty("near", std::to_string(e.near));
  RecordProperty("off", std::to_string(e.off));
  EXPECT_LT(e.near, 0.01);
  EXPECT_LT(e.off, 0.01);
  // the icosphere's panels stretched 3:1: the first-order surface error is largest at the nose (7.4 % there)
  EXPECT_LT(e.surface, 0.08);
}

TEST(PanelFlow, ErrorFallsWithPanelCount) {
  Errors previous{1e9, 1e9, 1e9};
  for (int level : {1, 2, 3}) {
    const PanelSolution s =
        core::solve_panel_flow(test::one_panel_each(test::icosphere(level)), kU * Vec3::UnitX());
    const Errors e = sphere_errors(s, 1.0);
    const std::string n = std::to_string(s.body.panels());
    RecordProperty("surface_" + n, std::to_string(e.surface));
    RecordProperty("off_" + n, std::to_string(e.off));
    EXPECT_LT(e.surface, 0.6 * previous.surface) << n << " panels";
    EXPECT_LT(e.off, 0.6 * previous.off) << n << " panels";
    previous = e;
  }
}

TEST(PanelFlow, NoFluxThroughTheBody) {
  const PanelSolution s = core::solve_panel_flow(
      test::one_panel_each(test::scaled(test::icosphere(3), Vec3(0.5, 0.2, 0.15))), kU * Vec3(1, 0.3, -0.2));
  double total = 0;
  for (std::size_t j = 0; j < s.body.panels(); ++j) total += std::abs(s.sigma_m_s(j)) * s.area_m2[j];
  EXPECT_LT(std::abs(core::panel_net_flux(s)), 1e-3 * total);
  // the normal velocity relative to the body over each panel, from the field itself (which sums far panels as
  // point sources per point, the system per panel pair: they differ by O((size / distance)^2))
  for (std::size_t i = 0; i < s.body.panels(); ++i)
    EXPECT_NEAR(core::panel_relative_normal_velocity(s, i), 0.0, 1e-4 * kU);
}

std::vector<Triangle> lower_half(const std::vector<Triangle>& all) {
  std::vector<Triangle> lower;
  for (const Triangle& t : all)
    if (std::max({t.v[0].z(), t.v[1].z(), t.v[2].z()}) <= 1e-12) lower.push_back(t);
  return lower;
}

TEST(PanelFlow, DoubleBodyEqualsTheWholeBody) {
  // a UV sphere has a vertex ring on its equator: its lower half plus the mirror image is the same surface
  const std::vector<Triangle> lower = lower_half(test::uv_sphere(32, 16));
  std::vector<Triangle> all = lower;
  for (const Triangle& t : lower) all.push_back(core::mirrored_z(t));
  const PanelSolution whole = core::solve_panel_flow(test::one_panel_each(all), kU * Vec3::UnitX());
  const PanelSolution half = core::solve_panel_flow(test::one_panel_each(lower, true), kU * Vec3::UnitX());
  for (const Vec3& p : {Vec3(1.2, 0.1, -0.3), Vec3(0.0, 1.05, -0.01), Vec3(-2, 0.5, -1), Vec3(0.7, 0.8, 0)}) {
    const Vec3 uw = core::panel_velocity(whole, p), uh = core::panel_velocity(half, p);
    EXPECT_LT((uw - uh).norm(), 1e-9 * kU) << p.transpose();
  }
  // and no vertical flow at the lid
  EXPECT_NEAR(core::panel_velocity(half, Vec3(1.3, 0.4, 0)).z(), 0.0, 1e-12);
}

TEST(PanelFlow, TableMatchesTheDirectField) {
  const PanelSolution s = core::solve_panel_flow(
      test::one_panel_each(lower_half(test::uv_sphere(24, 12)), true), kU * Vec3::UnitX());
  const core::FlowTable t = core::panel_flow_table(s, Vec3(-3, 0, -3), Vec3(3, 3, 0.5), 0.1);
  for (const Vec3& p : {Vec3(1.5, 0.3, -0.2), Vec3(-1.2, -1.4, -0.7), Vec3(0.0, 2.0, -1.9)}) {
    const Vec3 d = core::panel_velocity(s, p);
    EXPECT_LT((t.at(p) - d).norm(), 0.01 * d.norm() + 1e-6) << p.transpose();
  }
}

TEST(PanelFlow, RefusesMalformedBodies) {
  brash::core::PanelBody empty;
  EXPECT_THROW(core::solve_panel_flow(empty, Vec3::UnitX()), brash::InputError);
  brash::core::PanelBody bad = test::one_panel_each(test::icosphere(0));
  bad.first.back() = 3;
  EXPECT_THROW(core::solve_panel_flow(bad, Vec3::UnitX()), brash::InputError);
}

}  // namespace
