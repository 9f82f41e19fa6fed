#pragma once
// P(Delta theta): the distribution of the change of a rod's in-plane orientation between two
// frames tau apart (the paper's Fig. 2e-f, tau = 0.07 s). A single rod that is about to escape a
// trap shows a wide distribution; trapped rods, a narrow one.

#include <vector>

#include "engine/frame.hpp"
#include "metrics/histogram.hpp"

namespace rodsort::metrics {

/// Histogram over [-pi, pi] of the orientation changes (wrapped into (-pi, pi]) of the listed
/// rods, over every pair of frames `lag` frames apart.
Histogram orientation_change_distribution(const std::vector<engine::Frame>& frames,
                                          const std::vector<int>& rods, int lag = 1, int bins = 72);

/// 0, 1, ..., n - 1 for a frame of n rods.
std::vector<int> all_rods(const engine::Frame& frame);

}  // namespace rodsort::metrics
