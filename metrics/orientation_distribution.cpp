#include "metrics/orientation_distribution.hpp"

#include <cassert>
#include <numeric>

#include "engine/units.hpp"
#include "metrics/kinematics.hpp"

namespace rodsort::metrics {

Histogram orientation_change_distribution(const std::vector<engine::Frame>& frames,
                                          const std::vector<int>& rods, int lag, int bins) {
  assert(lag > 0);
  Histogram histogram(-kPi, kPi, bins);
  for (std::size_t k = 0; k + lag < frames.size(); ++k) {
    histogram.add(orientation_changes(frames[k], frames[k + lag], rods));
  }
  return histogram;
}

std::vector<int> all_rods(const engine::Frame& frame) {
  std::vector<int> rods(frame.rods.size());
  std::iota(rods.begin(), rods.end(), 0);
  return rods;
}

}  // namespace rodsort::metrics
