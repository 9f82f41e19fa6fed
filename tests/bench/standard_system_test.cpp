#include "bench/standard_system.hpp"

#include <catch2/catch.hpp>
#include <cmath>

#include "bench/lattice_placement.hpp"
#include "engine/model.hpp"

using namespace rodsort;
using namespace rodsort::bench;

namespace {

double periodic(double d, double box) { return d - box * std::round(d / box); }

/// Smallest gap between the surfaces of two rods' spheres, across the periodic edges [mm].
double gap(const engine::Model& model, const engine::RodInit& a, const engine::RodInit& b) {
  const auto& spheres = model.species[0].shape.spheres;
  double smallest = 1e9;
  for (const engine::Sphere& p : spheres) {
    for (const engine::Sphere& q : spheres) {
      const double dx = periodic(
          a.x + p.axial * std::cos(a.heading) - b.x - q.axial * std::cos(b.heading), model.box_x);
      const double dy = periodic(
          a.y + p.axial * std::sin(a.heading) - b.y - q.axial * std::sin(b.heading), model.box_y);
      smallest = std::min(smallest, std::hypot(dx, dy) - p.radius - q.radius);
    }
  }
  return smallest;
}

}  // namespace

TEST_CASE("standard systems keep the paper's density and trap", "[bench]") {
  const auto systems = standard_systems();
  REQUIRE(systems.size() == 10);
  CHECK(find_system("319").box == Approx(86.85));
  for (const SystemSpec& system : systems) {
    if (system.name == "single") continue;
    const double scale = system.box / kPaperBox;
    CHECK(system.rod_count == Approx(319 * scale * scale));
    // Filled systems are copies of the paper's system, each with its own trap.
    CHECK(system.trap_arm == Approx(kPaperArm * (system.filled_tiles > 0 ? 1.0 : scale)));
  }
  CHECK_THROWS_WITH(find_system("320"), Catch::Contains("319"));
}

TEST_CASE("rods start inside the cell without touching each other", "[bench]") {
  const std::string name = GENERATE(as<std::string>{}, "1276", "1276-full");
  INFO(name);
  const engine::Model model = build_model(find_system(name), 1e-4, 3);
  REQUIRE(model.rods.size() == 1276);
  CHECK(model.walls.size() == 3);
  for (std::size_t i = 0; i < model.rods.size(); ++i) {
    const engine::RodInit& rod = model.rods[i];
    CHECK((rod.x >= 0.0 && rod.x < model.box_x && rod.y >= 0.0 && rod.y < model.box_y));
    for (std::size_t j = 0; j < i; ++j) {
      if (std::hypot(periodic(rod.x - model.rods[j].x, model.box_x),
                     periodic(rod.y - model.rods[j].y, model.box_y)) > 6.0) {
        continue;
      }
      CHECK(gap(model, rod, model.rods[j]) >= kPlacementClearance - 1e-12);
    }
  }
}

TEST_CASE("placement is reproducible from the seed", "[bench]") {
  const engine::Model a = build_model(find_system("319"), 1e-4, 5);
  const engine::Model b = build_model(find_system("319"), 1e-4, 5);
  const engine::Model c = build_model(find_system("319"), 1e-4, 6);
  CHECK(a.rods.front().x == b.rods.front().x);
  CHECK(a.rods.back().heading == b.rods.back().heading);
  CHECK(a.rods.front().x != c.rods.front().x);
}

TEST_CASE("a full-trap system starts with its trap packed", "[bench]") {
  for (const char* name : {"319-full", "1276-full", "5104-full"}) {
    const SystemSpec system = find_system(name);
    const engine::Model model = build_model(system, 1e-4, 3);
    REQUIRE(static_cast<int>(model.rods.size()) == system.rod_count);
    // Rods whose centre lies in the trap's triangle: apex at the cell's centre less half the
    // trap's depth along +x (the bisector of centered_v_trap), opening 120 degrees.
    const double depth = system.trap_arm * std::cos(degrees_to_radians(60.0));
    const double apex_x = system.box / 2.0 - depth / 2.0;
    int inside = 0;
    double nearest_wall = 1e300;  // from a sphere's surface to an arm's inner face [mm]
    const double half = degrees_to_radians(60.0);
    for (const engine::RodInit& rod : model.rods) {
      const double along = rod.x - apex_x;
      const double across = std::abs(rod.y - system.box / 2.0);
      if (along > 0.0 && along < depth && across < along * std::tan(half)) {
        ++inside;
        for (const engine::Sphere& sphere : model.species.front().shape.spheres) {
          const double x = along + sphere.axial * std::cos(rod.heading);
          const double y = across + sphere.axial * std::sin(rod.heading);
          nearest_wall = std::min(
              nearest_wall, x * std::sin(half) - std::abs(y) * std::cos(half) - sphere.radius);
        }
      }
    }
    INFO(name << ": " << inside << " of " << system.rod_count << " rods in the trap");
    // The packed rods cover nearly half the triangle's area (each takes about 4.6 x 1.15 mm^2;
    // rows across the bisector leave the corners by the arms empty: 49% for 319-full).
    const double area =
        0.5 * system.trap_arm * system.trap_arm * std::sin(degrees_to_radians(120.0));
    CHECK(inside * 4.6 * 1.15 > 0.45 * area);
    // None of them is in a wall.
    CHECK(nearest_wall >= kPlacementClearance - 1e-9);
  }
}
