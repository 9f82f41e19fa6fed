#pragma once
// Summaries of a time series such as eta(t): where it settles and how fast it gets there. The
// paper's eta(t) at 115° rises and saturates near 0.9; near theta_c it shows spikes (failed
// nucleation attempts) that rarely last.

#include <vector>

namespace rodsort::metrics {

struct PlateauStats {
  double mean = 0.0;    ///< mean over the last half of the run (samples with t >= (t_0 + t_end)/2)
  double spread = 0.0;  ///< standard deviation over the same samples
  int samples = 0;      ///< in the last half
  /// First time at which the series, averaged over the trailing `smoothing` samples, reaches 90%
  /// of the plateau mean; NaN when it never does or when the plateau is not positive.
  double time_to_90 = 0.0;
};

/// times ascending, as many as values; smoothing >= 1 samples (1: the raw series).
PlateauStats plateau_stats(const std::vector<double>& times, const std::vector<double>& values,
                           int smoothing = 1);

}  // namespace rodsort::metrics
