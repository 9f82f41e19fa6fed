#include "engine/plate_drive.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

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

TEST_CASE("a rod resting on the base moves with the Bullet plate as the drive says", "[plates]") {
  // Below Gamma = 1 a rod never leaves the base: its height follows the Bullet body that carries
  // the base surface, which must move as A cos(2 pi f t). A slow, large drive (20 Hz, Gamma =
  // 0.8, A = 0.50 mm) makes the motion large against the contact's depth. The rod is one step
  // ahead of the plate: a step moves the plate to the step's end before contacts are found, so a
  // resting rod touches the plate where it will be at the end of the step, and then moves on with
  // the plate's velocity for that step (an offset of v dt, at most A 2 pi f dt = 0.0055 mm at the
  // paper's drive; docs/model.md, "The vibrated cell").
  Model model = testing::single_rod_model(testing::rod_species(preset_a_profile()));
  model.drive.frequency = 20.0;
  model.drive.amplitude = Drive::amplitude_from_gamma(0.8, model.drive.frequency);
  model.drive.gap = 5.0;
  const PlateDrive drive(model.drive);
  Simulation sim(model);
  sim.advance(2000);  // settled after 0.2 s
  const double rod0 = sim.frame().rods[0].z;
  const double base0 = drive.base_surface_z(sim.time());
  double worst = 0.0, highest = -1.0, lowest = 1.0;
  for (int i = 0; i < 1000; ++i) {  // two periods
    sim.step();
    const double followed = sim.frame().rods[0].z - rod0;
    const double expected =
        model.drive.amplitude *
            std::cos(2.0 * rodsort::kPi * model.drive.frequency * (sim.time() + model.dt)) -
        base0;
    worst = std::max(worst, std::abs(followed - expected));
    highest = std::max(highest, followed);
    lowest = std::min(lowest, followed);
  }
  INFO("largest difference from the drive: " << worst << " mm");
  CHECK(worst < 0.002);  // 0.0006 mm measured; without the step ahead it would be 0.0065
  CHECK(highest - lowest == Approx(2.0 * model.drive.amplitude).epsilon(0.02));
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
  // pass through the rod; the run must stop rather than go on with a rod outside the cell or deep
  // in a plate.
  Model model = testing::single_rod_model(testing::rod_species(preset_a_profile()));
  model.drive.amplitude = 2.0 / (2.0 * M_PI * model.drive.frequency * model.dt);
  Simulation sim(model);
  bool stopped = false;
  try {
    sim.advance(2000);
  } catch (const std::runtime_error& error) {
    stopped = true;
    CHECK_THAT(error.what(), Catch::Contains("rod 0 left the space between base and lid") ||
                                 Catch::Contains("rod 0 went"));
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
