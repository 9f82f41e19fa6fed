#include "metrics/sample_statistics.hpp"

#include <cmath>

namespace rodsort::metrics {

SampleStatistics sample_statistics(const std::vector<double>& values) {
  SampleStatistics result;
  if (values.empty()) return result;
  double sum = 0.0;
  for (const double v : values) sum += v;
  const double n = static_cast<double>(values.size());
  result.mean = sum / n;
  if (values.size() < 2) return result;
  double squares = 0.0;
  for (const double v : values) squares += (v - result.mean) * (v - result.mean);
  result.deviation = std::sqrt(squares / (n - 1.0));
  result.standard_error = result.deviation / std::sqrt(n);
  return result;
}

}  // namespace rodsort::metrics
