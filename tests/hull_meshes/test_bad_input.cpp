// Bad hull input is rejected or reported with a message naming the file and the problem.
#include <brash/error.hpp>
#include <brash/hull/mesh.hpp>
#include <gtest/gtest.h>

#include "simple_hulls.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <unistd.h>

namespace brash::hull {
namespace {

namespace fs = std::filesystem;

fs::path temp(const std::string& name) {
  return fs::temp_directory_path() / ("brash_bad_" + std::to_string(::getpid()) + "_" + name);
}

void write_bytes(const fs::path& f, const std::string& bytes) {
  std::ofstream(f, std::ios::binary) << bytes;
}

std::string read_bytes(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// Expects read_mesh to throw InputError whose message holds the file name and `what`.
void expect_error(const fs::path& f, const std::string& what) {
  try {
    (void)read_mesh(f);
    ADD_FAILURE() << "no error for " << f;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(f.string()), std::string::npos) << msg;
    EXPECT_NE(msg.find(what), std::string::npos) << msg;
  }
}

TEST(BadInput, OpenMeshIsNotClosed) {
  Mesh m = test::box(2, 1, 1);
  m.faces.pop_back();  // a hole: the removed triangle's three edges now have one face each
  const MeshCheck c = check_mesh(m);
  EXPECT_FALSE(c.closed);
  EXPECT_FALSE(c.outward);
  EXPECT_FALSE(c.ok());
  EXPECT_EQ(c.boundary_edges, 3);
}

TEST(BadInput, FlippedFaceIsNotOriented) {
  Mesh m = test::box(2, 1, 1);
  std::swap(m.faces[0][1], m.faces[0][2]);
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.closed);
  EXPECT_FALSE(c.oriented);
  EXPECT_EQ(c.misoriented_edges, 3);
}

TEST(BadInput, InwardMeshIsNotOutward) {
  Mesh m = test::box(2, 1, 1);
  for (auto& f : m.faces) std::swap(f[1], f[2]);
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.closed && c.oriented);
  EXPECT_FALSE(c.outward);
  EXPECT_NEAR(c.signed_volume_m3, -2.0, 1e-12);
}

TEST(BadInput, NanVertexInBinaryStl) {
  const auto f = temp("nan.stl");
  write_stl(f, test::box(2, 1, 1));
  std::string b = read_bytes(f);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(b.data() + 84 + 50 * 4 + 12 + 12 * 1 + 4, &nan, 4);  // facet 5, vertex 2, y
  write_bytes(f, b);
  expect_error(f, "vertex 2 of facet 5 is not a finite number");
  fs::remove(f);
}

TEST(BadInput, NanVertexInAsciiStl) {
  const auto f = temp("nan_ascii.stl");
  write_bytes(f, "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 nan 0\n"
                 "endloop\nendfacet\nendsolid x\n");
  expect_error(f, "vertex 3 of facet 1 is not a finite number");
  fs::remove(f);
}

TEST(GoodInput, AsciiStl) {
  const auto f = temp("tetra_ascii.stl");
  write_bytes(f, "solid t\n"
                 "facet normal 0 0 -1\n outer loop\n  vertex 0 0 0\n  vertex 0 1 0\n  vertex 1 0 0\n endloop\nendfacet\n"
                 "facet normal 0 -1 0\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 0 1\n endloop\nendfacet\n"
                 "facet normal -1 0 0\n outer loop\n  vertex 0 0 0\n  vertex 0 0 1\n  vertex 0 1 0\n endloop\nendfacet\n"
                 "facet normal 1 1 1\n outer loop\n  vertex 1 0 0\n  vertex 0 1 0\n  vertex 0 0 1\n endloop\nendfacet\n"
                 "endsolid t\n");
  const Mesh m = read_mesh(f);
  EXPECT_EQ(m.vertices.size(), 4u);
  EXPECT_EQ(m.faces.size(), 4u);
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.ok());
  EXPECT_NEAR(c.signed_volume_m3, 1.0 / 6.0, 1e-15);
  fs::remove(f);
}

TEST(BadInput, TruncatedBinaryStl) {
  const auto f = temp("truncated.stl");
  write_stl(f, test::box(2, 1, 1));
  std::string b = read_bytes(f);
  b.resize(b.size() - 20);
  write_bytes(f, b);
  expect_error(f, "truncated or corrupt binary STL: header says 12 facets");
  fs::remove(f);
}

