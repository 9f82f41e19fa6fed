// Angular noise: the collision kick and white rotational diffusion.
#include <catch2/catch.hpp>
#include <cmath>

#include "engine/simulation.hpp"
#include "paper_model.hpp"

using namespace rodsort::engine;

namespace {

constexpr double kFrameInterval = 0.07;  // [s], the paper's frame interval

struct NoiseMeasurement {
  double rotational_diffusion;  ///< D_r = <dtheta^2> / (2 tau) over frames tau apart [rad^2/s]
  double kick_rate;             ///< collision events per rod per second [1/s]
};

/// Free rods, each alone in its own cell (so that they never meet), for `seconds` after one second
/// of warm-up.
NoiseMeasurement measure(const Species& species, double dt, int rods, double seconds) {
  double sum_squares = 0.0;
  long increments = 0;
  double events = 0.0;
  const long steps_per_frame = std::lround(kFrameInterval / dt);
  const long frames = std::lround(seconds / kFrameInterval);
  for (int rod = 0; rod < rods; ++rod) {
    Simulation sim(testing::single_rod_model(species, dt, 1000 + static_cast<std::uint64_t>(rod)));
    sim.advance(std::lround(1.0 / dt));
    const std::int64_t kicks_before = sim.counters().kicks;
    double previous = std::atan2(sim.frame().rods[0].axis.y(), sim.frame().rods[0].axis.x());
    for (long f = 0; f < frames; ++f) {
      sim.advance(steps_per_frame);
      const RodFrame now = sim.frame().rods[0];
      const double angle = std::atan2(now.axis.y(), now.axis.x());
      const double change = std::remainder(angle - previous, 2.0 * rodsort::kPi);
      sum_squares += change * change;
      ++increments;
      previous = angle;
    }
    events += static_cast<double>(sim.counters().kicks - kicks_before);
  }
  const double elapsed = static_cast<double>(frames * steps_per_frame) * dt;
  return {sum_squares / static_cast<double>(increments) / (2.0 * kFrameInterval),
          events / (elapsed * rods)};
}

}  // namespace

TEST_CASE("the kick rate does not depend on dt", "[physics][noise]") {
  const Species rod = testing::rod_species(preset_a_profile(), 0.01);
  const double coarse = measure(rod, 1.0e-4, 10, 25.0).kick_rate;
  const double fine = measure(rod, 2.5e-5, 10, 25.0).kick_rate;
  INFO("kicks per second: " << coarse << " at dt = 1e-4, " << fine << " at dt = 2.5e-5");
  CHECK(coarse == Approx(fine).epsilon(0.10));
  // The rod hits the plates a few times per drive period (200 Hz).
  CHECK(coarse > 200.0);
  CHECK(coarse < 2000.0);
}

TEST_CASE("the rotational diffusion from kicks has converged in dt at 5e-5 s", "[physics][noise]") {
  // At dt = 1e-4 s D_r differs by ~13% from its small-dt value although the kick rate and the
  // mean squared kick agree within 5%: the rod's spin dynamics between kicks are not converged
  // there (docs/model.md, "Collision kick").
  const Species rod = testing::rod_species(preset_a_profile(), 0.01);
  const double coarse = measure(rod, 5.0e-5, 10, 25.0).rotational_diffusion;
  const double fine = measure(rod, 2.5e-5, 10, 25.0).rotational_diffusion;
  INFO("D_r [rad^2/s]: " << coarse << " at dt = 5e-5, " << fine << " at dt = 2.5e-5");
  CHECK(coarse == Approx(fine).epsilon(0.10));
}

TEST_CASE("rotational diffusion grows with the kick strength", "[physics][noise]") {
  const double weak = measure(testing::rod_species(preset_a_profile(), 0.005), 1e-4, 4, 10.0)
                          .rotational_diffusion;
  const double strong = measure(testing::rod_species(preset_a_profile(), 0.02), 1e-4, 4, 10.0)
                            .rotational_diffusion;
  CHECK(weak > 0.0);
  // Kicks add angular velocity in proportion to eps, so D_r grows about as eps^2 (16 times here).
  CHECK(strong > 4.0 * weak);
}

TEST_CASE("white angular noise gives the configured rotational diffusion", "[physics][noise]") {
  for (const double white_Dr : {0.1, 0.5}) {
    INFO("D_r = " << white_Dr);
    const Species rod = testing::rod_species(preset_a_profile(), 0.0, white_Dr);
    CHECK(measure(rod, 1.0e-4, 12, 20.0).rotational_diffusion == Approx(white_Dr).epsilon(0.10));
  }
}
