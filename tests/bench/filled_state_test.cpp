#include "bench/filled_state.hpp"

#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>

#include "bench/benchmark.hpp"
#include "bench/standard_system.hpp"
#include "engine/simulation.hpp"
#include "support/temp_directory.hpp"

using namespace rodsort;
using namespace rodsort::bench;

namespace {

/// A fill short enough for a test: 20 steps.
FillOptions short_fill(const std::filesystem::path& directory) {
  FillOptions fill;
  fill.directory = directory;
  fill.fill_time = 20 * fill.dt;
  return fill;
}

}  // namespace

TEST_CASE("a filled state is made once, kept, and read back the same", "[bench]") {
  testing::TempDirectory directory;
  const FillOptions fill = short_fill(directory.path() / "states");
  std::ostringstream first_log;
  const engine::State made = filled_paper_state(fill, first_log);
  CHECK_THAT(first_log.str(), Catch::Contains("filling the trap"));
  CHECK(made.step == 20);
  CHECK(made.rods.size() == 319);
  REQUIRE(std::filesystem::exists(filled_state_path(fill)));
  CHECK_FALSE(std::filesystem::exists(filled_state_path(fill).string() + ".partial"));

  std::ostringstream second_log;
  const engine::State kept = filled_paper_state(fill, second_log);
  CHECK(second_log.str().empty());
  CHECK(engine::hash_state(kept) == engine::hash_state(made));

  // Another seed is another file; a damaged file is made again.
  FillOptions other = fill;
  other.seed = 2;
  CHECK(filled_state_path(other) != filled_state_path(fill));
  std::filesystem::resize_file(filled_state_path(fill), 100);
  std::ostringstream third_log;
  CHECK(engine::hash_state(filled_paper_state(fill, third_log)) == engine::hash_state(made));
  CHECK_THAT(third_log.str(), Catch::Contains("filling the trap"));
}

TEST_CASE("tiles repeat the cell's walls and rods shifted by whole cells", "[bench]") {
  const engine::Model cell = build_model(find_system("319-full"), 1e-4, 1);
  const engine::Model tiled = tile_model(cell, 2);
  CHECK(tiled.box_x == Approx(2 * cell.box_x));
  REQUIRE(tiled.rods.size() == 4 * cell.rods.size());
  REQUIRE(tiled.walls.size() == 4 * cell.walls.size());
  const std::size_t n = cell.rods.size();
  // Tile 2 is one cell along x, tile 1 one cell along y.
  CHECK(tiled.rods[2 * n + 5].x == Approx(cell.rods[5].x + cell.box_x));
  CHECK(tiled.rods[2 * n + 5].y == Approx(cell.rods[5].y));
  CHECK(tiled.rods[n + 5].y == Approx(cell.rods[5].y + cell.box_y));
  CHECK(tiled.walls[3 * cell.walls.size()].center_x == Approx(cell.walls[0].center_x + cell.box_x));
  CHECK_THROWS_AS(tile_model(cell, 0), std::invalid_argument);
}

TEST_CASE("one tile continues the filled run exactly and four tiles step as four copies", "[bench]") {
  testing::TempDirectory directory;
  const FillOptions fill = short_fill(directory.path());
  std::ostringstream log;
  const engine::State filled = filled_paper_state(fill, log);
  const engine::Model cell = build_model(find_system("319-full"), fill.dt, fill.seed);

  // The run that made the state, stepped on, against the state restored into one tile.
  engine::Simulation original(cell);
  original.advance(30);
  engine::Simulation one_tile(build_model(find_system("319-filled"), fill.dt, fill.seed));
  one_tile.restore(tile_state(filled, cell, one_tile.state(), 1));
  one_tile.advance(10);
  CHECK(engine::hash_state(one_tile.state()) == engine::hash_state(original.state()));

  engine::Simulation four(build_model(find_system("319-filled-x4"), fill.dt, fill.seed));
  four.restore(tile_state(filled, cell, four.state(), 2));
  const engine::State start = four.state();
  const std::size_t n = filled.rods.size();
  for (const std::size_t k : {std::size_t{0}, std::size_t{100}, n - 1}) {
    CHECK(start.rods[k].position == filled.rods[k].position);
    CHECK(start.rods[3 * n + k].position[0] == Approx(filled.rods[k].position[0] + cell.box_x));
    CHECK(start.rods[3 * n + k].position[1] == Approx(filled.rods[k].position[1] + cell.box_y));
    CHECK(start.rods[3 * n + k].velocity == filled.rods[k].velocity);
    CHECK(start.rods[3 * n + k].kick_rng != filled.rods[k].kick_rng);
  }
  four.advance(10);  // throws if a rod overlaps a copy or leaves the plates
  CHECK(four.counters().deepest_overlap < 0.05);
  CHECK_THROWS_AS(tile_state(filled, cell, one_tile.state(), 2), std::invalid_argument);
}

TEST_CASE("filled systems are measured from their kept state", "[bench]") {
  testing::TempDirectory directory;
  Options options;
  options.state_directory = directory.path();
  options.fill_time = 20 * options.dt;
  options.simulated_time = 5 * options.dt;
  options.warmup = 0.0;
  std::ostringstream log;
  const Result result = run_system("319-filled-x4", options, log);
  CHECK(result.rods == 4 * 319);
  CHECK(result.steps == 5);
  CHECK(result.cpu_per_simulated > 0.0);
  CHECK_THAT(log.str(), Catch::Contains("filling the trap"));
}
