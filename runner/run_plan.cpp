#include "runner/run_plan.hpp"

#include <memory>

#include "trap/cell_wall.hpp"
#include "trap/obstacle.hpp"

namespace rodsort::runner {

metrics::MetricsConfig metrics_config(const scenarios::Scenario& scenario) {
  metrics::MetricsConfig config;
  for (std::size_t s = 0; s < scenario.model.species.size(); ++s) {
    config.species_names.push_back(scenario.model.species[s].name);
    config.species_area.push_back(scenario.species[s].projected_area);
  }
  config.trap_area = scenario.trap_area;
  if (scenario.trap) {
    std::shared_ptr<const trap::Obstacle> trap = scenario.trap;
    config.inside = [trap](const Eigen::Vector2d& point) { return trap->contains(point); };
  }
  if (scenario.cell) {
    // Within a rod's reach (its centre to its farthest tip) of the wall: touching it, or about to.
    std::vector<engine::RodShape> shapes;
    for (const engine::Species& species : scenario.model.species) shapes.push_back(species.shape);
    const double reach = trap::required_margin(shapes);
    std::shared_ptr<const trap::CellWall> cell = scenario.cell;
    config.at_wall = [cell, reach](const Eigen::Vector2d& point) {
      return cell->distance_to_wall(point) <= reach;
    };
  }
  config.window = scenario.metrics.window;
  config.stationary_speed_threshold = scenario.metrics.stationary_threshold;
  config.held_distance = scenario.metrics.held_distance;
  config.held_lag = scenario.metrics.held_lag;
  return config;
}

RunPlan make_run_plan(const scenarios::Scenario& scenario) {
  RunPlan plan;
  plan.name = scenario.name;
  plan.model = scenario.model;
  plan.duration_s = scenario.run.duration;
  plan.frame_interval_s = scenario.output.frame_interval;
  plan.schedule.total_steps = scenario.run.steps;
  plan.schedule.frame_steps = scenario.output.frame_steps;
  plan.schedule.trajectory_steps = scenario.output.trajectory_steps;
  plan.schedule.checkpoint_steps = scenario.output.checkpoint_steps;
  for (std::size_t i = 0; i < scenario.output.snapshot_steps.size(); ++i) {
    plan.schedule.snapshots.push_back(
        {scenario.output.snapshot_steps[i], scenario.output.bullet_snapshots[i]});
  }
  plan.metrics = metrics_config(scenario);
  plan.resolved_yaml = scenarios::resolved_yaml(scenario);
  plan.dump_style = scenario.output.trajectory_named ? DumpStyle::named : DumpStyle::plain;
  plan.rods_csv = scenario.output.rods_csv;
  plan.rods_h5md = scenario.output.rods_h5md;
  plan.h5md_precision =
      scenario.output.h5md_double ? metrics::H5mdPrecision::full : metrics::H5mdPrecision::single;
  return plan;
}

}  // namespace rodsort::runner
