#include "trap/v_trap.hpp"

#include <cassert>
#include <cmath>
#include <cstdio>

#include "engine/units.hpp"

namespace rodsort::trap {
namespace {

Eigen::Vector2d unit(double angle) { return {std::cos(angle), std::sin(angle)}; }

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

}  // namespace

VTrap::VTrap(Eigen::Vector2d apex, double opening_angle, double arm_length, double wall_thickness,
             double bisector_angle, int material)
    : apex_(apex),
      opening_angle_(opening_angle),
      arm_length_(arm_length),
      wall_thickness_(wall_thickness),
      bisector_angle_(bisector_angle),
      material_(material) {
  assert(opening_angle > 0.0 && opening_angle < kPi);
  assert(arm_length > 0.0);
  assert(wall_thickness > 0.0);
}

Eigen::Vector2d VTrap::bisector() const { return unit(bisector_angle_); }

Eigen::Vector2d VTrap::arm_end_left() const {
  return apex_ + arm_length_ * unit(bisector_angle_ + opening_angle_ / 2.0);
}

Eigen::Vector2d VTrap::arm_end_right() const {
  return apex_ + arm_length_ * unit(bisector_angle_ - opening_angle_ / 2.0);
}

std::vector<engine::Wall> VTrap::walls() const {
  const double half_angle = opening_angle_ / 2.0;
  const double t = wall_thickness_;
  std::vector<engine::Wall> walls;
  // side +1 is the left arm (counter-clockwise from the bisector), -1 the right one. The outward
  // normal of an arm turns away from the bisector, so the box lies outside the triangle.
  for (const double side : {1.0, -1.0}) {
    const double yaw = bisector_angle_ + side * half_angle;
    const Eigen::Vector2d along = unit(yaw);
    const Eigen::Vector2d outward = unit(yaw + side * kPi / 2.0);
    const Eigen::Vector2d center = apex_ + 0.5 * arm_length_ * along + 0.5 * t * outward;
    walls.push_back({center.x(), center.y(), 0.5 * arm_length_, 0.5 * t, yaw, material_});
  }
  // The notch behind the apex is the triangle (apex, apex + t n+, apex + t n-); in the bisector
  // frame the rectangle -t sin(a) <= x <= 0, |y| <= t cos(a) covers it and lies within the two
  // arm boxes elsewhere, so the cap changes nothing but the notch.
  const Eigen::Vector2d cap_center = apex_ - 0.5 * t * std::sin(half_angle) * bisector();
  walls.push_back({cap_center.x(), cap_center.y(), t * std::cos(half_angle),
                   0.5 * t * std::sin(half_angle), bisector_angle_ + kPi / 2.0, material_});
  return walls;
}

double VTrap::area() const { return 0.5 * arm_length_ * arm_length_ * std::sin(opening_angle_); }

bool VTrap::contains(const Eigen::Vector2d& point) const {
  // Inside the closed triangle: on the inner side of both arms and of the opening segment.
  const Eigen::Vector2d left = arm_end_left() - apex_;
  const Eigen::Vector2d right = arm_end_right() - apex_;
  const Eigen::Vector2d relative = point - apex_;
  return cross(left, relative) <= 0.0 && cross(right, relative) >= 0.0 &&
         cross(right - left, relative - left) <= 0.0;
}

std::vector<Eigen::Vector2d> VTrap::outline() const {
  return {apex_, arm_end_right(), arm_end_left()};
}

std::string VTrap::describe() const {
  char text[96];
  std::snprintf(text, sizeof text, "trap of arm %s mm at %.4g°", format_mm(arm_length_).c_str(),
                radians_to_degrees(opening_angle_));
  return text;
}

std::optional<std::string> VTrap::fit_error(double box_x, double box_y, double margin) const {
  std::optional<std::string> error = Obstacle::fit_error(box_x, box_y, margin);
  if (!error) return error;
  // A trap that is only off-centre is told to move; one too wide for its direction may still
  // fit turned: the cell's diagonal is its longest line.
  const VTrap centred = centered_v_trap(box_x, box_y, opening_angle_, arm_length_, wall_thickness_,
                                        bisector_angle_, material_);
  const double diagonal = std::atan2(box_y, box_x);
  const VTrap turned = centered_v_trap(box_x, box_y, opening_angle_, arm_length_, wall_thickness_,
                                       diagonal, material_);
  if (centred.Obstacle::fit_error(box_x, box_y, margin) &&
      !turned.Obstacle::fit_error(box_x, box_y, margin)) {
    char hint[96];
    std::snprintf(hint, sizeof hint,
                  "; centred with its bisector along the cell's diagonal (%.4g°) it would fit",
                  radians_to_degrees(diagonal));
    *error += hint;
  }
  return error;
}

VTrap centered_v_trap(double box_x, double box_y, double opening_angle, double arm_length,
                      double wall_thickness, double bisector_angle, int material) {
  const double depth = arm_length * std::cos(opening_angle / 2.0);
  const Eigen::Vector2d center(box_x / 2.0, box_y / 2.0);
  const Eigen::Vector2d apex = center - 0.5 * depth * unit(bisector_angle);
  return VTrap(apex, opening_angle, arm_length, wall_thickness, bisector_angle, material);
}

}  // namespace rodsort::trap
