#pragma once

#include <vector>

namespace rodsort::metrics {

/// Equal-width bins over [low, high); values outside are counted apart, never dropped silently.
struct Histogram {
  double low = 0.0;
  double high = 0.0;
  std::vector<long> counts;
  long below = 0;    ///< values < low
  long above = 0;    ///< values > high (high itself falls in the last bin)
  long invalid = 0;  ///< NaN

  Histogram(double low, double high, int bins);
  void add(double value);
  void add(const std::vector<double>& values);
  double bin_width() const;
  double bin_center(int bin) const;
  long total() const;  ///< every value added, outside and invalid ones included
  /// Probability density per bin, normalised over every value added: integrates to the fraction
  /// of values inside [low, high].
  std::vector<double> density() const;
};

}  // namespace rodsort::metrics