TEST(BadInput, TruncatedBinaryStlWithSolidHeader) {
  const auto f = temp("truncated_solid.stl");
  write_stl(f, test::box(2, 1, 1));
  std::string b = read_bytes(f);
  std::memcpy(b.data(), "solid", 5);
  b.resize(b.size() - 20);
  write_bytes(f, b);
  expect_error(f, "neither a binary STL of matching size nor a complete ASCII STL");
  fs::remove(f);
}

TEST(BadInput, BinaryStlWithSolidHeaderIsReadAsBinary) {
  const auto f = temp("solid_header.stl");
  write_stl(f, test::box(2, 1, 1));
  std::string b = read_bytes(f);
  std::memcpy(b.data(), "solid box", 9);
  write_bytes(f, b);
  const Mesh m = read_mesh(f);
  EXPECT_EQ(m.faces.size(), 12u);
  EXPECT_TRUE(check_mesh(m).ok());
  fs::remove(f);
}

TEST(BadInput, WrittenHeaderDoesNotStartWithSolid) {
  const auto f = temp("header.stl");
  write_stl(f, test::box(2, 1, 1));
  EXPECT_NE(read_bytes(f).substr(0, 5), "solid");
  fs::remove(f);
}

TEST(BadInput, EmptyFile) {
  const auto f = temp("empty.stl");
  write_bytes(f, "");
  expect_error(f, "file is empty");
  fs::remove(f);
}

TEST(BadInput, MissingFile) { expect_error(temp("does_not_exist.stl"), "cannot open"); }

TEST(BadInput, ZeroFacets) {
  const auto f = temp("zero.stl");
  write_stl(f, Mesh{});
  expect_error(f, "no triangles");
  fs::remove(f);
}

TEST(BadInput, HullInMillimetres) {
  Mesh m = test::box(7000, 1125, 625);
  const auto problems = unit_problems(m, 0.4125, 7.0);
  ASSERT_FALSE(problems.empty());
  EXPECT_NE(problems.front().find("millimetres"), std::string::npos) << problems.front();
  try {
    require_plausible_units(m, "hull_mm.stl", 0.4125, 7.0);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind("hull_mm.stl: ", 0), 0u) << msg;
    EXPECT_NE(msg.find("millimetres (scale by 0.001)"), std::string::npos) << msg;
  }
  EXPECT_TRUE(unit_problems(test::box(7.0, 1.125, 0.625), 0.4125, 7.0).empty());
}

TEST(BadInput, KeelNotAtZero) {
  Mesh m = test::box(7.0, 1.125, 0.625);
  for (auto& v : m.vertices) v.z() -= 0.4125;  // waterline at z = 0 instead of the keel
  const auto problems = unit_problems(m, 0.4125, 7.0);
  ASSERT_FALSE(problems.empty());
  EXPECT_NE(problems.front().find("keel"), std::string::npos);
}

TEST(BadInput, ObjReadNatively) {
  const auto f = temp("box.obj");
  write_bytes(f, "v 0 -0.5 0\nv 2 -0.5 0\nv 2 0.5 0\nv 0 0.5 0\nv 0 -0.5 1\nv 2 -0.5 1\nv 2 0.5 1\nv 0 0.5 1\n"
                 "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
  const Mesh m = read_mesh(f);
  EXPECT_EQ(m.faces.size(), 12u);  // six quads, each a fan of two triangles
  EXPECT_TRUE(check_mesh(m).ok());
  EXPECT_NEAR(check_mesh(m).signed_volume_m3, 2.0, 1e-12);  // doubles, not meshio's float32 STL
  fs::remove(f);
  const auto bad = temp("bad_index.obj");
  write_bytes(bad, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
  expect_error(bad, ":4: face index 9 outside the 3 vertices read so far");
  fs::remove(bad);
  const auto empty = temp("garbage.obj");
  write_bytes(empty, "this is not a mesh\n");
  expect_error(empty, "no faces ('f' lines) in the OBJ file");
  fs::remove(empty);
}

TEST(BadInput, OtherFormatThroughMeshio) {
  const auto f = temp("tetra.off");
  write_bytes(f, "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  const Mesh m = read_mesh(f);
  EXPECT_EQ(m.faces.size(), 4u);
  EXPECT_TRUE(check_mesh(m).ok());
  EXPECT_NEAR(check_mesh(m).signed_volume_m3, 1.0 / 6.0, 1e-6);
  fs::remove(f);
  const auto bad = temp("garbage.off");
  write_bytes(bad, "this is not a mesh\n");
  expect_error(bad, "meshio could not read it");
  fs::remove(bad);
}

}  // namespace
}  // namespace brash::hull
