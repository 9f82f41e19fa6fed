#include "metrics/histogram.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace rodsort::metrics {

Histogram::Histogram(double low, double high, int bins) : low(low), high(high), counts(bins, 0) {
  assert(high > low && bins > 0);
}

void Histogram::add(double value) {
  if (std::isnan(value)) {
    ++invalid;
  } else if (value < low) {
    ++below;
  } else if (value > high) {
    ++above;
  } else {
    const int bin = std::min(static_cast<int>((value - low) / bin_width()),
                             static_cast<int>(counts.size()) - 1);
    ++counts[bin];
  }
}

void Histogram::add(const std::vector<double>& values) {
  for (const double value : values) add(value);
}

double Histogram::bin_width() const { return (high - low) / static_cast<double>(counts.size()); }

double Histogram::bin_center(int bin) const { return low + (bin + 0.5) * bin_width(); }

long Histogram::total() const {
  long total = below + above + invalid;
  for (const long count : counts) total += count;
  return total;
}

std::vector<double> Histogram::density() const {
  std::vector<double> density(counts.size(), 0.0);
  const long n = total();
  if (n == 0) return density;
  for (std::size_t i = 0; i < counts.size(); ++i) density[i] = counts[i] / (n * bin_width());
  return density;
}

}  // namespace rodsort::metrics
