#pragma once
// What a top view of the cell shows that does not change from frame to frame: the periodic cell,
// the rods' shapes and colours by species, the trap's walls and area, and the words of the legend.
// A Scene is built once per run; each frame then only brings the rods' positions.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "engine/model.hpp"
#include "engine/rod_shape.hpp"
#include "render/palette.hpp"
#include "scenarios/scenario.hpp"

namespace rodsort::trap {
class Obstacle;
}

namespace rodsort::render {

struct SpeciesLook {
  std::string name;
  engine::RodShape shape;
  Colour colour;
  int count = 0;  ///< rods of this species, for the legend
};

struct Scene {
  std::string title;                ///< the scenario's name, written above the cell
  double box_x = 0.0, box_y = 0.0;  ///< periodic cell [0, box_x) x [0, box_y) [mm]
  std::vector<SpeciesLook> species;
  std::vector<engine::Wall> walls;  ///< drawn as the engine builds them
  /// Corners of the area the trap encloses (A_t), shaded under the rods; empty without a trap.
  std::vector<Eigen::Vector2d> trap_area;
  /// How stationary rods were picked, for the legend, e.g. "speed < 1 mm/s over 0.07 s".
  std::string stationary_rule;
};

/// The scene of a model: its cell, its species in the palette's order, its walls, and the trap's
/// area when `trap` is a V-trap (other obstacles show their walls only). `trap` may be null.
Scene make_scene(const engine::Model& model, const trap::Obstacle* trap, std::string title);

/// The scene of a loaded scenario (a run directory's scenario.resolved.yaml): its model and trap,
/// titled with its name, the legend stating its stationary threshold and window.
Scene scenario_scene(const scenarios::Scenario& scenario);

/// "speed < 1 mm/s over 0.07 s".
std::string stationary_rule_text(double threshold_mm_per_s, double window_s);

}  // namespace rodsort::render
