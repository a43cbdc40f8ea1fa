// fix brash/exit: a piece coasting out through the channel's open end is removed at a neighbour build, before
// the box guard sees it; the run goes on with the other pieces (and their contacts), on 1 and 2 ranks, and
// the count survives a restart. Without the fix the same scene stops with the guard's "left the box".
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "liggghts_runner.h"

using brash::test::fresh_dir;
using brash::test::read_table;
using brash::test::read_text;
using brash::test::run_liggghts;

namespace {
constexpr double d = 0.017578;

// A floating two-row raft in a 1 m box (x), and one piece at x = 0.1 m coasting towards x = 0 at 0.5 m/s
// (gravity and no fluid forces: the pieces rest on a wall at z = 0, so only x motion matters).
std::string scene(bool with_exit) {
  return fmt::format(R"X(atom_style granular
atom_modify map array sort 0 0.0
boundary f p f
newton off
communicate single vel yes
units si
region reg block 0 1 0 {L} -0.1 0.1 units box
create_box 1 reg
neighbor 0.0035 bin
neigh_modify delay 0
{contacts}
timestep 1e-4
lattice sc {d}
region raft block 0.4 0.6 0 {L} 0.0 0.001 units box
create_atoms 1 region raft
create_atoms 1 single 0.1 0.05 0.0 units box
set group all diameter {d} density 900
region start block 0.05 0.15 0 1 -0.1 0.1 units box
group runner region start
velocity runner set -0.5 0 0 units box
fix floor all wall/gran model hertz tangential history primitive type 1 zplane -0.0088
fix integr all nve/sphere
fix grav all gravity 9.81 vector 0 0 -1
fix guard all brash/guard every 10 box 0.0044 0.9956 -1 1 -0.09 0.09
{exit}
variable t equal step*dt
variable n equal atoms
fix out all print 500 "${{t}} ${{n}}" file out.txt screen no
thermo_style custom step atoms{exit_col}
thermo 1000
thermo_modify norm no lost ignore
run 1000
write_restart mid.restart
run 3000
write_restart end.restart
)X",
                     fmt::arg("contacts", brash::test::ice_contact_model("1.35")), fmt::arg("d", d),
                     fmt::arg("L", 10 * d),
                     fmt::arg("exit", with_exit ? "fix exit all brash/exit xlo 0.0079 xhi 0.9921" : ""),
                     fmt::arg("exit_col", with_exit ? " f_exit" : ""));
}

}  // namespace

TEST(LiggghtsExit, PieceLeavingThroughTheEndIsRemovedAndTheRunGoesOn) {
  for (int ranks : {1, 2}) {
    auto dir = fresh_dir(fmt::format("exit_np{}", ranks));
    ASSERT_EQ(run_liggghts(dir, scene(true), ranks), 0) << read_text(dir / "screen_in.lmp.txt");
    const std::string screen = read_text(dir / "screen_in.lmp.txt");
    EXPECT_NE(screen.find("1 piece(s) left the scene through the channel's ends"), std::string::npos)
        << screen;
    const auto rows = read_table(dir / "out.txt");
    ASSERT_GE(rows.size(), 8u);
    const int n = static_cast<int>(rows.front()[1]);  // at t = 0.05 s the piece is still in (x = 0.075 m)
    ASSERT_GT(n, 20);
    EXPECT_EQ(rows.back()[1], n - 1) << "ranks " << ranks;  // 0.1 m at 0.5 m/s: gone after ~0.2 s of 0.4 s
    // the count is kept in the restart file: a run read from it reports 1 removed so far
    // a run read from a restart file: from end.restart the count is kept (1 removed so far); from mid.restart
    // (step 1000, the piece still in) the piece is removed in the resumed run too (LIGGGHTS' own `lost error`
    // would stop it there: its count is the run's initial one after a read_restart; the fix checks instead)
    for (const std::string from : {"end", "mid"}) {
      const std::string again =
          std::string(
              "atom_style granular\natom_modify map array sort 0 0.0\nboundary f p f\nnewton off\n"
              "communicate single vel yes\nunits si\nread_restart ") +
          from + ".restart\nneighbor 0.0035 bin\nneigh_modify delay 0\n" +
          brash::test::ice_contact_model("1.35") +
          "\ntimestep 1e-4\nfix floor all wall/gran model hertz tangential history primitive type 1 zplane "
          "-0.0088\n"
          "fix exit all brash/exit xlo 0.0079 xhi 0.9921\nfix integr all nve/sphere\n"
          "fix grav all gravity 9.81 vector 0 0 -1\nvariable e equal f_exit\nvariable n equal atoms\n"
          "fix out all print 10 \"${e} ${n}\" file again.txt screen no\nthermo_modify norm no lost ignore\n"
          "run 4000 upto\nrun 10\n";
      ASSERT_EQ(run_liggghts(dir, again, ranks, "in_again.lmp"), 0)
          << read_text(dir / "screen_in_again.lmp.txt");
      const auto a = read_table(dir / "again.txt");
      ASSERT_FALSE(a.empty());
      EXPECT_EQ(a.back()[0], 1) << from;
      EXPECT_EQ(a.back()[1], n - 1) << from;
    }
  }
}

