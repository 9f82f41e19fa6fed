#include "scenarios/placement.hpp"

#include <catch2/catch.hpp>
#include <cmath>

#include "engine/units.hpp"
#include "scenarios/scenario.hpp"
#include "trap/obstacle.hpp"

using namespace rodsort;
using namespace rodsort::scenarios;

namespace {

Scenario load_ok(const std::string& yaml) {
  LoadResult result = load_scenario_text(yaml, "placement.yaml");
  INFO(format_diagnostics(result.diagnostics));
  REQUIRE(result.ok());
  return std::move(*result.scenario);
}

Eigen::Vector2d nearest_image(Eigen::Vector2d d, const engine::Model& model) {
  d.x() -= model.box_x * std::round(d.x() / model.box_x);
  d.y() -= model.box_y * std::round(d.y() / model.box_y);
  return d;
}

/// Centres and radii of every sphere of every rod, in the plane.
struct Disc {
  Eigen::Vector2d center;
  double radius;
  std::size_t rod;
};

std::vector<Disc> discs_of(const engine::Model& model) {
  std::vector<Disc> discs;
  for (std::size_t i = 0; i < model.rods.size(); ++i) {
    const engine::RodInit& rod = model.rods[i];
    const Eigen::Vector2d axis(std::cos(rod.heading), std::sin(rod.heading));
    for (const engine::Sphere& s :
         model.species[static_cast<std::size_t>(rod.species)].shape.spheres) {
      discs.push_back({Eigen::Vector2d(rod.x, rod.y) + s.axial * axis, s.radius, i});
    }
  }
  return discs;
}

/// Checks the actual spheres, not the capsules placement used: an independent test.
void check_no_overlap(const engine::Model& model) {
  const std::vector<Disc> discs = discs_of(model);
  double closest = 1e9;
  for (std::size_t i = 0; i < discs.size(); ++i) {
    for (std::size_t j = i + 1; j < discs.size(); ++j) {
      if (discs[i].rod == discs[j].rod) continue;
      const double gap = nearest_image(discs[j].center - discs[i].center, model).norm() -
                         discs[i].radius - discs[j].radius;
      closest = std::min(closest, gap);
    }
    for (const engine::Wall& wall : model.walls) {
      const Eigen::Vector2d d =
          nearest_image(discs[i].center - Eigen::Vector2d(wall.center_x, wall.center_y), model);
      const Eigen::Vector2d along(std::cos(wall.yaw), std::sin(wall.yaw));
      const Eigen::Vector2d across(-along.y(), along.x());
      const double x = std::max(std::abs(d.dot(along)) - wall.half_length, 0.0);
      const double y = std::max(std::abs(d.dot(across)) - wall.half_thickness, 0.0);
      closest = std::min(closest, std::hypot(x, y) - discs[i].radius);
    }
  }
  CHECK(closest > 0.0);
}

}  // namespace

TEST_CASE("segment distance", "[placement]") {
  using V = Eigen::Vector2d;
  CHECK(segment_distance(V(0, 0), V(1, 0), V(0, 1), V(1, 1)) == Approx(1.0));
  CHECK(segment_distance(V(0, 0), V(1, 0), V(0.5, -1), V(0.5, 1)) == Approx(0.0).margin(1e-15));
  CHECK(segment_distance(V(0, 0), V(1, 0), V(2, 1), V(3, 1)) == Approx(std::sqrt(2.0)));
  CHECK(segment_distance(V(0, 0), V(0, 0), V(3, 4), V(3, 4)) == Approx(5.0));
  CHECK(segment_distance(V(0, 0), V(2, 0), V(1, 0.5), V(1, 0.5)) == Approx(0.5));
}

TEST_CASE("rods start apart, clear of the walls, and the same for the same seed", "[placement]") {
  const Scenario first = load_ok("trap: {angle: 120}\n");
  REQUIRE(first.model.rods.size() > 300);
  check_no_overlap(first.model);
  for (const engine::RodInit& rod : first.model.rods) {
    CHECK(rod.x >= 0.0);
    CHECK(rod.x < first.model.box_x);
    CHECK(rod.y >= 0.0);
    CHECK(rod.y < first.model.box_y);
  }
  const Scenario again = load_ok("trap: {angle: 120}\n");
  for (std::size_t i = 0; i < first.model.rods.size(); ++i) {
    CHECK(again.model.rods[i].x == first.model.rods[i].x);
    CHECK(again.model.rods[i].heading == first.model.rods[i].heading);
  }
  const Scenario other = load_ok("trap: {angle: 120}\nseed: 2\n");
  CHECK(other.model.rods[0].x != first.model.rods[0].x);
}

TEST_CASE("headings are isotropic", "[placement]") {
  const Scenario scenario = load_ok("trap: none\nspecies: [{count: 1000}]\nbox: {size: 200}\n");
  double c = 0.0, s = 0.0;
  for (const engine::RodInit& rod : scenario.model.rods) {
    c += std::cos(rod.heading);
    s += std::sin(rod.heading);
  }
  // The mean of 1000 unit vectors of random direction has a spread of about 1/sqrt(2000).
  CHECK(std::hypot(c, s) / 1000.0 < 0.1);
}

TEST_CASE("a dense mixture still places every rod apart", "[placement]") {
  const Scenario scenario = load_ok(
      "trap: {angle: 60}\n"
      "box: {size: 70}\n"
      "population: {area_fraction: 0.3}\n"
      "species:\n"
      "  - {name: A, fraction: 0.5}\n"
      "  - {name: RnT, shape: {preset: RnT}, fraction: 0.5}\n");
  check_no_overlap(scenario.model);
  CHECK(scenario.model.rods.front().species == 0);
  CHECK(scenario.model.rods.back().species == 1);
}

TEST_CASE("rods can start inside the trap, pointing at its apex", "[placement]") {
  const Scenario scenario = load_ok(
      "trap: {angle: 60, direction: 0}\n"
      "species:\n"
      "  - {name: A, count: 2, initial: {region: inside_trap, heading: toward_apex}}\n"
      "  - {name: B, count: 20, initial: {region: outside_trap, heading: 90}}\n");
  check_no_overlap(scenario.model);
  for (const engine::RodInit& rod : scenario.model.rods) {
    const bool inside = scenario.trap->contains({rod.x, rod.y});
    CHECK(inside == (rod.species == 0));
    if (rod.species == 1) CHECK(rod.heading == Approx(degrees_to_radians(90.0)));
  }
  // The trap opens toward +x and the apex is on its left: rods pointing at it point toward -x.
  for (const engine::RodInit& rod : scenario.model.rods) {
    if (rod.species == 0) CHECK(std::cos(rod.heading) < -std::cos(degrees_to_radians(30.0)) + 1e-9);
  }
}
