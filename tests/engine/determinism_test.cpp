#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <sstream>

#include "engine/simulation.hpp"
#include "paper_model.hpp"

using namespace rodsort::engine;

namespace {

Model small_model() {
  Model model = testing::paper_model(20.0);
  model.seed = 7;
  model.species.push_back(testing::rod_species(preset_a_profile(), 0.01, 0.1));
  for (int i = 0; i < 12; ++i) {
    model.rods.push_back({0, 2.5 + 5.0 * (i % 4), 3.0 + 6.0 * (i / 4), 0.7 * i});
  }
  return model;
}

}  // namespace

TEST_CASE("same model and seed give identical states", "[determinism]") {
  Simulation a(small_model());
  Simulation b(small_model());
  a.advance(3000);
  b.advance(3000);
  CHECK(hash_state(a.state()) == hash_state(b.state()));
}

TEST_CASE("a different seed gives a different trajectory", "[determinism]") {
  Model other = small_model();
  other.seed = 8;
  Simulation a(small_model());
  Simulation b(other);
  a.advance(3000);
  b.advance(3000);
  CHECK(hash_state(a.state()) != hash_state(b.state()));
}

TEST_CASE("the state after 3000 steps is pinned", "[determinism]") {
  // Regenerate on purpose only, when the physics changes (print hash_state of this run).
  Simulation sim(small_model());
  sim.advance(3000);
  CHECK(hash_state(sim.state()) == 0x0f764550fdb5a521ULL);
}

TEST_CASE("state survives a write/read round trip", "[state]") {
  Simulation sim(small_model());
  sim.advance(500);
  const State state = sim.state();
  std::stringstream bytes;
  write_state(bytes, state);
  const State back = read_state(bytes);
  CHECK(hash_state(back) == hash_state(state));
  CHECK(back.step == 500);
  std::stringstream truncated(bytes.str().substr(0, 40));
  CHECK_THROWS(read_state(truncated));
}

/// Rods packed against a V-shaped trap in a small periodic cell: contacts with the base, the lid,
/// both walls, other rods and periodic images, with both noises on.
Model trap_model() {
  Model model = testing::paper_model(24.0);
  model.seed = 11;
  model.species.push_back(testing::rod_species(preset_a_profile(), 0.01, 0.1));
  const double arm = 7.0, half_angle = 0.6;
  for (const double side : {-1.0, 1.0}) {
    const double yaw = side * half_angle;
    model.walls.push_back(
        {12.0 + 0.5 * arm * std::cos(yaw), 12.0 + 0.5 * arm * std::sin(yaw), 0.5 * arm, 0.3, yaw});
  }
  // Rows of rods from edge to edge, heading roughly along +x; the first and last rows meet across
  // the periodic edge.
  for (int i = 0; i < 24; ++i) {
    const double x = 1.5 + 5.0 * (i % 4);
    const double y = 1.0 + 4.0 * (i / 4);
    if (x > 9.0 && std::abs(y - 12.0) < 5.0) continue;  // the trap's arms
    model.rods.push_back({0, x, y, 0.15 * (i % 5) - 0.3});
  }
  // Two rods in the trap, heading for its apex.
  model.rods.push_back({0, 16.5, 12.0, 3.14});
  model.rods.push_back({0, 20.5, 12.2, 3.0});
  return model;
}

