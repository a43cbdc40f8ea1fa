// brash::core::spatial_order: a permutation that puts neighbours in space next to each other in memory.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>

#include "brash/core/spatial_order.hpp"

namespace {

using brash::core::spatial_order;
using V = Eigen::Vector3d;

// pieces on a 40 x 8 x 2 lattice of spacing 1, shuffled as a packing writes them
std::vector<V> shuffled_lattice(unsigned seed) {
  std::vector<V> p;
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 40; ++x) p.emplace_back(x + 0.5, y + 0.5 - 4, z + 0.5 - 1);
  std::shuffle(p.begin(), p.end(), std::mt19937(seed));
  return p;
}

TEST(SpatialOrder, IsAPermutationSortedByCellXThenYThenZ) {
  const auto p = shuffled_lattice(1);
  const auto order = spatial_order(p, 1.0);
  ASSERT_EQ(order.size(), p.size());
  std::vector<std::size_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], i);
  for (std::size_t s = 1; s < order.size(); ++s) {
    const V &a = p[order[s - 1]], &b = p[order[s]];
    ASSERT_TRUE(a.x() < b.x() || (a.x() == b.x() && (a.y() < b.y() || (a.y() == b.y() && a.z() < b.z()))))
        << "slot " << s;
  }
}

TEST(SpatialOrder, PutsNeighboursInSpaceCloseInMemory) {
  // every pair of lattice neighbours (distance 1) is at most one x-slab (8 x 2 = 16 slots) apart in the
  // order; in the shuffled packing order they are hundreds apart on average
  const auto p = shuffled_lattice(2);
  const auto order = spatial_order(p, 1.0);
  std::vector<std::size_t> slot(p.size());
  for (std::size_t s = 0; s < order.size(); ++s) slot[order[s]] = s;
  double gap_packing = 0, n = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j)
      if ((p[i] - p[j]).norm() < 1.01) {
        const auto d = slot[i] > slot[j] ? slot[i] - slot[j] : slot[j] - slot[i];
        EXPECT_LE(d, 16u);
        gap_packing += double(j - i), n += 1;
      }
  EXPECT_GT(gap_packing / n, 100.0);
}

TEST(SpatialOrder, IsDeterministicWithTiesInPieceOrder) {
  // all pieces in one cell: the order is the packing's own
  const std::vector<V> p{{0.1, 0.1, 0.1}, {0.3, 0.2, 0.1}, {0.2, 0.4, 0.3}};
  EXPECT_EQ(spatial_order(p, 1.0), (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_TRUE(spatial_order({}, 1.0).empty());
  const auto q = shuffled_lattice(3);
  EXPECT_EQ(spatial_order(q, 2.0), spatial_order(q, 2.0));
}

TEST(SpatialOrder, RefusesABadCellOrPosition) {
  EXPECT_THROW(spatial_order({V(0, 0, 0)}, 0.0), std::invalid_argument);
  EXPECT_THROW(spatial_order({V(0, 0, 0)}, -1.0), std::invalid_argument);
  EXPECT_THROW(spatial_order({V(0, 0, 0), V(std::nan(""), 0, 0)}, 1.0), std::invalid_argument);
}

}  // namespace
