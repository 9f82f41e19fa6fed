// A collision across the periodic edge, or across a corner, must be the same collision as in the
// middle of the cell.
#include <catch2/catch.hpp>
#include <cmath>

#include "engine/simulation.hpp"
#include "paper_model.hpp"

using namespace rodsort::engine;

namespace {

constexpr double kBox = 30.0;

/// Two rods about to collide: rod 0 at `origin` heading +x and moving +x, rod 1 ahead of it,
/// turned across its path and moving -x. Returns the frame after `steps`, with `unwrapped`
/// replaced by each rod's displacement since the start.
Frame collide(const Eigen::Vector2d& origin, int steps) {
  Model model = testing::paper_model(kBox);
  model.species.push_back(testing::rod_species(preset_a_profile()));
  const auto wrap = [](double v) { return v - kBox * std::floor(v / kBox); };
  model.rods.push_back({0, wrap(origin.x()), wrap(origin.y()), 0.0});
  model.rods.push_back({0, wrap(origin.x() + 5.0), wrap(origin.y() + 0.3), 1.9});
  Simulation sim(model);
  State state = sim.state();
  state.rods[0].velocity = {80.0, 0.0, 0.0};
  state.rods[1].velocity = {-80.0, 0.0, 0.0};
  sim.restore(state);
  const Frame start = sim.frame();
  sim.advance(steps);
  Frame end = sim.frame();
  for (std::size_t i = 0; i < end.rods.size(); ++i) end.rods[i].unwrapped -= start.rods[i].unwrapped;
  return end;
}

/// Largest relative difference between two outcomes.
double difference(const Frame& a, const Frame& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.rods.size(); ++i) {
    const RodFrame& ra = a.rods[i];
    const RodFrame& rb = b.rods[i];
    worst = std::max(worst, (ra.unwrapped - rb.unwrapped).norm() / ra.unwrapped.norm());
    worst = std::max(worst, std::abs(ra.z - rb.z) / ra.z);
    worst = std::max(worst, (ra.axis - rb.axis).norm());
    worst = std::max(worst, (ra.velocity - rb.velocity).norm() / ra.velocity.norm());
    worst = std::max(worst, (ra.angular_velocity - rb.angular_velocity).norm() /
                                std::max(1.0, ra.angular_velocity.norm()));
  }
  return worst;
}

}  // namespace

TEST_CASE("a collision across an edge or a corner equals one in the middle", "[periodic]") {
  constexpr int kSteps = 300;
  const Eigen::Vector2d middle(12.0, 15.0);
  const Frame reference = collide(middle, kSteps);
  // The rods did collide: rod 0 no longer moves at +80 mm/s along x.
  REQUIRE(reference.rods[0].velocity.x() < 60.0);
  SECTION("across the x edge") {
    const Eigen::Vector2d origin(kBox - 2.5, 15.0);
    CHECK(difference(reference, collide(origin, kSteps)) < 1e-9);
  }
  SECTION("across the y edge") {
    const Eigen::Vector2d origin(12.0, kBox - 0.15);
    CHECK(difference(reference, collide(origin, kSteps)) < 1e-9);
  }
  SECTION("across a corner") {
    const Eigen::Vector2d origin(kBox - 2.5, kBox - 0.15);
    CHECK(difference(reference, collide(origin, kSteps)) < 1e-9);
  }
  SECTION("across the opposite corner") {
    const Eigen::Vector2d origin(kBox - 2.5, 0.1);
    CHECK(difference(reference, collide(origin, kSteps)) < 1e-9);
  }
}
