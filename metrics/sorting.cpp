#include "metrics/sorting.hpp"

#include <limits>

namespace rodsort::metrics {

Sorting sorting_measures(const TrappingCounts& counts) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  Sorting sorting;
  for (const Counts& c : counts.species) {
    sorting.fraction_inside.push_back(c.rods > 0 ? double(c.inside) / c.rods : kNaN);
    sorting.purity.push_back(counts.all.inside > 0 ? double(c.inside) / counts.all.inside : kNaN);
  }
  sorting.index = kNaN;
  if (sorting.fraction_inside.size() >= 2) {
    const double f0 = sorting.fraction_inside[0], f1 = sorting.fraction_inside[1];
    if (f0 + f1 > 0.0) sorting.index = (f0 - f1) / (f0 + f1);
  }
  return sorting;
}

}  // namespace rodsort::metrics
