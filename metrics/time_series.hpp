#pragma once
// Summaries of a time series such as eta(t): where it settles and how fast it gets there. The
// paper's eta(t) at 115° rises and saturates near 0.9; near theta_c it shows spikes (failed
// nucleation attempts) that rarely last.

#include <cmath>
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

/// A rise of the series above a level: a nucleation attempt when the series is eta_trap. It fails
/// when the series falls back below a lower level; the two levels keep the noise of a series near
/// one of them from counting as many attempts.
struct NucleationAttempt {
  double start = 0.0;      ///< [s] first sample above the rise level
  double peak_time = 0.0;  ///< [s] of the highest sample
  double peak = 0.0;
  /// [s] first sample below the fall level after the start: the attempt failed there. NaN while
  /// the series has not fallen back when it ends (the attempt holds).
  double end = 0.0;
  bool failed() const { return !std::isnan(end); }
};

/// The attempts of a series, in time order: each begins when the series exceeds `rise` and ends
/// when it drops below `fall` (0 <= fall < rise). times ascending, as many as values.
std::vector<NucleationAttempt> nucleation_attempts(const std::vector<double>& times,
                                                   const std::vector<double>& values, double rise,
                                                   double fall);

}  // namespace rodsort::metrics
