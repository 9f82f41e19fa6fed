#include "metrics/critical_angle.hpp"

#include <catch2/catch.hpp>

using namespace rodsort::metrics;

TEST_CASE("theta_c interpolates the crossing of half the low-angle plateau", "[metrics]") {
  // Plateau 0.8 (mean of 20°, 60°, 100°), half 0.4; eta drops between 120° (0.7) and 130° (0.1):
  // 0.4 is crossed halfway, at 125°. The points arrive unsorted.
  const CriticalAngle c = critical_angle(
      {{130, 0.1}, {20, 0.75}, {140, 0.05}, {100, 0.85}, {60, 0.8}, {120, 0.7}, {160, 0.0}});
  REQUIRE(c.found);
  CHECK(c.plateau == Approx(0.8));
  CHECK(c.half == Approx(0.4));
  CHECK(c.angle == Approx(125.0));
  CHECK(c.below == 120.0);
  CHECK(c.above == 130.0);
}

TEST_CASE("theta_c takes the first drop, interpolated unevenly", "[metrics]") {
  // Plateau from the two smallest angles: 0.9; half 0.45. Drop from 0.6 at 110° to 0.0 at 130°:
  // crossing at 110 + (0.6 - 0.45) / 0.6 * 20 = 115°. A later spike back above half is ignored.
  const CriticalAngle c =
      critical_angle({{90, 0.9}, {100, 0.9}, {110, 0.6}, {130, 0.0}, {140, 0.5}, {150, 0.0}}, 2);
  REQUIRE(c.found);
  CHECK(c.angle == Approx(115.0));
  CHECK(c.below == 110.0);
  CHECK(c.above == 130.0);
}

TEST_CASE("theta_c says why it cannot be found", "[metrics]") {
  const CriticalAngle flat = critical_angle({{20, 0.8}, {60, 0.8}, {100, 0.7}});
  CHECK_FALSE(flat.found);
  CHECK_THAT(flat.reason, Catch::Contains("never falls below half"));
  const CriticalAngle empty = critical_angle({{20, 0.0}, {60, 0.0}});
  CHECK_FALSE(empty.found);
  CHECK_THAT(empty.reason, Catch::Contains("not positive"));
  const CriticalAngle single = critical_angle({{20, 0.8}});
  CHECK_FALSE(single.found);
  CHECK_THAT(single.reason, Catch::Contains("at least two"));
}
