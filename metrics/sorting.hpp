#pragma once
// How well a trap sorts a mixture: which species end up inside it. The paper shows it with
// pictures (a trap at 70° fills with A rods and lets RnT rods go); these numbers say it per frame.
//
// - fraction inside, f_s = (rods of s inside the trap) / (rods of s);
// - purity, p_s = (rods of s inside the trap) / (rods inside the trap);
// - sorting index, S = (f_0 - f_1) / (f_0 + f_1) between the first two species: +1 when the trap
//   holds only species 0, 0 when both enter in proportion to their numbers (no sorting), -1 when
//   it holds only species 1. Dividing by f_0 + f_1 makes S independent of how much of a species
//   the trap can hold at all (a trap of area A_t never holds more than about A_t / a rods).
// Undefined values (no rod of a species; an empty trap) are NaN.

#include <vector>

#include "metrics/trapping.hpp"

namespace rodsort::metrics {

struct Sorting {
  std::vector<double> fraction_inside;  ///< f_s, per species
  std::vector<double> purity;           ///< p_s, per species
  double index = 0.0;                   ///< S; NaN with fewer than two species
};

/// From the `inside` counts (rods whose centre is inside, whatever their speed).
Sorting sorting_measures(const TrappingCounts& counts);

}  // namespace rodsort::metrics
