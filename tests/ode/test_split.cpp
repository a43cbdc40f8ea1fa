// The hull force split brash-ode records beside the total (hull_force.csv, brash::run::kSplitColumns) on the
// 720-sphere smoke case: bow + mid-body + stern and normal + tangential add up to fx_N on every row, and the
// split goes on across a resume from a restart file.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "brash/run/force_record.hpp"

namespace fs = std::filesystem;

namespace {

fs::path fresh(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("brash_ode_split_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

int ode(const std::string& args, const fs::path& log) {
  return std::system((std::string("'") + BRASH_ODE_EXE + "' " + args + " > '" + log.string() + "' 2>&1").c_str());
}

// Every row's parts add up to fx_N to the record's 9 significant digits; returns the largest |fx_N|.
double check_sums(const brash::run::ForceRecord& r) {
  EXPECT_TRUE(r.has_split());
  if (!r.has_split()) return 0;
  double fx_max = 0;
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    const double fx = r.rows[i].fx_N;
    double part[5];
    for (std::size_t k = 0; k < 5; ++k) part[k] = r.extra_value(i, r.split_column(k));
    const double tol = 3e-9 * (std::abs(part[0]) + std::abs(part[1]) + std::abs(part[2]) + std::abs(part[3]) +
                               std::abs(part[4]) + std::abs(fx)) + 1e-300;
    EXPECT_NEAR(part[0] + part[1] + part[2], fx, tol) << "t = " << r.rows[i].t_s;
    EXPECT_NEAR(part[3] + part[4], fx, tol) << "t = " << r.rows[i].t_s;
    fx_max = std::max(fx_max, std::abs(fx));
  }
  return fx_max;
}

}  // namespace

TEST(OdeSplit, PartsAddUpToTheTotalOnEveryRow) {
  const fs::path dir = fresh("sums");
  ASSERT_EQ(ode(std::string(BRASH_SMOKE_CASE) + " --out " + dir.string() + " --duration 0.2 --no-post",
                dir.string() + ".log"),
            0);
  const auto r = brash::run::read_hull_force_csv(dir / "hull_force.csv", false);
  ASSERT_EQ(r.rows.size(), 20u);
  EXPECT_GT(check_sums(r), 1.0);  // the bow met the ice
  std::ifstream meta(dir / "meta.json");
  const std::string text{std::istreambuf_iterator<char>(meta), {}};
  EXPECT_NE(text.find("\"x_par_fwd_m\""), std::string::npos);
  fs::remove_all(dir);
  fs::remove(dir.string() + ".log");
}

// A run stopped at a step and resumed from its restart file records the same split as one that ran through.
TEST(OdeSplit, ResumedRunRecordsTheSameSplit) {
  const fs::path whole = fresh("whole"), parts = fresh("parts");
  const std::string common = std::string(BRASH_SMOKE_CASE) + " --duration 0.1 --no-post --restart-every 0.025";
  ASSERT_EQ(ode(common + " --out " + whole.string(), whole.string() + ".log"), 0);
  EXPECT_NE(ode(common + " --out " + parts.string() + " --stop-after-step 130", parts.string() + ".log"), 0);
  ASSERT_EQ(ode("--resume " + parts.string() + " --no-post", parts.string() + ".resume.log"), 0);
  std::ifstream a(whole / "hull_force.csv"), b(parts / "hull_force.csv");
  const std::string ta{std::istreambuf_iterator<char>(a), {}}, tb{std::istreambuf_iterator<char>(b), {}};
  EXPECT_EQ(ta, tb);
  check_sums(brash::run::read_hull_force_csv(parts / "hull_force.csv", false));
  for (const auto& d : {whole, parts}) {
    fs::remove_all(d);
    for (const char* ext : {".log", ".resume.log"}) fs::remove(d.string() + ext);
  }
}
