// A contact as deep as the two bodies' reach there (two spheres' radii, or a sphere's radius and a
// wall's or plate's half-thickness), where it can no longer push them apart, stops the simulation
// with a message naming the bodies, the step and the depth; shallower overlaps, which dense piles
// and the white angular noise do produce (docs/model.md, "Checks while a run goes"), are resolved
// by the solver and only recorded.
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

TEST_CASE("a rod on top of another stops the simulation", "[breakdown]") {
  // Every sphere's centre on its twin's: as deep as two radii.
  Simulation sim(side_by_side(0.0));
  const std::string message = breakdown_message(sim, 10);
  CHECK_THAT(message, Catch::Contains("rod 0 went") || Catch::Contains("rod 1 went"));
  CHECK_THAT(message, Catch::Contains("deep into rod") && Catch::Contains("at step 0"));
}

TEST_CASE("a rod sunk into the base stops the simulation", "[breakdown]") {
  Model model = testing::single_rod_model(testing::rod_species(preset_a_profile()));
  Simulation sim(model);
  State state = sim.state();
  // Lying flat with its axis 1.1 mm below the base's surface: past the plate's mid-plane (the
  // plates are 2 mm thick) by more than every sphere's radius... less 1.1, which the gap's check
  // still accepts.
  state.rods[0].position[2] = sim.base_surface_z() - 1.1;
  sim.restore(state);
  const std::string message = breakdown_message(sim, 10);
  CHECK_THAT(message, Catch::Contains("rod 0 went") && Catch::Contains("deep into the base"));
}

TEST_CASE("overlaps short of the limit are resolved and recorded, not stopped", "[breakdown]") {
  // 0.1 mm and 0.6 mm deep (thick spheres, 0.55 mm radius): the solver pushes the rods apart.
  for (const double separation : {1.0, 0.5}) {
    Simulation sim(side_by_side(separation));
    CHECK(breakdown_message(sim, 2000).empty());
    CHECK(sim.counters().deepest_overlap == Approx(1.1 - separation).margin(0.01));
    // Resolved: from then on no deeper than a rod pressed on the vibrated base (0.023 mm).
    sim.reset_counters();
    sim.advance(1000);
    CHECK(sim.counters().deepest_overlap < 0.03);
  }
}
