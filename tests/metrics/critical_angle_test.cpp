#include "metrics/critical_angle.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>

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
  const CriticalAngle flat =
      critical_angle({{20, 0.8}, {60, 0.8}, {100, 0.7}, {120, 0.6}, {140, 0.5}});
  CHECK_FALSE(flat.found);
  CHECK_THAT(flat.reason, Catch::Contains("never falls below half"));
  const CriticalAngle single = critical_angle({{20, 0.8}});
  CHECK_FALSE(single.found);
  CHECK_THAT(single.reason, Catch::Contains("at least 5 angles"));
}

TEST_CASE("theta_c only where the data bear it", "[metrics]") {
  // Two angles show a drop but no plateau: refused, not interpolated.
  const CriticalAngle two = critical_angle({{100, 0.9}, {140, 0.0}});
  CHECK_FALSE(two.found);
  CHECK_THAT(two.reason, Catch::Contains("at least 5 angles (3 for the low-angle plateau"));
  // Runs too short for the traps to fill: eta ~ 0.01 everywhere, with a "drop" in the noise.
  const CriticalAngle unfilled =
      critical_angle({{60, 0.012}, {80, 0.011}, {100, 0.010}, {120, 0.004}, {140, 0.001}});
  CHECK_FALSE(unfilled.found);
  CHECK_THAT(unfilled.reason, Catch::Contains("below 0.1"));
  // Found, but eta at 80 degrees reached 90% of its level only at 120 s of 150: a caution.
  std::vector<SweepPoint> rising = {{60, 0.8, 20, 150},
                                    {80, 0.7, 120, 150},
                                    {100, 0.8, 30, 150},
                                    {120, 0.1, 5, 150},
                                    {140, 0.0, std::numeric_limits<double>::quiet_NaN(), 150}};
  const CriticalAngle late = critical_angle(rising);
  REQUIRE(late.found);
  CHECK_THAT(late.caution, Catch::Contains("at 80, eta was still rising") &&
                               Catch::Contains("at 120 s of 150 s"));
  // Levelled in the first half everywhere on the plateau (140 degrees, never, is not on it).
  rising[1].levelled_at = 40;
  const CriticalAngle settled = critical_angle(rising);
  REQUIRE(settled.found);
  CHECK(settled.caution.empty());
  // A plateau run that never reached 90% of its level is cautioned too.
  rising[0].levelled_at = std::numeric_limits<double>::quiet_NaN();
  CHECK_THAT(
      critical_angle(rising).caution,
      Catch::Contains("at 60, eta never reached 90% of its final level in the runs (150 s)"));
}

TEST_CASE("theta_c is cautioned when a trap beyond the drop fills again", "[metrics]") {
  // Seed 3 of the paper's system near the transition (docs/reproduction.md, section 1): no pile
  // at 130 and 135 degrees, one at 140.
  const std::vector<SweepPoint> seed3 = {{110, 0.909}, {115, 0.778}, {120, 0.506}, {125, 0.423},
                                         {130, 0.065}, {135, 0.095}, {140, 0.803}};
  const CriticalAngle result = critical_angle(seed3);
  REQUIRE(result.found);
  CHECK(result.angle == Approx(125.8).margin(0.1));
  CHECK_THAT(result.caution, Catch::Contains("at 140, beyond theta_c, eta is 0.803, above half "
                                             "the plateau again"));
  // Without the pile at 140 degrees nothing is held against it.
  std::vector<SweepPoint> monotonic = seed3;
  monotonic.back().eta = 0.03;
  CHECK(critical_angle(monotonic).caution.empty());
}

TEST_CASE("theta_c per seed: each seed alone, then their mean and standard error", "[metrics]") {
  // Three seeds over the same angles, dropping through half their plateau (0.4) at 125°, 135°
  // and 130° (each halfway between two angles), and a fourth whose traps never filled.
  const auto seed = [](double at_120, double at_130, double at_140) {
    return std::vector<SweepPoint>{{100, 0.8},    {105, 0.8},    {110, 0.8},
                                   {120, at_120}, {130, at_130}, {140, at_140}};
  };
  const std::vector<std::vector<SweepPoint>> seeds = {
      seed(0.7, 0.1, 0.0),
      seed(0.8, 0.6, 0.2),
      seed(0.8, 0.5, 0.0),
      {{100, 0.05}, {105, 0.0}, {110, 0.0}, {120, 0.0}, {130, 0.0}}};
  const SeedCriticalAngles c = critical_angle_per_seed(seeds);
  REQUIRE(c.per_seed.size() == 4);
  CHECK(c.per_seed[0].angle == Approx(125.0));
  CHECK(c.per_seed[1].angle == Approx(135.0));
  CHECK(c.per_seed[2].angle == Approx(130.0 + 10.0 * (0.5 - 0.4) / (0.5 - 0.0)));
  CHECK_FALSE(c.per_seed[3].found);
  CHECK_THAT(c.per_seed[3].reason, Catch::Contains("have not filled"));
  REQUIRE(c.found == 3);
  const double mean = (125.0 + 135.0 + 132.0) / 3.0;
  CHECK(c.mean == Approx(mean));
  const double sd = std::sqrt(((125.0 - mean) * (125.0 - mean) + (135.0 - mean) * (135.0 - mean) +
                               (132.0 - mean) * (132.0 - mean)) /
                              2.0);
  CHECK(c.standard_deviation == Approx(sd));
  CHECK(c.standard_error == Approx(sd / std::sqrt(3.0)));

  // One seed with a theta_c has a mean but no spread.
  const SeedCriticalAngles one = critical_angle_per_seed({seeds[0], seeds[3]});
  CHECK(one.found == 1);
  CHECK(one.mean == Approx(125.0));
  CHECK(std::isnan(one.standard_error));
}