// A walled end (channel.ends: walls writes the runner's end walls as primitive planes like this one): the
// coasting piece bounces off the wall at x = 0 and stays in the scene.
TEST(LiggghtsExit, AnEndWallKeepsThePieceIn) {
  auto dir = fresh_dir("exit_walled");
  std::string in = scene(true);
  const std::string floor = "fix floor all wall/gran";
  in.insert(in.find(floor), "fix end0 all wall/gran model hertz tangential history primitive type 1 xplane 0\n");
  ASSERT_EQ(run_liggghts(dir, in), 0) << read_text(dir / "screen_in.lmp.txt");
  EXPECT_EQ(read_text(dir / "screen_in.lmp.txt").find("left the scene"), std::string::npos);
  const auto rows = read_table(dir / "out.txt");
  ASSERT_GE(rows.size(), 8u);
  EXPECT_EQ(rows.back()[1], rows.front()[1]);  // every piece still there at t = 0.4 s
}

TEST(LiggghtsExit, WithoutItTheGuardStopsTheRun) {
  auto dir = fresh_dir("exit_none");
  EXPECT_NE(run_liggghts(dir, scene(false)), 0);
  EXPECT_NE(read_text(dir / "screen_in.lmp.txt").find("left the box: x ="), std::string::npos)
      << read_text(dir / "screen_in.lmp.txt");
}

// An atom LIGGGHTS drops elsewhere (here through the top of the box, the guard looking too rarely to see it)
// is not let through silently under `lost ignore`: the exit fix counts the atoms and stops the run.
TEST(LiggghtsExit, AtomLostThroughAnotherFaceStopsTheRun) {
  auto dir = fresh_dir("exit_lost");
  std::string in = scene(true);
  in.replace(in.find("velocity runner set -0.5 0 0"), std::string("velocity runner set -0.5 0 0").size(),
             "velocity runner set 0 0 8");
  in.replace(in.find("brash/guard every 10"), std::string("brash/guard every 10").size(),
             "brash/guard every 100000");
  EXPECT_NE(run_liggghts(dir, in), 0);
  EXPECT_NE(read_text(dir / "screen_in.lmp.txt").find("1 atom(s) lost: they left the box elsewhere"),
            std::string::npos)
      << read_text(dir / "screen_in.lmp.txt");
}

TEST(LiggghtsExit, BadArgumentsAreNamed) {
  auto dir = fresh_dir("exit_args");
  std::string in = scene(false);
  in.replace(in.find("run 1000"), 8, "fix exit all brash/exit xlo 0.5 xhi 0.2\nrun 0");
  EXPECT_NE(run_liggghts(dir, in), 0);
  EXPECT_NE(read_text(dir / "screen_in.lmp.txt").find("fix brash/exit: xlo 0.5 must be below xhi 0.2"),
            std::string::npos)
      << read_text(dir / "screen_in.lmp.txt");
  in = scene(false);
  in.replace(in.find("run 1000"), 8, "fix exit all brash/exit xlo 0.1 xhigh 0.9\nrun 0");
  EXPECT_NE(run_liggghts(dir, in), 0);
  EXPECT_NE(read_text(dir / "screen_in.lmp.txt").find("unknown keyword xhigh"), std::string::npos);
}
