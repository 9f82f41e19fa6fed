#include "metrics/time_series.hpp"

#include <catch2/catch.hpp>
#include <cmath>

using namespace rodsort::metrics;

TEST_CASE("plateau of a saturating eta(t)", "[metrics]") {
  // eta = 0.9 (1 - exp(-t / T)), T = 20 s, sampled every 0.07 s for 1000 s: the plateau is 0.9,
  // and 90% of it is reached when exp(-t / T) = 0.1, at t = T ln 10.
  std::vector<double> t, eta;
  for (int k = 0; k <= 14285; ++k) {
    t.push_back(0.07 * k);
    eta.push_back(0.9 * (1.0 - std::exp(-t.back() / 20.0)));
  }
  const PlateauStats stats = plateau_stats(t, eta);
  CHECK(stats.mean == Approx(0.9).epsilon(1e-6));
  CHECK(stats.spread == Approx(0.0).margin(1e-6));
  CHECK(stats.samples == 7143);
  CHECK(stats.time_to_90 == Approx(20.0 * std::log(10.0)).margin(0.07));
}

TEST_CASE("plateau spread and smoothing of a noisy series", "[metrics]") {
  // First half 0; second half alternates 0.8 and 1.0 (mean 0.9, spread 0.1). An early one-sample
  // spike to 1.0 at t = 10 reaches 90% on its own; a 5-sample average ignores it.
  std::vector<double> t, eta;
  for (int k = 0; k < 100; ++k) {
    t.push_back(k);
    eta.push_back(k < 50 ? 0.0 : (k % 2 == 0 ? 0.8 : 1.0));
  }
  eta[10] = 1.0;
  const PlateauStats raw = plateau_stats(t, eta);
  CHECK(raw.mean == Approx(0.9));
  CHECK(raw.spread == Approx(0.1));
  CHECK(raw.time_to_90 == Approx(10.0));
  const PlateauStats smooth = plateau_stats(t, eta, 5);
  // The first 5-sample window wholly in the plateau, k = 50..54, averages 0.88 >= 0.81; the one
  // before it, k = 49..53, only 0.72.
  CHECK(smooth.time_to_90 == 54.0);
}

TEST_CASE("a series that never rises has no time to plateau", "[metrics]") {
  const PlateauStats stats = plateau_stats({0, 1, 2, 3}, {0, 0, 0, 0});
  CHECK(stats.mean == 0.0);
  CHECK(std::isnan(stats.time_to_90));
}

TEST_CASE("nucleation attempts: rises above one level, failures below a lower one", "[metrics]") {
  // A spike to 0.5 that collapses, noise around 0.3 (between the levels, not new attempts), a
  // second collapse, then a pile that grows to 0.9 and holds to the end.
  const std::vector<double> eta = {0.0,  0.2, 0.5,  0.4, 0.05, 0.0, 0.35, 0.28, 0.32,
                                   0.29, 0.6, 0.08, 0.2, 0.4,  0.7, 0.9,  0.85, 0.9};
  std::vector<double> t;
  for (std::size_t k = 0; k < eta.size(); ++k) t.push_back(10.0 * static_cast<double>(k));
  const auto attempts = nucleation_attempts(t, eta, 0.3, 0.1);
  REQUIRE(attempts.size() == 3);
  CHECK(attempts[0].start == 20.0);
  CHECK(attempts[0].peak == 0.5);
  CHECK(attempts[0].end == 40.0);
  CHECK(attempts[0].failed());
  // 0.35 at 60 s starts the second; the dips to 0.28 and 0.29 do not end it.
  CHECK(attempts[1].start == 60.0);
  CHECK(attempts[1].peak == 0.6);
  CHECK(attempts[1].peak_time == 100.0);
  CHECK(attempts[1].end == 110.0);
  CHECK(attempts[2].start == 130.0);
  CHECK(attempts[2].peak == 0.9);
  CHECK(attempts[2].peak_time == 150.0);  // the first of the equal highest samples
  CHECK_FALSE(attempts[2].failed());
  // A series that never rises above the level has none.
  CHECK(nucleation_attempts(t, std::vector<double>(t.size(), 0.25), 0.3, 0.1).empty());
}
