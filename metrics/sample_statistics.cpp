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

LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sx += x[i];
    sy += y[i];
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
  }
  LineFit fit;
  const double denominator = n * sxx - sx * sx;
  if (denominator <= 0.0) return fit;
  fit.slope = (n * sxy - sx * sy) / denominator;
  fit.intercept = (sy - fit.slope * sx) / n;
  fit.determined = true;
  return fit;
}

}  // namespace rodsort::metrics
