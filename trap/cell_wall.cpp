#include "trap/cell_wall.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <limits>

#include "engine/segment_distance.hpp"
#include "engine/units.hpp"

namespace rodsort::trap {
namespace {

Eigen::Vector2d unit(double angle) { return {std::cos(angle), std::sin(angle)}; }

/// Edges needed for an arc of `radius` [mm] turning through `sweep` [rad] to stay within
/// kMaxSagitta of the polygon joining its points.
int arc_edges(double radius, double sweep) {
  const double ratio = std::max(-1.0, 1.0 - kMaxSagitta / radius);
  const double edge_angle = 2.0 * std::acos(ratio);
  return std::max(2, static_cast<int>(std::ceil(sweep / edge_angle)));
}

/// Points of the arc about `centre` from angle `from` counter-clockwise through `sweep`, without
/// its last point (the next arc's first).
void append_arc(std::vector<Eigen::Vector2d>& points, const Eigen::Vector2d& centre, double radius,
                double from, double sweep) {
  const int edges = arc_edges(radius, sweep);
  for (int i = 0; i < edges; ++i) {
    points.push_back(centre + radius * unit(from + sweep * i / edges));
  }
}

}  // namespace

CellWall::CellWall(Eigen::Vector2d centre, double diameter, int petals, double petal_depth,
                   double wall_thickness, int material)
    : centre_(centre),
      diameter_(diameter),
      petals_(petals),
      petal_depth_(petal_depth),
      wall_thickness_(wall_thickness),
      material_(material) {
  assert(diameter > 0.0 && wall_thickness > 0.0);
  const double radius = diameter / 2.0;
  if (petals == 0) {
    append_arc(polygon_, centre, radius, 0.0, 2.0 * kPi);
    return;
  }
  assert(petals >= 3 && petal_depth > 0.0 && petal_depth <= max_petal_depth(diameter, petals));
  // Petal k spans the cusps at angles 2 pi k / n and 2 pi (k + 1) / n on the circle of radius
  // R - d. Its arc passes through both cusps and through the point at R on the ray between
  // them: with h the half chord and s the sagitta, its radius is (h^2 + s^2) / (2 s).
  const double half_step = kPi / petals;
  const double cusp_radius = radius - petal_depth;
  const double half_chord = cusp_radius * std::sin(half_step);
  const double sagitta = radius - cusp_radius * std::cos(half_step);
  const double arc_radius = (half_chord * half_chord + sagitta * sagitta) / (2.0 * sagitta);
  const double sweep = 2.0 * std::asin(std::min(1.0, half_chord / arc_radius));
  for (int k = 0; k < petals; ++k) {
    const double middle = (2 * k + 1) * half_step;
    const Eigen::Vector2d arc_centre = centre + (radius - arc_radius) * unit(middle);
    append_arc(polygon_, arc_centre, arc_radius, middle - sweep / 2.0, sweep);
  }
}

CellWall CellWall::circle(Eigen::Vector2d centre, double diameter, double wall_thickness,
                          int material) {
  return CellWall(centre, diameter, 0, 0.0, wall_thickness, material);
}

CellWall CellWall::flower(Eigen::Vector2d centre, double diameter, int petals, double petal_depth,
                          double wall_thickness, int material) {
  return CellWall(centre, diameter, petals, petal_depth, wall_thickness, material);
}

double CellWall::max_petal_depth(double diameter, int petals) {
  // Going round the wall the direction turns by 2 pi: along each petal's arc by its sweep, and
  // back at each cusp, so a cusp turns by (sweep - 2 pi / n). Beyond a right angle the box of one
  // edge at a cusp would reach past the next edge into the cell; the arc's sweep is therefore at
  // most pi / 2 + 2 pi / n, and at most pi (a semicircle). With R_c = R - d the cusps' radius,
  // h = R_c sin(pi/n) the half chord and s = R - R_c cos(pi/n) the sagitta, an arc of sweep
  // sigma has s / h = tan(sigma / 4).
  const double step = kPi / petals;
  const double sweep = std::min(kPi, kPi / 2.0 + 2.0 * step);
  return 0.5 * diameter * (1.0 - 1.0 / (std::cos(step) + std::sin(step) * std::tan(sweep / 4.0)));
}

std::vector<engine::Wall> CellWall::walls() const {
  std::vector<engine::Wall> walls;
  walls.reserve(polygon_.size());
  for (std::size_t i = 0; i < polygon_.size(); ++i) {
    const Eigen::Vector2d& a = polygon_[i];
    const Eigen::Vector2d& b = polygon_[(i + 1) % polygon_.size()];
    const Eigen::Vector2d edge = b - a;
    // Counter-clockwise, the inside is on the left: the box lies to the right of the edge.
    const Eigen::Vector2d outward = Eigen::Vector2d(edge.y(), -edge.x()).normalized();
    const Eigen::Vector2d middle = 0.5 * (a + b) + 0.5 * wall_thickness_ * outward;
    walls.push_back({middle.x(), middle.y(), 0.5 * edge.norm(), 0.5 * wall_thickness_,
                     std::atan2(edge.y(), edge.x()), material_});
  }
  return walls;
}

double CellWall::area() const {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon_.size(); ++i) {
    const Eigen::Vector2d a = polygon_[i] - centre_;
    const Eigen::Vector2d b = polygon_[(i + 1) % polygon_.size()] - centre_;
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return 0.5 * twice;
}

bool CellWall::contains(const Eigen::Vector2d& point) const {
  // Crossing number: a ray toward +x crosses the polygon an odd number of times from inside.
  bool inside = false;
  for (std::size_t i = 0, j = polygon_.size() - 1; i < polygon_.size(); j = i++) {
    const Eigen::Vector2d& a = polygon_[i];
    const Eigen::Vector2d& b = polygon_[j];
    if ((a.y() > point.y()) != (b.y() > point.y()) &&
        point.x() < a.x() + (point.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y())) {
      inside = !inside;
    }
  }
  return inside;
}

std::string CellWall::describe() const {
  char text[128];
  if (petals_ == 0) {
    std::snprintf(text, sizeof text, "circular cell %s mm across", format_mm(diameter_).c_str());
  } else {
    std::snprintf(text, sizeof text, "flower cell %s mm across with %d petals %s mm deep",
                  format_mm(diameter_).c_str(), petals_, format_mm(petal_depth_).c_str());
  }
  return text;
}

double CellWall::distance_to_wall(const Eigen::Vector2d& point) const {
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < polygon_.size(); ++i) {
    nearest =
        std::min(nearest, engine::segment_distance_squared(
                              polygon_[i], polygon_[(i + 1) % polygon_.size()], point, point));
  }
  return std::sqrt(nearest);
}

