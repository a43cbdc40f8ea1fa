// The double-body panel flow of a hull mesh and the flow table's file (panel_flow.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <brash/hull/panel_flow.hpp>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <numbers>
#include <numeric>
#include <queue>

#include "brash/error.hpp"
#include "section.hpp"

namespace brash::hull {
namespace {

using core::Triangle;
using core::Vec3;

// A group of triangles, split first where it is large and bent: area x (1 + 4 (1 - cos of the widest normal
// angle)), so that the panels are finer round the stem, the bilge and the stern.
struct Group {
  std::vector<int> tri;
  double priority = 0;
  bool operator<(const Group& o) const { return priority < o.priority; }  // largest first in a priority queue
};

Group make_group(std::vector<int> tri, const std::vector<Triangle>& t) {
  Vec3 mean_n = Vec3::Zero();
  double area = 0;
  for (int k : tri) area += core::triangle_area(t[k]), mean_n += core::triangle_area(t[k]) * core::triangle_normal(t[k]);
  mean_n.normalize();
  double min_cos = 1.0;
  for (int k : tri) min_cos = std::min(min_cos, core::triangle_normal(t[k]).dot(mean_n));
  return {std::move(tri), area * (1.0 + 4.0 * (1.0 - min_cos))};
}

// split g in two (both non-empty; g has >= 2 triangles)
std::pair<Group, Group> split(const Group& g, const std::vector<Triangle>& t) {
  Vec3 mean_n = Vec3::Zero(), lo = Vec3::Constant(1e300), hi = -lo;
  for (int k : g.tri) {
    mean_n += core::triangle_area(t[k]) * core::triangle_normal(t[k]);
    const Vec3 c = core::triangle_centroid(t[k]);
    lo = lo.cwiseMin(c), hi = hi.cwiseMax(c);
  }
  mean_n.normalize();
  double min_cos = 1.0;
  for (int k : g.tri) min_cos = std::min(min_cos, core::triangle_normal(t[k]).dot(mean_n));
  // the key to split at the median of: a normal component where the normals differ by more than 45 degrees,
  // else the longest extent of the centroids
  const bool by_normal = min_cos < std::cos(std::numbers::pi / 4);
  Vec3 spread = hi - lo;
  if (by_normal) {
    Vec3 nlo = Vec3::Constant(2), nhi = -nlo;
    for (int k : g.tri)
      nlo = nlo.cwiseMin(core::triangle_normal(t[k])), nhi = nhi.cwiseMax(core::triangle_normal(t[k]));
    spread = nhi - nlo;
  }
  int axis = 0;
  spread.maxCoeff(&axis);
  auto key = [&](int k) {
    return by_normal ? core::triangle_normal(t[k])[axis] : core::triangle_centroid(t[k])[axis];
  };
  std::vector<int> order = g.tri;
  const auto mid = order.begin() + static_cast<std::ptrdiff_t>(order.size() / 2);
  std::nth_element(order.begin(), mid, order.end(), [&](int a, int b) { return key(a) < key(b); });
  return {make_group(std::vector<int>(order.begin(), mid), t), make_group(std::vector<int>(mid, order.end()), t)};
}

// the mesh's vertices' box
std::pair<Vec3, Vec3> box(const Mesh& mesh) {
  Vec3 lo = mesh.vertices.at(0), hi = lo;
  for (const auto& v : mesh.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  return {lo, hi};
}

}  // namespace

std::vector<Triangle> wetted_triangles(const Mesh& mesh, double water_z_m) {
  double volume = 0;  // the orientation: outward when the enclosed signed volume is positive
  for (const auto& f : mesh.faces)
    volume += mesh.vertices[f[0]].dot(mesh.vertices[f[1]].cross(mesh.vertices[f[2]])) / 6.0;
  const Vec3 shift(0, 0, water_z_m);
  std::vector<Triangle> out;
  for (const auto& f : mesh.faces) {
    std::array<Vec3, 3> p = {mesh.vertices[f[0]], mesh.vertices[f[1]], mesh.vertices[f[2]]};
    if (volume < 0) std::swap(p[1], p[2]);
    const std::vector<Eigen::Vector3d> poly = detail::clip_below(p[0], p[1], p[2], water_z_m);
    for (std::size_t k = 1; k + 1 < poly.size(); ++k) {  // a fan: the polygon keeps the triangle's order
      const Triangle t{{poly[0] - shift, poly[k] - shift, poly[k + 1] - shift}};
      const double size =
          std::max({(t.v[1] - t.v[0]).norm(), (t.v[2] - t.v[1]).norm(), (t.v[0] - t.v[2]).norm()});
      if (core::triangle_area(t) > 1e-10 * size * size) out.push_back(t);
    }
  }
  return out;
}

core::PanelBody group_panels(std::vector<Triangle> triangles, int max_panels) {
  if (triangles.empty()) throw InputError("panel flow: no triangles to make panels of");
  if (max_panels < 1) throw InputError("panel flow: max_panels must be >= 1");
  std::priority_queue<Group> queue;
  std::vector<int> all(triangles.size());
  std::iota(all.begin(), all.end(), 0);
  queue.push(make_group(std::move(all), triangles));
  std::vector<Group> done;  // single triangles: nothing to split
  while (!queue.empty() && queue.size() + done.size() < static_cast<std::size_t>(max_panels)) {
    Group g = queue.top();
    queue.pop();
    if (g.tri.size() == 1) {
      done.push_back(std::move(g));
      continue;
    }
    auto [a, b] = split(g, triangles);
    queue.push(std::move(a)), queue.push(std::move(b));
  }
  for (; !queue.empty(); queue.pop()) done.push_back(queue.top());
  core::PanelBody body;
  for (const Group& g : done) {
    for (int k : g.tri) body.triangles.push_back(triangles[k]);
    body.first.push_back(body.triangles.size());
  }
  return body;
}

core::PanelSolution panel_solution(const Mesh& mesh, double water_z_m, double ship_speed_m_s,
                                   const PanelFlowSettings& st) {
  if (mesh.vertices.empty()) throw InputError("panel flow: empty hull mesh");
  const auto [lo, hi] = box(mesh);
  if (!(water_z_m > lo.z()) || !(water_z_m < hi.z()))
    throw InputError(
        fmt::format("panel flow: the water level z = {} m of the hull's frame is not between its keel "
                    "(z = {} m) and its top (z = {} m)",
                    water_z_m, lo.z(), hi.z()));
  core::PanelBody body = group_panels(wetted_triangles(mesh, water_z_m), st.max_panels);
  body.mirror_z = true;
  return core::solve_panel_flow(std::move(body), Vec3(ship_speed_m_s, 0, 0), {.far_factor = st.far_factor});
}

core::FlowTable panel_flow(const Mesh& mesh, double water_z_m, double ship_speed_m_s,
                           const PanelFlowSettings& st) {
  if (!(st.table_spacing_fraction_of_draft > 0) || !(st.margin_fraction_of_breadth > 0))
    throw InputError("panel flow: the table needs a positive spacing and margin");
  return panel_flow(panel_solution(mesh, water_z_m, ship_speed_m_s, st), mesh, water_z_m, st);
}

core::FlowTable panel_flow(const core::PanelSolution& s, const Mesh& mesh, double water_z_m,
                           const PanelFlowSettings& st) {
  if (!(st.table_spacing_fraction_of_draft > 0) || !(st.margin_fraction_of_breadth > 0))
    throw InputError("panel flow: the table needs a positive spacing and margin");
  Vec3 lo = s.body.triangles[0].v[0], hi = lo;
  for (const Triangle& t : s.body.triangles)
    for (const Vec3& v : t.v) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  const double half_breadth = std::max(std::abs(lo.y()), std::abs(hi.y())), draft = -lo.z();
  const double margin = st.margin_fraction_of_breadth * 2.0 * half_breadth;
  const double spacing = st.table_spacing_fraction_of_draft * draft;
  // the box of thin_ship_flow's table (core::hull_flow_box): a margin around the wetted hull, y mirrored
  const auto [box_lo, box_hi] = core::hull_flow_box(lo, hi, half_breadth, margin, spacing);
  const TableGrid w = window_grid(box_lo, box_hi, spacing, st.window);
  const auto velocity = [&](const Vec3& p) { return core::panel_velocity(s, p); };
  return hull_table(velocity, mesh, water_z_m, draft, s.body_velocity_m_s, w, st.near_hull);
}

namespace {
// Version 2: per node u and Du/Dt, and the bricks of the cells along the hull. A file of version 1 (u only,
// no bricks) is still read: the table of a run started before, resumed.
constexpr char kMagic[] = "brash flow table 2\n";
constexpr char kMagicV1[] = "brash flow table 1\n";

template <class T>
void put(std::ofstream& out, const std::vector<T>& v) {
  const std::uint64_t n = v.size();
  out.write(reinterpret_cast<const char*>(&n), sizeof n);
  out.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(n * sizeof(T)));
}

template <class T>
bool get(std::ifstream& in, std::vector<T>& v) {
  std::uint64_t n = 0;
  if (!in.read(reinterpret_cast<char*>(&n), sizeof n) || n > (std::uint64_t{1} << 32)) return false;
  v.resize(n);
  return static_cast<bool>(in.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(n * sizeof(T))));
}

}  // namespace

