#include "metrics/single_rod.hpp"

#include <catch2/catch.hpp>
#include <random>

#include "engine/units.hpp"
#include "synthetic_frames.hpp"

using namespace rodsort::metrics;
using rodsort::kPi;
using testing::frame_at;
using testing::rod_at;

TEST_CASE("v0 is positive toward the thin end", "[metrics]") {
  // Rod 0 heads along +x and moves +x at 8 mm/s, across the cell's edge; rod 1 heads along
  // 3pi/4 and moves backwards (toward its thick end) at 2 mm/s; rod 2 moves sideways.
  std::vector<rodsort::engine::Frame> frames;
  const Eigen::Vector2d backwards =
      -2.0 * Eigen::Vector2d(std::cos(0.75 * kPi), std::sin(0.75 * kPi));
  for (int k = 0; k < 20; ++k) {
    const double t = 0.07 * k;
    frames.push_back(
        frame_at(t, {rod_at(95.0 + 8.0 * t, 10, 0.0),
                     rod_at(30 + backwards.x() * t, 30 + backwards.y() * t, 0.75 * kPi),
                     rod_at(50, 50 + 5.0 * t, 0.0)}));
  }
  CHECK(mean_axial_speed(frames, {0}) == Approx(8.0));
  CHECK(mean_axial_speed(frames, {1}) == Approx(-2.0));
  CHECK(mean_axial_speed(frames, {2}) == Approx(0.0).margin(1e-9));
  CHECK(mean_axial_speed(frames, {0, 1}, 3) == Approx(3.0));
}

TEST_CASE("v0 follows a turning rod", "[metrics]") {
  // A rod moving at 5 mm/s along its heading while the heading turns 1 rad/s.
  std::vector<rodsort::engine::Frame> frames;
  Eigen::Vector2d position(10, 10);
  const double dt = 0.01;
  for (int k = 0; k < 200; ++k) {
    const double phi = 1.0 * k * dt;
    frames.push_back(frame_at(k * dt, {rod_at(position.x(), position.y(), phi)}));
    const double mid = phi + 0.5 * dt;
    position += 5.0 * dt * Eigen::Vector2d(std::cos(mid), std::sin(mid));
  }
  CHECK(mean_axial_speed(frames, {0}, 7) == Approx(5.0).epsilon(1e-3));
}

TEST_CASE("D_r of a random walk of the heading", "[metrics]") {
  // 100 rods whose heading performs a Gaussian random walk with D_r = 0.7 rad^2/s, sampled every
  // 0.07 s; the heading wraps around +-pi many times.
  const double true_dr = 0.7, dt = 0.07;
  std::mt19937_64 rng(12345);
  std::normal_distribution<double> gauss(0.0, std::sqrt(2.0 * true_dr * dt));
  const int rods = 100, steps = 600;
  std::vector<double> phi(rods, 0.0);
  std::vector<rodsort::engine::Frame> frames;
  for (int k = 0; k < steps; ++k) {
    std::vector<rodsort::engine::RodFrame> frame;
    for (int r = 0; r < rods; ++r) {
      frame.push_back(rod_at(0, 0, phi[r]));
      phi[r] += gauss(rng);
    }
    frames.push_back(frame_at(k * dt, frame));
  }
  std::vector<int> all(rods);
  for (int r = 0; r < rods; ++r) all[r] = r;
  const RotationalDiffusion fit = rotational_diffusion(frames, all, 1, 20);
  CHECK(fit.coefficient == Approx(true_dr).epsilon(0.05));
  CHECK(fit.intercept == Approx(0.0).margin(0.02));
  REQUIRE(fit.lag_times.size() == 20);
  CHECK(fit.lag_times[0] == Approx(0.07));
  CHECK(fit.lag_times[19] == Approx(1.4));
  CHECK(fit.mean_square[9] == Approx(2.0 * true_dr * 0.7).epsilon(0.05));
}

TEST_CASE("D_r ignores a bounded rattle of the heading", "[metrics]") {
  // Heading = a random walk plus an independent +-0.3 rad rattle in every frame: the rattle adds a
  // constant to the mean square, which goes to the intercept, not to D_r.
  const double true_dr = 0.2, dt = 0.07;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> gauss(0.0, std::sqrt(2.0 * true_dr * dt));
  std::uniform_real_distribution<double> rattle(-0.3, 0.3);
  const int rods = 100, steps = 600;
  std::vector<double> phi(rods, 1.0);
  std::vector<rodsort::engine::Frame> frames;
  for (int k = 0; k < steps; ++k) {
    std::vector<rodsort::engine::RodFrame> frame;
    for (int r = 0; r < rods; ++r) {
      frame.push_back(rod_at(0, 0, phi[r] + rattle(rng)));
      phi[r] += gauss(rng);
    }
    frames.push_back(frame_at(k * dt, frame));
  }
  std::vector<int> all(rods);
  for (int r = 0; r < rods; ++r) all[r] = r;
  const RotationalDiffusion fit = rotational_diffusion(frames, all, 1, 10);
  CHECK(fit.coefficient == Approx(true_dr).epsilon(0.08));
  // Two independent uniform rattles of variance 0.6^2 / 12 each.
  CHECK(fit.intercept == Approx(2.0 * 0.36 / 12.0).margin(0.015));
}
