// The hull force split brash-liggghts-run records beside the total (hull_force.csv, brash::run::kSplitColumns)
// on the 720-sphere smoke case, whole channel and half channel (speedups.symmetry_y: the half hull's parts
// doubled, as its fx): bow + mid-body + stern and normal + tangential add up to fx_N on every row, to the six
// significant digits fix ave/time writes.
#include <gtest/gtest.h>

#include <cmath>

#include "brash/run/force_record.hpp"
#include "runner_case.h"

namespace fs = std::filesystem;

namespace {

fs::path smoke_case(const std::string& name, const std::string& extra) {
  const fs::path dir = brash::test::fresh_dir(name) / "case";
  fs::create_directories(dir);
  const fs::path src = fs::path(BRASH_SOURCE_DIR) / "tests/yade/smoke_case";
  fs::copy_file(src / "packing.csv", dir / "packing.csv");
  std::ofstream(dir / "case.yaml") << brash::test::read_text(src / "case.yaml") << extra;
  return dir;
}

void run_and_check(const fs::path& case_dir) {
  const fs::path out = case_dir.parent_path() / "run";
  const std::string cmd = brash::test::runner_command(case_dir, out) + " --duration 0.1 > '" +
                          (case_dir.parent_path() / "run.log").string() + "' 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << brash::test::read_text(case_dir.parent_path() / "run.log");
  const auto r = brash::run::read_hull_force_csv(out / "hull_force.csv", false);
  ASSERT_TRUE(r.has_split());
  ASSERT_GE(r.rows.size(), 10u);
  double fx_max = 0;
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    const double fx = r.rows[i].fx_N;
    double part[5], sum_abs = std::abs(fx);
    for (std::size_t k = 0; k < 5; ++k) sum_abs += std::abs(part[k] = r.extra_value(i, r.split_column(k)));
    const double tol = 1.5e-6 * sum_abs + 1e-300;
    EXPECT_NEAR(part[0] + part[1] + part[2], fx, tol) << "t = " << r.rows[i].t_s;
    EXPECT_NEAR(part[3] + part[4], fx, tol) << "t = " << r.rows[i].t_s;
    fx_max = std::max(fx_max, std::abs(fx));
  }
  EXPECT_GT(fx_max, 0.5);  // the bow met the ice
  EXPECT_NE(brash::test::read_text(out / "meta.json").find("\"x_par_fwd_m\""), std::string::npos);
  fs::remove_all(case_dir.parent_path());
}

}  // namespace

TEST(LiggghtsSplitRunner, PartsAddUpToTheTotalOnEveryRow) { run_and_check(smoke_case("split_whole", "")); }

TEST(LiggghtsSplitRunner, HalfChannelPartsAreTheWholeShips) {
  run_and_check(smoke_case("split_half", "speedups:\n  symmetry_y: true\n"));
}
