// LIGGGHTS' dumps -> particles/ (plugin/liggghts/runner/particle_snapshots.cpp) on hand-written dumps, no engine:
//   - without the moving window a snapshot is the dump's pieces, to the byte as it has always been written;
//   - with it, every snapshot holds every piece of packing.data: those never dumped yet held out where the
//   packing has them, those dumped before and gone since removed where they were last seen, both at rest, with
//   the state column 0 / 1 / 2; a resumed run's earlier snapshots give the last seen positions.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "brash/case.hpp"
#include "liggghts_runner.h"
#include "particle_snapshots.h"

namespace fs = std::filesystem;

namespace {

// A dump custom file of liggghts_input.cpp's columns (id x y z radius vx vy vz f_fl[1..5]).
void write_dump(const fs::path& run_dir, long step, const std::string& atoms) {
  std::ofstream(run_dir / "particles" / fmt::format("dump.{:010d}.txt", step))
      << "ITEM: TIMESTEP\n" << step << "\nITEM: NUMBER OF ATOMS\n3\nITEM: BOX BOUNDS ff ff ff\n0 1\n0 1\n0 1\n"
      << "ITEM: ATOMS id x y z radius vx vy vz f_fl[1] f_fl[2] f_fl[3] f_fl[4] f_fl[5]\n"
      << atoms;
}

fs::path make_run_dir(const std::string& name) {
  const fs::path dir = brash::test::fresh_dir(name);
  fs::create_directories(dir / "particles");
  // the scene's packing (liggghts_input.cpp's data_file): three pieces of diameter 0.02 m, piece 3 half under
  std::ofstream(dir / "packing.data") << "brash channel packing\n\n3 atoms\n3 atom types\n\n-1 2 xlo xhi\n-1 1 ylo yhi\n"
                                         "-1 1 zlo zhi\n\nAtoms\n\n"
                                         "1 1 0.02 900 0.1 0.2 -0.005\n2 1 0.02 900 0.3 0.2 -0.005\n"
                                         "3 1 0.02 900 0.5 0.2 0\n";
  return dir;
}

brash::Case window_case(bool moving_window) {
  brash::Case c;
  c.run.timestep_s = 1e-3;
  c.hull.start_x_m = -1.0;
  c.ship.speed_m_s = 0.5;
  c.water.level_m = 0.0;
  c.speedups.moving_window = moving_window;
  return c;
}

const std::string kStep0 = "1 0.1 0.2 -0.005 0.01 0 0 0 0.75 0.5 0.5 0.8 0\n2 0.3 0.2 -0.005 0.01 0 0 0 0.75 0.5 0.5 0.8 0\n";
const std::string kStep100 = "2 0.31 0.21 -0.004 0.01 0.1 0.01 0.001 0.7 0.5 0.5 0.8 1\n"
                             "3 0.49 0.2 0 0.01 0.05 0 0 0.5 0.5 0.5 0.8 1\n";

}  // namespace

TEST(ParticleSnapshots, WithoutTheWindowTheDumpsAsAlways) {
  const fs::path dir = make_run_dir("snapshots_plain");
  write_dump(dir, 100, "2 0.31 0.21 -0.004 0.01 0.1 0.01 0.001 0.7 0.5 0.5 0.8 1\n"
                       "1 0.123456789012 0.2 -0.005 0.01 0 0 0 0.123456789 0 0 0 0\n");
  EXPECT_EQ(brash::liggghts::convert_dumps(dir, window_case(false)), 1u);
  EXPECT_EQ(brash::test::read_text(dir / "particles/particles_0000000100.csv"),
            "id,x,y,z,radius,vx,vy,vz,submerged_fraction,ca_x,ca_y,ca_z,active\n"
            "1,0.123456789,0.2,-0.005,0.01,0,0,0,0.123457,0,0,0,0\n"
            "2,0.31,0.21,-0.004,0.01,0.1,0.01,0.001,0.7,0.5,0.5,0.8,1\n");
  EXPECT_EQ(brash::test::read_text(dir / "particles/index.csv"),
            "step,t_s,file,hull_x_m\n100,0.1,particles_0000000100.csv,-0.95\n");
  EXPECT_FALSE(fs::exists(dir / "particles/dump.0000000100.txt"));
  fs::remove_all(dir);
}

