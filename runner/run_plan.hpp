#pragma once
// Everything a run needs, taken from a loaded scenario: the engine's Model, when to write what,
// and how to measure. The run loop sees only this.

#include <string>
#include <vector>

#include "engine/model.hpp"
#include "metrics/metrics_observer.hpp"
#include "metrics/rods_h5md.hpp"
#include "runner/lammps_dump.hpp"
#include "runner/run_schedule.hpp"
#include "scenarios/scenario.hpp"

namespace rodsort::runner {

struct RunPlan {
  std::string name;
  engine::Model model;
  double duration_s = 0.0;        ///< simulated time of the whole run [s]
  double frame_interval_s = 0.0;  ///< between frames of rods.csv and metrics.csv [s]
  RunSchedule schedule;
  metrics::MetricsConfig metrics;  ///< its inside test holds the trap
  std::string resolved_yaml;       ///< scenario.resolved.yaml's text
  DumpStyle dump_style = DumpStyle::plain;  ///< of trajectory.dump and walls.dump
  bool rods_csv = true;                     ///< write rods.csv
  bool rods_h5md = false;                   ///< write rods.h5
  metrics::H5mdPrecision h5md_precision = metrics::H5mdPrecision::single;
};

RunPlan make_run_plan(const scenarios::Scenario& scenario);

/// What the metrics layer needs to know of a scenario (species, areas, trap, window, threshold);
/// also used by `rodsort analyze` on a finished run.
metrics::MetricsConfig metrics_config(const scenarios::Scenario& scenario);

}  // namespace rodsort::runner
