#pragma once
// What a run will cost, said before it starts: CPU time from the measured cost per rod and step
// (docs/performance.md), as a range from rods spread out to a filled trap. An estimate for planning
// (how many points fit in a night), not a promise: the machine, the trap angle and how soon the
// trap fills move it.

#include <cstdint>
#include <string>

#include "engine/model.hpp"

namespace rodsort::runner {

/// Measured CPU cost per rod and time step [s] (docs/performance.md, "Cost estimates").
inline constexpr double kRodStepCostDispersed = 0.63e-6;  ///< paper's system, rods spread out
inline constexpr double kRodStepCostFilled = 1.36e-6;     ///< 397 rods while a 70° trap fills
/// Rough plates add, per rod and step, about this plus kRoughCostPerSlope times the RMS slope
/// (base and lid together), from the single-rod roughness study.
inline constexpr double kRoughRodStepCost = 1.0e-6;
inline constexpr double kRoughCostPerSlope = 80.0e-6;

struct CostEstimate {
  double low_cpu_s;   ///< rods spread out all the time
  double high_cpu_s;  ///< a trap filled from the start
};

CostEstimate estimate_cost(const engine::Model& model, std::int64_t steps);

/// "about 2.5-5.4 CPU-min", with the unit chosen for the larger figure.
std::string describe_cost(const CostEstimate& cost);

}  // namespace rodsort::runner
