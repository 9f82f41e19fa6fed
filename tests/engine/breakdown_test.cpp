// A step that finds a rod's sphere deeper in a neighbour, a wall or a plate than its own radius
// stops the simulation with a message naming the bodies, the step and the depth; shallower
// overlaps, which a dense pile does produce (docs/model.md, "Checks while a run goes"), are
// resolved by the solver and only counted.
#include <catch2/catch.hpp>
#include <string>

#include "engine/simulation.hpp"
#include "paper_model.hpp"

using namespace rodsort::engine;

namespace {

/// Two rods of A side by side, heading along +x, their axes `separation` mm apart.
Model side_by_side(double separation) {
  Model model = testing::single_rod_model(testing::rod_species(preset_a_profile()));
  model.rods.push_back({0, 15.0, 15.0 + separation, 0.0});
  return model;
}

std::string breakdown_message(Simulation& sim, std::int64_t steps) {
  try {
    sim.advance(steps);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST_CASE("a rod deep in another stops the simulation", "[breakdown]") {
  // Thick spheres of radius 0.55 mm with centres 0.5 mm apart: 0.6 mm deep.
  Simulation sim(side_by_side(0.5));
  const std::string message = breakdown_message(sim, 10);
  CHECK_THAT(message, Catch::Contains("rod 0 went 0.6") || Catch::Contains("rod 1 went 0.6"));
  CHECK_THAT(message, Catch::Contains("deep into rod") && Catch::Contains("at step 0") &&
                          Catch::Contains("(0.55 mm)"));
}

TEST_CASE("a rod sunk into the base stops the simulation", "[breakdown]") {
  Model model = testing::single_rod_model(testing::rod_species(preset_a_profile()));
  Simulation sim(model);
  State state = sim.state();
  // Lying flat with its axis 0.1 mm below the base's surface: every sphere is deeper than its
  // radius.
  state.rods[0].position[2] = sim.base_surface_z() - 0.1;
  sim.restore(state);
  const std::string message = breakdown_message(sim, 10);
  CHECK_THAT(message, Catch::Contains("rod 0 went") && Catch::Contains("deep into the base"));
}

TEST_CASE("a shallow overlap is resolved and counted, not stopped", "[breakdown]") {
  // 0.1 mm deep: the solver pushes the rods apart.
  Simulation sim(side_by_side(1.0));
  CHECK(breakdown_message(sim, 2000).empty());
  CHECK(sim.counters().deepest_overlap == Approx(0.1).margin(0.01));
}
