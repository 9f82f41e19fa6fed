#include "scenarios/sweep.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace rodsort::scenarios;

namespace {

/// A folder of its own under the build tree, emptied for each test.
fs::path scratch(const std::string& name) {
  const fs::path folder = fs::path(RODSORT_BINARY_DIR) / "test-scratch" / "sweep" / name;
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

void write(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

}  // namespace

TEST_CASE("a sweep expands to every combination of its axes", "[sweep]") {
  const fs::path folder = scratch("grid");
  write(folder / "base.yaml", "name: base\ntrap: {angle: 120}\nrun: {duration: 1}\n");
  write(folder / "angles.yaml",
        "base: base.yaml\n"
        "grid:\n"
        "  - trap.angle: {from: 100, to: 130, step: 10}\n"
        "  - species[0].noise.kick_eps: [0.005, 0.01]\n"
        "  - seed: [1, 2, 3]\n");
  const SweepLoadResult result = load_sweep(folder / "angles.yaml");
  INFO(format_diagnostics(result.diagnostics));
  REQUIRE(result.ok());
  const Sweep& sweep = *result.sweep;
  CHECK(sweep.name == "angles");
  CHECK(sweep.keys == std::vector<std::string>{"trap.angle", "species[0].noise.kick_eps", "seed"});
  REQUIRE(sweep.points.size() == 4 * 2 * 3);
  CHECK(sweep.points[0].name == "angle-100_kick_eps-0.005_seed-1");
  CHECK(sweep.points[1].name == "angle-100_kick_eps-0.005_seed-2");
  CHECK(sweep.points[23].name == "angle-130_kick_eps-0.01_seed-3");
  CHECK(sweep.points[23].index == 23);
  CHECK(sweep.points[6].overrides[0].value_text() == "110");

  const LoadResult point = load_sweep_point(sweep, sweep.points[23]);
  REQUIRE(point.ok());
  CHECK(point.scenario->name == "base_angle-130_kick_eps-0.01_seed-3");
  CHECK(point.scenario->spec.trap->angle.value == 130.0);
  CHECK(point.scenario->model.species[0].noise.kick_eps == 0.01);
  CHECK(point.scenario->model.seed == 3);
  CHECK(point.scenario->spec.trap->angle.where.to_string() ==
        (folder / "angles.yaml").string() + ":3:17");
}

TEST_CASE("keys of one axis change together, and the base may be inline", "[sweep]") {
  const fs::path folder = scratch("zip");
  write(folder / "sizes.yaml",
        "name: sizes\n"
        "base:\n"
        "  trap: {angle: 125}\n"
        "  run: {duration: 1}\n"
        "grid:\n"
        "  - trap.angle: [125, 135]\n"
        "  - box.size: [86.85, 130.275]\n"
        "    trap.arm_length: [45, 67.5]\n");
  const SweepLoadResult result = load_sweep(folder / "sizes.yaml");
  INFO(format_diagnostics(result.diagnostics));
  REQUIRE(result.ok());
  REQUIRE(result.sweep->points.size() == 4);
  CHECK(result.sweep->points[1].name == "angle-125_size-130.275_arm_length-67.5");
  const LoadResult big = load_sweep_point(*result.sweep, result.sweep->points[3]);
  REQUIRE(big.ok());
  CHECK(big.scenario->model.box_x == 130.275);
  // count auto scales with the trap: 1.5^2 as many rods as in the paper's cell.
  const LoadResult small = load_sweep_point(*result.sweep, result.sweep->points[2]);
  CHECK(static_cast<double>(big.scenario->model.rods.size()) ==
        Approx(2.25 * static_cast<double>(small.scenario->model.rods.size())).epsilon(0.01));
}

TEST_CASE("sweep errors name the sweep file's lines", "[sweep]") {
  const fs::path folder = scratch("errors");
  write(folder / "bad.yaml",
        "base: {trap: {angle: 120}}\n"
        "grid:\n"
        "  - trap.angle: [100, 190]\n"
        "  - box.size: [80, 90]\n"
        "    trap.arm_length: [40]\n"
        "  - seeds: [1]\n");
  const SweepLoadResult result = load_sweep(folder / "bad.yaml");
  CHECK_FALSE(result.ok());
  const std::string text = format_diagnostics(result.diagnostics);
  CHECK_THAT(text,
             Catch::Contains("bad.yaml:5:5: trap.arm_length: has 1 values but box.size has 2"));

  write(folder / "point.yaml",
        "base: {trap: {angle: 120}, run: {duration: 1}}\n"
        "grid:\n"
        "  - trap.angle: [100, 190]\n"
        "  - seeds: [1]\n");
  const std::string points = format_diagnostics(load_sweep(folder / "point.yaml").diagnostics);
  CHECK_THAT(points,
             Catch::Contains("point.yaml:3:23: trap.angle: must be in (0, 180) degrees, got "
                             "190 [point angle-190_seeds-1]"));
  CHECK_THAT(points, Catch::Contains("point.yaml:4:5: seeds: unknown key \"seeds\"; did you mean "
                                     "\"seed\"?"));

  write(folder / "nobase.yaml", "grid: [{trap.angle: [1]}]\nbsae: x.yaml\n");
  const std::string nobase = format_diagnostics(load_sweep(folder / "nobase.yaml").diagnostics);
  CHECK_THAT(nobase, Catch::Contains("bsae: unknown key \"bsae\"; did you mean \"base\"?"));
  CHECK_THAT(nobase, Catch::Contains("base: missing"));
}

TEST_CASE("a sweep's set values apply to every point", "[sweep]") {
  const fs::path folder = scratch("set");
  write(folder / "base.yaml", "name: base\ntrap: {angle: 120}\n");
  write(folder / "long.yaml",
        "base: base.yaml\n"
        "set:\n"
        "  run.duration: 7\n"
        "  species[0].count: 2\n"
        "grid:\n"
        "  - trap.angle: [100, 110]\n");
  const SweepLoadResult result = load_sweep(folder / "long.yaml");
  INFO(format_diagnostics(result.diagnostics));
  REQUIRE(result.ok());
  REQUIRE(result.sweep->points.size() == 2);
  CHECK(result.sweep->points[1].name == "angle-110");
  const LoadResult point = load_sweep_point(*result.sweep, result.sweep->points[1]);
  REQUIRE(point.ok());
  CHECK(point.scenario->run.duration == 7.0);
  CHECK(point.scenario->model.rods.size() == 2);
  CHECK(point.scenario->name == "base_angle-110");
}
