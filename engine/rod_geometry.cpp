#include "engine/rod_geometry.hpp"

#include <BulletCollision/CollisionShapes/btCollisionShape.h>

#include <algorithm>
#include <cassert>
#include <cmath>

namespace rodsort::engine {

RodGeometry::RodGeometry(const RodShape& shape) {
  assert(!shape.spheres.empty());
  axial_min = shape.spheres.front().axial;
  axial_max = axial_min;
  for (const Sphere& sphere : shape.spheres) {
    axial.push_back(sphere.axial);
    radius.push_back(sphere.radius);
    lateral.push_back(sphere.lateral);
    max_radius = std::max(max_radius, sphere.radius);
    axial_min = std::min(axial_min, sphere.axial);
    axial_max = std::max(axial_max, sphere.axial);
  }
  max_lateral = shape.max_lateral;
  straight = max_lateral == 0.0;
  ascending = std::is_sorted(axial.begin(), axial.end());
  if (axial_max > axial_min) {
    inverse_spacing = static_cast<double>(axial.size() - 1) / (axial_max - axial_min);
  }
  axial_center = 0.5 * (axial_min + axial_max);
  for (const Sphere& sphere : shape.spheres) {
    bounding_radius = std::max(
        bounding_radius, std::hypot(sphere.axial - axial_center, sphere.lateral) + sphere.radius);
  }
}

const RodGeometry& RodGeometry::of(const btCollisionShape& shape) {
  assert(shape.getUserPointer() != nullptr);
  return *static_cast<const RodGeometry*>(shape.getUserPointer());
}

}  // namespace rodsort::engine
