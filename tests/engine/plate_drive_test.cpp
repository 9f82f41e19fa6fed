#include <catch2/catch.hpp>
#include <cmath>

#include "engine/plate_drive.hpp"
#include "engine/simulation.hpp"
#include "paper_model.hpp"

using namespace rodsort::engine;

TEST_CASE("plates follow A cos(2 pi f t), the lid a gap above", "[plates]") {
  const Model model = testing::single_rod_model(testing::rod_species(preset_a_profile()));
  const PlateDrive drive(model.drive);
  CHECK(model.drive.amplitude == Approx(0.0435).epsilon(0.01));
  CHECK(model.drive.gamma() == Approx(7.0).epsilon(1e-12));
  Simulation sim(model);
  for (int i = 0; i < 37; ++i) sim.step();
  const double t = sim.time();
  CHECK(t == Approx(37 * model.dt).epsilon(1e-12));
  CHECK(sim.base_surface_z() ==
        Approx(model.drive.amplitude * std::cos(2 * rodsort::kPi * 200.0 * t)).margin(1e-12));
  CHECK(sim.lid_surface_z() - sim.base_surface_z() == Approx(1.2).epsilon(1e-12));
}

TEST_CASE("the solver sees the exact plate velocity: one internal step per step", "[plates]") {
  for (const double dt : {1.0e-4, 2.5e-5}) {
    const Model model = testing::single_rod_model(testing::rod_species(preset_a_profile()), dt);
    const PlateDrive drive(model.drive);
    Simulation sim(model);
    for (int i = 0; i < 200; ++i) {
      const double before = sim.time();
      sim.step();
      const double expected = (drive.base_surface_z(before + dt) - drive.base_surface_z(before)) / dt;
      REQUIRE(sim.base_velocity_z() == Approx(expected).margin(1e-6));
    }
  }
}

TEST_CASE("plates that pass through a rod stop the run with a message", "[plates]") {
  // Plates that move 2 mm a step (validation refuses this: a tenth of a millimetre is the bound)
  // run into the rod deeper than its spheres' radii; the run must stop rather than go on with a
  // rod inside a plate.
  Model model = testing::single_rod_model(testing::rod_species(preset_a_profile()));
  model.drive.amplitude = 2.0 / (2.0 * M_PI * model.drive.frequency * model.dt);
  Simulation sim(model);
  bool stopped = false;
  try {
    sim.advance(2000);
  } catch (const std::runtime_error& error) {
    stopped = true;
    CHECK_THAT(error.what(),
               Catch::Contains("rod 0 went") &&
                   (Catch::Contains("deep into the lid") || Catch::Contains("deep into the base")));
  }
  CHECK(stopped);
}

TEST_CASE("a rod outside the space between base and lid stops the run with a message", "[plates]") {
  Model model = testing::single_rod_model(testing::rod_species(preset_a_profile()));
  Simulation sim(model);
  State state = sim.state();
  state.rods[0].position[2] = sim.lid_surface_z() + 1.5 * model.drive.gap;
  sim.restore(state);
  bool stopped = false;
  try {
    sim.advance(10);
  } catch (const std::runtime_error& error) {
    stopped = true;
    CHECK_THAT(error.what(),
               Catch::Contains("rod 0 left the space between base and lid at step 0, t = 0 s"));
  }
  CHECK(stopped);
}
