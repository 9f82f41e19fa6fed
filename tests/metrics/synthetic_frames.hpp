#pragma once
// Hand-made frames with known answers for the metrics tests.

#include <cmath>

#include "engine/frame.hpp"

namespace rodsort::metrics::testing {

/// A rod lying flat at the unwrapped position (xu, yu), wrapped into a square cell of side `box`,
/// pointing (thick to thin) along `heading` [rad].
inline engine::RodFrame rod_at(double xu, double yu, double heading, int species = 0,
                               double box = 100.0) {
  engine::RodFrame rod;
  rod.species = species;
  rod.unwrapped = {xu, yu};
  rod.position = {xu - box * std::floor(xu / box), yu - box * std::floor(yu / box)};
  rod.z = 0.6;
  rod.axis = {std::cos(heading), std::sin(heading), 0.0};
  rod.velocity = Eigen::Vector3d::Zero();
  rod.angular_velocity = Eigen::Vector3d::Zero();
  return rod;
}

inline engine::Frame frame_at(double time, std::vector<engine::RodFrame> rods) {
  engine::Frame frame;
  frame.time = time;
  frame.rods = std::move(rods);
  return frame;
}

}  // namespace rodsort::metrics::testing
