#include "trap/cell_wall.hpp"

#include <catch2/catch.hpp>
#include <cmath>

#include "engine/units.hpp"
#include "trap/v_trap.hpp"

using rodsort::degrees_to_radians;
using rodsort::kPi;
using rodsort::trap::CellWall;
using rodsort::trap::kMaxSagitta;

namespace {

const Eigen::Vector2d kCentre(70.0, 70.0);  // [mm]
constexpr double kDiameter = 130.0;         // the paper's experimental cell [mm]
constexpr double kThickness = 1.0;          // [mm]

Eigen::Vector2d unit(double angle) { return {std::cos(angle), std::sin(angle)}; }

bool in_wall(const rodsort::engine::Wall& wall, const Eigen::Vector2d& point) {
  const Eigen::Vector2d along = unit(wall.yaw);
  const Eigen::Vector2d across(-along.y(), along.x());
  const Eigen::Vector2d relative = point - Eigen::Vector2d(wall.center_x, wall.center_y);
  return std::abs(relative.dot(along)) <= wall.half_length + 1e-9 &&
         std::abs(relative.dot(across)) <= wall.half_thickness + 1e-9;
}

bool in_any_wall(const std::vector<rodsort::engine::Wall>& walls, const Eigen::Vector2d& point) {
  for (const auto& wall : walls) {
    if (in_wall(wall, point)) return true;
  }
  return false;
}

/// Every ray from the centre meets the walls just outside the inner face, and no wall reaches
/// inside it: the wall is closed and lies outside the cell.
void check_closed_and_outside(const CellWall& cell) {
  const auto walls = cell.walls();
  const auto polygon = cell.outline();
  REQUIRE(walls.size() == polygon.size());
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
    const Eigen::Vector2d outward = Eigen::Vector2d(b.y() - a.y(), a.x() - b.x()).normalized();
    for (const double s : {0.0, 0.25, 0.5, 0.75}) {
      const Eigen::Vector2d on_face = a + s * (b - a);
      INFO("edge " << i << " at " << s);
      CHECK(in_any_wall(walls, on_face + 0.5 * kThickness * outward));
      CHECK_FALSE(in_any_wall(walls, on_face - 0.01 * outward));
      CHECK(cell.contains(on_face - 0.01 * outward));
      CHECK_FALSE(cell.contains(on_face + 0.01 * outward));
    }
  }
}

}  // namespace

TEST_CASE("a circular cell's wall follows its circle within the sagitta", "[trap]") {
  const CellWall cell = CellWall::circle(kCentre, kDiameter, kThickness);
  const double radius = kDiameter / 2.0;
  for (const Eigen::Vector2d& corner : cell.outline()) {
    CHECK((corner - kCentre).norm() == Approx(radius).margin(1e-9));
  }
  // The polygon's edges bulge in by at most the sagitta: the centre is that much nearer.
  CHECK(cell.distance_to_wall(kCentre) <= radius);
  CHECK(cell.distance_to_wall(kCentre) >= radius - kMaxSagitta);
  CHECK(cell.area() == Approx(kPi * radius * radius).epsilon(2.0 * kMaxSagitta / radius));
  CHECK(cell.area() < kPi * radius * radius);
  CHECK(cell.contains(kCentre));
  CHECK(cell.contains(kCentre + (radius - 0.05) * unit(0.3)));
  CHECK_FALSE(cell.contains(kCentre + (radius + 0.05) * unit(0.3)));
  CHECK(cell.distance_to_wall(kCentre + (radius - 2.0) * unit(1.0)) ==
        Approx(2.0).margin(kMaxSagitta));
  CHECK(cell.describe() == "circular cell 130 mm across");
  check_closed_and_outside(cell);
}

