#include "trap/v_trap.hpp"

#include <catch2/catch.hpp>
#include <cmath>

#include "engine/units.hpp"

using rodsort::degrees_to_radians;
using rodsort::kPi;
using rodsort::trap::centered_v_trap;
using rodsort::trap::VTrap;

namespace {

constexpr double kPaperBox = 19.3 * 4.5;  // [mm]
constexpr double kPaperArm = 45.0;        // [mm]

Eigen::Vector2d along(const rodsort::engine::Wall& wall) {
  return {std::cos(wall.yaw), std::sin(wall.yaw)};
}
Eigen::Vector2d across(const rodsort::engine::Wall& wall) {
  return {-std::sin(wall.yaw), std::cos(wall.yaw)};
}
Eigen::Vector2d center(const rodsort::engine::Wall& wall) { return {wall.center_x, wall.center_y}; }

bool in_wall(const rodsort::engine::Wall& wall, const Eigen::Vector2d& point) {
  const Eigen::Vector2d relative = point - center(wall);
  return std::abs(relative.dot(along(wall))) <= wall.half_length + 1e-12 &&
         std::abs(relative.dot(across(wall))) <= wall.half_thickness + 1e-12;
}

}  // namespace

TEST_CASE("VTrap area is L^2 sin(theta) / 2", "[trap]") {
  const VTrap trap({10.0, 20.0}, degrees_to_radians(120.0), kPaperArm, 0.5);
  CHECK(trap.area() == Approx(0.5 * 45.0 * 45.0 * std::sin(degrees_to_radians(120.0))));
  CHECK(trap.area() == Approx(876.85).epsilon(1e-4));
  const VTrap right_angle({0.0, 0.0}, kPi / 2.0, 10.0, 1.0, 0.7);
  CHECK(right_angle.area() == Approx(50.0));
}

TEST_CASE("VTrap contains the triangle of its apex and arm ends", "[trap]") {
  // Bisector along +y, apex at the origin, 90° opening, arms of 10 mm: corners (0,0),
  // (-7.07, 7.07), (7.07, 7.07).
  const VTrap trap({0.0, 0.0}, kPi / 2.0, 10.0, 1.0, kPi / 2.0);
  const double end = 10.0 / std::sqrt(2.0);
  CHECK(trap.arm_end_left().isApprox(Eigen::Vector2d(-end, end)));
  CHECK(trap.arm_end_right().isApprox(Eigen::Vector2d(end, end)));
  CHECK(trap.contains({0.0, 1.0}));
  CHECK(trap.contains({0.0, end - 1e-6}));
  CHECK(trap.contains({0.9, 1.0}));
  CHECK(trap.contains({-0.9, 1.0}));
  CHECK(trap.contains({0.0, 0.0}));
  CHECK_FALSE(trap.contains({1.1, 1.0}));        // outside the right arm
  CHECK_FALSE(trap.contains({-1.1, 1.0}));       // outside the left arm
  CHECK_FALSE(trap.contains({0.0, -0.1}));       // behind the apex
  CHECK_FALSE(trap.contains({0.0, end + 0.1}));  // beyond the opening
  CHECK_FALSE(trap.contains({-end - 0.1, end - 0.05}));
}

TEST_CASE("VTrap inner faces meet at the apex and run the arm length", "[trap]") {
  for (const double degrees : {20.0, 40.0, 70.0, 120.0, 160.0}) {
    const double bisector = 0.3;
    const VTrap trap({40.0, 40.0}, degrees_to_radians(degrees), kPaperArm, 0.8, bisector);
    const auto walls = trap.walls();
    REQUIRE(walls.size() == 3);
    for (int side = 0; side < 2; ++side) {
      const auto& wall = walls[side];
      CHECK(wall.material == rodsort::engine::MaterialTable::kWall);
      CHECK(wall.half_length == Approx(kPaperArm / 2.0));
      CHECK(wall.half_thickness == Approx(0.4));
      // The face toward the bisector line runs from the apex to the arm end.
      const Eigen::Vector2d to_bisector = trap.bisector().dot(across(wall)) > 0.0
                                              ? Eigen::Vector2d(across(wall))
                                              : Eigen::Vector2d(-across(wall));
      const Eigen::Vector2d face_center = center(wall) + wall.half_thickness * to_bisector;
      const Eigen::Vector2d start = face_center - wall.half_length * along(wall);
      const Eigen::Vector2d finish = face_center + wall.half_length * along(wall);
      CHECK((start - trap.apex()).norm() < 1e-9);
      const Eigen::Vector2d arm_end = side == 0 ? trap.arm_end_left() : trap.arm_end_right();
      CHECK((finish - arm_end).norm() < 1e-9);
    }
  }
}

