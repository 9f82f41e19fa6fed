#include "metrics/sorting.hpp"

#include <cassert>
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

Held held_measures(const engine::Frame& frame, const std::vector<bool>& held, int species_count) {
  assert(held.size() == frame.rods.size());
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  Held measures;
  measures.species.assign(species_count, 0);
  std::vector<int> rods(species_count, 0);
  for (std::size_t i = 0; i < frame.rods.size(); ++i) {
    const int s = frame.rods[i].species;
    assert(0 <= s && s < species_count);
    ++rods[s];
    if (!held[i]) continue;
    ++measures.species[s];
    ++measures.all;
  }
  for (int s = 0; s < species_count; ++s) {
    measures.fraction.push_back(rods[s] > 0 ? double(measures.species[s]) / rods[s] : kNaN);
    measures.purity.push_back(measures.all > 0 ? double(measures.species[s]) / measures.all : kNaN);
  }
  return measures;
}

}  // namespace rodsort::metrics