std::optional<std::string> CellWall::enclosure_error(const Obstacle& obstacle,
                                                     double clearance) const {
  // The distance between two polygons is the least distance between an edge of each; a wall
  // that crosses the cell's wall is at distance 0, one wholly outside has its corners outside.
  double nearest = std::numeric_limits<double>::infinity();
  bool outside = false;
  for (const engine::Wall& wall : obstacle.walls()) {
    const auto box = corners(wall);
    for (std::size_t c = 0; c < box.size(); ++c) {
      if (!contains(box[c])) outside = true;
      for (std::size_t i = 0; i < polygon_.size(); ++i) {
        nearest = std::min(nearest, engine::segment_distance_squared(
                                        box[c], box[(c + 1) % box.size()], polygon_[i],
                                        polygon_[(i + 1) % polygon_.size()]));
      }
    }
  }
  nearest = std::sqrt(nearest);
  if (outside) {
    return obstacle.describe() + " reaches outside the " + describe() +
           "; make it smaller or move it toward the cell's centre";
  }
  if (nearest < clearance) {
    return obstacle.describe() + " comes within " + format_mm(nearest) + " mm of the " +
           describe() + "'s wall, but a rod must pass between them: at least " +
           format_mm(clearance) + " mm (the longest rod) are needed";
  }
  return std::nullopt;
}

double enclosing_box(double diameter, double wall_thickness, double margin) {
  return std::ceil(diameter + 2.0 * (wall_thickness + margin));
}

}  // namespace rodsort::trap