TEST_CASE("VTrap walls lie outside the triangle and close the notch behind the apex", "[trap]") {
  for (const double degrees : {20.0, 70.0, 125.0, 160.0}) {
    const VTrap trap({0.0, 0.0}, degrees_to_radians(degrees), 20.0, 1.0, -1.1);
    const auto walls = trap.walls();
    const Eigen::Vector2d inward = trap.bisector();
    // Points a hair inside the triangle are never inside a wall.
    int points_in_walls = 0;
    for (int i = 1; i < 100; ++i) {
      for (int j = 1; j < 100; ++j) {
        const double a = i / 100.0, b = j / 100.0;
        if (a + b >= 1.0) continue;
        const Eigen::Vector2d point = trap.apex() + a * (trap.arm_end_left() - trap.apex()) +
                                      b * (trap.arm_end_right() - trap.apex());
        const Eigen::Vector2d shrunk = point + 1e-6 * inward;
        for (const auto& wall : walls) points_in_walls += in_wall(wall, shrunk) ? 1 : 0;
      }
    }
    CHECK(points_in_walls == 0);
    // Just behind the apex, the cap fills what the two arm boxes leave open.
    const double notch_depth = std::sin(trap.opening_angle() / 2.0);  // t sin(theta / 2), t = 1
    const Eigen::Vector2d behind = trap.apex() - 0.5 * notch_depth * inward;
    CHECK_FALSE(in_wall(walls[0], behind));
    CHECK_FALSE(in_wall(walls[1], behind));
    CHECK(in_wall(walls[2], behind));
    // The cap's corners lie within the outline of the arm boxes.
    const auto& cap = walls[2];
    for (const double s : {-1.0, 1.0}) {
      for (const double u : {-1.0, 1.0}) {
        const Eigen::Vector2d corner = center(cap) + (s * cap.half_length * 0.999) * along(cap) +
                                       (u * cap.half_thickness * 0.999) * across(cap);
        CHECK((in_wall(walls[0], corner) || in_wall(walls[1], corner) ||
               (corner - trap.apex()).dot(inward) < 0.0));
      }
    }
  }
}

TEST_CASE("centered_v_trap centres apex and opening about the cell centre", "[trap]") {
  const VTrap trap =
      centered_v_trap(kPaperBox, kPaperBox, degrees_to_radians(120.0), kPaperArm, 0.5);
  const Eigen::Vector2d opening_middle = 0.5 * (trap.arm_end_left() + trap.arm_end_right());
  const Eigen::Vector2d cell_center(kPaperBox / 2.0, kPaperBox / 2.0);
  CHECK(((trap.apex() + opening_middle) / 2.0 - cell_center).norm() < 1e-9);
  CHECK(trap.bisector().isApprox(Eigen::Vector2d(1.0, 0.0)));
  CHECK(trap.contains(cell_center));
  // Its walls stay in the cell for every angle the paper uses in its own box up to 125°.
  for (double degrees = 20.0; degrees <= 125.0; degrees += 5.0) {
    const VTrap t =
        centered_v_trap(kPaperBox, kPaperBox, degrees_to_radians(degrees), kPaperArm, 0.5);
    const auto bounds = t.bounds();
    CHECK(bounds.min.minCoeff() > 0.0);
    CHECK(bounds.max.maxCoeff() < kPaperBox);
    CHECK_FALSE(t.fit_error(kPaperBox, kPaperBox, 2.6));
  }
}

TEST_CASE("VTrap fit check names the reason a trap does not fit", "[trap]") {
  SECTION("too wide for the cell") {
    const VTrap trap = centered_v_trap(50.0, 50.0, degrees_to_radians(120.0), 45.0, 0.5);
    const auto error = trap.fit_error(50.0, 50.0, 0.0);
    REQUIRE(error);
    CHECK_THAT(*error, Catch::Contains("trap of arm 45 mm at 120°"));
    CHECK_THAT(*error, Catch::Contains("spans 78.44 mm in y"));
    CHECK_THAT(*error, Catch::Contains("the cell is 50 mm tall"));
  }
  SECTION("the margin is what does not fit") {
    const VTrap trap = centered_v_trap(80.0, 80.0, degrees_to_radians(120.0), 45.0, 0.5);
    CHECK_FALSE(trap.fit_error(80.0, 80.0, 0.0));
    const auto error = trap.fit_error(80.0, 80.0, 2.6);
    REQUIRE(error);
    CHECK_THAT(*error, Catch::Contains("2.6 mm of clearance"));
  }
  SECTION("off centre") {
    const VTrap trap({60.0, 40.0}, degrees_to_radians(60.0), 30.0, 0.5);
    const auto error = trap.fit_error(80.0, 80.0, 2.6);
    REQUIRE(error);
    CHECK_THAT(*error, Catch::Contains("reaches x from"));
    CHECK_THAT(*error, Catch::Contains("[2.6, 77.4] mm"));
    CHECK_THAT(*error, Catch::Contains("toward the cell centre"));
    CHECK_THAT(*error, !Catch::Contains("diagonal"));
  }
  SECTION("a wide trap in the paper's box fits along the diagonal") {
    const VTrap trap =
        centered_v_trap(kPaperBox, kPaperBox, degrees_to_radians(160.0), kPaperArm, 0.5);
    const auto error = trap.fit_error(kPaperBox, kPaperBox, 2.6);
    REQUIRE(error);
    CHECK_THAT(*error, Catch::Contains("diagonal (45°) it would fit"));
    const VTrap turned =
        centered_v_trap(kPaperBox, kPaperBox, degrees_to_radians(160.0), kPaperArm, 0.5, kPi / 4.0);
    CHECK_FALSE(turned.fit_error(kPaperBox, kPaperBox, 2.6));
  }
}

TEST_CASE("required_margin is the longest reach from a centre of mass to a tip", "[trap]") {
  rodsort::engine::RodShape a{};
  a.thick_tip = -1.9;
  a.thin_tip = 2.6;
  rodsort::engine::RodShape b{};
  b.thick_tip = -3.0;
  b.thin_tip = 1.0;
  CHECK(rodsort::trap::required_margin({a}) == Approx(2.6));
  CHECK(rodsort::trap::required_margin({a, b}) == Approx(3.0));
}
