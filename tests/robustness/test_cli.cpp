// Bad command lines of the brash tools: unknown options, missing or wrong case/run folders.
// Each must exit non-zero and say which option or path is wrong (CLI11 exits 109 on an extra argument,
// 105/106 on a failed validation; our own errors exit 1).
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
  const std::string quick = std::string(BRASH_SOURCE_DIR) + "/cases/jbc_quick";
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