void write_flow_table(const std::filesystem::path& file, const core::FlowTable& t, const std::string& key) {
  const std::filesystem::path tmp = file.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw InputError(fmt::format("{}: cannot write the flow table", tmp.string()));
    const std::uint64_t key_size = key.size();
    const std::int32_t nodes[3] = {t.nodes().x(), t.nodes().y(), t.nodes().z()};
    const double box[6] = {t.lo().x(), t.lo().y(), t.lo().z(), t.hi().x(), t.hi().y(), t.hi().z()};
    const char flags[2] = {t.mirror_y() ? char{1} : char{0}, t.has_acceleration() ? char{1} : char{0}};
    out.write(kMagic, sizeof kMagic - 1);
    out.write(reinterpret_cast<const char*>(&key_size), sizeof key_size).write(key.data(), key.size());
    out.write(reinterpret_cast<const char*>(box), sizeof box)
        .write(reinterpret_cast<const char*>(nodes), sizeof nodes);
    out.write(flags, sizeof flags);
    put(out, t.values());
    put(out, t.cell_bricks());
    std::vector<std::int64_t> bricks;  // offset, factor
    for (const auto& b : t.bricks()) bricks.push_back(static_cast<std::int64_t>(b.offset)), bricks.push_back(b.factor);
    put(out, bricks);
    put(out, t.brick_values());
    if (!out) throw InputError(fmt::format("{}: cannot write the flow table", tmp.string()));
  }
  std::filesystem::rename(tmp, file);
}

