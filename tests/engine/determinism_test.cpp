#include <catch2/catch.hpp>
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
  CHECK(hash_state(sim.state()) == 0xe6ef67c7bb362ef2ULL);
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

TEST_CASE("restoring a state rebuilds the same world", "[state]") {
  Simulation a(small_model());
  a.advance(700);
  const State checkpoint = a.state();
  a.restore(checkpoint);  // a rebuilt world continues exactly like a fresh one given the state
  Simulation b(small_model());
  b.restore(checkpoint);
  CHECK(hash_state(b.state()) == hash_state(checkpoint));
  a.advance(800);
  b.advance(800);
  CHECK(hash_state(a.state()) == hash_state(b.state()));
  CHECK(b.time() == Approx(0.15).epsilon(1e-12));
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
