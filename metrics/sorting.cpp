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

Held held_measures(const engine::Frame& frame, const std::vector<bool>& held,
                   const TrappingCounts& counts) {
  assert(held.size() == frame.rods.size());
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const int species_count = static_cast<int>(counts.species.size());
  Held measures;
  measures.species.assign(species_count, 0);
  for (std::size_t i = 0; i < frame.rods.size(); ++i) {
    if (!held[i]) continue;
    const int s = frame.rods[i].species;
    assert(0 <= s && s < species_count);
    ++measures.species[s];
    ++measures.all;
  }
  for (int s = 0; s < species_count; ++s) {
    const int rods = counts.species[s].rods;
    measures.fraction.push_back(rods > 0 ? double(measures.species[s]) / rods : kNaN);
    measures.purity.push_back(measures.all > 0 ? double(measures.species[s]) / measures.all : kNaN);
  }
  return measures;
}

}  // namespace rodsort::metrics