namespace {

// key: the key the file must have; nullptr: any
std::optional<core::FlowTable> read_table(const std::filesystem::path& file, const std::string* key) {
  std::ifstream in(file, std::ios::binary);
  char magic[sizeof kMagic - 1];
  std::uint64_t key_size = 0;
  if (!in.read(magic, sizeof magic)) return std::nullopt;
  const std::string m(magic, sizeof magic);
  const bool v1 = m == kMagicV1;
  if (!v1 && m != kMagic) return std::nullopt;
  if (!in.read(reinterpret_cast<char*>(&key_size), sizeof key_size) || key_size > (1u << 16)) return std::nullopt;
  std::string stored(key_size, '\0');
  if (!in.read(stored.data(), static_cast<std::streamsize>(key_size)) || (key && stored != *key))
    return std::nullopt;
  double box[6];
  std::int32_t nodes[3];
  char flags[2] = {0, 0};
  in.read(reinterpret_cast<char*>(box), sizeof box).read(reinterpret_cast<char*>(nodes), sizeof nodes);
  in.read(flags, v1 ? 1 : 2);
  std::vector<double> values, brick_values;
  std::vector<std::int32_t> cells;
  std::vector<std::int64_t> bricks;
  if (!in || !get(in, values)) return std::nullopt;
  if (!v1 && (!get(in, cells) || !get(in, bricks) || !get(in, brick_values) || bricks.size() % 2))
    return std::nullopt;
  try {
    core::FlowTable t = core::FlowTable::from_values(Vec3(box[0], box[1], box[2]), Vec3(box[3], box[4], box[5]),
                                                     Eigen::Vector3i(nodes[0], nodes[1], nodes[2]), flags[0] != 0,
                                                     std::move(values), flags[1] != 0);
    std::vector<core::FlowTable::Brick> b;
    for (std::size_t k = 0; k < bricks.size(); k += 2) {
      if (bricks[k] < 0) return std::nullopt;
      b.push_back({static_cast<std::uint64_t>(bricks[k]), static_cast<std::int32_t>(bricks[k + 1])});
    }
    if (!cells.empty() || !b.empty()) t.set_bricks(std::move(cells), std::move(b), std::move(brick_values));
    return t;
  } catch (const InputError&) {
    return std::nullopt;  // a damaged file: computed again
  }
}

}  // namespace

std::optional<core::FlowTable> read_flow_table(const std::filesystem::path& file, const std::string& key) {
  return read_table(file, &key);
}

std::optional<core::FlowTable> read_flow_table(const std::filesystem::path& file) { return read_table(file, nullptr); }

}  // namespace brash::hull