TEST_CASE("a flower cell's petals reach the diameter and its cusps the petal depth", "[trap]") {
  const int petals = 16;
  const double depth = 5.0;
  const CellWall cell = CellWall::flower(kCentre, kDiameter, petals, depth, kThickness);
  const double radius = kDiameter / 2.0;
  double nearest = radius, farthest = 0.0;
  for (const Eigen::Vector2d& corner : cell.outline()) {
    nearest = std::min(nearest, (corner - kCentre).norm());
    farthest = std::max(farthest, (corner - kCentre).norm());
  }
  CHECK(nearest == Approx(radius - depth).margin(1e-9));  // the cusps
  CHECK(farthest <= radius + 1e-9);
  CHECK(farthest >= radius - kMaxSagitta);  // the petal tips
  // The cusps point into the cell at angles 2 pi k / n, the petal tips between them.
  for (int k = 0; k < petals; ++k) {
    const Eigen::Vector2d cusp = kCentre + (radius - depth) * unit(2.0 * kPi * k / petals);
    CHECK(cell.distance_to_wall(cusp) == Approx(0.0).margin(1e-9));
    CHECK(cell.contains(kCentre + (radius - 0.1) * unit(2.0 * kPi * (k + 0.5) / petals)));
    CHECK_FALSE(cell.contains(kCentre + (radius - depth + 0.1) * unit(2.0 * kPi * k / petals)));
  }
  const double inner = radius - depth;
  CHECK(cell.area() > kPi * inner * inner);
  CHECK(cell.area() < kPi * radius * radius);
  CHECK(cell.describe() == "flower cell 130 mm across with 16 petals 5 mm deep");
  check_closed_and_outside(cell);
}

TEST_CASE("a flower's deepest petals turn the wall by a right angle at the cusps", "[trap]") {
  for (const int petals : {4, 8, 16, 40}) {
    INFO(petals << " petals");
    const double depth = CellWall::max_petal_depth(kDiameter, petals);
    const CellWall cell = CellWall::flower(kCentre, kDiameter, petals, depth, kThickness);
    const auto corners = cell.outline();
    // The first corner is a petal's first point, just after a cusp: the turn there is the angle
    // between the last edge and the first.
    const Eigen::Vector2d in = corners[0] - corners.back();
    const Eigen::Vector2d out = corners[1] - corners[0];
    const double turn = std::atan2(in.x() * out.y() - in.y() * out.x(), in.dot(out));
    // Turning right (clockwise) by a right angle, less the angle of one edge along the arc.
    CHECK(turn < 0.0);
    CHECK(-turn == Approx(kPi / 2.0).margin(0.15));
    CHECK(-turn <= kPi / 2.0 + 1e-9);
    check_closed_and_outside(cell);
  }
  // Four petals at their deepest are semicircles: the cell is the square of the cusps and four
  // half discs on its sides.
  const double depth = CellWall::max_petal_depth(kDiameter, 4);
  const double cusp = kDiameter / 2.0 - depth;
  const double half_side = cusp * std::sin(kPi / 4.0);
  CHECK(cusp * std::cos(kPi / 4.0) + half_side == Approx(kDiameter / 2.0));
  const CellWall four = CellWall::flower(kCentre, kDiameter, 4, depth, kThickness);
  CHECK(four.area() ==
        Approx(4.0 * half_side * half_side + 2.0 * kPi * half_side * half_side).epsilon(1e-3));
}

TEST_CASE("a trap inside a cell is refused when it reaches the wall or leaves no way past",
          "[trap]") {
  const CellWall cell = CellWall::flower(kCentre, kDiameter, 16, 5.0, kThickness);
  const double box = 2.0 * kCentre.x();
  // The paper's widest trap, centred: its arm ends lie some 44.5 mm from the centre, 15 mm
  // inside the cusps.
  const auto wide = rodsort::trap::centered_v_trap(box, box, degrees_to_radians(160.0), 45.0, 1.0);
  CHECK_FALSE(cell.enclosure_error(wide, 4.5));
  CHECK(cell.enclosure_error(wide, 20.0).value_or("").find("comes within") != std::string::npos);
  // Moved 14 mm across: an arm end comes within 4.5 mm of the cusp at 90 degrees.
  const rodsort::trap::VTrap near(wide.apex() + Eigen::Vector2d(0.0, 14.0),
                                  degrees_to_radians(160.0), 45.0, 1.0);
  const auto near_error = cell.enclosure_error(near, 4.5);
  REQUIRE(near_error);
  CHECK(near_error->find("a rod must pass between them") != std::string::npos);
  const rodsort::trap::VTrap out(wide.apex() + Eigen::Vector2d(0.0, 40.0),
                                 degrees_to_radians(160.0), 45.0, 1.0);
  CHECK(cell.enclosure_error(out, 4.5).value_or("").find("reaches outside") != std::string::npos);
}
