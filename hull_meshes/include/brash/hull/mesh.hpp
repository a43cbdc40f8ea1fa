// Triangle meshes of hulls: the Mesh type, STL/OBJ/meshio reading, binary STL writing, topology checks,
// unit sanity checks and band clipping. Units are metres; hull frame x forward, y to port, z up.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace brash::hull {

// Indexed triangle mesh. Faces are counter-clockwise seen from outside (outward normals).
struct Mesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> faces;
};

// Reads a hull mesh. STL (binary or ASCII; binary is recognised by its exact size 84 + 50 n, so a binary
// file whose header starts with "solid" is still read right) and Wavefront OBJ (polygons split into fans of
// triangles) are read natively; any other extension is converted to a temporary STL by meshio
// (/usr/bin/python3). Identical vertices are welded.
// Throws brash::InputError naming the file and the problem (missing, empty, truncated, NaN, no faces).
Mesh read_mesh(const std::filesystem::path& file);

// Writes a binary STL (float32). The 80-byte header never starts with "solid" (LIGGGHTS and others would
// take the file for ASCII). Written to a temporary file in the same folder and renamed, so readers never
// see a half-written file. Throws brash::InputError if the file cannot be written.
void write_stl(const std::filesystem::path& file, const Mesh& mesh);

// Topology and orientation of a mesh.
struct MeshCheck {
  bool closed = false;         // every edge has exactly two faces
  bool manifold = false;       // no edge has more than two faces
  bool oriented = false;       // every directed edge is used at most once (neighbours agree)
  bool outward = false;        // closed, oriented and the enclosed signed volume is positive
  int boundary_edges = 0;      // edges with one face
  int nonmanifold_edges = 0;   // edges with three or more faces
  int misoriented_edges = 0;   // directed edges used twice
  int degenerate_faces = 0;    // zero area or repeated vertex index
  int vertices = 0, faces = 0, edges = 0;
  int euler_characteristic = 0;   // V - E + F; 2 for one closed genus-0 surface
  double signed_volume_m3 = 0;    // enclosed volume (meaningful when closed)
  double area_m2 = 0;
  Eigen::Vector3d min_m = Eigen::Vector3d::Zero(), max_m = Eigen::Vector3d::Zero();
  bool ok() const { return closed && manifold && oriented && outward && degenerate_faces == 0; }
};

MeshCheck check_mesh(const Mesh& mesh);

// Units sanity: compares the mesh extents with the expected draft and length. Returns a list of
// problems (empty when plausible), e.g. "hull is 7000 m long but --lpp is 7 m: the file looks like
// millimetres (scale by 0.001)". lpp_m <= 0 skips the length comparison.
std::vector<std::string> unit_problems(const Mesh& mesh, double draft_m, double lpp_m);

// Same check, but throws brash::InputError "<file>: <problems>" when there is any.
void require_plausible_units(const Mesh& mesh, const std::filesystem::path& file, double draft_m,
                             double lpp_m);

// Keeps the triangles with at least one point in [z_lo, z_hi] (an open strip; used to speed up DEM
// contact search). Unused vertices are dropped.
Mesh clip_band(const Mesh& mesh, double z_lo, double z_hi);

}  // namespace brash::hull