TEST_CASE("a restored world steps on exactly as the world it was saved from", "[state]") {
  Simulation original(trap_model());
  original.advance(1500);  // rods landed and pushing on the walls
  // Saved at a step when rods touch a plate and a wall, so that those contacts are in the test.
  const auto touches = [](const State& state, bool wall) {
    return std::any_of(state.contacts.begin(), state.contacts.end(),
                       [&](const SurfaceContactState& c) { return (c.surface >= 2) == wall; });
  };
  State current = original.state();
  for (int extra = 0; extra < 2000 && !(touches(current, false) && touches(current, true));
       ++extra) {
    original.step();
    current = original.state();
  }
  REQUIRE(touches(current, false));
  REQUIRE(touches(current, true));
  std::stringstream bytes;
  write_state(bytes, current);
  const State saved = read_state(bytes);

  Simulation restored(trap_model());
  restored.restore(saved);
  CHECK(hash_state(restored.state()) == hash_state(saved));
  // Compared every 500 steps over 4000 (0.4 s, some 20 drive periods).
  for (int block = 0; block < 8; ++block) {
    original.advance(500);
    restored.advance(500);
    REQUIRE(hash_state(restored.state()) == hash_state(original.state()));
  }
  CHECK(restored.counters().kicks > 0);
}

TEST_CASE("the state of the trap system after 3000 steps is pinned", "[determinism]") {
  // Walls, periodic images and both noises. Regenerate on purpose only, when the physics changes.
  Simulation sim(trap_model());
  sim.advance(3000);
  CHECK(hash_state(sim.state()) == 0xf1b079f8c56c7cdbULL);
}

TEST_CASE("a world restored from its own state steps on unchanged", "[state]") {
  Simulation a(small_model());
  Simulation b(small_model());
  a.advance(700);
  b.advance(700);
  a.restore(a.state());
  a.advance(800);
  b.advance(800);
  CHECK(hash_state(a.state()) == hash_state(b.state()));
  CHECK(a.time() == Approx(0.15).epsilon(1e-12));
}

TEST_CASE("a state that cannot be restored is refused before the world is touched", "[state]") {
  Simulation sim(small_model());
  sim.advance(200);
  const State good = sim.state();
  State fewer = good;
  fewer.rods.pop_back();
  CHECK_THROWS_WITH(sim.restore(fewer),
                    Catch::Contains("the state has") && Catch::Contains("rods, the model"));
  State not_finite = good;
  not_finite.rods[3].position[1] = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(sim.restore(not_finite), Catch::Contains("rod 3 of the state: position"));
  State sheared = good;
  sheared.rods[2].basis[1] += 0.01;
  CHECK_THROWS_WITH(sim.restore(sheared), Catch::Contains("rod 2 of the state: its frame"));
  // The simulation is as it was: it steps on exactly like an untouched copy.
  Simulation twin(small_model());
  twin.advance(200);
  sim.advance(300);
  twin.advance(300);
  CHECK(hash_state(sim.state()) == hash_state(twin.state()));
}

namespace {

/// Steps `model` as it is and with Model::test_every_pair, 500 steps at a time for `blocks`
/// blocks, and requires every bit of the two states to agree after each; returns how many tests
/// the first run skipped.
std::int64_t skips_that_change_nothing(const Model& model, int blocks) {
  Simulation skipping(model);
  Model every_pair_model = model;
  every_pair_model.test_every_pair = true;
  Simulation every_pair(every_pair_model);
  for (int block = 0; block < blocks; ++block) {
    skipping.advance(500);
    every_pair.advance(500);
    REQUIRE(hash_state(skipping.state()) == hash_state(every_pair.state()));
  }
  CHECK(every_pair.counters().pair_tests_skipped == 0);
  return skipping.counters().pair_tests_skipped;
}

}  // namespace

TEST_CASE("rod-wall and rod-rod tests skipped while apart change nothing, with walls and images",
          "[determinism]") {
  // 0.3 s: rods reach the walls and push on them.
  CHECK(skips_that_change_nothing(trap_model(), 6) > 1000);
}

TEST_CASE("rod pairs skipped while apart change nothing in a dense system", "[determinism]") {
  // 0.2 s of rows running head-on into each other, across the periodic edges. The skips happened:
  // 29,300 of them here (in a filled trap, ~1,380 per step: docs/performance.md).
  CHECK(skips_that_change_nothing(testing::dense_paper_model(), 4) > 10000);
}
