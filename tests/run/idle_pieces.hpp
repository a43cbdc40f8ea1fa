// A particle snapshot's idle far-field pieces (any engine's particles/*.csv with the `active` column): they float at
// rest with their real submerged fraction (the core's immersion of their position, water level 0), no Ca and
// active = 0, and, where the snapshot has the hull force columns (LIGGGHTS), no force on the hull; the integrated
// pieces have active = 1. Both kinds must be present.
#pragma once
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "brash/core/immersion.hpp"

namespace brash::test {

inline void expect_idle_pieces_afloat(const std::string& snapshot_csv) {
  std::istringstream rows(snapshot_csv);
  std::string line;
  std::getline(rows, line);
  const std::string header = "id,x,y,z,radius,vx,vy,vz,submerged_fraction,ca_x,ca_y,ca_z,active";
  const bool with_force = line == header + ",hull_fx_N,hull_fy_N,hull_fz_N";
  if (!with_force) {
    ASSERT_EQ(line, header);
  }
  int idle = 0, active = 0;
  while (std::getline(rows, line)) {
    std::vector<double> v;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) v.push_back(std::stod(cell));
    ASSERT_EQ(v.size(), with_force ? 16u : 13u) << line;
    if (v[12] == 1) {
      ++active;
      continue;
    }
    ASSERT_EQ(v[12], 0.0) << line;
    ++idle;
    const double fraction = brash::core::immersion(v[4], v[3], 0.0).fraction;
    EXPECT_GT(fraction, 0.0) << line;  // the bed floats
    EXPECT_NEAR(v[8], fraction, 1e-5) << line;
    for (int c = 9; c <= 11; ++c) EXPECT_EQ(v[c], 0.0) << line;
    for (std::size_t c = 13; c < v.size(); ++c) EXPECT_EQ(v[c], 0.0) << line;
  }
  EXPECT_GT(idle, 0);
  EXPECT_GT(active, 0);
}

}  // namespace brash::test
