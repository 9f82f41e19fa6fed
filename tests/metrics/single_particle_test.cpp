// The single-particle measures on tracks whose answers are known: straight runs, steady turning,
// run-and-tumble series, one and two peaks.

#include "metrics/single_particle.hpp"

#include <Eigen/Geometry>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>

using namespace rodsort;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

/// A rod at `speed` along its heading, the heading turning at `turn_rate`, sampled every `dt`.
metrics::Track steady_track(double speed, double turn_rate, double dt, int samples) {
  metrics::Track track;
  Eigen::Vector2d position(0.0, 0.0);
  for (int i = 0; i < samples; ++i) {
    const double phi = 0.3 + turn_rate * dt * i;
    track.time.push_back(dt * i);
    track.heading.push_back(phi);
    track.position.push_back(position);
    // Exact displacement along an arc, so the chord follows the mean heading of its ends.
    const double next = phi + turn_rate * dt;
    const double chord =
        turn_rate == 0.0 ? speed * dt : 2.0 * speed / turn_rate * std::sin(0.5 * turn_rate * dt);
    position += chord * Eigen::Vector2d(std::cos(0.5 * (phi + next)), std::sin(0.5 * (phi + next)));
  }
  return track;
}

/// The row-major basis of a rod turned by `heading` about the vertical, then `tilt` about its
/// left (thin end down for tilt > 0), then `roll` about its own axis.
std::array<double, 9> basis_of(double heading, double tilt, double roll) {
  const Eigen::Matrix3d rotation = (Eigen::AngleAxisd(heading, Eigen::Vector3d::UnitZ()) *
                                    Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitY()) *
                                    Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
                                       .toRotationMatrix();
  std::array<double, 9> basis;
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 3; ++column) basis[3 * row + column] = rotation(row, column);
  }
  return basis;
}

}  // namespace

TEST_CASE("the roll is the turn about the rod's own axis, whatever its heading and tilt",
          "[metrics][single]") {
  for (const double heading : {0.0, 1.0, -2.5, 3.1}) {
    for (const double tilt : {0.0, 0.05, -0.3}) {
      for (const double roll : {0.0, 0.4, 1.5707963, -2.0, 3.0}) {
        INFO("heading " << heading << ", tilt " << tilt << ", roll " << roll);
        CHECK_THAT(metrics::roll_angle(basis_of(heading, tilt, roll)), WithinAbs(roll, 1e-12));
      }
    }
  }
  // Body y pointing up is a roll of a quarter turn, down of minus a quarter.
  CHECK_THAT(metrics::roll_angle(basis_of(0.7, 0.0, std::numbers::pi / 2)),
             WithinAbs(std::numbers::pi / 2, 1e-12));
}

TEST_CASE("a roll track unwraps the roll across +-pi and reads a steady spin as a turn rate",
          "[metrics][single]") {
  const metrics::Track track = steady_track(10.0, 0.0, 0.01, 200);
  std::vector<double> roll;
  for (int i = 0; i < 200; ++i)
    roll.push_back(std::remainder(-2.0 + 0.5 * i * 0.01 * 10, 2 * std::numbers::pi));
  const metrics::Track rolled = metrics::roll_track(track, roll);
  REQUIRE(rolled.heading.size() == 200);
  CHECK(rolled.position == track.position);
  CHECK_THAT(rolled.heading.back() - rolled.heading.front(), WithinAbs(0.5 * 199 * 0.1, 1e-9));
  CHECK_THAT(metrics::turn_rate(rolled), WithinAbs(5.0, 1e-9));
}

TEST_CASE("track_of unwraps the heading across +-pi and keeps unwrapped positions",
          "[metrics][single]") {
  std::vector<engine::Frame> frames;
  for (int i = 0; i < 5; ++i) {
    engine::Frame frame;
    frame.time = 0.01 * i;
    engine::RodFrame rod;
    rod.velocity.setZero();
    rod.angular_velocity.setZero();
    const double phi = 3.0 + 0.1 * i;  // crosses pi between the second and third frame
    rod.axis = Eigen::Vector3d(std::cos(phi), std::sin(phi), 0.0);
    rod.unwrapped = Eigen::Vector2d(100.0 * i, 0.0);
    rod.position = Eigen::Vector2d(1.0, 0.0);
    frame.rods.push_back(rod);
    frames.push_back(frame);
  }
  const metrics::Track track = metrics::track_of(frames, 0);
  REQUIRE(track.heading.size() == 5);
  CHECK_THAT(track.heading.back() - track.heading.front(), WithinAbs(0.4, 1e-12));
  CHECK_THAT(track.position.back().x(), WithinAbs(400.0, 1e-12));
}

