#include "metrics/kinematics.hpp"

#include <cassert>
#include <cmath>

#include "engine/units.hpp"

namespace rodsort::metrics {

double heading(const engine::RodFrame& rod) { return std::atan2(rod.axis.y(), rod.axis.x()); }

double wrap_angle(double angle) {
  double wrapped = std::remainder(angle, 2.0 * kPi);  // in [-pi, pi]
  if (wrapped <= -kPi) wrapped += 2.0 * kPi;
  return wrapped;
}

std::vector<double> window_speeds(const engine::Frame& earlier, const engine::Frame& later) {
  assert(earlier.rods.size() == later.rods.size());
  assert(later.time > earlier.time);
  const double window = later.time - earlier.time;
  std::vector<double> speeds(later.rods.size());
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    speeds[i] = (later.rods[i].unwrapped - earlier.rods[i].unwrapped).norm() / window;
  }
  return speeds;
}

std::vector<double> orientation_changes(const engine::Frame& earlier, const engine::Frame& later,
                                        const std::vector<int>& rods) {
  std::vector<double> changes;
  changes.reserve(rods.size());
  for (const int rod : rods) {
    changes.push_back(wrap_angle(heading(later.rods.at(rod)) - heading(earlier.rods.at(rod))));
  }
  return changes;
}

}  // namespace rodsort::metrics
