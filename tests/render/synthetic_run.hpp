#pragma once
// A small scene and run for the render tests, built by hand: rod A and rod RnT in a 40 x 30 mm
// cell with a 90° trap of 12 mm arms in the middle, and a run directory whose rods.csv holds a
// few frames of four rods.

#include <cmath>
#include <filesystem>
#include <fstream>

#include "engine/rod_shape.hpp"
#include "engine/units.hpp"
#include "metrics/metrics_observer.hpp"
#include "metrics/rods_csv.hpp"
#include "render/frame_marks.hpp"
#include "render/scene.hpp"
#include "trap/v_trap.hpp"

namespace rodsort::render::testing {

inline constexpr double kBoxX = 40.0;           // [mm]
inline constexpr double kBoxY = 30.0;           // [mm]
inline constexpr double kFrameInterval = 0.07;  // [s]
inline constexpr double kSpeed = 10.0;          // of the moving rods [mm/s]

struct TestScene {
  trap::VTrap trap = trap::centered_v_trap(kBoxX, kBoxY, kPi / 2.0, 12.0, 0.5);
  engine::Model model;
  Scene scene;

  TestScene() {
    model.box_x = kBoxX;
    model.box_y = kBoxY;
    model.species.push_back({"A",
                             engine::make_rod_shape(engine::preset_a_profile(), kBrassDensity),
                             {},
                             engine::MaterialTable::kFirstRod});
    model.species.push_back({"RnT",
                             engine::make_rod_shape(engine::preset_rnt_profile(), kBrassDensity),
                             {},
                             engine::MaterialTable::kFirstRod});
    model.walls = trap.walls();
    model.rods = {
        {0, 6.0, 6.0, 0.0}, {1, 34.0, 24.0, kPi / 2.0}, {0, 0.5, 26.0, 0.0}, {0, 0.0, 0.0, kPi}};
    scene = make_scene(model, &trap, "render test");
    scene.stationary_rule =
        stationary_rule_text(metrics::kDefaultStationarySpeed, metrics::kDefaultWindow);
  }

  metrics::MetricsConfig metrics_config() const {
    metrics::MetricsConfig config;
    for (const engine::Species& species : model.species) {
      config.species_names.push_back(species.name);
      config.species_area.push_back(species.shape.projected_area);
    }
    config.trap_area = trap.area();
    const trap::VTrap trap_copy = trap;
    config.inside = [trap_copy](const Eigen::Vector2d& point) { return trap_copy.contains(point); };
    return config;
  }
};

inline engine::RodFrame rod(int species, double x, double y, double heading) {
  engine::RodFrame rod;
  rod.species = species;
  rod.position = {x, y};
  rod.unwrapped = rod.position;
  rod.axis = {std::cos(heading), std::sin(heading), 0.0};
  rod.velocity.setZero();
  rod.angular_velocity.setZero();
  return rod;
}

/// Rod 0 (A) moving along +x in the open, rod 1 (RnT) moving along +y, rod 2 (A) resting across
/// the left edge of the cell, rod 3 (A) resting inside the trap.
inline engine::Frame test_frame(const trap::VTrap& trap, double time = 1.25) {
  engine::Frame frame;
  frame.time = time;
  frame.rods.push_back(rod(0, 6.0 + kSpeed * time, 6.0, 0.0));
  frame.rods.push_back(rod(1, 34.0, 14.0 + kSpeed * time, kPi / 2.0));
  frame.rods.push_back(rod(0, 0.5, 26.0, 0.0));
  const Eigen::Vector2d in_trap = trap.apex() + 4.0 * trap.bisector();
  frame.rods.push_back(rod(0, in_trap.x(), in_trap.y(), kPi));
  return frame;
}

inline FrameMarks test_marks() { return {{false, false, false, true}, 0.25, 0.2}; }

/// Writes rods.csv of `frames` frames, kFrameInterval apart from t = 0, into `directory`.
inline void write_test_run(const std::filesystem::path& directory, const TestScene& test,
                           int frames) {
  std::ofstream out(directory / "rods.csv");
  metrics::RodsCsvWriter writer(out, {"A", "RnT"});
  writer.write_header();
  for (int k = 0; k < frames; ++k) writer.write(test_frame(test.trap, kFrameInterval * k));
}

}  // namespace rodsort::render::testing