TEST_CASE("the tilt: the fraction of frames with the thin end down, over every track",
          "[metrics][single]") {
  // Frames whose axis tilts by the given vertical components (thin end down when negative).
  const auto tilted = [](std::vector<double> tilts) {
    std::vector<engine::Frame> frames;
    for (std::size_t i = 0; i < tilts.size(); ++i) {
      engine::Frame frame;
      frame.time = 0.01 * static_cast<double>(i);
      engine::RodFrame rod;
      rod.velocity.setZero();
      rod.angular_velocity.setZero();
      const double level = std::sqrt(1.0 - tilts[i] * tilts[i]);
      rod.axis = Eigen::Vector3d(level, 0.0, tilts[i]);
      rod.unwrapped.setZero();
      rod.position.setZero();
      frame.rods.push_back(rod);
      frames.push_back(frame);
    }
    return metrics::track_of(frames, 0);
  };
  const metrics::Track first = tilted({-0.04, -0.03, 0.02, -0.05});
  REQUIRE(first.tilt.size() == 4);
  CHECK_THAT(first.tilt[2], WithinAbs(0.02, 1e-15));
  CHECK_THAT(first.heading[2], WithinAbs(0.0, 1e-15));  // the tilt leaves the heading alone
  CHECK_THAT(metrics::thin_end_down_fraction({first}), WithinAbs(0.75, 1e-15));
  // Pooled over frames, not averaged over tracks: 3 + 0 of 4 + 2 frames.
  const metrics::Track second = tilted({0.01, 0.0});
  CHECK_THAT(metrics::thin_end_down_fraction({first, second}), WithinAbs(0.5, 1e-15));
  CHECK(std::isnan(metrics::thin_end_down_fraction({})));
}

TEST_CASE("axial velocity is the speed toward the thin end, negative backward",
          "[metrics][single]") {
  const metrics::Track forward = steady_track(3.6, 0.5, 0.01, 200);
  for (const double v : metrics::axial_velocities(forward, 7, 1))
    CHECK_THAT(v, WithinRel(3.6, 0.01));
  const metrics::Track backward = steady_track(-2.0, 0.0, 0.01, 50);
  const std::vector<double> back = metrics::axial_velocities(backward, 7, 7);
  CHECK(back.size() == 7);  // windows 0-7, 7-14, ..., 42-49
  for (const double v : back) CHECK_THAT(v, WithinAbs(-2.0, 1e-12));
}

TEST_CASE("lag statistics of a steady turn: ballistic MSD, cos correlation, and D_r of a line",
          "[metrics][single]") {
  const double omega = 0.2;  // rad/s
  const metrics::Track track = steady_track(0.0, omega, 0.01, 500);
  const metrics::LagStatistics lags = metrics::lag_statistics({track}, {10, 100});
  CHECK_THAT(lags.lag_time[1], WithinAbs(1.0, 1e-12));
  CHECK_THAT(lags.heading_msd[1], WithinAbs(omega * omega, 1e-12));
  CHECK_THAT(lags.orientation_correlation[1], WithinAbs(std::cos(omega), 1e-12));
  CHECK_THAT(lags.position_msd[0], WithinAbs(0.0, 1e-12));
  const metrics::Track straight = steady_track(5.0, 0.0, 0.01, 300);
  CHECK_THAT(metrics::lag_statistics({straight}, {50}).position_msd[0], WithinRel(6.25, 1e-9));
  // MSD = c + 2 D t recovers D whatever the intercept.
  CHECK_THAT(metrics::rotational_diffusion_fit(
                 {0.07, 0.14, 0.21},
                 {0.01 + 2 * 0.3 * 0.07, 0.01 + 2 * 0.3 * 0.14, 0.01 + 2 * 0.3 * 0.21}),
             WithinRel(0.3, 1e-9));
}

