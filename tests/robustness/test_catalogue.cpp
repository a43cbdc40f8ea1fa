// Catalogue of bad inputs: case files, packings, hull meshes, run files of brash-post and
// command-line arguments. Each entry must be rejected with the expected error type / exit code and a
// message that names the file (and the line or key where there is one) and the problem.
// LIGGGHTS fix arguments: tests/liggghts/test_bed_and_errors.cpp (fix icefluid) and
// test_guard.cpp here (fix brash/guard).
#include <gtest/gtest.h>

#include <brash/case.hpp>
#include <brash/error.hpp>
#include <brash/hull/mesh.hpp>
#include <brash/packing.hpp>

#include <array>
#include <cstring>
#include <limits>

#include "catalogue.hpp"

#ifdef BRASH_HAVE_POST
#include <brash/post/force_history.hpp>
#include <brash/post/run_meta.hpp>
#endif

using namespace brash::robust;

namespace {

// ------------------------------------------------------------------ helpers per input kind

template <class F>
Outcome library_call(F&& f) {
  try {
    f();
  } catch (const brash::InputError& e) {
    return {-1, e.what()};
  } catch (const std::exception& e) {
    return {-3, std::string("not an InputError: ") + e.what()};
  }
  return {};
}

Entry bad_case(std::string name, std::string yaml, std::vector<std::string> expect) {
  return {std::move(name),
          [yaml](const fs::path& dir) {
            write_file(dir / "case.yaml", yaml);
            return library_call([&] { brash::load_case(dir / "case.yaml"); });
          },
          std::move(expect)};
}

Entry bad_packing(std::string name, std::string csv, std::vector<std::string> expect) {
  return {std::move(name),
          [csv](const fs::path& dir) {
            write_file(dir / "packing.csv", csv);
            return library_call([&] { brash::read_packing_csv(dir / "packing.csv"); });
          },
          std::move(expect)};
}

// A case's packing (brash::read_case_packing, what every runner reads): the YADE smoke case's ice (35 mm pieces,
// 0.07 m thick) in a 0.2 x 1.6 m channel, water at z = 0; packing.csv holds one good piece and `row` (line 3).
const std::string kPackedCase =
    "name: packed\nchannel: {length_m: 0.2, width_m: 1.6}\n"
    "ice: {thickness_m: 0.07, diameter_mean_m: 0.035, diameter_sd_m: 0.00175, packing_file: packing.csv}\n"
    "contact: {youngs_modulus_pa: 5.0e6}\n"
    "run: {duration_s: 0.2, timestep_s: 1.0e-4, output_interval_s: 0.01, window_s: [0.1, 0.2]}\n";

Entry bad_case_packing(std::string name, std::string row, std::vector<std::string> expect) {
  return {std::move(name),
          [row](const fs::path& dir) {
            write_file(dir / "case.yaml", kPackedCase);
            write_file(dir / "packing.csv", "id,x,y,z,diameter\n1,0.1,0,0,0.035\n" + row + "\n");
            return library_call([&] { brash::read_case_packing(brash::load_case(dir / "case.yaml")); });
          },
          std::move(expect)};
}

// A closed, outward 1 x 0.5 x 0.4 box (keel at z = 0), scaled by `s`.
brash::hull::Mesh box_mesh(double s = 1.0) {
  brash::hull::Mesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.emplace_back(s * ((i & 1) ? 1.0 : 0.0), s * ((i & 2) ? 0.25 : -0.25), s * ((i & 4) ? 0.4 : 0.0));
  // Outward (counter-clockwise seen from outside) faces of the cube with corners indexed by bits x|y<<1|z<<2.
  m.faces = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
             {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

std::string binary_stl_bytes(const fs::path& dir, const brash::hull::Mesh& m) {
  brash::hull::write_stl(dir / "tmp_box.stl", m);
  std::string b = read_text(dir / "tmp_box.stl");
  fs::remove(dir / "tmp_box.stl");
  return b;
}

Entry bad_mesh_bytes(std::string name, std::function<std::string(const fs::path&)> bytes, std::vector<std::string> expect,
                     std::string file = "hull.stl") {
  return {std::move(name),
          [bytes, file](const fs::path& dir) {
            const std::string b = bytes(dir);
            write_file(dir / file, b);
            return library_call([&] { brash::hull::read_mesh(dir / file); });
          },
          std::move(expect)};
}

std::string exe(const char* path) { return std::string("'") + path + "'"; }

// brash-hull check command line (hull.stl in the entry's folder).
std::string fmt_check(const fs::path& dir, double draft, double lpp) {
  return exe(BRASH_HULL_EXE) + " check '" + (dir / "hull.stl").string() + "' --draft " + std::to_string(draft) + " --lpp " + std::to_string(lpp);
}

// brash-hull check of a mesh file written by `make` (exit 2 = check or unit sanity failed).
Entry bad_mesh_check(std::string name, std::function<brash::hull::Mesh()> make, std::vector<std::string> expect,
                     double draft = 0.2, double lpp = 1.0) {
  return {std::move(name),
          [make, draft, lpp](const fs::path& dir) {
            brash::hull::write_stl(dir / "hull.stl", make());
            return run_command(dir, fmt_check(dir, draft, lpp));
          },
          std::move(expect), 2};
}

std::string ascii_box_stl(const brash::hull::Mesh& m, std::size_t faces, bool close) {
  std::string s = "solid box\n";
  for (std::size_t f = 0; f < faces && f < m.faces.size(); ++f) {
    s += "  facet normal 0 0 0\n    outer loop\n";
    for (const int v : m.faces[f])
      s += "      vertex " + std::to_string(m.vertices[v].x()) + " " + std::to_string(m.vertices[v].y()) + " " +
           std::to_string(m.vertices[v].z()) + "\n";
    s += "    endloop\n  endfacet\n";
  }
  if (close) s += "endsolid box\n";
  return s;
}

const std::string kGoodCase = "name: robust\nrun: {duration_s: 2.0, timestep_s: 5.0e-5, output_interval_s: 0.01}\n";

std::vector<Entry> catalogue() {
  std::vector<Entry> c;
  // ---------------------------------------------------------------- case files (brash::load_case)
  c.push_back(bad_case("case_unknown_top_key", "name: x\ncolour: red\n",
                       {"{dir}/case.yaml:2:1", "key 'colour'", "unknown key"}));
  c.push_back(bad_case("case_unknown_section_key", "name: x\nice:\n  porosityy: 0.3\n",
                       {"{dir}/case.yaml:3:3", "key 'ice.porosityy'", "unknown key"}));
  c.push_back(bad_case("case_unknown_guards_key", "name: x\nguards:\n  max_penetration: 0.3\n",
                       {"{dir}/case.yaml:3:3", "key 'guards.max_penetration'", "unknown key"}));
  c.push_back(bad_case("case_guards_negative_penetration", "name: x\nguards: {max_hull_penetration_d: -1}\n",
                       {"{dir}/case.yaml:2", "key 'guards.max_hull_penetration_d'", "[0, 10]"}));
  c.push_back(bad_case("case_guards_every_zero", "name: x\nguards: {every_steps: 0}\n",
                       {"{dir}/case.yaml:2", "key 'guards.every_steps'", "integer"}));
  c.push_back(bad_case("case_wrong_type_text_for_number", "name: x\nship: {speed_m_s: fast}\n",
                       {"{dir}/case.yaml:2", "key 'ship.speed_m_s'", "expected a number, got 'fast'"}));
  c.push_back(bad_case("case_wrong_type_section_is_number", "name: x\nice: 5\n",
                       {"{dir}/case.yaml:2", "key 'ice'", "expected a mapping"}));
  c.push_back(bad_case("case_wrong_type_list_for_number", "name: x\nwater: {density_kg_m3: [1000]}\n",
                       {"{dir}/case.yaml:2", "key 'water.density_kg_m3'", "expected a number"}));
  c.push_back(bad_case("case_nan", "name: x\nice: {density_kg_m3: .nan}\n",
                       {"{dir}/case.yaml:2", "key 'ice.density_kg_m3'", "finite"}));
  c.push_back(bad_case("case_inf", "name: x\nwater: {gravity_m_s2: .inf}\n",
                       {"{dir}/case.yaml:2", "key 'water.gravity_m_s2'", "finite"}));
  c.push_back(bad_case("case_negative_density", "name: x\nice: {density_kg_m3: -900}\n",
                       {"{dir}/case.yaml:2", "key 'ice.density_kg_m3'", "> 0"}));
  c.push_back(bad_case("case_ice_heavier_than_water", "name: x\nice: {density_kg_m3: 1020}\n",
                       {"{dir}/case.yaml:2", "key 'ice.density_kg_m3'", "lighter than water"}));
  c.push_back(bad_case("case_porosity_above_one", "name: x\nice: {porosity: 1.2}\n",
                       {"{dir}/case.yaml:2", "key 'ice.porosity'", "in (0, 1)"}));
  c.push_back(bad_case("case_porosity_zero", "name: x\nice: {porosity: 0}\n",
                       {"{dir}/case.yaml:2", "key 'ice.porosity'", "in (0, 1)"}));
  c.push_back(bad_case("case_zero_size_spheres", "name: x\nice: {diameter_mean_m: 0.01, diameter_sd_m: 0.004}\n",
                       {"{dir}/case.yaml:2", "key 'ice.diameter_sd_m'", "no zero-size spheres"}));
  c.push_back(bad_case("case_window_outside_run", "name: x\nrun: {duration_s: 10, window_s: [5, 20]}\n",
                       {"{dir}/case.yaml:2", "key 'run.window_s'", "<= run.duration_s = 10"}));
  c.push_back(bad_case("case_window_reversed", "name: x\nrun: {duration_s: 10, window_s: [8, 2]}\n",
                       {"{dir}/case.yaml:2", "key 'run.window_s'", "start < end"}));
  c.push_back(bad_case("case_window_three_numbers", "name: x\nrun: {window_s: [1, 2, 3]}\n",
                       {"{dir}/case.yaml:2", "key 'run.window_s'", "two numbers"}));
  c.push_back(bad_case("case_dt_above_output_interval",
                       "name: x\nrun: {timestep_s: 0.02, output_interval_s: 0.01}\n",
                       {"{dir}/case.yaml:2", "key 'run.timestep_s'", "longer than run.output_interval_s"}));
  // dt too large for the Hertz contact stiffness (Rayleigh time of the smallest sphere).
  c.push_back(bad_case("case_dt_too_large_for_contact_stiffness",
                       "name: x\ncontact: {youngs_modulus_pa: 1.0e9}\nrun: {timestep_s: 5.0e-5}\n",
                       {"{dir}/case.yaml:3", "key 'run.timestep_s'", "Rayleigh time", "contacts are unstable"}));
  c.push_back(bad_case("case_output_interval_above_duration",
                       "name: x\nrun: {duration_s: 0.5, window_s: [0, 0.5], output_interval_s: 1.0, timestep_s: 1e-4}\n",
                       {"{dir}/case.yaml:2", "key 'run.output_interval_s'", "longer than run.duration_s"}));
  c.push_back(bad_case("case_unknown_enum", "name: x\nfluid: {treatment: semi}\n",
                       {"{dir}/case.yaml:2", "key 'fluid.treatment'", "unknown value 'semi'"}));
  c.push_back(bad_case("case_negative_seed", "name: x\nice: {seed: -1}\n",
                       {"{dir}/case.yaml:2", "key 'ice.seed'", "non-negative integer"}));
  c.push_back(bad_case("case_poisson_impossible", "name: x\ncontact: {poisson_ratio: 0.5}\n",
                       {"{dir}/case.yaml:2", "key 'contact.poisson_ratio'", "in (-1, 0.5)"}));
  c.push_back(bad_case("case_negative_band", "name: x\nhull: {band_m: [-0.1, 0.1]}\n",
                       {"{dir}/case.yaml:2", "key 'hull.band_m'", ">= 0"}));
  // Found by fuzz_case (tests/fuzz): a list used as a key escaped as a yaml-cpp exception without the file name.
  c.push_back(bad_case("case_list_as_key_fuzz_regression", "name: x\nrun: {duration_s: 4}\nfsicr: {[0.1, 0.1]}\n",
                       {"{dir}/case.yaml:3", "key 'fsicr'", "keys must be plain names"}));
  c.push_back(bad_case("case_mapping_as_top_key", "name: x\n? {a: 1}\n: 2\n",
                       {"{dir}/case.yaml:2", "key '<top>'", "keys must be plain names"}));
  // Found by a bad-input battery: yaml-cpp keeps one of two equal keys without a word.
  c.push_back(bad_case("case_key_given_twice", "name: x\nice:\n  seed: 1\n  porosity: 0.3\n  seed: 2\n",
                       {"{dir}/case.yaml:5:3", "key 'ice.seed'", "given twice", "first at line 3"}));
  c.push_back(bad_case("case_key_given_twice_in_a_flow_mapping", "name: x\nship: {speed_m_s: 0.3, speed_m_s: 0.5}\n",
                       {"{dir}/case.yaml:2", "key 'ship.speed_m_s'", "given twice", "first at line 2"}));
  c.push_back(bad_case("case_section_given_twice", "name: x\nice: {seed: 1}\nrun: {duration_s: 4}\nice: {porosity: 0.3}\n",
                       {"{dir}/case.yaml:4:1", "key 'ice'", "given twice", "first at line 2"}));
  // An ice layer thinner than one piece was accepted without a word.
  c.push_back(bad_case("case_ice_thinner_than_a_piece", "name: x\nice: {thickness_m: 0.03, diameter_mean_m: 0.035}\n",
                       {"{dir}/case.yaml:2", "key 'ice.thickness_m'", "0.03 m", "ice.diameter_mean_m = 0.035 m"}));
  c.push_back(bad_case("case_default_thickness_thinner_than_the_pieces", "name: x\nice:\n  diameter_mean_m: 0.04\n",
                       {"{dir}/case.yaml:3", "key 'ice.thickness_m'", "default", "ice.diameter_mean_m = 0.04 m"}));
  c.push_back(bad_case("case_yaml_syntax", "name: x\nice: {porosity: [0.3\n",
                       {"{dir}/case.yaml:", "YAML syntax error"}));
  c.push_back(bad_case("case_empty_file", "", {"{dir}/case.yaml", "empty case file"}));
  c.push_back(bad_case("case_missing_name", "ice: {porosity: 0.3}\n", {"{dir}/case.yaml", "key 'name'", "missing"}));
  c.push_back({"case_missing_file",
               [](const fs::path& dir) { return library_call([&] { brash::load_case(dir / "nope.yaml"); }); },
               {"{dir}/nope.yaml", "cannot open case file"}});

  // ---------------------------------------------------------------- packings (brash::read_packing_csv)
  const std::string ph = "# stats\nid,x,y,z,diameter\n";
  c.push_back(bad_packing("packing_nan", ph + "1,0.1,0.2,0,0.02\n2,0.5,nan,0,0.02\n",
                          {"{dir}/packing.csv:4", "column 3 is not a finite number"}));
  c.push_back(bad_packing("packing_inf_diameter", ph + "1,0.1,0.2,0,inf\n",
                          {"{dir}/packing.csv:3", "column 5 is not a finite number"}));
  c.push_back(bad_packing("packing_non_numeric", ph + "1,0.1,abc,0,0.02\n",
                          {"{dir}/packing.csv:3", "column 3 is not a finite number", "abc"}));
  c.push_back(bad_packing("packing_too_many_columns", ph + "1,0.1,0.2,0,0.02,7\n",
                          {"{dir}/packing.csv:3", "expected 5 columns", "got 6"}));
  c.push_back(bad_packing("packing_truncated_line", ph + "1,0.1,0.2,0,0.02\n2,0.3,0.1",
                          {"{dir}/packing.csv:4", "expected 5 columns", "got 3", "truncated"}));
  c.push_back(bad_packing("packing_negative_diameter", ph + "1,0.1,0.2,0,-0.02\n",
                          {"{dir}/packing.csv:3", "diameter must be > 0"}));
  c.push_back(bad_packing("packing_wrong_header", "id,x,y,z,r\n1,0,0,0,0.02\n",
                          {"{dir}/packing.csv:1", "expected header 'id,x,y,z,diameter'"}));
  c.push_back(bad_packing("packing_empty", "", {"{dir}/packing.csv", "no 'id,x,y,z,diameter' header"}));
  // overlapping spheres were read silently before.
  c.push_back(bad_packing("packing_overlapping_spheres", ph + "1,0.1,0.2,0,0.02\n2,0.5,0.5,0,0.02\n3,0.11,0.2,0,0.02\n",
                          {"{dir}/packing.csv:5", "sphere id 3 overlaps sphere id 1 (line 3)", "must not overlap"}));
  // Two pieces with one id were read silently.
  c.push_back(bad_packing("packing_duplicate_id", ph + "1,0.1,0.2,0,0.02\n2,0.5,0.5,0,0.02\n1,0.9,0.2,0,0.02\n",
                          {"{dir}/packing.csv:5", "piece id 1 is given twice", "first at line 3"}));
  // Pieces that cannot be the case's ice: they reached LIGGGHTS and stopped it with "Did not assign all
  // atoms correctly" (outside its box), or ran. Each piece must lie in the channel and float in the water.
  c.push_back(bad_case_packing("packing_piece_beyond_the_channel_end", "2,1.2,0,0,0.035",
                               {"{dir}/packing.csv:3", "piece id 2 (x 1.2, y 0, z 0 m, d 0.035 m)",
                                "outside the channel [0, 0.2] x [-0.8, 0.8] m", "x + d/2 = 1.2175 m > channel.length_m = 0.2 m"}));
  c.push_back(bad_case_packing("packing_piece_before_the_channel_start", "2,0.01,0.3,0,0.035",
                               {"{dir}/packing.csv:3", "outside the channel", "x - d/2 = -0.0075 m < 0"}));
  c.push_back(bad_case_packing("packing_piece_through_a_side_wall", "2,0.1,-0.79,0,0.035",
                               {"{dir}/packing.csv:3", "outside the channel", "|y| + d/2 = 0.8075 m > channel.width_m / 2 = 0.8 m"}));
  c.push_back(bad_case_packing("packing_piece_far_above_the_water", "2,0.1,0.3,0.4,0.035",
                               {"{dir}/packing.csv:3", "piece id 2", "far above the water", "0.3825 m above water.level_m = 0 m",
                                "1 x ice.diameter_mean_m = 0.035 m"}));
  c.push_back(bad_case_packing("packing_piece_far_below_the_water", "2,0.1,0.3,-0.6,0.035",
                               {"{dir}/packing.csv:3", "piece id 2", "far below the water", "0.6 m below water.level_m = 0 m",
                                "5 x ice.thickness_m = 0.35 m"}));
  c.push_back(bad_case_packing("packing_duplicate_id_in_a_case", "1,0.1,0.3,0,0.035",
                               {"{dir}/packing.csv:3", "piece id 1 is given twice (first at line 2)"}));
  c.push_back({"packing_missing_file",
               [](const fs::path& dir) { return library_call([&] { brash::read_packing_csv(dir / "none.csv"); }); },
               {"{dir}/none.csv", "cannot open packing file"}});

  // ---------------------------------------------------------------- hull meshes (brash::hull::read_mesh)
  c.push_back(bad_mesh_bytes("mesh_empty_file", [](const fs::path&) { return std::string(); },
                             {"{dir}/hull.stl", "file is empty"}));
  c.push_back(bad_mesh_bytes("mesh_truncated_binary",
                             [](const fs::path& d) {
                               const auto b = binary_stl_bytes(d, box_mesh());
                               return b.substr(0, b.size() - 70);
                             },
                             {"{dir}/hull.stl", "truncated or corrupt binary STL", "header says 12 facets"}));
  c.push_back(bad_mesh_bytes("mesh_shorter_than_header", [](const fs::path&) { return std::string(40, 'x'); },
                             {"{dir}/hull.stl", "shorter than the 84-byte header"}));
  c.push_back(bad_mesh_bytes("mesh_nan_vertex_binary",
                             [](const fs::path& d) {
                               auto b = binary_stl_bytes(d, box_mesh());
                               const float nan = std::numeric_limits<float>::quiet_NaN();
                               std::memcpy(b.data() + 84 + 50 * 4 + 12 + 12 + 4, &nan, 4);  // facet 5, vertex 2, y
                               return b;
                             },
                             {"{dir}/hull.stl", "vertex 2 of facet 5 is not a finite number"}));
  c.push_back(bad_mesh_bytes("mesh_nan_vertex_ascii",
                             [](const fs::path&) {
                               return replace_all(ascii_box_stl(box_mesh(), 12, true), "vertex 1.000000 0.250000 0.400000",
                                                  "vertex 1.0 nan 0.4");
                             },
                             {"{dir}/hull.stl", "is not a finite number"}));
  c.push_back(bad_mesh_bytes("mesh_truncated_ascii",
                             [](const fs::path&) { return ascii_box_stl(box_mesh(), 5, false).substr(0, 400); },
                             {"{dir}/hull.stl", "no 'endsolid': truncated?"}));
  c.push_back(bad_mesh_bytes("mesh_ascii_facet_with_two_vertices",
                             [](const fs::path&) {
                               return "solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\n"
                                      "endfacet\nendsolid a\n";
                             },
                             {"{dir}/hull.stl", "facet 1 has 2 vertices, not 3"}));
  c.push_back(bad_mesh_bytes("mesh_ascii_non_numeric_vertex",
                             [](const fs::path&) {
                               return "solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 zero\nvertex 1 0 0\n"
                                      "vertex 0 1 0\nendloop\nendfacet\nendsolid a\n";
                             },
                             {"{dir}/hull.stl", "vertex '0 0 zero' is not numeric"}));
  c.push_back(bad_mesh_bytes("mesh_zero_facets",
                             [](const fs::path& d) { return binary_stl_bytes(d, brash::hull::Mesh{}); },
                             {"{dir}/hull.stl", "no triangles"}));
  c.push_back({"mesh_is_a_directory",
               [](const fs::path& dir) {
                 fs::create_directories(dir / "hull.stl");
                 return library_call([&] { brash::hull::read_mesh(dir / "hull.stl"); });
               },
               {"{dir}/hull.stl", "is a directory"}});
  c.push_back({"mesh_missing_file",
               [](const fs::path& dir) { return library_call([&] { brash::hull::read_mesh(dir / "none.stl"); }); },
               {"{dir}/none.stl", "cannot open"}});
  c.push_back({"mesh_in_millimetres",
               [](const fs::path& dir) {
                 return library_call([&] {
                   brash::hull::require_plausible_units(box_mesh(1000.0), dir / "hull.stl", 0.2, 1.0);
                 });
               },
               {"{dir}/hull.stl", "millimetres (scale by 0.001)"}});
  // Topology problems are found by brash-hull check (exit 2, message on stderr naming the file).
  c.push_back(bad_mesh_check("mesh_open_cli",
                             [] {
                               auto m = box_mesh();
                               m.faces.pop_back();
                               return m;
                             },
                             {"{dir}/hull.stl", "mesh is not closed", "boundary edges"}));
  c.push_back(bad_mesh_check("mesh_inverted_normals_cli",
                             [] {
                               auto m = box_mesh();
                               for (auto& f : m.faces) std::swap(f[1], f[2]);
                               return m;
                             },
                             {"{dir}/hull.stl", "faces are not consistently outward"}));
  c.push_back(bad_mesh_check("mesh_in_millimetres_cli", [] { return box_mesh(1000.0); },
                             {"{dir}/hull.stl", "millimetres"}));

#ifdef BRASH_HAVE_POST
  // ---------------------------------------------------------------- run files read by brash-post
  auto bad_force = [](std::string name, std::string csv, std::vector<std::string> expect) {
    return Entry{std::move(name),
                 [csv](const fs::path& dir) {
                   write_file(dir / "hull_force.csv", csv);
                   return library_call([&] { brash::post::read_force_history(dir / "hull_force.csv", false); });
                 },
                 std::move(expect)};
  };
  const std::string fh = "t_s,fx_N,fy_N,fz_N\n";
  c.push_back(bad_force("force_csv_truncated_record", fh + "0.01,1,2,3\n0.02,1,2",
                        {"{dir}/hull_force.csv:3", "3 fields, expected 4"}));
  c.push_back(bad_force("force_csv_non_numeric", fh + "0.01,1,2,3\n0.02,abc,2,3\n",
                        {"{dir}/hull_force.csv:3", "column 'fx_N'", "'abc' is not a number"}));
  c.push_back(bad_force("force_csv_nan", fh + "0.01,nan,2,3\n", {"{dir}/hull_force.csv:2", "not finite"}));
  c.push_back(bad_force("force_csv_time_not_increasing", fh + "0.02,1,2,3\n0.01,1,2,3\n",
                        {"{dir}/hull_force.csv:3", "does not increase"}));
  c.push_back(bad_force("force_csv_wrong_header", "t,fx,fy,fz\n0.01,1,2,3\n",
                        {"{dir}/hull_force.csv:1", "expected 't_s,fx_N,fy_N,fz_N'"}));
  c.push_back(bad_force("force_csv_empty", "", {"{dir}/hull_force.csv:1", "empty file"}));
  c.push_back({"meta_json_invalid",
               [](const fs::path& dir) {
                 write_file(dir / "meta.json", "{\"engine\": \"liggghts\", \"dt_s\": ");
                 return library_call([&] { brash::post::read_run_meta(dir / "meta.json"); });
               },
               {"{dir}/meta.json", "invalid JSON"}});
  c.push_back({"meta_json_wrong_type",
               [](const fs::path& dir) {
                 write_file(dir / "meta.json", "{\"engine\": \"liggghts\", \"dt_s\": \"small\"}");
                 return library_call([&] { brash::post::read_run_meta(dir / "meta.json"); });
               },
               {"{dir}/meta.json", "key 'dt_s'"}});
#endif
  return c;
}

}  // namespace

class Catalogue : public ::testing::TestWithParam<Entry> {};

TEST_P(Catalogue, RejectedWithClearMessage) {
  const Entry& e = GetParam();
  const fs::path dir = fresh_dir(e.name);
  const Outcome o = e.run(dir);
  ASSERT_NE(o.exit_code, -2) << e.name << ": the bad input was accepted";
  ASSERT_NE(o.exit_code, -3) << e.name << ": " << o.message;
  expect_clear_error(e, o, dir);
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(BadInput, Catalogue, ::testing::ValuesIn(catalogue()),
                         [](const ::testing::TestParamInfo<Entry>& i) { return i.param.name; });

TEST(Catalogue, HasAtLeastThirtyEntries) { EXPECT_GE(catalogue().size(), 30u); }

// The new checks must not reject what the project ships: the committed cases load.
TEST(Catalogue, CommittedCasesStillLoad) {
  for (const char* name : {"jbc_quick", "jbc_ia_5kn"}) {
    const fs::path file = fs::path(BRASH_SOURCE_DIR) / "cases" / name / "case.yaml";
    EXPECT_NO_THROW(brash::load_case(file)) << file;
  }
  const fs::path dir = fresh_dir("good_case");
  write_file(dir / "case.yaml", kGoodCase);
  EXPECT_NO_THROW(brash::load_case(dir / "case.yaml"));
}

// A generated packing (touching spheres, 9-decimal rounding) passes the new overlap check.
TEST(Catalogue, GeneratedPackingReadsBack) {
  brash::PackingRequest q;
  q.length_m = 0.4;
  q.width_m = 0.3;
  q.diameter_mean_m = 0.035;
  q.diameter_sd_m = 0.00175;
  q.thickness_m = 0.07;
  const auto p = brash::generate_packing(q);
  const fs::path dir = fresh_dir("good_packing");
  brash::write_packing_csv(dir / "packing.csv", p);
  EXPECT_EQ(brash::read_packing_csv(dir / "packing.csv").size(), p.spheres.size());
}

// The case check's bounds take what a packing may hold: pieces touching an end and a side wall, one
// whose bottom is just under a diameter above the water, one just under 5 ice thicknesses down.
TEST(Catalogue, CasePackingNearTheBoundsReads) {
  const fs::path dir = fresh_dir("packing_near_bounds");
  write_file(dir / "case.yaml", kPackedCase);
  write_file(dir / "packing.csv",
             "id,x,y,z,diameter\n1,0.0175,0.7825,0,0.035\n2,0.1825,-0.7825,0.05,0.035\n3,0.1,0.3,-0.34,0.035\n");
  EXPECT_EQ(brash::read_case_packing(brash::load_case(dir / "case.yaml")).size(), 3u);
  fs::remove_all(dir);
}
