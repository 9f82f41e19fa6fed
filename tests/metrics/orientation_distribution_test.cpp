#include "metrics/orientation_distribution.hpp"

#include <catch2/catch.hpp>

#include "engine/units.hpp"
#include "synthetic_frames.hpp"

using namespace rodsort::metrics;
using rodsort::degrees_to_radians;
using rodsort::kPi;
using testing::frame_at;
using testing::rod_at;

TEST_CASE("Histogram bins, outliers and density", "[metrics]") {
  Histogram histogram(-1.0, 1.0, 4);
  histogram.add({-1.0, -0.75, -0.1, 0.0, 0.99, 1.0, 1.5, -2.0, std::nan("")});
  CHECK(histogram.counts == std::vector<long>{2, 1, 1, 2});
  CHECK(histogram.below == 1);
  CHECK(histogram.above == 1);
  CHECK(histogram.invalid == 1);
  CHECK(histogram.total() == 9);
  CHECK(histogram.bin_center(0) == Approx(-0.75));
  const auto density = histogram.density();
  CHECK(density[0] == Approx(2.0 / (9 * 0.5)));
}

TEST_CASE("P(dtheta) counts turns across +-pi as small turns", "[metrics]") {
  // Rod 0 turns +2.4° every frame from 178.3° (crossing +-pi on the first step); rod 1 turns -3.4°
  // every frame from -179.5°; rod 2 spins fast but is not chosen. (Turns sit mid-bin.)
  std::vector<rodsort::engine::Frame> frames;
  for (int k = 0; k < 5; ++k) {
    frames.push_back(frame_at(0.07 * k, {rod_at(1, 1, degrees_to_radians(178.3 + 2.4 * k)),
                                         rod_at(1, 1, degrees_to_radians(-179.5 - 3.4 * k)),
                                         rod_at(1, 1, degrees_to_radians(100.0 * k))}));
  }
  const Histogram p = orientation_change_distribution(frames, {0, 1}, 1, 360);  // 1° bins
  CHECK(p.total() == 8);
  CHECK(p.below + p.above + p.invalid == 0);
  const int bin_plus_2_4 = static_cast<int>((degrees_to_radians(2.4) + kPi) / p.bin_width());
  const int bin_minus_3_4 = static_cast<int>((degrees_to_radians(-3.4) + kPi) / p.bin_width());
  CHECK(p.counts[bin_plus_2_4] == 4);
  CHECK(p.counts[bin_minus_3_4] == 4);

  const Histogram lag2 = orientation_change_distribution(frames, {0}, 2, 360);
  CHECK(lag2.total() == 3);
  CHECK(lag2.counts[static_cast<int>((degrees_to_radians(4.8) + kPi) / lag2.bin_width())] == 3);
  CHECK(all_rods(frames[0]) == std::vector<int>{0, 1, 2});
}
