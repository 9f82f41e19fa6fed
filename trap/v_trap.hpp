#pragma once
// The paper's V-shaped trap: two thin straight walls, standing on the base and spanning the gap,
// that meet at an apex with an opening angle theta between them (paper: 20°-160°).
//
// Geometry, as built here (b = bisector, the direction from the apex into the opening):
//
//                       arm end +
//                     /
//                   /   <- inner face of arm +; the wall's thickness lies outside
//        apex  . -----------> b           the trap's area is the triangle of the
//                   `                     apex and the two arm ends
//                     `
//                       arm end -
//
// - The arm length L (paper: 10 rod lengths, 45 mm) is measured along the inner face, from the
//   apex to the arm end, and the two inner faces meet exactly at the apex. The enclosed triangle
//   is then bounded by the walls' faces that the rods touch, its area is exactly the paper's
//   A_t = L^2 sin(theta) / 2, and contains() tests that triangle.
// - Each wall is a box of the given thickness lying outside the triangle, from the apex to the
//   arm end. Behind the apex the two boxes leave a small wedge-shaped notch between their outer
//   corners, where a rod coming from outside could wedge; a third, small box (the cap) fills it
//   without reaching into the trap or beyond the outline of the two arms.

#include <Eigen/Core>

#include "engine/materials.hpp"
#include "trap/obstacle.hpp"

namespace rodsort::trap {

class VTrap final : public Obstacle {
 public:
  /// opening_angle in (0, pi) [rad]; arm_length, wall_thickness > 0 [mm]; bisector_angle is the
  /// direction from the apex into the opening, from +x [rad]; material indexes the Model's
  /// MaterialTable.
  VTrap(Eigen::Vector2d apex, double opening_angle, double arm_length, double wall_thickness,
        double bisector_angle = 0.0, int material = engine::MaterialTable::kWall);

  const Eigen::Vector2d& apex() const { return apex_; }      ///< [mm]
  double opening_angle() const { return opening_angle_; }    ///< theta [rad]
  double arm_length() const { return arm_length_; }          ///< L, along the inner face [mm]
  double wall_thickness() const { return wall_thickness_; }  ///< [mm]
  double bisector_angle() const { return bisector_angle_; }  ///< from +x [rad]
  int material() const { return material_; }
  Eigen::Vector2d bisector() const;  ///< unit vector from the apex into the opening
  /// The ends of the arms' inner faces: the triangle's other two corners [mm].
  Eigen::Vector2d arm_end_left() const;
  Eigen::Vector2d arm_end_right() const;

  /// Arm +, arm -, then the cap that fills the notch behind the apex.
  std::vector<engine::Wall> walls() const override;
  /// A_t = L^2 sin(theta) / 2 [mm^2].
  double area() const override;
  /// Inside the closed triangle of the apex and the two arm ends.
  bool contains(const Eigen::Vector2d& point) const override;
  /// The triangle: apex, right arm end, left arm end.
  std::vector<Eigen::Vector2d> outline() const override;
  std::string describe() const override;
  /// Obstacle::fit_error(), plus a hint when a bisector along the cell's diagonal would fit.
  std::optional<std::string> fit_error(double box_x, double box_y, double margin) const override;

 private:
  Eigen::Vector2d apex_;
  double opening_angle_;
  double arm_length_;
  double wall_thickness_;
  double bisector_angle_;
  int material_;
};

/// The default placement: the apex and the middle of the opening (the segment joining the arm
/// ends) lie at equal distances on either side of the cell's centre, along the bisector. The
/// triangle's extent along the bisector is thus centred in the cell; across it, the triangle is
/// symmetric about the bisector line through the centre. With bisector_angle = 0 the trap opens
/// toward +x.
VTrap centered_v_trap(double box_x, double box_y, double opening_angle, double arm_length,
                      double wall_thickness, double bisector_angle = 0.0,
                      int material = engine::MaterialTable::kWall);

}  // namespace rodsort::trap
