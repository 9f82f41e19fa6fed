#pragma once
// Initial positions for benchmark systems: rods on a jittered square lattice, each with a random
// heading, none overlapping another rod (across the periodic edges too) or a wall.

#include <vector>

#include "engine/model.hpp"
#include "engine/random_stream.hpp"
#include "engine/rod_shape.hpp"

namespace rodsort::bench {

/// Smallest gap kept between a rod and its neighbours or the walls at the start [mm].
inline constexpr double kPlacementClearance = 0.05;

/// `count` rods of species 0 with `shape` in the periodic cell [0, box_x) x [0, box_y), outside
/// `walls`. Uses the finest lattice that is coarse enough for every rod to find a free heading
/// and jitter; throws std::runtime_error when even a lattice with one site per rod fails.
std::vector<engine::RodInit> place_on_lattice(const engine::RodShape& shape, int count,
                                              double box_x, double box_y,
                                              const std::vector<engine::Wall>& walls,
                                              engine::RandomStream& random);

}  // namespace rodsort::bench
