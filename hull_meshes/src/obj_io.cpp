// Wavefront OBJ reading for read_mesh (mesh.hpp). Every error names the file and the line.
#include <brash/error.hpp>
#include <brash/hull/mesh.hpp>

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "mesh_readers.hpp"

namespace brash::hull {

namespace fs = std::filesystem;

// Wavefront OBJ: `v x y z` and `f a b c ...` (a/b/c may carry /texture/normal indices, negative = from the end);
// polygons are split into a fan of triangles. Vertices at the same position are welded (exporters that split
// vertices by normal would otherwise leave the surface open).
Mesh read_obj(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(fmt::format("{}: cannot open the file", file.string()));
  std::vector<Eigen::Vector3d> raw;
  std::vector<int> weld;  // raw vertex -> welded index
  std::map<std::array<double, 3>, int> seen;
  Mesh mesh;
  std::string line;
  for (int line_no = 1; std::getline(in, line); ++line_no) {
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    const auto bad = [&](const std::string& what) {
      return InputError(fmt::format("{}:{}: {} ('{}')", file.string(), line_no, what, line));
    };
    if (tag == "v") {
      std::array<double, 3> p{};
      if (!(ls >> p[0] >> p[1] >> p[2])) throw bad("a vertex needs three numbers");
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) throw bad("vertex is not finite");
      raw.emplace_back(p[0], p[1], p[2]);
      const auto [it, inserted] = seen.emplace(p, static_cast<int>(mesh.vertices.size()));
      if (inserted) mesh.vertices.emplace_back(p[0], p[1], p[2]);
      weld.push_back(it->second);
    } else if (tag == "f") {
      std::vector<int> poly;
      for (std::string ref; ls >> ref;) {
        long idx = 0;
        try {
          idx = std::stol(ref.substr(0, ref.find('/')));
        } catch (const std::exception&) {
          throw bad(fmt::format("face index '{}' is not a number", ref));
        }
        const long n = static_cast<long>(raw.size());
        const long zero_based = idx > 0 ? idx - 1 : n + idx;
        if (idx == 0 || zero_based < 0 || zero_based >= n)
          throw bad(fmt::format("face index {} outside the {} vertices read so far", idx, n));
        poly.push_back(weld[static_cast<std::size_t>(zero_based)]);
      }
      if (poly.size() < 3) throw bad("a face needs at least three vertices");
      for (std::size_t k = 1; k + 1 < poly.size(); ++k) mesh.faces.push_back({poly[0], poly[k], poly[k + 1]});
    }
  }
  if (mesh.faces.empty()) throw InputError(fmt::format("{}: no faces ('f' lines) in the OBJ file", file.string()));
  return mesh;
}

}  // namespace brash::hull
