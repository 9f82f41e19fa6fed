#include "engine/apart_pair.hpp"

#include <catch2/catch.hpp>
#include <cstdint>
#include <limits>

using namespace rodsort::engine;

TEST_CASE("a pair apart is skipped until its bodies have travelled the gap", "[engine][skip]") {
  Travel a = 5'000, b = 7'000;  // picometres already travelled
  std::int64_t skipped = 0;
  ApartPair pair(&a, &b, &skipped);
  CHECK_FALSE(pair.skips());  // never tested yet
  pair.tested(0.001);         // 1 micrometre apart: 999,900 pm usable after the margin
  CHECK(pair.skips());
  a += 500'000;
  b += 499'899;
  CHECK(pair.skips());  // 999,899 pm travelled together
  b += 1;
  CHECK_FALSE(pair.skips());  // 999,900 pm: they might touch
  CHECK(skipped == 2);
  pair.tested(0.0);  // touching: tested at every step
  CHECK_FALSE(pair.skips());
  pair.tested(5e-8);  // within the rounding margin: tested at every step
  CHECK_FALSE(pair.skips());
}

TEST_CASE("a still wall adds no travel, and unknown travel is never skipped", "[engine][skip]") {
  Travel rod = 0;
  ApartPair wall(&rod, &kStill, nullptr);
  wall.tested(0.5);
  rod = travel_of_move(0.4999);
  CHECK(wall.skips());
  rod += travel_of_move(0.0001);
  CHECK_FALSE(wall.skips());
  ApartPair unknown(&rod, nullptr, nullptr);
  unknown.tested(10.0);
  CHECK_FALSE(unknown.skips());
}

TEST_CASE("moves are rounded up, and huge or undefined moves and gaps stay in range",
          "[engine][skip]") {
  CHECK(travel_of_move(0.0) == 1);
  CHECK(travel_of_move(1e-12) == 2);
  CHECK(travel_of_move(0.25) == 250'000'001);
  CHECK(travel_of_move(std::numeric_limits<double>::quiet_NaN()) == travel_of_move(kFarthest));
  CHECK(travel_of_move(std::numeric_limits<double>::infinity()) == travel_of_move(kFarthest));
  Travel a = 0, b = 0;
  ApartPair pair(&a, &b, nullptr);
  pair.tested(std::numeric_limits<double>::infinity());  // as far as a kilometre
  a = travel_of_move(0.9 * kFarthest);
  CHECK(pair.skips());
  a = travel_of_move(kFarthest);
  CHECK_FALSE(pair.skips());
}
