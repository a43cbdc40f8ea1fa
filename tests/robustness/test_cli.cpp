// Bad command lines of the brash tools: unknown options, missing or wrong case/run folders, impossible FSICR
// geometry, a packing that is not the case's ice. Each must exit non-zero and say which option, path or line is
// wrong (CLI11 exits 109 on an extra argument, 105/106 on a failed validation; our own errors exit 1, input
// errors 2).
#include <gtest/gtest.h>

#include "catalogue.hpp"

using namespace brash::robust;

namespace {

std::string q(const char* path) { return std::string("'") + path + "'"; }

Entry cli(std::string name, std::string command, std::vector<std::string> expect, int exit_code = 256) {
  return {std::move(name),
          [command](const fs::path& dir) { return run_command(dir, replace_all(command, "{dir}", dir.string())); },
          std::move(expect), exit_code};
}

std::vector<Entry> commands() {
  std::vector<Entry> c;
  const std::string run = q(BRASH_LIGGGHTS_RUN_EXE), pack = q(BRASH_PACK_EXE), hull = q(BRASH_HULL_EXE);
  const std::string quick = std::string(BRASH_SOURCE_DIR) + "/cases/jbc_narrow";
  c.push_back(cli("liggghts_run_unknown_option", run + " " + quick + " --frobnicate", {"--frobnicate"}));
  c.push_back(cli("liggghts_run_missing_case_dir", run + " {dir}/no_such_case --prepare-only",
                  {"{dir}/no_such_case"}));
  c.push_back(cli("liggghts_run_no_arguments", run, {"case_dir"}));
  c.push_back(cli("liggghts_run_ranks_zero", run + " " + quick + " --np 0", {"--np"}));
  c.push_back(cli("liggghts_run_bad_model_override", run + " " + quick + " --model viscous --prepare-only --out {dir}/r",
                  {"viscous"}));
  c.push_back(cli("liggghts_run_case_dir_without_case_yaml", "mkdir -p {dir}/empty_case && " + run +
                                                                " {dir}/empty_case --prepare-only --out {dir}/r",
                  {"{dir}/empty_case"}));
  c.push_back(cli("pack_unknown_option", pack + " " + quick + " --frobnicate", {"--frobnicate"}));
  c.push_back(cli("pack_missing_case_dir", pack + " {dir}/no_such_case --out {dir}/p.csv", {"{dir}/no_such_case"}));
  c.push_back(cli("pack_porosity_impossible", pack + " " + quick + " --porosity 1.5 --out {dir}/p.csv",
                  {"porosity"}));
  c.push_back(cli("pack_drops_out_of_range", pack + " " + quick + " --drops 0 --out {dir}/p.csv", {"--drops"}));
  c.push_back(cli("hull_unknown_subcommand", hull + " fix hull.stl", {"unknown command 'fix'"}, 109));
  c.push_back(cli("hull_check_missing_draft", hull + " check hull.stl", {"--draft"}));
  c.push_back(cli("hull_check_missing_file", hull + " check {dir}/none.stl --draft 0.4", {"{dir}/none.stl", "cannot open"},
                  1));
#ifdef BRASH_POST_EXE
  const std::string post = q(BRASH_POST_EXE);
  c.push_back(cli("post_unknown_option", post + " {dir} --frobnicate", {"--frobnicate"}));
  c.push_back(cli("post_missing_run_dir", post + " {dir}/no_such_run", {"{dir}/no_such_run"}));
#endif
  return c;
}

}  // namespace

class Cli : public ::testing::TestWithParam<Entry> {};

