#include "runner/cost_estimate.hpp"

#include <algorithm>
#include <cstdio>

namespace rodsort::runner {

CostEstimate estimate_cost(const engine::Model& model, std::int64_t steps) {
  const double rod_steps = static_cast<double>(model.rods.size()) * static_cast<double>(steps);
  const double slope = model.roughness.base_slope + model.roughness.lid_slope;
  const double rough = slope > 0.0 ? kRoughRodStepCost + kRoughCostPerSlope * slope : 0.0;
  return {rod_steps * (kRodStepCostDispersed + rough), rod_steps * (kRodStepCostFilled + rough)};
}

namespace {

bool measured_long_enough(std::int64_t done_steps, std::int64_t total_steps) {
  return done_steps > 0 &&
         static_cast<double>(done_steps) >= kMeasuredMinFraction * static_cast<double>(total_steps);
}

}  // namespace

std::optional<double> measured_rod_step_cost(const RunRecord& record) {
  if (record.rods <= 0 || record.cpu_s <= 0.0 ||
      !measured_long_enough(record.steps, record.total_steps)) {
    return std::nullopt;
  }
  return record.cpu_s / (static_cast<double>(record.rods) * static_cast<double>(record.steps));
}

std::optional<MeasuredCost> median_rod_step_cost(const std::vector<RunRecord>& records) {
  std::vector<double> costs;
  for (const RunRecord& record : records) {
    if (const auto cost = measured_rod_step_cost(record)) costs.push_back(*cost);
  }
  if (costs.empty()) return std::nullopt;
  std::sort(costs.begin(), costs.end());
  const std::size_t middle = costs.size() / 2;
  const double median =
      costs.size() % 2 == 1 ? costs[middle] : 0.5 * (costs[middle - 1] + costs[middle]);
  return MeasuredCost{median, costs.size()};
}

std::optional<CostEstimate> cost_at_own_rate(std::int64_t done_steps, std::int64_t total_steps,
                                             double cpu_s) {
  if (!measured_long_enough(done_steps, total_steps) || cpu_s <= 0.0) return std::nullopt;
  const std::int64_t left = std::max<std::int64_t>(total_steps - done_steps, 0);
  const double cost = cpu_s / static_cast<double>(done_steps) * static_cast<double>(left);
  return CostEstimate{cost, cost};
}

RemainingCost remaining_cost(const engine::Model& model, std::int64_t done_steps,
                             std::int64_t total_steps, double cpu_s) {
  if (const auto own = cost_at_own_rate(done_steps, total_steps, cpu_s)) return {*own, true};
  return {estimate_cost(model, std::max<std::int64_t>(total_steps - done_steps, 0)), false};
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
  char low[32];
  char high[32];
  std::snprintf(low, sizeof low, "%.2g", cost.low_cpu_s / scale);
  std::snprintf(high, sizeof high, "%.2g", cost.high_cpu_s / scale);
  const std::string range = std::string(low) == high ? high : std::string(low) + "-" + high;
  return "about " + range + " " + unit;
}

}  // namespace rodsort::runner
