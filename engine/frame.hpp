#pragma once
// What observers see of a simulation at one instant: plain numbers, no Bullet types, so that
// metrics run the same on a live simulation and on frames read back from rods.csv.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace rodsort::engine {

struct RodFrame {
  int species = 0;
  Eigen::Vector2d position;          ///< centre of mass wrapped into the cell [mm]
  Eigen::Vector2d unwrapped;         ///< centre of mass, never wrapped [mm]
  double z = 0.0;                    ///< height of the centre of mass [mm]
  Eigen::Vector3d axis;              ///< unit vector from the thick to the thin end
  Eigen::Vector3d velocity;          ///< of the centre of mass [mm/s]
  Eigen::Vector3d angular_velocity;  ///< [rad/s]
};

struct Frame {
  double time = 0.0;  ///< [s]
  std::vector<RodFrame> rods;
};

}  // namespace rodsort::engine
