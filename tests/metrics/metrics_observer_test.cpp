#include "metrics/metrics_observer.hpp"

#include <catch2/catch.hpp>

#include "synthetic_frames.hpp"

using namespace rodsort::metrics;
using testing::frame_at;
using testing::rod_at;

namespace {

bool in_square(const Eigen::Vector2d& p) {
  return p.x() >= 40 && p.x() <= 60 && p.y() >= 40 && p.y() <= 60;
}

// Species "A" (area 2) and "RnT" (area 1.5). Rod 0 (A) rests inside the square trap; rod 1 (A)
// moves at 10 mm/s along +x through the trap; rod 2 (RnT) rests outside.
rodsort::engine::Frame frame(double t) {
  return frame_at(t,
                  {rod_at(50, 50, 0, 0), rod_at(35 + 10 * t, 45, 0, 0), rod_at(99.95, 10, 0, 1)});
}

MetricsConfig config() {
  MetricsConfig c;
  c.species_names = {"A", "RnT"};
  c.species_area = {2.0, 1.5};
  c.trap_area = 400.0;
  c.inside = in_square;
  return c;
}

}  // namespace

TEST_CASE("MetricsObserver rows from frames every tau", "[metrics]") {
  MetricsObserver observer(config());
  CHECK_FALSE(observer.observe(frame(0.0)));
  const auto first = observer.observe(frame(0.07));
  REQUIRE(first);
  CHECK(first->time == Approx(0.07));
  CHECK(first->window == Approx(0.07));
  CHECK(first->counts.all.stationary == 2);
  CHECK(first->stationary == std::vector<bool>{true, false, true});
  CHECK(first->counts.all.inside == 1);  // rod 1 is at x = 35.7, not yet inside
  CHECK(first->efficiency.eta == Approx((2.0 + 1.5) / 400.0));
  CHECK(first->efficiency.eta_trap == Approx(2.0 / 400.0));
  CHECK(first->mean_speed == Approx(10.0 / 3.0));
  // Rod 1 enters the trap at t = 0.5 s.
  std::optional<MetricsRow> row;
  for (int k = 2; k <= 10; ++k) row = observer.observe(frame(0.07 * k));
  REQUIRE(row);
  CHECK(row->time == Approx(0.7));
  CHECK(row->counts.all.inside == 2);
  CHECK(row->counts.all.stationary_inside == 1);
  CHECK(row->counts.species[0].inside == 2);
  CHECK(row->sorting.fraction_inside[0] == Approx(1.0));
  CHECK(row->sorting.fraction_inside[1] == Approx(0.0));
  CHECK(row->sorting.index == Approx(1.0));
}

TEST_CASE("MetricsObserver measures over tau when frames come more often", "[metrics]") {
  MetricsObserver observer(config());
  CHECK_FALSE(observer.observe(frame(0.0)));
  CHECK_FALSE(observer.observe(frame(0.035)));
  for (int k = 2; k < 8; ++k) {
    const auto row = observer.observe(frame(0.035 * k));
    REQUIRE(row);
    CHECK(row->window == Approx(0.07));
    CHECK(row->mean_speed == Approx(10.0 / 3.0));
  }
}

TEST_CASE("MetricsObserver with a threshold above the movers' speed", "[metrics]") {
  MetricsConfig c = config();
  c.stationary_speed_threshold = 12.0;
  MetricsObserver observer(c);
  observer.observe(frame(0.0));
  const auto row = observer.observe(frame(0.07));
  REQUIRE(row);
  CHECK(row->counts.all.stationary == 3);
}

TEST_CASE("metrics.csv header and lines", "[metrics]") {
  MetricsObserver observer(config());
  CHECK(observer.csv_header() ==
        "t,eta,eta_trap,n_rods,n_stationary,n_trap,n_stationary_trap,mean_speed,"
        "n_stationary_A,n_trap_A,n_stationary_trap_A,eta_A,eta_trap_A,fraction_trap_A,purity_A,"
        "n_stationary_RnT,n_trap_RnT,n_stationary_trap_RnT,eta_RnT,eta_trap_RnT,fraction_trap_RnT,"
        "purity_RnT,sorting_index,n_held_trap,n_held_trap_A,fraction_held_A,purity_held_A,"
        "n_held_trap_RnT,fraction_held_RnT,purity_held_RnT");
  observer.observe(frame(0.0));
  const auto row = observer.observe(frame(0.07));
  REQUIRE(row);
  // Held needs a frame 5 s earlier.
  CHECK(observer.csv_line(*row) ==
        "0.07,0.00875,0.005,3,2,1,1,3.33333333,1,1,1,0.005,0.005,0.5,1,1,0,0,0.00375,0,0,0,1,"
        "nan,nan,nan,nan,nan,nan,nan");
}

