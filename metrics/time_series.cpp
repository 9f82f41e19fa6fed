#include "metrics/time_series.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace rodsort::metrics {

PlateauStats plateau_stats(const std::vector<double>& times, const std::vector<double>& values,
                           int smoothing) {
  assert(times.size() == values.size());
  assert(smoothing >= 1);
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  PlateauStats stats;
  stats.time_to_90 = kNaN;
  if (times.empty()) {
    stats.mean = stats.spread = kNaN;
    return stats;
  }
  const double half_time = 0.5 * (times.front() + times.back());
  double sum = 0.0, square_sum = 0.0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (times[i] < half_time) continue;
    sum += values[i];
    square_sum += values[i] * values[i];
    ++stats.samples;
  }
  stats.mean = sum / stats.samples;
  stats.spread = std::sqrt(std::max(0.0, square_sum / stats.samples - stats.mean * stats.mean));
  if (!(stats.mean > 0.0)) return stats;
  double window_sum = 0.0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    window_sum += values[i];
    if (i >= static_cast<std::size_t>(smoothing)) window_sum -= values[i - smoothing];
    if (i + 1 < static_cast<std::size_t>(smoothing)) continue;
    if (window_sum / smoothing >= 0.9 * stats.mean) {
      stats.time_to_90 = times[i];
      break;
    }
  }
  return stats;
}

std::vector<NucleationAttempt> nucleation_attempts(const std::vector<double>& times,
                                                   const std::vector<double>& values, double rise,
                                                   double fall) {
  assert(times.size() == values.size());
  assert(0.0 <= fall && fall < rise);
  std::vector<NucleationAttempt> attempts;
  bool above = false;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!above) {
      if (!(values[i] > rise)) continue;
      above = true;
      attempts.push_back({times[i], times[i], values[i], std::numeric_limits<double>::quiet_NaN()});
      continue;
    }
    NucleationAttempt& current = attempts.back();
    if (values[i] > current.peak) {
      current.peak = values[i];
      current.peak_time = times[i];
    }
    if (values[i] < fall) {
      current.end = times[i];
      above = false;
    }
  }
  return attempts;
}

}  // namespace rodsort::metrics