TEST_CASE("a steady turn is told from diffusion: turn rate, D_r about the turn, circling",
          "[metrics][single]") {
  // A heading that turns at `omega` and diffuses with D about the turn, 40 s sampled every 0.01 s.
  const double dt = 0.01, diffusion = 0.1;
  const auto diffusing_track = [&](double omega) {
    std::mt19937_64 random(7);
    std::normal_distribution<double> normal;
    metrics::Track track = steady_track(0.0, omega, dt, 4001);
    double walk = 0.0;
    for (double& phi : track.heading) {
      phi += walk;
      walk += std::sqrt(2.0 * diffusion * dt) * normal(random);
    }
    return track;
  };
  const std::vector<int> lags = {7, 14, 21, 28, 35, 42, 49, 56, 63, 70};
  const auto fitted = [&](const metrics::Track& track) {
    const metrics::LagStatistics statistics = metrics::lag_statistics({track}, lags);
    return metrics::rotational_diffusion_fit(statistics.lag_time, statistics.heading_msd);
  };

  const metrics::Track circling = diffusing_track(3.0);
  const double rate = metrics::turn_rate(circling);
  // The walk adds sqrt(2 D T) ~ 2.8 rad to the 120 rad of the turn over 40 s.
  CHECK_THAT(rate, WithinAbs(3.0, 0.15));
  // Read as diffusion, the turn gives a D_r some forty times too large...
  CHECK(fitted(circling) > 20.0 * diffusion);
  // ... and taken out first, the diffusion about it (one 40 s walk: within 30%).
  const double about_turn = fitted(metrics::without_steady_turn(circling, rate));
  CHECK_THAT(about_turn, WithinRel(diffusion, 0.3));
  CHECK(metrics::circles(rate, 40.0, about_turn));

  const metrics::Track diffusing = diffusing_track(0.0);
  const double drift = metrics::turn_rate(diffusing);
  CHECK(std::abs(drift) < 0.3);
  CHECK_FALSE(
      metrics::circles(drift, 40.0, fitted(metrics::without_steady_turn(diffusing, drift))));
  // A rod that keeps its heading exactly does not circle, however small its D.
  CHECK_FALSE(metrics::circles(1e-12, 40.0, 0.0));
  // Over one full turn, steadily and without diffusion, it does.
  CHECK(metrics::circles(0.2, 40.0, 0.0));
  CHECK(std::isnan(metrics::turn_rate(metrics::Track{})));
}

TEST_CASE("runs and tumbles count only segments bounded on both sides", "[metrics][single]") {
  // run (cut) | tumble x3 | run x2 | tumble (cut)
  const std::vector<double> series = {5, 5, 0, 0.5, 0, 6, 7, 0};
  const metrics::RunsAndTumbles r = metrics::runs_and_tumbles({series, {9, 9}}, 0.07, 1.0);
  CHECK_THAT(r.running_fraction, WithinAbs(6.0 / 10.0, 1e-12));
  CHECK(r.runs == 1);
  CHECK(r.tumbles == 1);
  CHECK_THAT(r.mean_run, WithinAbs(0.14, 1e-12));
  CHECK_THAT(r.mean_tumble, WithinAbs(0.21, 1e-12));
  CHECK(std::isnan(metrics::runs_and_tumbles({{9, 9, 9}}, 0.07, 1.0).mean_run));
}

TEST_CASE("the backward fraction counts windows against the heading faster than 1 mm/s",
          "[metrics][single]") {
  // A rest rattling at +-0.9 mm/s is not backward; -1.1 and -4 mm/s are.
  CHECK(metrics::backward_fraction({5.0, 0.9, -0.9, -1.1, -4.0, 3.0, -1.0, 2.0}) == 2.0 / 8.0);
  CHECK(metrics::backward_fraction({12.0, 14.0}) == 0.0);
  CHECK(std::isnan(metrics::backward_fraction({})));
}