TEST_CASE("metrics.csv without a trap", "[metrics]") {
  MetricsConfig c;
  c.species_names = {"A"};
  c.species_area = {2.0};
  MetricsObserver observer(c);
  CHECK(observer.csv_header() ==
        "t,eta,eta_trap,n_rods,n_stationary,n_trap,n_stationary_trap,mean_speed,"
        "n_stationary_A,n_trap_A,n_stationary_trap_A,eta_A,eta_trap_A,fraction_trap_A,purity_A");
  observer.observe(frame_at(0.0, {rod_at(1, 1, 0)}));
  const auto row = observer.observe(frame_at(0.07, {rod_at(1, 1, 0)}));
  REQUIRE(row);
  CHECK(observer.csv_line(*row) == "0.07,nan,nan,1,1,0,0,0,1,0,0,nan,nan,0,nan");
}

TEST_CASE("MetricsObserver counts the rods the trap holds", "[metrics]") {
  MetricsConfig c = config();
  c.held_lag = 0.35;
  MetricsObserver observer(c);
  CHECK(observer.history() == 0.35);
  // Rod 0 (A) rests inside; rod 1 (A) crosses the trap at 10 mm/s; rod 2 (RnT) creeps inside at
  // 2 mm/s, slower than the stationary threshold: 0.7 mm in 0.35 s.
  const auto creeping = [](double t) {
    return frame_at(
        t, {rod_at(50, 50, 0, 0), rod_at(35 + 10 * t, 45, 0, 0), rod_at(45 + 2 * t, 55, 0, 1)});
  };
  std::optional<MetricsRow> row;
  for (int k = 0; k <= 4; ++k) row = observer.observe(creeping(0.07 * k));
  REQUIRE(row);
  CHECK_FALSE(row->held);  // no frame 0.35 s earlier yet
  for (int k = 5; k <= 12; ++k) row = observer.observe(creeping(0.07 * k));
  REQUIRE(row);
  REQUIRE(row->held);
  CHECK(row->counts.all.inside == 3);
  CHECK(row->counts.all.stationary_inside == 2);
  CHECK(row->held->all == 2);
  CHECK(row->held->species == std::vector<int>{1, 1});
  CHECK(row->held->fraction[0] == Approx(0.5));
  CHECK(row->held->fraction[1] == Approx(1.0));
  CHECK(row->held->purity[0] == Approx(0.5));
  CHECK(row->held->purity[1] == Approx(0.5));

  // At 1 mm in 0.7 s the creeping rod moves 1.4 mm: not held, though stationary by speed.
  c.held_lag = 0.7;
  MetricsObserver longer(c);
  CHECK(longer.history() == 0.7);
  for (int k = 0; k <= 12; ++k) row = longer.observe(creeping(0.07 * k));
  REQUIRE(row);
  REQUIRE(row->held);
  CHECK(row->held->species == std::vector<int>{1, 0});
  CHECK(row->held->purity[0] == Approx(1.0));
  CHECK(row->counts.all.stationary_inside == 2);
}

TEST_CASE("MetricsObserver without a trap counts nothing held", "[metrics]") {
  MetricsConfig c;
  c.species_names = {"A"};
  c.species_area = {2.0};
  c.held_lag = 0.07;
  MetricsObserver observer(c);
  CHECK(observer.history() == 0.07);
  observer.observe(frame_at(0.0, {rod_at(1, 1, 0)}));
  const auto row = observer.observe(frame_at(0.07, {rod_at(1, 1, 0)}));
  REQUIRE(row);
  CHECK_FALSE(row->held);
}
