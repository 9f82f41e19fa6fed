#include "trap/obstacle.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace rodsort::trap {

std::array<Eigen::Vector2d, 4> corners(const engine::Wall& wall) {
  const Eigen::Vector2d center(wall.center_x, wall.center_y);
  const Eigen::Vector2d along(std::cos(wall.yaw), std::sin(wall.yaw));
  const Eigen::Vector2d across(-along.y(), along.x());
  const Eigen::Vector2d length = wall.half_length * along;
  const Eigen::Vector2d thickness = wall.half_thickness * across;
  return {center - length - thickness, center + length - thickness, center + length + thickness,
          center - length + thickness};
}

Bounds Obstacle::bounds() const {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Bounds bounds{Eigen::Vector2d(kInf, kInf), Eigen::Vector2d(-kInf, -kInf)};
  for (const engine::Wall& wall : walls()) {
    for (const Eigen::Vector2d& corner : corners(wall)) {
      bounds.min = bounds.min.cwiseMin(corner);
      bounds.max = bounds.max.cwiseMax(corner);
    }
  }
  return bounds;
}

std::optional<std::string> Obstacle::fit_error(double box_x, double box_y, double margin) const {
  const Bounds extent = bounds();
  const char* axis_names[2] = {"x", "y"};
  const char* width_names[2] = {"wide", "tall"};
  const double box[2] = {box_x, box_y};
  for (int axis = 0; axis < 2; ++axis) {
    const double span = extent.max[axis] - extent.min[axis];
    if (span + 2.0 * margin > box[axis]) {
      return describe() + " spans " + format_mm(span) + " mm in " + axis_names[axis] +
             (margin > 0.0 ? " and needs " + format_mm(margin) +
                                 " mm of clearance from each edge (the reach of a rod)"
                           : std::string()) +
             ", but the cell is " + format_mm(box[axis]) + " mm " + width_names[axis];
    }
  }
  for (int axis = 0; axis < 2; ++axis) {
    if (extent.min[axis] < margin || extent.max[axis] > box[axis] - margin) {
      return describe() + " reaches " + axis_names[axis] + " from " + format_mm(extent.min[axis]) +
             " to " + format_mm(extent.max[axis]) + " mm, but must stay within [" +
             format_mm(margin) + ", " + format_mm(box[axis] - margin) +
             "] mm (the cell less a clearance of " + format_mm(margin) +
             " mm, the reach of a rod, from each edge); move it toward the cell centre";
    }
  }
  return std::nullopt;
}

double required_margin(const std::vector<engine::RodShape>& shapes) {
  double margin = 0.0;
  for (const engine::RodShape& shape : shapes) {
    margin = std::max({margin, -shape.thick_tip, shape.thin_tip});
  }
  return margin;
}

std::string format_mm(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

}  // namespace rodsort::trap
