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

/// Default distance and lag of the held count [mm, s]: a pile's rods move less than 1 mm in 5 s,
/// a free rod at 2-4 mm/s moves 10-20 mm (docs/metrics.md).
inline constexpr double kDefaultHeldDistance = 1.0;
inline constexpr double kDefaultHeldLag = 5.0;

/// What the trap holds, told from what passes through it. A rod is held when its centre is inside
/// the trap and it moved less than a set distance over a set lag (1 mm in 5 s by default): the
/// rods of a pile do, a free rod does not, however slow it is. The paper's stationary rule (speed
/// below 5 mm/s over 0.07 s) counts as stationary every rod slower than that, so where rods move
/// at 2-4 mm/s (docs/model.md, the clearance) it counts the ones that wander through the trap.
struct Held {
  int all = 0;                   ///< held rods
  std::vector<int> species;      ///< held rods of each species
  std::vector<double> fraction;  ///< of each species' rods; NaN for a species without rods
  std::vector<double> purity;    ///< each species' share of the held rods; NaN when none is held
};

/// `held` per rod (inside and still over the lag); `counts`, the frame's counts, give each
/// species' rods. Species outside those of `counts` are a broken invariant.
Held held_measures(const engine::Frame& frame, const std::vector<bool>& held,
                   const TrappingCounts& counts);

}  // namespace rodsort::metrics