TEST_CASE("runs and tumbles measure the turn over each complete segment", "[metrics][single]") {
  constexpr double kPi = std::numbers::pi;
  // run (cut) | tumble x2 | run x2 | tumble | run x1 | tumble (cut)
  const std::vector<double> series = {5, 0, 0, 6, 7, 0, 8, 0};
  // Headings at the nine window boundaries. The first tumble turns the rod by 1.5 pi, which is
  // -0.5 pi taken to (-pi, pi]; the second by 0.3; the complete runs by 0.1 and -0.2. The cut
  // segments at either end turn it by 2.0 and 1.0, which must not count.
  const std::vector<double> headings = {0.0,
                                        2.0,
                                        2.0 + 0.7,
                                        2.0 + 1.5 * kPi,
                                        2.05 + 1.5 * kPi,
                                        2.1 + 1.5 * kPi,
                                        2.4 + 1.5 * kPi,
                                        2.2 + 1.5 * kPi,
                                        3.2 + 1.5 * kPi};
  const metrics::RunsAndTumbles r = metrics::runs_and_tumbles({series}, 0.07, 1.0, {headings});
  CHECK(r.runs == 2);
  CHECK(r.tumbles == 2);
  CHECK_THAT(r.tumble_turn_rms, WithinAbs(std::sqrt((0.25 * kPi * kPi + 0.09) / 2.0), 1e-12));
  CHECK_THAT(r.run_turn_rms, WithinAbs(std::sqrt((0.01 + 0.04) / 2.0), 1e-12));
  // Without headings there are no turns; with headings but no complete tumble, none either.
  CHECK(std::isnan(metrics::runs_and_tumbles({series}, 0.07, 1.0).tumble_turn_rms));
  CHECK(std::isnan(metrics::runs_and_tumbles({{9, 9}}, 0.07, 1.0, {{0.0, 0.1, 0.2}}).run_turn_rms));
}

TEST_CASE("window_boundary_headings lays the boundaries of back-to-back windows",
          "[metrics][single]") {
  metrics::Track track;
  for (int i = 0; i < 10; ++i) {
    track.time.push_back(0.01 * i);
    track.position.emplace_back(0.1 * i, 0.0);
    track.heading.push_back(0.5 * i);
    track.tilt.push_back(-0.1);
  }
  // Windows of 3 samples: 0-3, 3-6, 6-9; their boundaries are samples 0, 3, 6 and 9.
  CHECK(metrics::axial_velocities(track, 3, 3).size() == 3);
  CHECK(metrics::window_boundary_headings(track, 3) == std::vector<double>{0.0, 1.5, 3.0, 4.5});
  // Windows of 4: 0-4 and 4-8; sample 9 is past the last window's end.
  CHECK(metrics::axial_velocities(track, 4, 4).size() == 2);
  CHECK(metrics::window_boundary_headings(track, 4) == std::vector<double>{0.0, 2.0, 4.0});
}

TEST_CASE("quantile interpolates between order statistics", "[metrics][single]") {
  CHECK_THAT(metrics::quantile({4, 1, 3, 2, 5}, 0.9), WithinAbs(4.6, 1e-12));
  CHECK_THAT(metrics::quantile({7}, 0.5), WithinAbs(7.0, 1e-12));
}

TEST_CASE("two_peaks tells one peak from two", "[metrics][single]") {
  std::mt19937_64 random(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  const auto density_of = [](const std::vector<double>& values, std::vector<double>& centres) {
    std::vector<double> density(80, 0.0);
    centres.clear();
    for (int b = 0; b < 80; ++b) centres.push_back(-10.0 + 0.25 * (b + 0.5));
    for (const double v : values) {
      const int b = static_cast<int>(std::floor((v + 10.0) / 0.25));
      if (b >= 0 && b < 80) density[static_cast<std::size_t>(b)] += 1.0;
    }
    return density;
  };
  std::vector<double> one, two, centres;
  for (int i = 0; i < 20000; ++i) {
    one.push_back(2.0 + 1.5 * normal(random));
    two.push_back(i % 3 == 0 ? 6.0 + 0.5 * normal(random) : 0.7 * normal(random));
  }
  const metrics::TwoPeaks single = metrics::two_peaks(centres, density_of(one, centres));
  CHECK_FALSE(single.bimodal());
  CHECK_THAT(single.main, WithinAbs(2.0, 0.5));
  const metrics::TwoPeaks pair = metrics::two_peaks(centres, density_of(two, centres));
  CHECK(pair.bimodal());
  CHECK_THAT(pair.main, WithinAbs(0.0, 0.3));
  CHECK_THAT(pair.second, WithinAbs(6.0, 0.3));
  CHECK(pair.valley < 0.05);
}
