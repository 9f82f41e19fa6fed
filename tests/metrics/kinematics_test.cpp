#include "metrics/kinematics.hpp"

#include <catch2/catch.hpp>

#include "engine/units.hpp"
#include "synthetic_frames.hpp"

using namespace rodsort::metrics;
using rodsort::degrees_to_radians;
using rodsort::kPi;
using testing::frame_at;
using testing::rod_at;

TEST_CASE("wrap_angle maps differences into -pi < a <= pi", "[metrics]") {
  CHECK(wrap_angle(0.3) == Approx(0.3));
  CHECK(wrap_angle(2.0 * kPi + 0.3) == Approx(0.3));
  CHECK(wrap_angle(-2.0 * kPi - 0.3) == Approx(-0.3));
  CHECK(wrap_angle(degrees_to_radians(358.0)) == Approx(degrees_to_radians(-2.0)));
  CHECK(wrap_angle(kPi) == Approx(kPi));
  CHECK(wrap_angle(-kPi) == Approx(kPi));
  CHECK(wrap_angle(3.0 * kPi) == Approx(kPi));
}

TEST_CASE("heading is the in-plane angle of the thick-to-thin axis", "[metrics]") {
  CHECK(heading(rod_at(0, 0, 0.4)) == Approx(0.4));
  CHECK(heading(rod_at(0, 0, -2.9)) == Approx(-2.9));
  auto tilted = rod_at(0, 0, 0.0);
  tilted.axis = Eigen::Vector3d(0.0, 0.6, 0.8);  // tilted out of the plane, pointing +y in it
  CHECK(heading(tilted) == Approx(kPi / 2.0));
}

TEST_CASE("window speeds come from unwrapped positions", "[metrics]") {
  // Rod 0 rests; rod 1 moves 0.7 mm in x in 0.07 s across the right edge of a 100 mm cell (its
  // wrapped x jumps from 99.8 to 0.5); rod 2 moves (0.3, 0.4) mm.
  const auto earlier = frame_at(1.0, {rod_at(50, 50, 0), rod_at(99.8, 20, 0), rod_at(10, 10, 1.0)});
  const auto later =
      frame_at(1.07, {rod_at(50, 50, 0), rod_at(100.5, 20, 0), rod_at(10.3, 10.4, 1.0)});
  REQUIRE(later.rods[1].position.x() == Approx(0.5));
  const auto speeds = window_speeds(earlier, later);
  REQUIRE(speeds.size() == 3);
  CHECK(speeds[0] == Approx(0.0).margin(1e-12));
  CHECK(speeds[1] == Approx(10.0));
  CHECK(speeds[2] == Approx(0.5 / 0.07));
}

TEST_CASE("orientation changes are wrapped across +-pi", "[metrics]") {
  const auto earlier = frame_at(
      0.0, {rod_at(1, 1, degrees_to_radians(179.0)), rod_at(1, 1, degrees_to_radians(-179.0)),
            rod_at(1, 1, degrees_to_radians(10.0))});
  const auto later = frame_at(
      0.07, {rod_at(1, 1, degrees_to_radians(-179.0)), rod_at(1, 1, degrees_to_radians(178.0)),
             rod_at(1, 1, degrees_to_radians(-20.0))});
  const auto changes = orientation_changes(earlier, later, {0, 1, 2});
  CHECK(changes[0] == Approx(degrees_to_radians(2.0)));
  CHECK(changes[1] == Approx(degrees_to_radians(-3.0)));
  CHECK(changes[2] == Approx(degrees_to_radians(-30.0)));
  const auto chosen = orientation_changes(earlier, later, {2});
  REQUIRE(chosen.size() == 1);
  CHECK(chosen[0] == Approx(degrees_to_radians(-30.0)));
}
