// Tests of case variants (brash/case_derive.hpp): derive_case, write_derived_case, case_value,
// differing_case_keys.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>
#include <sys/wait.h>
#include <unistd.h>

#include "brash/case.hpp"
#include "brash/case_derive.hpp"
#include "brash/error.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kRepo = BRASH_SOURCE_DIR;
const fs::path kQuick = kRepo / "cases/jbc_quick/case.yaml";

fs::path temp_dir(const std::string& tag) {
  const fs::path d = fs::temp_directory_path() / ("brash_test_derive_" + tag + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

void write(const fs::path& f, const std::string& text) {
  fs::create_directories(f.parent_path());
  std::ofstream(f) << text;
}

// The InputError message of write_derived_case, or "" when it succeeded.
std::string refusal(const brash::CaseOverrides& o, const fs::path& out) {
  try {
    (void)brash::write_derived_case(kQuick, o, out);
  } catch (const brash::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(DeriveCase, ChangesExactlyTheKeysGiven) {
  const fs::path out = temp_dir("exact");
  const brash::Case d = brash::write_derived_case(kQuick,
                                                  {{"fluid.model", "drag"},
                                                   {"run.duration_s", "1.0"},
                                                   {"run.window_s", "[0.375,0.75]"},
                                                   {"ship.speed_m_s", "0.3"},
                                                   {"fluid.ca_table", "uniform 0.5"}},
                                                  out);
  brash::Case expected = brash::load_case(kQuick);
  expected.fluid.model = brash::FluidModel::Drag;
  expected.run.duration_s = 1.0;
  expected.run.window_s = {0.375, 0.75};
  expected.ship.speed_m_s = 0.3;
  expected.fluid.ca_table = brash::CaTableSpec::uniform(0.5);
  EXPECT_EQ(d, expected);  // every other key, the hull file and the packing file included, is the base's
  EXPECT_EQ(brash::load_case(out / "case.yaml"), d);
}

TEST(DeriveCase, RunDirectoryCaseAsBase) {  // a run's resolved case.yaml (absolute paths, every key written)
  const fs::path dir = temp_dir("resolved");
  const brash::Case base = brash::load_case(kQuick);
  write(dir / "run/case.yaml", brash::dump_case_yaml(base));
  const brash::Case d = brash::write_derived_case(dir / "run/case.yaml", {{"speedups.farfield", "true"}}, dir / "ff");
  brash::Case expected = base;
  expected.speedups.farfield = true;
  EXPECT_EQ(d, expected);
}

TEST(DeriveCase, PackingFollowsWhatThePackingDependsOn) {
  const fs::path out = temp_dir("packing");
  const brash::Case base = brash::load_case(kQuick);
  // the same ice (a key the packing does not read, or a packing key at its base value): the base's packing
  EXPECT_EQ(brash::write_derived_case(kQuick, {{"friction.ice_hull", "0.2"}}, out / "a").ice.packing_file,
            base.ice.packing_file);
  EXPECT_EQ(brash::write_derived_case(kQuick, {{"ice.seed", "1"}}, out / "b").ice.packing_file, base.ice.packing_file);
  // other ice: the derived folder's own packing
  for (const auto& [key, value] : brash::CaseOverrides{{"ice.seed", "3"},
                                                       {"ice.diameter_mean_m", "0.034"},
                                                       {"channel.length_m", "5.0"},
                                                       {"water.level_m", "0.01"}}) {
    const fs::path dir = out / ("c_" + key);
    const brash::Case d = brash::write_derived_case(kQuick, {{key, value}}, dir);
    EXPECT_EQ(d.ice.packing_file, fs::absolute(dir / "generated/packing.csv").lexically_normal()) << key;
    EXPECT_FALSE(brash::same_packing_inputs(d, base)) << key;
  }
  // a packing file given as an override is taken as given, relative to the derived folder
  EXPECT_EQ(brash::write_derived_case(kQuick, {{"ice.seed", "3"}, {"ice.packing_file", "p/seed3.csv"}}, out / "d")
                .ice.packing_file,
            fs::absolute(out / "d/p/seed3.csv").lexically_normal());
  EXPECT_EQ(brash::write_derived_case(kQuick, {{"ice.density_kg_m3", "500"},
                                               {"ice.packing_file", base.ice.packing_file.string()}},
                                      out / "e")
                .ice.packing_file,
            base.ice.packing_file);
}

// A base whose folder cannot be written (an installed case): the same ice is made in the derived case's own folder,
// since the runners make a missing packing and its settled bed beside it. Derived by a user who cannot write the
// base's folder: a forked process that drops to "nobody" when the tests run as root.
TEST(DeriveCase, ReadOnlyBaseGivesThePackingToTheDerivedFolder) {
  const fs::path dir = temp_dir("readonly");
  const std::string quick_text = [] {
    std::ifstream in(kQuick);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }();
  write(dir / "installed/case.yaml", quick_text);
  write(dir / "mine/case.yaml", quick_text);
  fs::create_directories(dir / "user");
  fs::permissions(dir / "installed", fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                                         fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
  fs::permissions(dir, fs::perms::all);
  fs::permissions(dir / "user", fs::perms::all);
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0)) ::_exit(3);
    try {
      const brash::Case d = brash::write_derived_case(dir / "installed/case.yaml", {{"ice.seed", "1"}}, dir / "user/v");
      ::_exit(d.ice.packing_file == fs::absolute(dir / "user/v/generated/packing.csv").lexically_normal() ? 0 : 1);
    } catch (...) {
      ::_exit(2);
    }
  }
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "1: packing not in the derived folder, 2: refused, 3: could not drop to nobody";
  // the same base in a folder its user can write keeps sharing the base's packing
  EXPECT_EQ(brash::write_derived_case(dir / "mine/case.yaml", {{"ice.seed", "1"}}, dir / "own").ice.packing_file,
            fs::absolute(dir / "mine/generated/packing.csv").lexically_normal());
  fs::permissions(dir / "installed", fs::perms::owner_all);
  fs::remove_all(dir);
}

// One rule for a shorter run, shared with the runners' --duration: the window moves inside the run, unless the
// variant sets its own; a longer run keeps its base's window.
TEST(DeriveCase, ShorterRunKeepsItsWindowInside) {
  const fs::path out = temp_dir("window");
  const brash::Case quick = brash::load_case(kQuick);
  ASSERT_EQ(quick.run.window_s, (std::array<double, 2>{5.5, 11.0}));
  EXPECT_EQ(brash::write_derived_case(kQuick, {{"run.duration_s", "0.1"}}, out / "a").run.window_s,
            (std::array<double, 2>{0.05, 0.1}));
  EXPECT_EQ(brash::write_derived_case(kQuick, {{"run.duration_s", "8"}}, out / "b").run.window_s,
            (std::array<double, 2>{4.0, 8.0}));
  EXPECT_EQ(brash::write_derived_case(kQuick, {{"run.duration_s", "20"}}, out / "c").run.window_s, quick.run.window_s);
  EXPECT_EQ(brash::write_derived_case(kQuick, {{"run.duration_s", "8"}, {"run.window_s", "[6, 7]"}}, out / "d")
                .run.window_s,
            (std::array<double, 2>{6.0, 7.0}));
  // a window that does not fit, set by the variant itself, is still refused naming the key
  EXPECT_NE(refusal({{"run.duration_s", "8"}, {"run.window_s", "[6, 9]"}}, out / "e").find("run.window_s"),
            std::string::npos);
}

TEST(DeriveCase, RelativePathsOfTheBaseFolderBecomeAbsolute) {
  const fs::path dir = temp_dir("paths");
  write(dir / "base/my_hull.stl", "solid x\nendsolid x\n");
  write(dir / "base/case.yaml", "name: b\nhull:\n  file: my_hull.stl\nice:\n  packing_file: pk/packing.csv\n");
  const brash::Case base = brash::load_case(dir / "base/case.yaml");
  ASSERT_EQ(base.hull.file, fs::absolute(dir / "base/my_hull.stl").lexically_normal());
  const brash::Case d = brash::write_derived_case(dir / "base/case.yaml", {{"run.duration_s", "20"}}, dir / "variant");
  EXPECT_EQ(d.hull.file, base.hull.file);
  EXPECT_EQ(d.ice.packing_file, fs::absolute(dir / "base/pk/packing.csv").lexically_normal());
  // a hull name found elsewhere (the build's hull_meshes) stays a name and is found in the same place
  const brash::Case quick = brash::load_case(kQuick);
  EXPECT_EQ(brash::write_derived_case(kQuick, {}, dir / "quick").hull.file, quick.hull.file);
  std::ifstream in(dir / "quick/case.yaml");
  const std::string text(std::istreambuf_iterator<char>(in), {});
  EXPECT_NE(text.find("file: jbc_panamax_model.stl"), std::string::npos) << text;
}

TEST(DeriveCase, RefusesWhatTheLoaderRefusesNamingTheKey) {
  const fs::path out = temp_dir("refused");
  const std::pair<brash::CaseOverrides, std::string> bad[] = {
      {{{"fluid.modle", "drag"}}, "fluid.modle"},            // unknown key
      {{{"fluid.model", "potential"}}, "fluid.model"},       // unknown value
      {{{"ice.porosity", "1.5"}}, "ice.porosity"},           // out of range
      {{{"run.window_s", "[0.375, 20]"}}, "run.window_s"},   // beyond run.duration_s
      {{{"run.timestep_s", "abc"}}, "run.timestep_s"},       // not a number
      {{{"ice.seed", "2"}, {"ice.seed", "3"}}, "ice.seed"},  // given twice
      {{{"name.x", "1"}}, "name.x"},                         // into a value
      {{{"run..x", "1"}}, "run..x"},                         // not a dotted key
      {{{"run.window_s", "[0.3"}}, "run.window_s"},          // not YAML
      {{{"bogus.key", "1"}}, "bogus"},                       // unknown section
  };
  for (const auto& [overrides, key] : bad) {
    const std::string msg = refusal(overrides, out);
    EXPECT_NE(msg.find("key '" + key), std::string::npos) << key << ": " << msg;
    EXPECT_NE(msg.find("case.yaml"), std::string::npos) << msg;
    EXPECT_FALSE(fs::exists(out / "case.yaml")) << key;
  }
  EXPECT_NE(refusal({{"ice.seed", "2"}, {"ice.seed", "3"}}, out).find("twice"), std::string::npos);
  EXPECT_THROW((void)brash::parse_case_override("fluid.model"), brash::InputError);
  EXPECT_THROW((void)brash::parse_case_override("=drag"), brash::InputError);
  EXPECT_EQ(brash::parse_case_override("run.window_s=[1,2]"), (brash::CaseOverride{"run.window_s", "[1,2]"}));
  EXPECT_EQ(brash::parse_case_override("fluid.ca_table=uniform 0.5=x").second, "uniform 0.5=x");
}

TEST(DeriveCase, EmptyValueRemovesTheKey) {
  const fs::path out = temp_dir("remove");
  ASSERT_TRUE(brash::load_case(kQuick).hull.band_m.has_value());
  EXPECT_FALSE(brash::write_derived_case(kQuick, {{"hull.band_m", ""}}, out / "a").hull.band_m.has_value());
  // a removed key takes the loader's default: the window of a short run is its last 60 %
  const brash::Case d = brash::write_derived_case(kQuick, {{"run.window_s", "~"}, {"run.duration_s", "2"}}, out / "b");
  EXPECT_EQ(d.run.window_s, (std::array<double, 2>{0.8, 2.0}));
}

TEST(DeriveCase, ExistingCaseNeedsOverwriteAndStalePackingGoes) {
  const fs::path out = temp_dir("overwrite");
  (void)brash::write_derived_case(kQuick, {{"ice.seed", "3"}}, out);
  EXPECT_THROW((void)brash::write_derived_case(kQuick, {{"ice.seed", "3"}}, out), brash::InputError);
  write(out / "generated/packing.csv", "# seed 3\n");
  write(out / "generated/packing.json", "{}\n");
  (void)brash::write_derived_case(kQuick, {{"ice.seed", "3"}, {"fluid.model", "drag"}}, out, true);
  EXPECT_TRUE(fs::exists(out / "generated/packing.csv"));  // the same ice: kept
  (void)brash::write_derived_case(kQuick, {{"ice.seed", "4"}}, out, true);
  EXPECT_FALSE(fs::exists(out / "generated/packing.csv"));  // other ice: removed, the runner makes the new one
  EXPECT_FALSE(fs::exists(out / "generated/packing.json"));
  EXPECT_EQ(brash::load_case(out / "case.yaml").ice.seed, 4u);
}

TEST(DeriveCase, DerivedTextLoadsAnywhere) {
  const std::string text = brash::derive_case(kQuick, {{"ice.seed", "5"}});
  const fs::path dir = temp_dir("text");
  write(dir / "x/case.yaml", text);
  const brash::Case d = brash::load_case(dir / "x/case.yaml");
  EXPECT_EQ(d.ice.seed, 5u);
  EXPECT_EQ(d.ice.packing_file, fs::absolute(dir / "x/generated/packing.csv").lexically_normal());
  EXPECT_EQ(text.rfind("# Derived by brash-case from ", 0), 0u) << text;
}

TEST(CaseValue, ResolvedValuesByDottedKey) {
  const brash::Case c = brash::load_case(kQuick);
  EXPECT_EQ(brash::case_value(c, "run.timestep_s"), "0.0008");
  EXPECT_EQ(brash::case_value(c, "run.window_s"), "[5.5, 11.0]");
  EXPECT_EQ(brash::case_value(c, "fluid.model"), "both");
  EXPECT_EQ(brash::case_value(c, "ice.density_kg_m3"), "900.0");
  EXPECT_EQ(brash::case_value(c, "water.density_kg_m3"), "1000.0");
  EXPECT_EQ(brash::case_value(c, "guards.every_steps"), "10");  // a default
  EXPECT_EQ(brash::case_value(c, "name"), "jbc_quick");
  EXPECT_EQ(brash::case_value(c, "ice.packing_file"), c.ice.packing_file.string());
  for (const char* key : {"fluid.modle", "run", "fsicr.alpha_deg", "name.x"}) {
    try {
      (void)brash::case_value(c, key);
      ADD_FAILURE() << key << " gave a value";
    } catch (const brash::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("key '") + key + "'"), std::string::npos) << e.what();
    }
  }
}

// The keys two resolved cases differ in, sorted, a key set on one side only included (fsicr.alpha_deg: the base
// sets no fsicr key).
TEST(DifferingCaseKeys, ListsEachDifferingKeyOnce) {
  const brash::Case a = brash::load_case(kQuick);
  EXPECT_TRUE(brash::differing_case_keys(a, a).empty());
  brash::Case b = a;
  b.ice.seed = a.ice.seed + 1;
  b.ship.speed_m_s = 2 * a.ship.speed_m_s;
  b.name = "jbc_quick_s2";
  b.fsicr.alpha_deg = 25;
  EXPECT_EQ(brash::differing_case_keys(a, b),
            (std::vector<std::string>{"fsicr.alpha_deg", "ice.seed", "name", "ship.speed_m_s"}));
}
