#pragma once
// The wall of a bounded cell: the experiment's 13 cm disc (the paper's Fig. 2a), closed by a wall
// that stands on the base and spans the gap, plain or flower-shaped.
//
// The paper's experiments run in a circular cell whose wall is scalloped ("flower shaped") so that
// rods do not cluster along it: a rod sliding along a concave scallop is turned back into the bulk
// at the cusp where two scallops meet. The paper gives the cell's diameter (13 cm) but not the
// number or depth of the scallops; here they are parameters.
//
// Geometry, as built here (c = the cell's centre, R = diameter / 2):
//
//   circle   the inner face is the circle of radius R about c.
//   flower   n petals: the cusps lie on the circle of radius R - d (d = the petal depth), at
//            angles 2 pi k / n; between two cusps the inner face is a circular arc bulging
//            outward whose farthest point lies at R. The deeper the petals, the sharper the
//            cusps; a cusp may turn the wall by at most a right angle (max_petal_depth: 5.1 mm
//            for 16 petals on 130 mm, 9.9 mm for 8), beyond which the boxes of the edges
//            meeting there would reach past each other into the cell.
//
// The inner face is a polygon that follows the curve within kMaxSagitta (a tenth of rod A's
// thinnest sphere radius), counter-clockwise, and each of its edges is one engine::Wall box of the
// given thickness lying outside the cell: the rods meet the same boxes, through the same collision
// path, as the V trap's arms. The inner faces of neighbouring boxes meet exactly at the polygon's
// corners, so the wall is closed from inside; outside, where no rod goes, the boxes leave wedges
// between them at the corners that turn inward and overlap at the cusps.
//
// The engine's cell stays periodic: the box around the wall keeps it clear of the periodic edges
// by a rod's reach, so no rod ever reaches an edge and the periodic images never meet anything.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "engine/materials.hpp"
#include "trap/obstacle.hpp"

namespace rodsort::trap {

/// Largest distance between the curve of the cell's wall and the polygon of its inner face [mm].
inline constexpr double kMaxSagitta = 0.02;

class CellWall final : public Obstacle {
 public:
  /// A plain circular wall: centre [mm], diameter of the inner face > 0 [mm], wall_thickness > 0
  /// [mm]; material indexes the Model's MaterialTable.
  static CellWall circle(Eigen::Vector2d centre, double diameter, double wall_thickness,
                         int material = engine::MaterialTable::kWall);
  /// A flower-shaped wall of `petals` >= 3 scallops whose inner face reaches out to `diameter`
  /// and in to diameter - 2 petal_depth at the cusps; 0 < petal_depth <= max_petal_depth().
  static CellWall flower(Eigen::Vector2d centre, double diameter, int petals, double petal_depth,
                         double wall_thickness, int material = engine::MaterialTable::kWall);
  /// The deepest petals of a flower of that diameter and petal count: those whose cusps turn the
  /// wall by a right angle, or semicircles when that comes first (3 and 4 petals) [mm].
  static double max_petal_depth(double diameter, int petals);

  const Eigen::Vector2d& centre() const { return centre_; }  ///< [mm]
  double diameter() const { return diameter_; }              ///< across the petals' tips [mm]
  int petals() const { return petals_; }                     ///< 0 for a circle
  double petal_depth() const { return petal_depth_; }        ///< 0 for a circle [mm]
  double wall_thickness() const { return wall_thickness_; }  ///< [mm]

  /// One box per edge of the inner face's polygon.
  std::vector<engine::Wall> walls() const override;
  /// Area inside the inner face [mm^2].
  double area() const override;
  /// Inside the inner face's polygon.
  bool contains(const Eigen::Vector2d& point) const override;
  std::vector<Eigen::Vector2d> outline() const override { return polygon_; }
  std::string describe() const override;

  /// Distance from a point to the inner face [mm].
  double distance_to_wall(const Eigen::Vector2d& point) const;
  /// Why `obstacle` does not stand inside the cell with at least `clearance` [mm] between each of
  /// its walls and the cell's wall, or nothing when it does.
  std::optional<std::string> enclosure_error(const Obstacle& obstacle, double clearance) const;

 private:
  CellWall(Eigen::Vector2d centre, double diameter, int petals, double petal_depth,
           double wall_thickness, int material);

  Eigen::Vector2d centre_;
  double diameter_;
  int petals_;
  double petal_depth_;
  double wall_thickness_;
  int material_;
  std::vector<Eigen::Vector2d> polygon_;  ///< the inner face, counter-clockwise [mm]
};

/// Side of the square periodic box that holds a cell wall clear of its edges by `margin` [mm]
/// (required_margin() of the rods), rounded up to a whole mm.
double enclosing_box(double diameter, double wall_thickness, double margin);

}  // namespace rodsort::trap
