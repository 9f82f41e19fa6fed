#include "metrics/sample_statistics.hpp"

#include <catch2/catch.hpp>
#include <cmath>

using Catch::Matchers::WithinAbs;

TEST_CASE("sample statistics: mean, n-1 deviation, standard error", "[metrics]") {
  const auto s = rodsort::metrics::sample_statistics({2.0, 4.0, 4.0, 4.0, 5.0, 5.0, 7.0, 9.0});
  CHECK_THAT(s.mean, WithinAbs(5.0, 1e-12));
  CHECK_THAT(s.deviation, WithinAbs(std::sqrt(32.0 / 7.0), 1e-12));
  CHECK_THAT(s.standard_error, WithinAbs(std::sqrt(32.0 / 7.0) / std::sqrt(8.0), 1e-12));
  const auto one = rodsort::metrics::sample_statistics({3.0});
  CHECK(one.mean == 3.0);
  CHECK(one.standard_error == 0.0);
  CHECK(rodsort::metrics::sample_statistics({}).mean == 0.0);
}

TEST_CASE("fit_line: least squares, and no line from a single x", "[metrics]") {
  const auto line = rodsort::metrics::fit_line({1.0, 2.0, 3.0, 4.0}, {3.1, 4.9, 7.1, 8.9});
  REQUIRE(line.determined);
  CHECK_THAT(line.slope, WithinAbs(1.96, 1e-12));
  CHECK_THAT(line.intercept, WithinAbs(1.1, 1e-12));
  CHECK_FALSE(rodsort::metrics::fit_line({2.0}, {5.0}).determined);
  CHECK_FALSE(rodsort::metrics::fit_line({2.0, 2.0}, {5.0, 6.0}).determined);
}
