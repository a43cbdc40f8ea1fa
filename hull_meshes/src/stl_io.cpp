// STL reading (binary and ASCII, decided by file size) and writing (binary, atomic), the dispatch by extension
// (OBJ: obj_io.cpp) and the meshio fallback for other formats. Every error names the file.
#include <brash/error.hpp>
#include <brash/hull/mesh.hpp>

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <atomic>
#include <map>
#include <sstream>
#include <unistd.h>

#include "mesh_readers.hpp"

namespace brash::hull {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const fs::path& file, const std::string& what) {
  throw InputError(fmt::format("{}: {}", file.string(), what));
}

std::string read_all(const fs::path& file) {
  if (fs::is_directory(file)) fail(file, "is a directory, not a mesh file");
  std::ifstream in(file, std::ios::binary);
  if (!in) fail(file, "cannot open the file (missing or unreadable)");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Welds identical coordinates into one vertex (exact match, as STL stores each corner separately).
class Welder {
 public:
  explicit Welder(Mesh& mesh) : mesh_(mesh) {}
  int index(const Eigen::Vector3d& p) {
    auto key = std::array<double, 3>{p.x(), p.y(), p.z()};
    auto [it, inserted] = ids_.try_emplace(key, static_cast<int>(mesh_.vertices.size()));
    if (inserted) mesh_.vertices.push_back(p);
    return it->second;
  }

 private:
  Mesh& mesh_;
  std::map<std::array<double, 3>, int> ids_;
};

void add_facet(const fs::path& file, Mesh& mesh, Welder& welder, const std::array<Eigen::Vector3d, 3>& p,
               std::size_t facet) {
  for (int k = 0; k < 3; ++k)
    if (!p[k].allFinite())
      fail(file, fmt::format("vertex {} of facet {} is not a finite number (NaN or inf)", k + 1, facet + 1));
  mesh.faces.push_back({welder.index(p[0]), welder.index(p[1]), welder.index(p[2])});
}

Mesh parse_binary(const fs::path& file, const std::string& data, std::uint32_t n) {
  Mesh mesh;
  Welder welder(mesh);
  mesh.faces.reserve(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    const char* rec = data.data() + 84 + 50 * std::size_t{i};
    std::array<Eigen::Vector3d, 3> p;
    for (int k = 0; k < 3; ++k) {
      float xyz[3];
      std::memcpy(xyz, rec + 12 + 12 * k, sizeof xyz);
      p[k] = Eigen::Vector3d(xyz[0], xyz[1], xyz[2]);
    }
    add_facet(file, mesh, welder, p, i);
  }
  return mesh;
}

Mesh parse_ascii(const fs::path& file, const std::string& data) {
  Mesh mesh;
  Welder welder(mesh);
  std::istringstream in(data);
  std::string word;
  std::array<Eigen::Vector3d, 3> p;
  int corner = 0;
  std::size_t facet = 0;
  while (in >> word) {
    if (word == "vertex") {
      if (corner == 3) fail(file, fmt::format("ASCII STL facet {} has more than 3 vertices", facet + 1));
      std::string sx, sy, sz;
      if (!(in >> sx >> sy >> sz)) fail(file, fmt::format("ASCII STL facet {}: incomplete vertex", facet + 1));
      try {
        p[corner] = Eigen::Vector3d(std::stod(sx), std::stod(sy), std::stod(sz));
      } catch (const std::exception&) {
        fail(file, fmt::format("ASCII STL facet {}: vertex '{} {} {}' is not numeric", facet + 1, sx, sy, sz));
      }
      ++corner;
    } else if (word == "endfacet") {
      if (corner != 3) fail(file, fmt::format("ASCII STL facet {} has {} vertices, not 3", facet + 1, corner));
      add_facet(file, mesh, welder, p, facet);
      corner = 0;
      ++facet;
    }
  }
  if (corner != 0) fail(file, "ASCII STL ends inside a facet (truncated file)");
  return mesh;
}

Mesh read_stl(const fs::path& file) {
  const std::string data = read_all(file);
  if (data.empty()) fail(file, "file is empty");
  if (data.size() >= 84) {
    std::uint32_t n = 0;
    std::memcpy(&n, data.data() + 80, 4);
    if (data.size() == 84 + 50 * std::uint64_t{n}) return parse_binary(file, data, n);
  }
  const auto first = data.find_first_not_of(" \t\r\n");
  const bool says_solid = first != std::string::npos && data.compare(first, 5, "solid") == 0;
  if (!says_solid) {
    if (data.size() < 84) fail(file, fmt::format("truncated binary STL: {} bytes, shorter than the 84-byte header", data.size()));
    std::uint32_t n = 0;
    std::memcpy(&n, data.data() + 80, 4);
    fail(file, fmt::format("truncated or corrupt binary STL: header says {} facets ({} bytes) but the file has {} bytes",
                           n, 84 + 50 * std::uint64_t{n}, data.size()));
  }
  if (data.find("endsolid") == std::string::npos)
    fail(file, "starts with 'solid' but is neither a binary STL of matching size nor a complete ASCII STL "
               "(no 'endsolid': truncated?)");
  return parse_ascii(file, data);
}

std::string lower_ext(const fs::path& file) {
  std::string e = file.extension().string();
  for (auto& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

// Formats other than STL and OBJ go through meshio in /usr/bin/python3: say plainly when that interpreter or its
// meshio is missing instead of passing on a Python traceback.
void require_meshio(const fs::path& file) {
  const char* python = "/usr/bin/python3";
  const auto hint = fmt::format("convert the hull to STL or OBJ, or install the Debian package python3-meshio");
  if (::access(python, X_OK) != 0)
    fail(file, fmt::format("{} files are read through meshio, but {} is missing ({})", lower_ext(file), python, hint));
  const std::string cmd = fmt::format("{} -c 'import meshio' >/dev/null 2>&1", python);
  if (std::system(cmd.c_str()) != 0)
    fail(file, fmt::format("{} files are read through meshio, but {} cannot import meshio ({})", lower_ext(file),
                           python, hint));
}

// Other formats: meshio writes a binary STL of the triangles (quads are split) into a temp file.
Mesh read_with_meshio(const fs::path& file) {
  static std::atomic<int> counter{0};
  if (!fs::exists(file)) fail(file, "cannot open the file (missing)");
  if (fs::is_directory(file)) fail(file, "is a directory, not a mesh file");
  require_meshio(file);
  const fs::path tmp = fs::temp_directory_path() / fmt::format("brash_hull_{}_{}.stl", ::getpid(), counter++);
  const std::string py =
      "import sys, meshio, numpy as np\n"
      "m = meshio.read(sys.argv[1])\n"
      "tris = []\n"
      "for c in m.cells:\n"
      "    d = np.asarray(c.data)\n"
      "    if c.type == 'triangle': tris.append(d)\n"
      "    elif c.type == 'quad': tris += [d[:, [0, 1, 2]], d[:, [0, 2, 3]]]\n"
      "if not tris: sys.exit('no triangle or quad cells')\n"
      "meshio.write(sys.argv[2], meshio.Mesh(m.points[:, :3], [('triangle', np.vstack(tris))]), file_format='stl', binary=True)\n";
  const fs::path script = fs::path(tmp).replace_extension(".py");
  {
    std::ofstream out(script);
    out << py;
  }
  const std::string cmd = fmt::format("/usr/bin/python3 '{}' '{}' '{}' 2>'{}.err'", script.string(), file.string(),
                                      tmp.string(), tmp.string());
  const int rc = std::system(cmd.c_str());
  std::string err;
  if (rc != 0) {
    std::ifstream e(tmp.string() + ".err");
    std::ostringstream ss;
    ss << e.rdbuf();
    err = ss.str();
  }
  std::error_code ec;
  fs::remove(script, ec);
  fs::remove(tmp.string() + ".err", ec);
  if (rc != 0) {
    fs::remove(tmp, ec);
    const auto last = err.find_last_not_of("\n");
    const auto line = err.substr(err.rfind('\n', last == std::string::npos ? 0 : last) + 1);
    fail(file, fmt::format("meshio could not read it ({})", line));
  }
  try {
    Mesh mesh = read_stl(tmp);
    fs::remove(tmp, ec);
    return mesh;
  } catch (const InputError& e) {
    fs::remove(tmp, ec);
    fail(file, fmt::format("after meshio conversion: {}", e.what()));
  }
}

}  // namespace

Mesh read_mesh(const fs::path& file) {
  const std::string ext = lower_ext(file);
  Mesh mesh = ext == ".stl" ? read_stl(file) : ext == ".obj" ? read_obj(file) : read_with_meshio(file);
  if (mesh.faces.empty()) fail(file, "no triangles in the mesh");
  return mesh;
}

void write_stl(const fs::path& file, const Mesh& mesh) {
  const fs::path tmp = fs::path(file).concat(fmt::format(".tmp{}", ::getpid()));
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) fail(file, "cannot create the output file");
    char header[80] = {};
    // ended by a line end: LIGGGHTS reads an STL's first line as text (up to the first '\n', quotes paired) to
    // see that it is not "solid ...", and the binary data after the header may hold an unpaired quote
    std::snprintf(header, sizeof header, "brash binary STL, metres, %zu triangles\n", mesh.faces.size());
    out.write(header, 80);
    const auto n = static_cast<std::uint32_t>(mesh.faces.size());
    out.write(reinterpret_cast<const char*>(&n), 4);
    for (const auto& f : mesh.faces) {
      const Eigen::Vector3d& a = mesh.vertices.at(f[0]);
      const Eigen::Vector3d& b = mesh.vertices.at(f[1]);
      const Eigen::Vector3d& c = mesh.vertices.at(f[2]);
      Eigen::Vector3d nrm = (b - a).cross(c - a);
      if (nrm.norm() > 0) nrm.normalize();
      float rec[12];
      for (int k = 0; k < 3; ++k) {
        rec[k] = static_cast<float>(nrm[k]);
        rec[3 + k] = static_cast<float>(a[k]);
        rec[6 + k] = static_cast<float>(b[k]);
        rec[9 + k] = static_cast<float>(c[k]);
      }
      out.write(reinterpret_cast<const char*>(rec), sizeof rec);
      const std::uint16_t attr = 0;
      out.write(reinterpret_cast<const char*>(&attr), 2);
    }
    if (!out) fail(file, "write failed (disk full?)");
  }
  std::error_code ec;
  fs::rename(tmp, file, ec);
  if (ec) {
    fs::remove(tmp, ec);
    fail(file, "cannot rename the temporary file into place");
  }
}

}  // namespace brash::hull
