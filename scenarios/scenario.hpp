#pragma once
// The entry point of the scenarios layer: a scenario file (plus `--set` overrides) in, a Scenario
// or the list of everything wrong with it out. A Scenario is what a run needs: the compiled
// engine::Model (physics, initial rods), the trap as an obstacle for the measurements, and the
// settings that are not physics (duration, outputs, metrics). Nothing is written for a refused
// scenario, and a scenario that loads can be written back (resolved_yaml) so that reading the
// written file gives the same Model.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/model.hpp"
#include "scenarios/diagnostic.hpp"
#include "scenarios/override.hpp"
#include "scenarios/scenario_spec.hpp"

namespace rodsort::trap {
class Obstacle;
class CellWall;
}  // namespace rodsort::trap

namespace rodsort::scenarios {

struct RunSettings {
  double duration;     ///< simulated time [s]
  std::int64_t steps;  ///< duration / dt, rounded
};

struct OutputSettings {
  double frame_interval;                 ///< between rows of rods.csv [s]
  std::int64_t frame_steps;              ///< the same in steps (>= 1)
  bool rods_csv = true;                  ///< output.rods_format: csv or both (rods.csv)
  bool rods_h5md = false;                ///< output.rods_format: h5md or both (rods.h5)
  bool h5md_double = false;              ///< output.h5md_precision: double
  double trajectory_interval;            ///< between frames of the sphere trajectory [s]; 0: none
  bool trajectory_named = false;         ///< output.trajectory_style: named (species names, TIME)
  std::int64_t trajectory_steps;         ///< the same in steps; 0: none
  std::vector<double> bullet_snapshots;  ///< times of .bullet snapshots [s], sorted
  std::vector<std::int64_t> snapshot_steps;  ///< the same in steps
  double checkpoint_interval;                ///< simulated time between checkpoints [s]
  std::int64_t checkpoint_steps;             ///< the same in steps (>= 1)
};

struct MetricsSettings {
  double window;                ///< tau: speeds are displacements over this window [s]
  double stationary_threshold;  ///< a rod slower than this is stationary [mm/s]
  double held_distance;         ///< a rod in the trap that moved less than this is held [mm]
  double held_lag;              ///< over this time [s]
};

/// What compile() derived, written into resolved scenarios for the record.
struct SpeciesDerived {
  int count;              ///< rods of this species
  double projected_area;  ///< a, area of the rod's 2D projection [mm^2]
  double mass;            ///< [g]
  double length;          ///< tip to tip [mm]
};

struct Scenario {
  std::string name;
  std::filesystem::path source;  ///< file it was read from; empty when read from text
  engine::Model model;           ///< everything the engine needs, initial rods included
  std::shared_ptr<const trap::Obstacle> trap;  ///< nullptr for `trap: none`
  double trap_area = 0.0;                      ///< A_t [mm^2]; 0 without a trap
  /// The wall closing a bounded cell; nullptr for the periodic cell (`cell.shape: periodic`).
  std::shared_ptr<const trap::CellWall> cell;
  double cell_area = 0.0;  ///< where the rods move: the box, or inside the cell's wall [mm^2]
  std::vector<SpeciesDerived> species;  ///< parallel to model.species
  RunSettings run{};
  OutputSettings output{};
  MetricsSettings metrics{};
  ScenarioSpec spec;  ///< the file as read, every default resolved: what resolved_yaml writes
};

struct LoadResult {
  std::optional<Scenario> scenario;     ///< absent when there is any error
  std::vector<Diagnostic> diagnostics;  ///< errors and warnings, in the order found

  bool ok() const { return scenario.has_value(); }
};

/// Reads, checks and compiles a scenario file, after applying `overrides` in order.
LoadResult load_scenario(const std::filesystem::path& path,
                         const std::vector<Override>& overrides = {});
/// The same, with overrides given as `--set` arguments ("trap.angle=130").
LoadResult load_scenario_with_options(const std::filesystem::path& path,
                                      const std::vector<std::string>& set_options);
/// Reads a scenario from YAML text; `source` names it in messages and gives its default name.
LoadResult load_scenario_text(std::string_view yaml, const std::string& source,
                              const std::vector<Override>& overrides = {});
/// Checks and compiles a parsed tree (a sweep's inline base, for instance).
LoadResult load_scenario_tree(SourceNode tree, const std::string& default_name,
                              const std::vector<Override>& overrides = {});

/// The scenario as YAML with every default explicit, and a `derived:` section (amplitude, rod
/// counts, areas, masses) that is ignored when read. Reading it back gives the same Model.
std::string resolved_yaml(const Scenario& scenario);

}  // namespace rodsort::scenarios
