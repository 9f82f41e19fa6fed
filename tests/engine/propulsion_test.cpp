// Self-propulsion of a single rod on the vibrated plate: the physics the whole project rests on.
#include <catch2/catch.hpp>
#include <cmath>

#include "engine/simulation.hpp"
#include "paper_model.hpp"

using namespace rodsort::engine;

namespace {

/// Mean velocity along the initial axis over `seconds` after one second of warm-up [mm/s].
double axial_speed(const Species& species, double seconds, double dt = 1.0e-4) {
  Simulation sim(testing::single_rod_model(species, dt));
  sim.advance(std::lround(1.0 / dt));
  const Frame start = sim.frame();
  sim.advance(std::lround(seconds / dt));
  const Frame end = sim.frame();
  const Eigen::Vector2d axis = start.rods[0].axis.head<2>().normalized();
  return (end.rods[0].unwrapped - start.rods[0].unwrapped).dot(axis) / seconds;
}

double heading(const RodFrame& rod) { return std::atan2(rod.axis.y(), rod.axis.x()); }

}  // namespace

TEST_CASE("a tapered rod moves toward its thin end at a few mm/s", "[physics][propulsion]") {
  const double first = axial_speed(testing::rod_species(preset_a_profile()), 3.0);
  // Experiments: 3.6 +- 2.5 mm/s; Bullet models of rod A give ~8-13 mm/s (docs/model.md).
  CHECK(first > 2.0);
  CHECK(first < 20.0);
}

TEST_CASE("a cylinder of the same size does not propel", "[physics][propulsion]") {
  const double speed =
      axial_speed(testing::rod_species(linear_taper_profile(4.5, 0.4, 0.4, 9)), 3.0);
  CHECK(std::abs(speed) < 0.3);
}

TEST_CASE("without noise a rod keeps its heading", "[physics][noise]") {
  Simulation sim(testing::single_rod_model(testing::rod_species(preset_a_profile())));
  sim.advance(5000);
  const double start = heading(sim.frame().rods[0]);
  sim.advance(50000);
  const double end = heading(sim.frame().rods[0]);
  CHECK(std::abs(std::remainder(end - start, 2.0 * rodsort::kPi)) < 0.05);
}
