#include "brash/core/spatial_order.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace brash::core {

std::vector<std::size_t> spatial_order(const std::vector<Eigen::Vector3d>& positions_m, double cell_m) {
  if (!(cell_m > 0) || !std::isfinite(cell_m))
    throw std::invalid_argument(fmt::format("spatial_order: cell size {} m must be positive", cell_m));
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < positions_m.size(); ++i) {
    if (!positions_m[i].allFinite())
      throw std::invalid_argument(fmt::format("spatial_order: piece {} has a non-finite position", i + 1));
    lo = lo.cwiseMin(positions_m[i]);
  }
  std::vector<std::array<long long, 3>> cell(positions_m.size());
  for (std::size_t i = 0; i < positions_m.size(); ++i)
    for (int k = 0; k < 3; ++k) cell[i][k] = std::llround(std::floor((positions_m[i][k] - lo[k]) / cell_m));
  std::vector<std::size_t> order(positions_m.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return cell[a] < cell[b]; });
  return order;
}

}  // namespace brash::core
