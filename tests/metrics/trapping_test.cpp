#include "metrics/trapping.hpp"

#include <catch2/catch.hpp>

#include "metrics/kinematics.hpp"
#include "metrics/sorting.hpp"
#include "synthetic_frames.hpp"

using namespace rodsort::metrics;
using testing::frame_at;
using testing::rod_at;

namespace {

// A square "trap" [40, 60]^2 of area 400 mm^2 stands in for a real one: metrics only see a
// predicate.
bool in_square(const Eigen::Vector2d& p) {
  return p.x() >= 40 && p.x() <= 60 && p.y() >= 40 && p.y() <= 60;
}
constexpr double kSquareArea = 400.0;

}  // namespace

TEST_CASE("stationary rods inside and outside the trap, over the window", "[metrics]") {
  // Species 0 (area 2 mm^2) and 1 (area 1.5 mm^2). Over 0.07 s:
  //  0: sp 0, inside, rattles 0.21 mm        -> stationary (3 mm/s), inside
  //  1: sp 0, inside, moves 0.5 mm           -> moving, inside
  //  2: sp 1, inside, rests                  -> stationary, inside
  //  3: sp 0, outside, rests (stuck on a wall outside)   -> stationary, outside
  //  4: sp 1, outside, crosses the periodic edge, 0.42 mm (6 mm/s) -> moving, outside
  //  5: sp 1, enters the trap during the window -> moving, inside
  const auto earlier =
      frame_at(2.0, {rod_at(50, 50, 0, 0), rod_at(45, 45, 1, 0), rod_at(55, 41, 2, 1),
                     rod_at(20, 20, 0, 0), rod_at(99.9, 5, 0, 1), rod_at(39.8, 50, 0, 1)});
  const auto later =
      frame_at(2.07, {rod_at(50.21, 50, 0, 0), rod_at(45.5, 45, 1, 0), rod_at(55, 41, 2, 1),
                      rod_at(20, 20, 0, 0), rod_at(100.32, 5, 0, 1), rod_at(40.3, 50, 0, 1)});
  const auto speeds = window_speeds(earlier, later);
  const auto stationary = stationary_flags(speeds, kDefaultStationarySpeed);
  CHECK(stationary == std::vector<bool>{true, false, true, true, false, false});
  const auto inside = inside_flags(later, in_square);
  CHECK(inside == std::vector<bool>{true, true, true, false, false, true});

  const TrappingCounts counts = count_trapping(later, stationary, inside, 2);
  CHECK(counts.all.rods == 6);
  CHECK(counts.all.stationary == 3);
  CHECK(counts.all.inside == 4);
  CHECK(counts.all.stationary_inside == 2);
  CHECK(counts.species[0].rods == 3);
  CHECK(counts.species[0].stationary == 2);
  CHECK(counts.species[0].inside == 2);
  CHECK(counts.species[0].stationary_inside == 1);
  CHECK(counts.species[1].stationary == 1);
  CHECK(counts.species[1].inside == 2);
  CHECK(counts.species[1].stationary_inside == 1);

  const Efficiency efficiency = trapping_efficiency(counts, {2.0, 1.5}, kSquareArea);
  CHECK(efficiency.eta == Approx((2 * 2.0 + 1 * 1.5) / 400.0));
  CHECK(efficiency.eta_trap == Approx((2.0 + 1.5) / 400.0));
  CHECK(efficiency.eta_species[0] == Approx(4.0 / 400.0));
  CHECK(efficiency.eta_species[1] == Approx(1.5 / 400.0));
  CHECK(efficiency.eta_trap_species[0] == Approx(2.0 / 400.0));
  CHECK(efficiency.eta_trap_species[1] == Approx(1.5 / 400.0));

  // A lower threshold makes the rattling rod 0 a mover.
  CHECK(stationary_flags(speeds, 2.0) == std::vector<bool>{false, false, true, true, false, false});
}

TEST_CASE("eta of a single species is N0 a / A_t", "[metrics]") {
  std::vector<rodsort::engine::RodFrame> rods;
  for (int i = 0; i < 10; ++i) rods.push_back(rod_at(41 + i, 50, 0));
  const auto frame = frame_at(0, rods);
  std::vector<bool> stationary(10, false);
  for (int i = 0; i < 7; ++i) stationary[i] = true;
  const auto counts = count_trapping(frame, stationary, inside_flags(frame, in_square), 1);
  const auto efficiency = trapping_efficiency(counts, {2.5}, kSquareArea);
  CHECK(efficiency.eta == Approx(7 * 2.5 / kSquareArea));
  CHECK(efficiency.eta_trap == Approx(efficiency.eta));
}

TEST_CASE("sorting measures of a mixture", "[metrics]") {
  TrappingCounts counts;
  counts.species.resize(2);
  counts.species[0].rods = 150;
  counts.species[0].inside = 60;
  counts.species[1].rods = 225;
  counts.species[1].inside = 15;
  counts.all.rods = 375;
  counts.all.inside = 75;
  const Sorting sorting = sorting_measures(counts);
  CHECK(sorting.fraction_inside[0] == Approx(0.4));
  CHECK(sorting.fraction_inside[1] == Approx(15.0 / 225.0));
  CHECK(sorting.purity[0] == Approx(0.8));
  CHECK(sorting.purity[1] == Approx(0.2));
  const double f0 = 0.4, f1 = 15.0 / 225.0;
  CHECK(sorting.index == Approx((f0 - f1) / (f0 + f1)));

  SECTION("no sorting when both species enter in proportion") {
    counts.species[1].inside = 90;
    counts.all.inside = 150;
    CHECK(sorting_measures(counts).index == Approx(0.0).margin(1e-12));
  }
  SECTION("only species 0 inside") {
    counts.species[1].inside = 0;
    counts.all.inside = 60;
    CHECK(sorting_measures(counts).index == Approx(1.0));
    CHECK(sorting_measures(counts).purity[0] == Approx(1.0));
  }
  SECTION("an empty trap leaves purity and index undefined") {
    counts.species[0].inside = counts.species[1].inside = counts.all.inside = 0;
    const Sorting empty = sorting_measures(counts);
    CHECK(std::isnan(empty.purity[0]));
    CHECK(std::isnan(empty.index));
    CHECK(empty.fraction_inside[0] == 0.0);
  }
}

TEST_CASE("a single species has no sorting index", "[metrics]") {
  TrappingCounts counts;
  counts.species.resize(1);
  counts.species[0].rods = counts.all.rods = 10;
  counts.species[0].inside = counts.all.inside = 4;
  const Sorting sorting = sorting_measures(counts);
  CHECK(sorting.fraction_inside[0] == Approx(0.4));
  CHECK(sorting.purity[0] == Approx(1.0));
  CHECK(std::isnan(sorting.index));
}
