#pragma once
// What a run will cost, said before it starts: CPU time from the measured cost per rod and step
// (docs/performance.md), as a range from rods spread out to a filled trap. An estimate for planning
// (how many points fit in a night), not a promise: the machine, the trap angle and how soon the
// trap fills move it.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/model.hpp"
#include "runner/run_record.hpp"

namespace rodsort::runner {

/// Measured CPU cost per rod and time step [s] (docs/performance.md, "Cost estimates").
inline constexpr double kRodStepCostDispersed = 0.63e-6;  ///< paper's system, rods spread out
inline constexpr double kRodStepCostFilled = 1.36e-6;     ///< 397 rods while a 70° trap fills
/// Rough plates add, per rod and step, about this plus kRoughCostPerSlope times the RMS slope
/// (base and lid together), from the single-rod roughness study.
inline constexpr double kRoughRodStepCost = 1.0e-6;
inline constexpr double kRoughCostPerSlope = 80.0e-6;

/// A run's own cost counts once it has taken this fraction of its steps: the rate of its first
/// moments, before the rods meet and a trap fills, says little about the rest.
inline constexpr double kMeasuredMinFraction = 0.05;

struct CostEstimate {
  double low_cpu_s;   ///< rods spread out all the time
  double high_cpu_s;  ///< a trap filled from the start
};

CostEstimate estimate_cost(const engine::Model& model, std::int64_t steps);

/// The CPU time per rod and step [s] a run has cost so far, from its run.json; nullopt before
/// it has taken kMeasuredMinFraction of its steps.
std::optional<double> measured_rod_step_cost(const RunRecord& record);

struct MeasuredCost {
  double rod_step_cpu_s;  ///< the median over the runs [s]
  std::size_t runs;       ///< how many runs had a measured cost
};

/// The median of the runs' measured costs per rod and step; nullopt when none has one.
std::optional<MeasuredCost> median_rod_step_cost(const std::vector<RunRecord>& records);

/// What is left of a run that has taken `done_steps` of `total_steps` in `cpu_s`, at its own
/// rate so far (both ends equal); nullopt before it has taken kMeasuredMinFraction of them.
std::optional<CostEstimate> cost_at_own_rate(std::int64_t done_steps, std::int64_t total_steps,
                                             double cpu_s);

struct RemainingCost {
  CostEstimate cost;
  bool own_rate;  ///< at the run's own rate so far, not the measured range
};

/// What is left of a run that has taken `done_steps` of `total_steps` in `cpu_s`: at its own
/// rate when it has one (cost_at_own_rate), else the range for the steps left.
RemainingCost remaining_cost(const engine::Model& model, std::int64_t done_steps,
                             std::int64_t total_steps, double cpu_s);

/// "about 2.5-5.4 CPU-min", with the unit chosen for the larger figure; "about 3.1 CPU-h" when
/// both ends agree.
std::string describe_cost(const CostEstimate& cost);

}  // namespace rodsort::runner
