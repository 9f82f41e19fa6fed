#pragma once
// Mean, spread and standard error of independent samples (one number per rod, per seed), the
// error bars the single-rod measurements report; and the least-squares line of their fits.

#include <vector>

namespace rodsort::metrics {

struct SampleStatistics {
  double mean = 0.0;
  double deviation = 0.0;       ///< sample standard deviation (n - 1); 0 for fewer than 2 values
  double standard_error = 0.0;  ///< of the mean: deviation / sqrt(n)
};

/// Statistics of the values; all zero when there is none.
SampleStatistics sample_statistics(const std::vector<double>& values);

/// Least-squares line y = intercept + slope x. `determined` is false when the x values do not
/// fix a line (fewer than two distinct ones); slope and intercept are then 0.
struct LineFit {
  double slope = 0.0;
  double intercept = 0.0;
  bool determined = false;
};
LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace rodsort::metrics
