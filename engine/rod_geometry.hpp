#pragma once
// The spheres of a rod in its body frame, laid out for the collision algorithms: Bullet's compound
// shape keeps a full transform and a shape pointer per child, while a rod only needs each sphere's
// position on the body x axis and its radius. Attached to the rod's btCompoundShape as its user
// pointer, so that an algorithm handed a collision object finds it without a lookup.

#include <vector>

#include "engine/rod_shape.hpp"

class btCollisionShape;

namespace rodsort::engine {

struct RodGeometry {
  std::vector<double> axial;   ///< sphere centres on the body x axis, in the compound's order [mm]
  std::vector<double> radius;  ///< [mm]
  double max_radius = 0.0;     ///< [mm]
  double axial_min = 0.0;      ///< the axis segment through every centre, from axial_min
  double axial_max = 0.0;      ///< to axial_max [mm]
  double axial_center = 0.0;   ///< centre of the sphere that bounds the rod, on the axis [mm]
  double bounding_radius = 0.0;  ///< its radius [mm]

  explicit RodGeometry(const RodShape& shape);

  /// The geometry attached to a rod's compound shape.
  static const RodGeometry& of(const btCollisionShape& shape);
};

}  // namespace rodsort::engine
