// Mesh topology checks (closed, manifold, oriented, outward), unit sanity and band clipping.
#include <brash/error.hpp>
#include <brash/hull/mesh.hpp>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace brash::hull {

MeshCheck check_mesh(const Mesh& mesh) {
  MeshCheck c;
  c.vertices = static_cast<int>(mesh.vertices.size());
  c.faces = static_cast<int>(mesh.faces.size());
  std::map<std::pair<int, int>, int> directed;  // (from, to) -> uses
  for (const auto& f : mesh.faces) {
    const Eigen::Vector3d& a = mesh.vertices.at(f[0]);
    const Eigen::Vector3d& b = mesh.vertices.at(f[1]);
    const Eigen::Vector3d& d = mesh.vertices.at(f[2]);
    const Eigen::Vector3d n = (b - a).cross(d - a);
    c.area_m2 += 0.5 * n.norm();
    c.signed_volume_m3 += a.dot(b.cross(d)) / 6.0;
    if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2] || n.norm() == 0.0) ++c.degenerate_faces;
    for (int k = 0; k < 3; ++k) ++directed[{f[k], f[(k + 1) % 3]}];
  }
  std::map<std::pair<int, int>, int> undirected;
  for (const auto& [e, n] : directed) {
    undirected[{std::min(e.first, e.second), std::max(e.first, e.second)}] += n;
    if (n > 1) c.misoriented_edges += n - 1;
  }
  for (const auto& [e, n] : undirected) {
    if (n == 1) ++c.boundary_edges;
    if (n > 2) ++c.nonmanifold_edges;
  }
  c.edges = static_cast<int>(undirected.size());
  c.euler_characteristic = c.vertices - c.edges + c.faces;
  c.closed = c.faces > 0 && c.boundary_edges == 0 && c.nonmanifold_edges == 0;
  c.manifold = c.nonmanifold_edges == 0;
  c.oriented = c.misoriented_edges == 0;
  c.outward = c.closed && c.oriented && c.signed_volume_m3 > 0;
  if (!mesh.vertices.empty()) {
    c.min_m = c.max_m = mesh.vertices.front();
    for (const auto& v : mesh.vertices) {
      c.min_m = c.min_m.cwiseMin(v);
      c.max_m = c.max_m.cwiseMax(v);
    }
  }
  return c;
}

std::vector<std::string> unit_problems(const Mesh& mesh, double draft_m, double lpp_m) {
  std::vector<std::string> out;
  if (mesh.vertices.empty()) return {"mesh has no vertices"};
  const MeshCheck c = check_mesh(mesh);
  const Eigen::Vector3d size = c.max_m - c.min_m;
  const double length = size.x();
  // The largest ships are ~460 m long; model hulls are rarely below 0.2 m.
  if (length > 600.0)
    out.push_back(fmt::format("hull is {:.6g} m long, longer than any ship: the file is probably in millimetres "
                              "(scale by 0.001)", length));
  if (length > 0 && length < 0.05)
    out.push_back(fmt::format("hull is only {:.6g} m long: wrong units (kilometres?)", length));
  if (lpp_m > 0 && length > 0) {
    const double ratio = length / lpp_m;
    if (ratio > 2.0 || ratio < 0.5) {
      std::string hint;
      if (std::abs(std::log10(ratio) - 3.0) < 0.3) hint = ": the file looks like millimetres (scale by 0.001)";
      else if (std::abs(std::log10(ratio) - 2.0) < 0.3) hint = ": the file looks like centimetres (scale by 0.01)";
      else if (std::abs(std::log10(ratio) + 3.0) < 0.3) hint = ": the file looks like kilometres (scale by 1000)";
      out.push_back(fmt::format("hull is {:.6g} m long but Lpp is {:.6g} m{}", length, lpp_m, hint));
    }
  }
  if (draft_m <= 0) out.push_back(fmt::format("draft {:.6g} m is not positive", draft_m));
  if (c.min_m.z() > draft_m)
    out.push_back(fmt::format("the keel is at z = {:.6g} m, above the waterline z = {:.6g} m (keel must be at z = 0)",
                              c.min_m.z(), draft_m));
  if (std::abs(c.min_m.z()) > 0.05 * std::max(size.z(), 1e-12))
    out.push_back(fmt::format("the keel is at z = {:.6g} m, not at z = 0 (hull frame: keel at z = 0)", c.min_m.z()));
  if (c.max_m.z() < draft_m)
    out.push_back(fmt::format("the hull top z = {:.6g} m is below the waterline z = {:.6g} m", c.max_m.z(), draft_m));
  return out;
}

void require_plausible_units(const Mesh& mesh, const std::filesystem::path& file, double draft_m, double lpp_m) {
  const auto problems = unit_problems(mesh, draft_m, lpp_m);
  if (!problems.empty()) throw InputError(fmt::format("{}: {}", file.string(), fmt::join(problems, "; ")));
}

Mesh clip_band(const Mesh& mesh, double z_lo, double z_hi) {
  Mesh out;
  std::vector<int> remap(mesh.vertices.size(), -1);
  for (const auto& f : mesh.faces) {
    double lo = mesh.vertices[f[0]].z(), hi = lo;
    for (int k = 1; k < 3; ++k) {
      lo = std::min(lo, mesh.vertices[f[k]].z());
      hi = std::max(hi, mesh.vertices[f[k]].z());
    }
    if (hi < z_lo || lo > z_hi) continue;
    std::array<int, 3> g{};
    for (int k = 0; k < 3; ++k) {
      int& r = remap[f[k]];
      if (r < 0) {
        r = static_cast<int>(out.vertices.size());
        out.vertices.push_back(mesh.vertices[f[k]]);
      }
      g[k] = r;
    }
    out.faces.push_back(g);
  }
  return out;
}

}  // namespace brash::hull
