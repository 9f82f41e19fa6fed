#pragma once
// The spheres of a rod in its body frame, laid out for the collision algorithms: Bullet's compound
// shape keeps a full transform and a shape pointer per child, while a rod only needs each sphere's
// position on the body x axis, its radius and, for a rod that is not straight, its offset along the
// body y axis. Attached to the rod's btCompoundShape as its user
// pointer, so that an algorithm handed a collision object finds it without a lookup.

#include <cstddef>
#include <vector>

#include "engine/rod_shape.hpp"

class btCollisionShape;

namespace rodsort::engine {

struct RodGeometry {
  std::vector<double> axial;   ///< sphere centres on the body x axis, in the compound's order [mm]
  std::vector<double> radius;  ///< [mm]
  /// Offsets of the centres along the body y axis [mm]; all 0 for a straight rod.
  std::vector<double> lateral;
  /// Whether every centre lies on the axis: the algorithms then leave the offsets out.
  bool straight = true;
  /// The largest |lateral|: every centre lies within this of the axis segment below [mm].
  double max_lateral = 0.0;
  double max_radius = 0.0;       ///< [mm]
  double axial_min = 0.0;        ///< the axis segment through every centre, from axial_min
  double axial_max = 0.0;        ///< to axial_max [mm]
  double axial_center = 0.0;     ///< centre of the sphere that bounds the rod, on the axis [mm]
  double bounding_radius = 0.0;  ///< its radius [mm]
  /// Whether `axial` ascends (every preset and profile-built rod): then the spheres near a point
  /// of the axis are found by first_at_or_beyond and first_beyond.
  bool ascending = false;
  /// Spheres per millimetre of axis, were they evenly spaced: where the search starts [1/mm].
  double inverse_spacing = 0.0;

  /// With ascending centres: the first sphere whose centre is at or beyond `x` on the axis
  /// (axial.size() if none), as std::lower_bound finds it; from a guess by even spacing, which for
  /// a rod of evenly spaced spheres is right or one off.
  std::size_t first_at_or_beyond(double x) const {
    std::size_t j = guess(x);
    while (j < axial.size() && axial[j] < x) ++j;
    while (j > 0 && axial[j - 1] >= x) --j;
    return j;
  }
  /// With ascending centres: the first sphere whose centre is beyond `x`, as std::upper_bound.
  std::size_t first_beyond(double x) const {
    std::size_t j = guess(x);
    while (j < axial.size() && axial[j] <= x) ++j;
    while (j > 0 && axial[j - 1] > x) --j;
    return j;
  }

  explicit RodGeometry(const RodShape& shape);

  /// The geometry attached to a rod's compound shape.
  static const RodGeometry& of(const btCollisionShape& shape);

 private:
  std::size_t guess(double x) const {
    const double at = (x - axial_min) * inverse_spacing;
    if (!(at > 0.0)) return 0;
    return at < static_cast<double>(axial.size()) ? static_cast<std::size_t>(at) : axial.size();
  }
};

}  // namespace rodsort::engine
