#include "runner/cost_estimate.hpp"

#include <cstdio>

namespace rodsort::runner {

CostEstimate estimate_cost(const engine::Model& model, std::int64_t steps) {
  const double rod_steps = static_cast<double>(model.rods.size()) * static_cast<double>(steps);
  const double slope = model.roughness.base_slope + model.roughness.lid_slope;
  const double rough = slope > 0.0 ? kRoughRodStepCost + kRoughCostPerSlope * slope : 0.0;
  return {rod_steps * (kRodStepCostDispersed + rough), rod_steps * (kRodStepCostFilled + rough)};
}

std::string describe_cost(const CostEstimate& cost) {
  double scale = 1.0;
  const char* unit = "CPU-s";
  if (cost.high_cpu_s >= 2.0 * 3600.0) {
    scale = 3600.0;
    unit = "CPU-h";
  } else if (cost.high_cpu_s >= 120.0) {
    scale = 60.0;
    unit = "CPU-min";
  }
  char text[80];
  std::snprintf(text, sizeof text, "about %.2g-%.2g %s", cost.low_cpu_s / scale,
                cost.high_cpu_s / scale, unit);
  return text;
}

}  // namespace rodsort::runner
