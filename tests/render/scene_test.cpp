#include "render/scene.hpp"

#include <catch2/catch.hpp>

#include "scenarios/scenario.hpp"
#include "trap/obstacle.hpp"

using namespace rodsort;

TEST_CASE("The scene of the quickstart scenario", "[render][scene]") {
  const scenarios::LoadResult loaded = scenarios::load_scenario(
      std::filesystem::path(RODSORT_SOURCE_DIR) / "scenarios" / "quickstart.yaml");
  INFO(scenarios::format_diagnostics(loaded.diagnostics));
  REQUIRE(loaded.ok());
  const scenarios::Scenario& scenario = *loaded.scenario;
  const render::Scene scene = render::scenario_scene(scenario);
  CHECK(scene.title == "quickstart");
  CHECK(scene.box_x == 50.0);
  CHECK(scene.box_y == 50.0);
  REQUIRE(scene.species.size() == 1);
  CHECK(scene.species[0].name == "A");
  CHECK(scene.species[0].count == static_cast<int>(scenario.model.rods.size()));
  CHECK(scene.species[0].count == scenario.species[0].count);
  CHECK(scene.walls.size() == scenario.trap->walls().size());
  // The shaded area is the trap's triangle, of area A_t.
  REQUIRE(scene.trap_area.size() == 3);
  const Eigen::Vector2d u = scene.trap_area[1] - scene.trap_area[0];
  const Eigen::Vector2d v = scene.trap_area[2] - scene.trap_area[0];
  CHECK(0.5 * std::abs(u.x() * v.y() - u.y() * v.x()) == Approx(scenario.trap_area));
  CHECK(scene.stationary_rule == render::stationary_rule_text(scenario.metrics.stationary_threshold,
                                                              scenario.metrics.window));
  CHECK(render::stationary_rule_text(5.0, 0.07) == "speed < 5 mm/s over 0.07 s");
}
