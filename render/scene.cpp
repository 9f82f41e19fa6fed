#include "render/scene.hpp"

#include <cstdio>

#include "trap/obstacle.hpp"

namespace rodsort::render {

Scene make_scene(const engine::Model& model, const trap::Obstacle* trap, std::string title) {
  Scene scene;
  scene.title = std::move(title);
  scene.box_x = model.box_x;
  scene.box_y = model.box_y;
  for (std::size_t s = 0; s < model.species.size(); ++s) {
    scene.species.push_back(
        {model.species[s].name, model.species[s].shape, species_colour(static_cast<int>(s)), 0});
  }
  for (const engine::RodInit& rod : model.rods) {
    ++scene.species[static_cast<std::size_t>(rod.species)].count;
  }
  scene.walls = model.walls;
  if (trap != nullptr) scene.trap_area = trap->outline();
  return scene;
}

Scene scenario_scene(const scenarios::Scenario& scenario) {
  Scene scene = make_scene(scenario.model, scenario.trap.get(), scenario.name);
  scene.stationary_rule =
      stationary_rule_text(scenario.metrics.stationary_threshold, scenario.metrics.window);
  return scene;
}

std::string stationary_rule_text(double threshold_mm_per_s, double window_s) {
  char text[96];
  std::snprintf(text, sizeof text, "speed < %g mm/s over %g s", threshold_mm_per_s, window_s);
  return text;
}

}  // namespace rodsort::render
