// The exact contact solve (Model::exact_contact_solver) against the solver's ten sweeps: rod A's
// speed belongs to the contact problem, not to an unconverged solve (docs/model.md, "An exact
// contact solve").
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>

#include "engine/simulation.hpp"
#include "paper_model.hpp"

using namespace rodsort::engine;

namespace {

struct SpeedMeasurement {
  double speed = 0.0;              ///< mean axial speed over rods and windows [mm/s]
  std::int64_t fallbacks = 0;      ///< SimulationCounters::exact_solver_fallbacks, all rods
  std::int64_t steps = 0;          ///< steps measured, all rods
  Eigen::Vector2d first_position;  ///< rod 0's unwrapped centre at the end [mm]
};

/// Rod A with the paper's kick, `rods` rods each alone in its own cell from its own seed, for
/// `seconds` after one second of warm-up: the axial speed over 0.07 s windows.
SpeedMeasurement measure(bool exact, double cfm, int rods, double seconds) {
  constexpr double kDt = 1.0e-4, kWindow = 0.07;
  const long steps_per_window = std::lround(kWindow / kDt);
  const long windows = std::lround(seconds / kWindow);
  SpeedMeasurement result;
  double sum = 0.0;
  for (int rod = 0; rod < rods; ++rod) {
    Model model = testing::single_rod_model(testing::rod_species(preset_a_profile(), 0.01), kDt,
                                            300 + static_cast<std::uint64_t>(rod));
    model.exact_contact_solver = exact;
    model.constraint_force_mixing = cfm;
    Simulation sim(model);
    sim.advance(std::lround(1.0 / kDt));
    for (long w = 0; w < windows; ++w) {
      const RodFrame start = sim.frame().rods[0];
      sim.advance(steps_per_window);
      const RodFrame end = sim.frame().rods[0];
      const Eigen::Vector2d axis = (start.axis + end.axis).head<2>().normalized();
      sum += (end.unwrapped - start.unwrapped).head<2>().dot(axis) / kWindow;
    }
    result.fallbacks += sim.counters().exact_solver_fallbacks;
    result.steps += sim.step_count();
    if (rod == 0) result.first_position = sim.frame().rods[0].unwrapped;
  }
  result.speed = sum / static_cast<double>(rods * windows);
  return result;
}

}  // namespace

TEST_CASE("rod A moves as fast with an exact contact solve as with the solver's sweeps",
          "[physics][propulsion]") {
  // Measured with 24 rods x 20 s (docs/model.md): 14.25 +- 0.01 mm/s with ten sweeps, 14.12 to
  // 14.23 +- 0.01 exact (compliance 0 to 1e-5 s/g). Here 6 rods x 6 s, a standard error of about
  // 0.05 mm/s each; the tolerance (2%, 0.28 mm/s) is four of them, and a solve that stopped short
  // of convergence by as much as the iteration count once moved v0 (7%) fails it.
  const SpeedMeasurement sweeps = measure(false, 0.0, 6, 6.0);
  const SpeedMeasurement exact = measure(true, 1.0e-8, 6, 6.0);
  INFO("v0 [mm/s]: " << sweeps.speed << " with ten sweeps, " << exact.speed << " exact");
  CHECK(exact.speed == Approx(sweeps.speed).epsilon(0.02));
  CHECK(sweeps.fallbacks == 0);
  // A compliance of 1e-8 s/g (1e-4 per g on the diagonal at dt = 1e-4 s, against 61 per g for the
  // rod's mass alone) keeps every problem solvable.
  CHECK(exact.fallbacks == 0);
  // The two solves really differ: the trajectories part.
  CHECK((exact.first_position - sweeps.first_position).norm() > 1.0e-3);
}

TEST_CASE("a rigid exact contact solve gives up only on rare degenerate landings",
          "[physics][propulsion]") {
  // Without compliance a rod lying on a plate along a line of contacts makes the problem singular
  // now and then; Bullet's Dantzig solver then gives up and the sweeps take over. Measured: 0.76%
  // of steps at dt = 1e-4 s (24 rods x 20 s).
  const SpeedMeasurement rigid = measure(true, 0.0, 2, 6.0);
  const double fraction = static_cast<double>(rigid.fallbacks) / static_cast<double>(rigid.steps);
  INFO("fallbacks: " << rigid.fallbacks << " of " << rigid.steps << " steps");
  CHECK(rigid.fallbacks > 0);
  CHECK(fraction < 0.03);
}
