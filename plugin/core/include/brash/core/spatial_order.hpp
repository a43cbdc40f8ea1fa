// A spatial order for a set of pieces: neighbours in space become neighbours in memory. An engine that stores
// its bodies in this order (brash-ode) walks them and their contacts with far fewer cache misses than in a
// packing's random order (docs/ode.md, "The spheres in a spatial order"). Pieces keep their ids:
// the order maps a storage slot to the piece's index in the packing.
#pragma once
#include <Eigen/Core>
#include <cstddef>
#include <vector>

namespace brash::core {

// Slot -> piece index: the pieces sorted by the cubic cell of side cell_m that holds their centre, cells in
// order of x, then y, then z (the channel's long axis first, so a slab across the channel is contiguous),
// ties by piece index. Deterministic; the identity for one piece or none. Throws std::invalid_argument for
// cell_m <= 0 or a non-finite position.
std::vector<std::size_t> spatial_order(const std::vector<Eigen::Vector3d>& positions_m, double cell_m);

}  // namespace brash::core
