// The solver takes the contacts batch by batch (engine/solver_batches.cpp), which is claimed to
// give exactly the result of one call with every contact when the sweeps meet the contacts in a
// fixed order. Checked here on a system with several batches and islands of many rods.
#include "engine/solver_batches.hpp"

#include <catch2/catch.hpp>

#include "engine/simulation.hpp"
#include "paper_model.hpp"

using namespace rodsort::engine;

namespace {

/// 480 rods in rows along +x, end to end with 0.5 mm gaps and 0.4 mm between rows: they soon run
/// into each other and form islands of many rods, across the periodic edges too.
Model crowded_model() {
  Model model = testing::paper_model(60.0);
  model.seed = 5;
  model.species.push_back(testing::rod_species(preset_a_profile(), 0.01, 0.1));
  for (int row = 0; row < 40; ++row) {
    for (int column = 0; column < 12; ++column) {
      const double stagger = row % 2 == 0 ? 0.0 : 2.5;
      model.rods.push_back({0, 2.5 + 5.0 * column + stagger, 0.75 + 1.5 * row, 0.0});
    }
  }
  model.fixed_sweep_order = true;
  return model;
}

std::uint64_t hash_after(const Model& model, int steps) {
  Simulation sim(model);
  sim.advance(steps);
  return hash_state(sim.state());
}

}  // namespace

TEST_CASE("solving batch by batch equals one solve of every contact", "[solver]") {
  const Model batched = crowded_model();
  REQUIRE(batched.rods.size() > 3 * SolverBatches::kTargetRods);
  Model single = batched;
  single.single_solver_batch = true;
  constexpr int kSteps = 1500;
  CHECK(hash_after(batched, kSteps) == hash_after(single, kSteps));

  // And with the white noise turned through the solver's position correction.
  Model full = batched;
  full.full_turn_correction = true;
  Model full_single = single;
  full_single.full_turn_correction = true;
  CHECK(hash_after(full, kSteps) == hash_after(full_single, kSteps));

  // The comparison can fail: another order of the contacts gives another state.
  Model reversed = batched;
  reversed.reverse_contact_order = true;
  CHECK(hash_after(reversed, kSteps) != hash_after(batched, kSteps));
}