TEST(ParticleSnapshots, WithTheWindowEveryPieceOfThePackingWithItsState) {
  const fs::path dir = make_run_dir("snapshots_window");
  write_dump(dir, 0, kStep0);     // piece 3 held out
  write_dump(dir, 100, kStep100);  // piece 3 entered, piece 1 removed
  EXPECT_EQ(brash::liggghts::convert_dumps(dir, window_case(true)), 2u);
  const std::string header = "id,x,y,z,radius,vx,vy,vz,submerged_fraction,ca_x,ca_y,ca_z,active,state\n";
  EXPECT_EQ(brash::test::read_text(dir / "particles/particles_0000000000.csv"),
            header + "1,0.1,0.2,-0.005,0.01,0,0,0,0.75,0.5,0.5,0.8,0,0\n"
                     "2,0.3,0.2,-0.005,0.01,0,0,0,0.75,0.5,0.5,0.8,0,0\n"
                     "3,0.5,0.2,0,0.01,0,0,0,0.5,0,0,0,0,1\n");  // where the packing has it, half under, at rest
  EXPECT_EQ(brash::test::read_text(dir / "particles/particles_0000000100.csv"),
            header + "1,0.1,0.2,-0.005,0.01,0,0,0,0.75,0,0,0,0,2\n"  // where it was last seen, at rest
                     "2,0.31,0.21,-0.004,0.01,0.1,0.01,0.001,0.7,0.5,0.5,0.8,1,0\n"
                     "3,0.49,0.2,0,0.01,0.05,0,0,0.5,0.5,0.5,0.8,1,0\n");
  // a resumed attempt's dump: its removed piece 2 from the snapshot the earlier attempt converted
  write_dump(dir, 200, "3 0.48 0.2 0 0.01 0.05 0 0 0.5 0.5 0.5 0.8 1\n");
  EXPECT_EQ(brash::liggghts::convert_dumps(dir, window_case(true)), 1u);
  EXPECT_EQ(brash::test::read_text(dir / "particles/particles_0000000200.csv"),
            header + "1,0.1,0.2,-0.005,0.01,0,0,0,0.75,0,0,0,0,2\n"
                     "2,0.31,0.21,-0.004,0.01,0,0,0,0.7,0,0,0,0,2\n"
                     "3,0.48,0.2,0,0.01,0.05,0,0,0.5,0.5,0.5,0.8,1,0\n");
  EXPECT_EQ(brash::test::read_text(dir / "particles/index.csv"),
            "step,t_s,file,hull_x_m\n0,0,particles_0000000000.csv,-1\n100,0.1,particles_0000000100.csv,-0.95\n"
            "200,0.2,particles_0000000200.csv,-0.9\n");
  fs::remove_all(dir);
}

// The runner's dumps carry the hull wall's force on each piece (f_force_hullwall, store_force yes): the snapshot
// gets the force of each piece on the hull, negated, after active (and state, 0 for a piece outside the scene).
TEST(ParticleSnapshots, TheHullWallsForceOnEachPieceIsItsForceOnTheHull) {
  const fs::path dir = make_run_dir("snapshots_force");
  const auto write_force_dump = [&](long step, const std::string& atoms) {
    std::ofstream(dir / "particles" / fmt::format("dump.{:010d}.txt", step))
        << "ITEM: TIMESTEP\n" << step << "\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS ff ff ff\n0 1\n0 1\n0 1\n"
        << "ITEM: ATOMS id x y z radius vx vy vz f_fl[1] f_fl[2] f_fl[3] f_fl[4] f_fl[5] f_force_hullwall[1] "
           "f_force_hullwall[2] f_force_hullwall[3]\n"
        << atoms;
  };
  write_force_dump(100, "2 0.31 0.21 -0.004 0.01 0.1 0.01 0.001 0.7 0.5 0.5 0.8 1 0.25 -0.5 0\n"
                        "1 0.1 0.2 -0.005 0.01 0 0 0 0.75 0 0 0 0 0 0 0\n");
  EXPECT_EQ(brash::liggghts::convert_dumps(dir, window_case(false)), 1u);
  EXPECT_EQ(brash::test::read_text(dir / "particles/particles_0000000100.csv"),
            "id,x,y,z,radius,vx,vy,vz,submerged_fraction,ca_x,ca_y,ca_z,active,hull_fx_N,hull_fy_N,hull_fz_N\n"
            "1,0.1,0.2,-0.005,0.01,0,0,0,0.75,0,0,0,0,0,0,0\n"
            "2,0.31,0.21,-0.004,0.01,0.1,0.01,0.001,0.7,0.5,0.5,0.8,1,-0.25,0.5,0\n");
  fs::remove(dir / "particles/particles_0000000100.csv");
  write_force_dump(100, "2 0.31 0.21 -0.004 0.01 0.1 0.01 0.001 0.7 0.5 0.5 0.8 1 0.25 -0.5 0\n");
  EXPECT_EQ(brash::liggghts::convert_dumps(dir, window_case(true)), 1u);
  EXPECT_EQ(brash::test::read_text(dir / "particles/particles_0000000100.csv"),
            "id,x,y,z,radius,vx,vy,vz,submerged_fraction,ca_x,ca_y,ca_z,active,state,hull_fx_N,hull_fy_N,hull_fz_N\n"
            "1,0.1,0.2,-0.005,0.01,0,0,0,0.84375,0,0,0,0,1,0,0,0\n"
            "2,0.31,0.21,-0.004,0.01,0.1,0.01,0.001,0.7,0.5,0.5,0.8,1,0,-0.25,0.5,0\n"
            "3,0.5,0.2,0,0.01,0,0,0,0.5,0,0,0,0,1,0,0,0\n");
  fs::remove_all(dir);
}

TEST(ParticleSnapshots, WithTheWindowAMissingPackingIsNamed) {
  const fs::path dir = make_run_dir("snapshots_no_packing");
  fs::remove(dir / "packing.data");
  write_dump(dir, 0, kStep0);
  try {
    brash::liggghts::convert_dumps(dir, window_case(true));
    ADD_FAILURE() << "no error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("packing.data: cannot read the scene's packing"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}
