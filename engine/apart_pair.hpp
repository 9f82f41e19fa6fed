#pragma once
// The skipping of a pair of bodies that were apart at their last test (rod_rod_collision.cpp,
// rod_wall_collision.cpp). Each rod carries its travel: a bound on how far any of its sphere
// centres has moved since the world was built (BodyTag::travel), summed step by step in whole
// picometres, each step's move rounded up, so that the sums are exact integers and never fall
// short of the true move however long the run. A pair found `gap` apart is skipped until the two
// bodies together have travelled that far: no point of theirs can meet before then.

#include <cmath>
#include <cstdint>
#include <limits>

namespace rodsort::engine {

/// BodyTag::travel, in whole picometres (1e-9 mm).
using Travel = std::int64_t;
inline constexpr double kTravelPerMm = 1e9;

/// The travel of a body that never moves (a wall).
inline constexpr Travel kStill = 0;

/// Moves and gaps are counted up to a kilometre: a larger move (or one that is not a number)
/// counts as that, a larger gap as that, so that no conversion leaves the integers [mm].
inline constexpr double kFarthest = 1e6;

/// A step's move of `mm`, as travel: rounded up, and one more, for the rounding of `mm` itself.
inline Travel travel_of_move(double mm) {
  return static_cast<Travel>(std::ceil((mm < kFarthest ? mm : kFarthest) * kTravelPerMm)) + 1;
}

class ApartPair {
 public:
  /// `a` and `b`: the two bodies' travel (&kStill for a wall); null for either, never skipped.
  /// Skips are counted in `*skipped` (null: not counted).
  ApartPair(const Travel* a, const Travel* b, std::int64_t* skipped)
      : a_(a), b_(b), skipped_(skipped) {}

  /// Whether the pair's test is skipped at this step. Counts the skip.
  bool skips() {
    if (a_ == nullptr || b_ == nullptr || *a_ + *b_ >= skip_below_) return false;
    if (skipped_ != nullptr) ++*skipped_;
    return true;
  }

  /// After a test that made nothing, with the two bodies at least `gap` apart [mm] (a gap of 0
  /// or less, after a test that made a point: test again at the next step).
  void tested(double gap) {
    // A tenth of a nanometre is taken off, for the rounding of the gap.
    constexpr double kMargin = 1e-7;  // [mm]
    if (a_ == nullptr || b_ == nullptr || !(gap > kMargin)) {
      skip_below_ = kNever;
      return;
    }
    const double usable = (gap < kFarthest ? gap : kFarthest) - kMargin;
    skip_below_ = *a_ + *b_ + static_cast<Travel>(std::floor(usable * kTravelPerMm));
  }

 private:
  static constexpr Travel kNever = std::numeric_limits<Travel>::min();

  const Travel* a_;
  const Travel* b_;
  std::int64_t* skipped_;
  Travel skip_below_ = kNever;  ///< skipped while the two travels sum to less than this
};

}  // namespace rodsort::engine
