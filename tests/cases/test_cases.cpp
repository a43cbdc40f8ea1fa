// Tests of the case folders (every cases/*/case.yaml loads; the quick case is small) and of the
// brash-pack and brash-case commands (run as processes, as a user would).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <sys/wait.h>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <unistd.h>
#include <utility>

#include "brash/case.hpp"
#include "brash/error.hpp"
#include "brash/packing.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kRepo = BRASH_SOURCE_DIR;
const fs::path kBin = BRASH_BIN_DIR;

fs::path temp_dir(const std::string& tag) {
  const fs::path d = fs::temp_directory_path() / ("brash_test_cases_" + tag + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// Runs a command, returns its exit code; stdout+stderr go to `log`.
int run(const std::string& cmd, const fs::path& log) {
  const int rc = std::system((cmd + " > '" + log.string() + "' 2>&1").c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

std::string slurp(const fs::path& f) {
  std::ifstream in(f);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

TEST(CaseFolders, EveryCommittedCaseLoads) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(kRepo / "cases")) {
    if (!fs::exists(e.path() / "case.yaml")) continue;
    const brash::Case c = brash::load_case(e.path() / "case.yaml");
    EXPECT_EQ(c.name, e.path().filename().string());
    EXPECT_EQ(c.hull.file.filename(), "jbc_panamax_model.stl");
    ++n;
  }
  EXPECT_GE(n, 2);
}

// Every committed case's generated packing passes the check every runner makes before it starts (pieces in the
// channel, floating in the water, unique ids; brash::read_case_packing).
TEST(CaseFolders, GeneratedPackingsPassTheRunnersCheck) {
  const fs::path dir = temp_dir("generated_packings");
  int n = 0;
  for (const auto& e : fs::directory_iterator(kRepo / "cases")) {
    if (!fs::exists(e.path() / "case.yaml")) continue;
    brash::Case c = brash::load_case(e.path() / "case.yaml");
    c.ice.packing_file = dir / (c.name + ".csv");
    brash::write_packing_csv(c.ice.packing_file, brash::generate_packing(brash::packing_request(c, c.name)));
    EXPECT_NO_THROW(brash::read_case_packing(c)) << c.name;
    ++n;
  }
  EXPECT_GE(n, 2);
  fs::remove_all(dir);
}

// The quick case (make run): the paper's channel width, a window that starts once the bow is in the ice and ends
// while the stem is still 1.5 m from the open far end (the ice ahead thins there), and a bed small enough for
// minutes on 2 cores. Its report's own checks: tests/pipeline (the run itself).
TEST(CaseFolders, QuickCaseWindowEndsBeforeTheFarEnd) {
  const brash::Case c = brash::load_case(kRepo / "cases/jbc_quick/case.yaml");
  EXPECT_DOUBLE_EQ(c.ship.speed_m_s, 0.482);
  EXPECT_EQ(c.fluid.model, brash::FluidModel::Both);
  EXPECT_DOUBLE_EQ(c.channel.width_m, 2.25);
  EXPECT_LE(c.run.duration_s, 12.0);
  const double stem_at_window_start_m = c.hull.start_x_m + c.hull.lpp_m + c.ship.speed_m_s * c.run.window_s[0];
  const double stem_at_window_end_m = c.hull.start_x_m + c.hull.lpp_m + c.ship.speed_m_s * c.run.window_s[1];
  EXPECT_GT(stem_at_window_start_m, 2.0);                       // the bow (~2 m) is in the ice
  EXPECT_LT(stem_at_window_end_m, c.channel.length_m - 1.5);    // the ice ahead is not yet thinning
  // the record ends on an output row exactly at duration_s (else the window is reported truncated)
  const double steps_per_row = c.run.output_interval_s / c.run.timestep_s;
  EXPECT_NEAR(steps_per_row, std::round(steps_per_row), 1e-9);
  auto q = brash::packing_request(c, "jbc_quick");
  const auto p = brash::generate_packing(q);
  EXPECT_GT(p.stats.count, 15000u);
  EXPECT_LT(p.stats.count, 20000u);
}

TEST(BrashPack, WritesCsvAndJsonForACase) {
  const fs::path dir = temp_dir("pack");
  fs::copy_file(kRepo / "cases/jbc_narrow/case.yaml", dir / "case.yaml");
  const std::string pack = (kBin / "brash-pack").string();
  ASSERT_EQ(run(pack + " " + dir.string(), dir / "log.txt"), 0) << slurp(dir / "log.txt");
  const fs::path csv = dir / "generated/packing.csv", json = dir / "generated/packing.json";
  ASSERT_TRUE(fs::exists(csv));
  ASSERT_TRUE(fs::exists(json));
  const auto spheres = brash::read_case_packing(brash::load_case(dir / "case.yaml"));  // what the runners read
  const auto j = nlohmann::json::parse(slurp(json));
  EXPECT_EQ(j.at("count").get<std::size_t>(), spheres.size());
  EXPECT_EQ(j.at("mode").get<std::string>(), "volume");
  EXPECT_LT(j.at("max_overlap_over_d").get<double>(), 1e-6);
  // --out and a second run: identical bytes.
  ASSERT_EQ(run(pack + " " + dir.string() + " --out " + (dir / "again.csv").string(), dir / "log2.txt"), 0);
  EXPECT_EQ(slurp(dir / "again.csv"), slurp(csv));
  // Strict mode with the paper porosity is impossible: exit 2, message names the file and the key.
  EXPECT_EQ(run(pack + " " + dir.string() + " --mode strict_two_layer --out " + (dir / "s.csv").string(),
                dir / "log3.txt"),
            2);
  const std::string err = slurp(dir / "log3.txt");
  EXPECT_NE(err.find("case.yaml"), std::string::npos) << err;
  EXPECT_NE(err.find("ice.porosity"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(dir / "s.csv"));
}

TEST(BrashCase, NewCaseFromParameters) {
  const fs::path dir = temp_dir("new");
  const std::string cmd = (kBin / "brash-case").string() + " new my_case --template jbc_ia_5kn --cases-dir " + dir.string() +
                          " --speed 0.3 --scale 28.5 --width 1.8 --thickness 0.05 --diameter 0.025"
                          " --friction-ice 1.0 --friction-hull 0.05 --fluid-model drag --treatment explicit"
                          " --duration 10 --band 0.3 0.1";
  ASSERT_EQ(run(cmd, dir / "log.txt"), 0) << slurp(dir / "log.txt");
  const brash::Case c = brash::load_case(dir / "my_case/case.yaml");
  EXPECT_EQ(c.name, "my_case");
  EXPECT_DOUBLE_EQ(c.ship.speed_m_s, 0.3);
  EXPECT_DOUBLE_EQ(c.ship.scale_lambda, 28.5);
  EXPECT_DOUBLE_EQ(c.hull.lpp_m, 7.0);
  EXPECT_DOUBLE_EQ(c.channel.width_m, 1.8);
  EXPECT_DOUBLE_EQ(c.channel.length_m, 21.0);  // from the template asked for by name (the paper case)
  EXPECT_DOUBLE_EQ(c.ice.thickness_m, 0.05);
  EXPECT_DOUBLE_EQ(c.ice.diameter_mean_m, 0.025);
  EXPECT_DOUBLE_EQ(c.ice.diameter_sd_m, 0.00125);
  EXPECT_DOUBLE_EQ(c.friction.ice_ice, 1.0);
  EXPECT_DOUBLE_EQ(c.friction.ice_wall, 1.0);
  EXPECT_DOUBLE_EQ(c.friction.ice_hull, 0.05);
  EXPECT_EQ(c.fluid.model, brash::FluidModel::Drag);
  EXPECT_EQ(c.fluid.treatment, brash::Treatment::Explicit);
  EXPECT_DOUBLE_EQ(c.run.duration_s, 10.0);
  EXPECT_DOUBLE_EQ(c.run.window_s[0], 4.0);
  EXPECT_DOUBLE_EQ(c.run.window_s[1], 10.0);
  ASSERT_TRUE(c.hull.band_m.has_value());
  EXPECT_EQ(*c.hull.band_m, (std::array<double, 2>{0.3, 0.1}));
  EXPECT_EQ(c.ice.packing_file, fs::absolute(dir / "my_case/generated/packing.csv").lexically_normal());
  // Existing case: refused without --force.
  EXPECT_EQ(run(cmd, dir / "log2.txt"), 2);
  EXPECT_NE(slurp(dir / "log2.txt").find("exists"), std::string::npos);
  // Froude scaling with --scale: hull and speed follow.
  ASSERT_EQ(run((kBin / "brash-case").string() + " new s40 --cases-dir " + dir.string() + " --scale 40",
                dir / "log3.txt"), 0) << slurp(dir / "log3.txt");
  const brash::Case s = brash::load_case(dir / "s40/case.yaml");
  EXPECT_NEAR(s.hull.lpp_m, 7.0 * 28.5 / 40, 1e-9);
  EXPECT_NEAR(s.ship.speed_m_s, 0.482 * std::sqrt(28.5 / 40), 1e-9);
}

// --scale moves the ice with the hull by Froude similarity (thickness, piece size and its sd by old / new lambda):
// at full scale the brash is as thick as the template's, the thickness FSICR's R_CH assumes for the ice class.
TEST(BrashCase, NewScaleScalesTheIceByFroude) {
  const fs::path dir = temp_dir("scale_ice");
  const brash::Case paper = brash::load_case(kRepo / "cases/jbc_ia_5kn/case.yaml");
  ASSERT_EQ(paper.ship.scale_lambda, 28.5);
  ASSERT_EQ(run((kBin / "brash-case").string() + " new s50 --template jbc_ia_5kn --cases-dir " + dir.string() + " --scale 50",
                dir / "log.txt"), 0) << slurp(dir / "log.txt");
  const brash::Case s = brash::load_case(dir / "s50/case.yaml");
  const double k = 28.5 / 50;
  EXPECT_NEAR(s.ice.thickness_m, paper.ice.thickness_m * k, 1e-12);
  EXPECT_NEAR(s.ice.diameter_mean_m, paper.ice.diameter_mean_m * k, 1e-12);
  EXPECT_NEAR(s.ice.diameter_sd_m, paper.ice.diameter_sd_m * k, 1e-12);
  EXPECT_NEAR(s.ice.thickness_m * s.ship.scale_lambda, paper.ice.thickness_m * paper.ship.scale_lambda, 1e-9);
  EXPECT_NEAR(s.run.timestep_s, paper.run.timestep_s * k, 1e-15);  // the same fraction of the pieces' Rayleigh time
  EXPECT_NE(slurp(dir / "log.txt").find("the ice scaled by Froude"), std::string::npos) << slurp(dir / "log.txt");
  // ice given on the command line wins
  ASSERT_EQ(run((kBin / "brash-case").string() + " new t50 --template jbc_ia_5kn --cases-dir " + dir.string() +
                    " --scale 50 --thickness 0.03 --diameter 0.012",
                dir / "log2.txt"), 0) << slurp(dir / "log2.txt");
  const brash::Case t = brash::load_case(dir / "t50/case.yaml");
  EXPECT_DOUBLE_EQ(t.ice.thickness_m, 0.03);
  EXPECT_DOUBLE_EQ(t.ice.diameter_mean_m, 0.012);
}

// The default template is the quick case (small and fast); the paper case by name; a template by its folder.
TEST(BrashCase, NewCaseTemplateByDefaultNameOrFolder) {
  const fs::path dir = temp_dir("templates");
  const std::string bc = (kBin / "brash-case").string() + " new ";
  ASSERT_EQ(run(bc + "q --cases-dir " + dir.string(), dir / "log.txt"), 0) << slurp(dir / "log.txt");
  const brash::Case quick = brash::load_case(kRepo / "cases/jbc_quick/case.yaml");
  const brash::Case q = brash::load_case(dir / "q/case.yaml");
  EXPECT_EQ(q.channel.length_m, quick.channel.length_m);
  EXPECT_EQ(q.ice.diameter_mean_m, quick.ice.diameter_mean_m);
  EXPECT_EQ(q.run.duration_s, quick.run.duration_s);
  EXPECT_EQ(q.description, "made by brash-case from jbc_quick");
  ASSERT_EQ(run(bc + "p --template jbc_ia_5kn --cases-dir " + dir.string(), dir / "log2.txt"), 0)
      << slurp(dir / "log2.txt");
  const brash::Case paper = brash::load_case(kRepo / "cases/jbc_ia_5kn/case.yaml");
  EXPECT_EQ(brash::load_case(dir / "p/case.yaml").channel.length_m, paper.channel.length_m);
  // a folder (not only its case.yaml) and a name that is neither
  ASSERT_EQ(run(bc + "f --template " + (kRepo / "cases/jbc_ia_5kn").string() + " --cases-dir " + dir.string(),
                dir / "log3.txt"), 0) << slurp(dir / "log3.txt");
  EXPECT_EQ(brash::load_case(dir / "f/case.yaml").ice.diameter_mean_m, paper.ice.diameter_mean_m);
  EXPECT_EQ(run(bc + "n --template no_such_case --cases-dir " + dir.string(), dir / "log4.txt"), 2);
  EXPECT_NE(slurp(dir / "log4.txt").find("--template no_such_case"), std::string::npos) << slurp(dir / "log4.txt");
  EXPECT_FALSE(fs::exists(dir / "n"));
}

TEST(BrashCase, InvalidValueLeavesNoFolder) {
  const fs::path dir = temp_dir("bad");
  EXPECT_EQ(run((kBin / "brash-case").string() + " new bad --cases-dir " + dir.string() + " --fluid-model potential",
                dir / "log.txt"),
            2);
  const std::string err = slurp(dir / "log.txt");
  EXPECT_NE(err.find("fluid.model"), std::string::npos) << err;
  EXPECT_NE(err.find("case.yaml"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(dir / "bad"));
  EXPECT_EQ(run((kBin / "brash-case").string() + " new x --cases-dir " + dir.string() + " --porosity 1.5",
                dir / "log2.txt"),
            2);
  EXPECT_NE(slurp(dir / "log2.txt").find("ice.porosity"), std::string::npos);
}

// brash-case derive: a variant through the case library (brash/case_derive.hpp); brash-case get: a resolved value.
TEST(BrashCase, DeriveWritesAValidatedVariant) {
  const fs::path dir = temp_dir("derive");
  const std::string bin = (kBin / "brash-case").string();
  const std::string base = (kRepo / "cases/jbc_quick").string();
  ASSERT_EQ(run(bin + " derive " + base + " --set fluid.model=drag --set run.duration_s=1.0"
                    " --set 'run.window_s=[0.375,0.75]' --set 'fluid.ca_table=uniform 0.5' --out " + (dir / "v").string(),
                dir / "log.txt"),
            0)
      << slurp(dir / "log.txt");
  brash::Case expected = brash::load_case(kRepo / "cases/jbc_quick/case.yaml");
  expected.fluid.model = brash::FluidModel::Drag;
  expected.run.duration_s = 1.0;
  expected.run.window_s = {0.375, 0.75};
  expected.fluid.ca_table = brash::CaTableSpec::uniform(0.5);
  EXPECT_EQ(brash::load_case(dir / "v/case.yaml"), expected);
  // an existing case is kept without --force
  EXPECT_EQ(run(bin + " derive " + base + " --set ice.seed=2 --out " + (dir / "v").string(), dir / "log2.txt"), 2);
  EXPECT_NE(slurp(dir / "log2.txt").find("exists"), std::string::npos);
  EXPECT_EQ(brash::load_case(dir / "v/case.yaml").ice.seed, 1u);
  ASSERT_EQ(run(bin + " derive " + base + " --set ice.seed=2 --force --out " + (dir / "v").string(), dir / "log3.txt"), 0)
      << slurp(dir / "log3.txt");
  const brash::Case s2 = brash::load_case(dir / "v/case.yaml");
  EXPECT_EQ(s2.ice.seed, 2u);
  EXPECT_EQ(s2.fluid.model, brash::FluidModel::Both);  // the base's again: only the keys given
  EXPECT_EQ(s2.ice.packing_file, fs::absolute(dir / "v/generated/packing.csv").lexically_normal());
  // a bad key or value: exit 2, the message names the key, nothing written
  for (const std::string key : {"fluid.modle=drag", "ice.porosity=1.5"}) {
    EXPECT_EQ(run(bin + " derive " + base + " --set " + key + " --out " + (dir / "bad").string(), dir / "log4.txt"), 2);
    EXPECT_NE(slurp(dir / "log4.txt").find("key '" + key.substr(0, key.find('='))), std::string::npos)
        << slurp(dir / "log4.txt");
    EXPECT_FALSE(fs::exists(dir / "bad/case.yaml"));
  }
}

// Published references describe one hull, speed, ice and fluid (docs/case_format.md "references"): a case made by
// new or derive that changes any of them does not carry the paper case's, and the command says so; one that
// changes only how the run is computed keeps them.
TEST(BrashCase, ReferencesOnlyWhereTheyDescribeTheCase) {
  const fs::path dir = temp_dir("references");
  const std::string bin = (kBin / "brash-case").string();
  const std::string paper = (kRepo / "cases/jbc_ia_5kn").string();
  ASSERT_TRUE(brash::load_case(kRepo / "cases/jbc_ia_5kn/case.yaml").references.declared());
  const auto made = [&](const std::string& args, const std::string& name) {
    const fs::path log = dir / (name + ".log");
    EXPECT_EQ(run(bin + " " + args, log), 0) << slurp(log);
    return std::make_pair(brash::load_case(dir / name / "case.yaml"), slurp(log));
  };
  for (const std::string opts : {"--speed 0.3", "--scale 50", "--thickness 0.05", "--ice-class IB", "--width 3"}) {
    const std::string name = "new" + std::to_string(opts.size()) + opts.substr(2, 3);
    const auto [c, log] = made("new " + name + " --template jbc_ia_5kn --cases-dir " + dir.string() + " " + opts, name);
    EXPECT_FALSE(c.references.declared()) << opts;
    EXPECT_NE(log.find("references"), std::string::npos) << opts << ": " << log;
    EXPECT_EQ(slurp(dir / name / "case.yaml").find("393"), std::string::npos) << opts;
  }
  const auto [same, same_log] = made("new same --template jbc_ia_5kn --cases-dir " + dir.string() + " --duration 10", "same");
  EXPECT_EQ(same.references, brash::load_case(kRepo / "cases/jbc_ia_5kn/case.yaml").references);
  for (const std::string key : {"ship.speed_m_s=0.3", "hull.draft_m=0.4", "ice.diameter_mean_m=0.02",
                                "friction.ice_hull=0.2", "fluid.drag_coefficient=1.0"}) {
    const std::string name = "d_" + key.substr(0, key.find('='));
    const auto [c, log] = made("derive " + paper + " --set " + key + " --out " + (dir / name).string(), name);
    EXPECT_FALSE(c.references.declared()) << key;
    EXPECT_NE(log.find("references"), std::string::npos) << key << ": " << log;
    EXPECT_NE(log.find(key.substr(0, key.find('='))), std::string::npos) << key << ": " << log;
  }
  for (const std::string key : {"ice.seed=2", "fluid.model=drag", "run.timestep_s=2.0e-4", "speedups.farfield=false"}) {
    const std::string name = "k_" + key.substr(0, key.find('='));
    const auto [c, log] = made("derive " + paper + " --set " + key + " --out " + (dir / name).string(), name);
    EXPECT_TRUE(c.references.declared()) << key;
  }
  // references set with the change are the user's own: kept as set
  const auto [own, own_log] = made("derive " + paper + " --set ship.speed_m_s=0.3 --set 'references.source=my tank' "
                                   "--out " + (dir / "own").string(), "own");
  EXPECT_EQ(own.references.source, "my tank");
}

TEST(BrashCase, GetPrintsAResolvedValue) {
  const fs::path dir = temp_dir("get");
  const std::string bin = (kBin / "brash-case").string();
  ASSERT_EQ(run(bin + " get " + (kRepo / "cases/jbc_quick").string() + " run.timestep_s", dir / "out.txt"), 0);
  EXPECT_EQ(slurp(dir / "out.txt"), "0.0008\n");
  ASSERT_EQ(run(bin + " get " + (kRepo / "cases/jbc_quick/case.yaml").string() + " guards.every_steps", dir / "o2.txt"), 0);
  EXPECT_EQ(slurp(dir / "o2.txt"), "10\n");
  EXPECT_EQ(run(bin + " get " + (kRepo / "cases/jbc_quick").string() + " run.timestep", dir / "o3.txt"), 2);
  EXPECT_NE(slurp(dir / "o3.txt").find("run.timestep"), std::string::npos);
}
