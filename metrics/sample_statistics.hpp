#pragma once
// Mean, spread and standard error of independent samples (one number per rod, per seed), the
// error bars the single-rod measurements report.

#include <vector>

namespace rodsort::metrics {

struct SampleStatistics {
  double mean = 0.0;
  double deviation = 0.0;       ///< sample standard deviation (n - 1); 0 for fewer than 2 values
  double standard_error = 0.0;  ///< of the mean: deviation / sqrt(n)
};

/// Statistics of the values; all zero when there is none.
SampleStatistics sample_statistics(const std::vector<double>& values);

}  // namespace rodsort::metrics