TEST_P(Cli, RejectedWithClearMessage) {
  const Entry& e = GetParam();
  const fs::path dir = fresh_dir(e.name);
  const Outcome o = e.run(dir);
  expect_clear_error(e, o, dir);
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(BadArguments, Cli, ::testing::ValuesIn(commands()),
                         [](const ::testing::TestParamInfo<Entry>& i) { return i.param.name; });

// A packing that cannot be the case's ice: a piece beyond the channel's end, one far above the water,
// two pieces with one id. They used to reach LIGGGHTS (and stop it with "Did not assign all atoms correctly")
// or run; brash-liggghts-run now refuses them naming the packing file and line, before it makes the run
// directory.
TEST(CliPacking, RunnerRefusesAPackingThatIsNotTheCasesIceBeforeWritingAnything) {
  const fs::path smoke = fs::path(BRASH_SOURCE_DIR) / "tests/yade/smoke_case/case.yaml";  // channel 0.2 x 1.6 m
  const struct {
    const char *name, *row, *problem;
  } bad[] = {
      {"beyond_the_channel_end", "2,1.2,0,0,0.035", "outside the channel"},
      {"far_above_the_water", "2,0.1,0.3,0.4,0.035", "above the water"},
      {"duplicate_id", "1,0.1,0.3,0,0.035", "piece id 1 is given twice"},
  };
  for (const auto& b : bad) {
    const fs::path dir = fresh_dir(std::string("runner_packing_") + b.name);
    fs::create_directories(dir / "case");
    fs::copy_file(smoke, dir / "case/case.yaml");
    write_file(dir / "case/packing.csv", std::string("id,x,y,z,diameter\n1,0.1,0,0,0.035\n") + b.row + "\n");
    const Outcome o = run_command(dir, q(BRASH_LIGGGHTS_RUN_EXE) + " '" + (dir / "case").string() +
                                           "' --prepare-only --no-post --out '" + (dir / "run").string() + "'");
    EXPECT_NE(o.exit_code, 0) << b.name << ": " << o.message;
    EXPECT_NE(o.message.find((dir / "case/packing.csv:3: ").string()), std::string::npos) << b.name << ": " << o.message;
    EXPECT_NE(o.message.find(b.problem), std::string::npos) << b.name << ": " << o.message;
    EXPECT_FALSE(fs::exists(dir / "run")) << b.name << ": a run directory was written";
    fs::remove_all(dir);
  }
}

#ifdef BRASH_POST_EXE
// brash-post fsicr with geometry no hull has printed "R_CH = -nan kN" (negative beam) or a number
// with a validity-range warning, and exited 0. Impossible values are input errors naming the option (exit 2,
// nothing computed); values outside the rule's validity range stay warnings.
TEST(CliFsicr, ImpossibleGeometryIsAnErrorNamingTheOption) {
  const std::string good = q(BRASH_POST_EXE) +
                           " fsicr --L 199.11 --B 32 --T 11.733 --alpha 25 --phi2 60 --Lpar 100 --Lbow 40 --Awf 900";
  const struct {
    const char *from, *to, *named;
  } bad[] = {
      {"--B 32", "--B -32", "--B -32: "},
      {"--L 199.11", "--L 0", "--L 0: "},
      {"--T 11.733", "--T nan", "--T nan: "},
      {"--T 11.733", "--T inf", "--T inf: "},
      {"--Awf 900", "--Awf -900", "--Awf -900: "},
      {"--Lbow 40", "--Lbow 250", "--Lbow 250: "},
      {"--Lpar 100", "--Lpar 210", "--Lpar 210: "},
      {"--Lpar 100", "--Lpar 170", "--Lbow 40 + --Lpar 170"},
      {"--alpha 25", "--alpha 95", "--alpha 95: "},
      {"--alpha 25", "--alpha 0", "--alpha 0: "},
      {"--phi2 60", "--phi2 -10", "--phi2 -10: "},
      {"--phi2 60", "--phi2 60 --phi1 120", "--phi1 120: "},
  };
  const fs::path dir = fresh_dir("fsicr_impossible");
  for (const auto& b : bad) {
    const Outcome o = run_command(dir, replace_all(good, b.from, b.to));
    EXPECT_EQ(o.exit_code, 2) << b.to << ": " << o.message;
    EXPECT_NE(o.message.find(b.named), std::string::npos) << b.to << ": " << o.message;
    EXPECT_EQ(o.message.find("R_CH"), std::string::npos) << b.to << ": " << o.message;  // nothing computed
  }
  // Possible, but outside the rule's validity range (alpha 10 deg, draught 3 m): R_CH with warnings.
  const Outcome w = run_command(dir, replace_all(replace_all(good, "--alpha 25", "--alpha 10"), "--T 11.733", "--T 3"));
  EXPECT_EQ(w.exit_code, 0) << w.message;
  EXPECT_NE(w.message.find("R_CH = "), std::string::npos) << w.message;
  EXPECT_NE(w.message.find("warning: alpha_deg = 10 outside the FSICR validity range"), std::string::npos) << w.message;
  EXPECT_NE(w.message.find("warning: T_m = 3 outside the FSICR validity range"), std::string::npos) << w.message;
  fs::remove_all(dir);
}
#endif
