#pragma once
// An obstacle is whatever static walls stand in the cell: the engine only ever sees the
// engine::Wall boxes it hands over, so a new obstacle shape is a new class beside VTrap and never
// a change to the engine.
//
// Walls are not repeated across the periodic edges (the engine's periodic images meet rods only).
// A rod whose centre sits near an edge reaches across it, and the part that reaches across would
// pass through any wall standing there. An obstacle must therefore keep clear of the cell's edges
// by at least the reach of the largest rod: fit_error() checks it.

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "engine/model.hpp"
#include "engine/rod_shape.hpp"

namespace rodsort::trap {

/// Axis-aligned bounding box in the plane [mm].
struct Bounds {
  Eigen::Vector2d min;
  Eigen::Vector2d max;
};

class Obstacle {
 public:
  virtual ~Obstacle() = default;

  /// The static boxes, spanning the gap, that the engine builds.
  virtual std::vector<engine::Wall> walls() const = 0;
  /// Area the obstacle encloses, the A_t of eta = N0 a / A_t [mm^2].
  virtual double area() const = 0;
  /// Whether a point of the plane lies in the enclosed area. Points are taken as given: pass
  /// positions wrapped into the cell, which is where an obstacle that passed fit_error() lies.
  virtual bool contains(const Eigen::Vector2d& point) const = 0;
  /// The boundary of the enclosed area, counter-clockwise, for drawing it [mm].
  virtual std::vector<Eigen::Vector2d> outline() const = 0;
  /// Short description for messages, e.g. "trap of arm 45 mm at 120°".
  virtual std::string describe() const = 0;

  /// Bounding box of every corner of every wall [mm].
  Bounds bounds() const;

  /// Why the obstacle does not fit in the periodic cell [0, box_x) x [0, box_y) with `margin` [mm]
  /// of clearance from every edge, or nothing when it fits. Pass required_margin() of the rods.
  virtual std::optional<std::string> fit_error(double box_x, double box_y, double margin) const;
};

/// The four corners of a wall's box in the plane, going round it [mm].
std::array<Eigen::Vector2d, 4> corners(const engine::Wall& wall);

/// Clearance an obstacle needs from the cell's edges so that no rod reaches a wall across a
/// periodic edge: the largest distance from a rod's centre of mass to one of its tips [mm].
double required_margin(const std::vector<engine::RodShape>& shapes);

/// Formats a length in mm for messages: "45", "77.94", "0.25".
std::string format_mm(double value);

}  // namespace rodsort::trap
