#include "scenarios/scenario.hpp"

#include <sys/stat.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "engine/rod_shape.hpp"
#include "engine/units.hpp"
#include "trap/cell_wall.hpp"
#include "trap/obstacle.hpp"

using namespace rodsort;
using namespace rodsort::scenarios;

namespace {

Scenario load_ok(const std::string& yaml, const std::vector<std::string>& set = {}) {
  Diagnostics diagnostics;
  std::vector<Override> overrides;
  for (const std::string& option : set) overrides.push_back(*parse_set_option(option, diagnostics));
  LoadResult result = load_scenario_text(yaml, "test.yaml", overrides);
  INFO(format_diagnostics(result.diagnostics));
  REQUIRE(result.ok());
  return std::move(*result.scenario);
}

std::string errors_of(const std::string& yaml, const std::vector<std::string>& set = {}) {
  Diagnostics diagnostics;
  std::vector<Override> overrides;
  for (const std::string& option : set) {
    if (auto parsed = parse_set_option(option, diagnostics)) overrides.push_back(*parsed);
  }
  if (diagnostics.has_errors()) return format_diagnostics(diagnostics.all());
  const LoadResult result = load_scenario_text(yaml, "test.yaml", overrides);
  CHECK_FALSE(result.ok());
  return format_diagnostics(result.diagnostics);
}

/// Every field of two models, exactly.
void check_same_model(const engine::Model& a, const engine::Model& b) {
  CHECK(a.box_x == b.box_x);
  CHECK(a.box_y == b.box_y);
  CHECK(a.drive.frequency == b.drive.frequency);
  CHECK(a.drive.amplitude == b.drive.amplitude);
  CHECK(a.drive.gap == b.drive.gap);
  CHECK(a.roughness.base_slope == b.roughness.base_slope);
  CHECK(a.roughness.lid_slope == b.roughness.lid_slope);
  CHECK(a.roughness.wavelength == b.roughness.wavelength);
  CHECK(a.dt == b.dt);
  CHECK(a.seed == b.seed);
  CHECK(a.solver_iterations == b.solver_iterations);
  CHECK(a.full_turn_correction == b.full_turn_correction);
  CHECK(a.exact_contact_solver == b.exact_contact_solver);
  CHECK(a.constraint_force_mixing == b.constraint_force_mixing);
  REQUIRE(a.species.size() == b.species.size());
  for (std::size_t i = 0; i < a.species.size(); ++i) {
    const engine::Species& s = a.species[i];
    const engine::Species& t = b.species[i];
    CHECK(s.name == t.name);
    CHECK(s.material == t.material);
    CHECK(s.noise.kick_eps == t.noise.kick_eps);
    CHECK(s.noise.white_Dr == t.noise.white_Dr);
    CHECK(s.shape.mass == t.shape.mass);
    CHECK(s.shape.inertia_transverse == t.shape.inertia_transverse);
    REQUIRE(s.shape.spheres.size() == t.shape.spheres.size());
    for (std::size_t k = 0; k < s.shape.spheres.size(); ++k) {
      CHECK(s.shape.spheres[k].axial == t.shape.spheres[k].axial);
      CHECK(s.shape.spheres[k].radius == t.shape.spheres[k].radius);
      CHECK(s.shape.spheres[k].lateral == t.shape.spheres[k].lateral);
    }
  }
  REQUIRE(a.rods.size() == b.rods.size());
  for (std::size_t i = 0; i < a.rods.size(); ++i) {
    CHECK(a.rods[i].species == b.rods[i].species);
    CHECK(a.rods[i].x == b.rods[i].x);
    CHECK(a.rods[i].y == b.rods[i].y);
    CHECK(a.rods[i].heading == b.rods[i].heading);
  }
  REQUIRE(a.walls.size() == b.walls.size());
  for (std::size_t i = 0; i < a.walls.size(); ++i) {
    CHECK(a.walls[i].center_x == b.walls[i].center_x);
    CHECK(a.walls[i].center_y == b.walls[i].center_y);
    CHECK(a.walls[i].half_length == b.walls[i].half_length);
    CHECK(a.walls[i].half_thickness == b.walls[i].half_thickness);
    CHECK(a.walls[i].yaw == b.walls[i].yaw);
  }
  REQUIRE(a.materials.names() == b.materials.names());
  const auto count = static_cast<int>(a.materials.names().size());
  for (int i = 0; i < count; ++i) {
    for (int j = 0; j < count; ++j) {
      CHECK(a.materials.get(i, j).friction == b.materials.get(i, j).friction);
      CHECK(a.materials.get(i, j).restitution == b.materials.get(i, j).restitution);
    }
  }
}

}  // namespace

TEST_CASE("defaults are the paper's values", "[scenario]") {
  const Scenario scenario = load_ok("trap: {angle: 120}\n");
  const engine::Model& model = scenario.model;
  CHECK(scenario.name == "test");
  CHECK(model.box_x == 86.85);
  CHECK(model.box_y == 86.85);
  CHECK(model.drive.frequency == 200.0);
  CHECK(model.drive.gap == 1.2);
  // Gamma = A (2 pi f)^2 / g = 7 at f = 200 Hz.
  CHECK(model.drive.amplitude == Approx(0.0435).epsilon(0.002));
  CHECK(model.drive.gamma() == Approx(7.0).epsilon(1e-12));
  CHECK(model.dt == 1.0e-4);
  REQUIRE(model.species.size() == 1);
  CHECK(model.species[0].name == "A");
  CHECK(model.species[0].noise.kick_eps == 0.01);
  CHECK(model.species[0].noise.white_Dr == 0.0);
  CHECK(model.species[0].shape.length == Approx(4.5));
  CHECK(model.species[0].shape.max_radius == Approx(0.55));

  const double trap_area = 45.0 * 45.0 * std::sin(degrees_to_radians(120.0)) / 2.0;
  CHECK(scenario.trap_area == Approx(trap_area).epsilon(1e-12));
  REQUIRE(scenario.trap != nullptr);
  CHECK(scenario.trap->area() == Approx(trap_area).epsilon(1e-12));
  const double a = model.species[0].shape.projected_area;
  const auto expected = static_cast<std::size_t>(std::llround(1.2 * trap_area / a));
  CHECK(model.rods.size() == expected);
  CHECK(scenario.species[0].count == static_cast<int>(expected));
  CHECK(model.walls.size() == scenario.trap->walls().size());

  const engine::MaterialTable& m = model.materials;
  const int rod = m.index_of("rod");
  CHECK(m.get(rod, rod).friction == 0.05);
  CHECK(m.get(rod, rod).restitution == 0.3);
  CHECK(m.get(rod, engine::MaterialTable::kBase).restitution == 0.1);
  CHECK(m.get(rod, engine::MaterialTable::kLid).friction == 0.01);
  CHECK(m.get(rod, engine::MaterialTable::kWall).restitution == 0.65);

  CHECK(scenario.run.duration == 300.0);
  CHECK(scenario.run.steps == 3000000);
  CHECK(scenario.output.frame_interval == 0.07);
  CHECK(scenario.output.frame_steps == 700);
  CHECK(scenario.metrics.window == 0.07);
}

TEST_CASE("a mixture counted auto shares r A_t by number fraction", "[scenario]") {
  const Scenario scenario = load_ok(
      "trap: {angle: 70}\n"
      "species:\n"
      "  - {name: A, fraction: 0.4, noise: {kick_eps: 0, white_Dr: 0.1}}\n"
      "  - {name: RnT, shape: {preset: RnT}, fraction: 0.6}\n");
  const double a_A = scenario.model.species[0].shape.projected_area;
  const double a_R = scenario.model.species[1].shape.projected_area;
  const double total = 1.2 * scenario.trap_area / (0.4 * a_A + 0.6 * a_R);
  CHECK(scenario.species[0].count == std::llround(0.4 * total));
  CHECK(scenario.species[1].count == std::llround(0.6 * total));
  CHECK(scenario.model.species[1].shape.length == Approx(3.5));
  CHECK(scenario.model.species[0].noise.white_Dr == 0.1);
  const double covered = scenario.species[0].count * a_A + scenario.species[1].count * a_R;
  CHECK(covered == Approx(1.2 * scenario.trap_area).epsilon(0.01));
}

TEST_CASE("without a trap, count auto takes an area fraction", "[scenario]") {
  const Scenario scenario = load_ok("trap: none\npopulation: {area_fraction: 0.1}\n");
  CHECK(scenario.trap == nullptr);
  CHECK(scenario.model.walls.empty());
  const double a = scenario.model.species[0].shape.projected_area;
  CHECK(static_cast<long>(scenario.model.rods.size()) == std::lround(0.1 * 86.85 * 86.85 / a));
}

TEST_CASE("overrides given with --set apply before the checks", "[scenario][override]") {
  const std::string base = "name: base\ntrap: {angle: 120}\n";
  SECTION("a value, a new section, and an item of the default species list") {
    const Scenario scenario =
        load_ok(base, {"trap.angle=70", "run.duration=5", "species[0].noise.kick_eps=0.02",
                       "box.size=[100, 90]"});
    CHECK(scenario.spec.trap->angle.value == 70.0);
    CHECK(scenario.run.duration == 5.0);
    CHECK(scenario.model.species[0].noise.kick_eps == 0.02);
    CHECK(scenario.model.box_x == 100.0);
    CHECK(scenario.model.box_y == 90.0);
    CHECK(scenario.spec.trap->angle.where.source == "--set trap.angle=70");
  }
  SECTION("null restores the default; a section replaces `none`") {
    const Scenario scenario = load_ok("trap: none\nspecies: [{count: 10}]\ndrive: {gap: 1.3}\n",
                                      {"drive.gap=null", "trap.angle=100"});
    CHECK(scenario.model.drive.gap == 1.2);
    REQUIRE(scenario.trap != nullptr);
    CHECK(scenario.trap->area() == Approx(0.5 * 45 * 45 * std::sin(degrees_to_radians(100))));
  }
  SECTION("errors name the option") {
    const std::string errors = errors_of(base, {"trap.angle=190"});
    CHECK_THAT(
        errors,
        Catch::Contains("--set trap.angle=190: trap.angle: must be in (0, 180) degrees, got 190"));
  }
  SECTION("an unknown key in an option gets a suggestion") {
    const std::string errors = errors_of(base, {"trap.angel=100"});
    CHECK_THAT(errors, Catch::Contains("--set trap.angel=100: trap.angel: unknown key \"angel\"; "
                                       "did you mean \"angle\"?"));
  }
  SECTION("malformed options and paths") {
    CHECK_THAT(errors_of(base, {"trap.angle"}), Catch::Contains("expected key.path=value"));
    CHECK_THAT(errors_of(base, {"species[x].count=3"}), Catch::Contains("malformed key path"));
    CHECK_THAT(errors_of(base, {"species[3].count=3"}),
               Catch::Contains("species has 1 items; the index may be at most 1"));
    CHECK_THAT(errors_of(base, {"run[0]=3"}), Catch::Contains("run is not a list"));
  }
}

TEST_CASE("the resolved scenario reads back to the same model", "[scenario][resolved]") {
  const std::string yaml =
      "name: roundtrip\n"
      "seed: 7\n"
      "drive: {amplitude: 0.05}\n"
      "roughness: {base_slope: 0.04, wavelength: 0.3}\n"
      "trap: {angle: 75, direction: 30, wall_thickness: 0.7}\n"
      "species:\n"
      "  - {name: A, fraction: 0.5, noise: {white_Dr: 0.3}}\n"
      "  - {name: B, shape: {taper: {length: 4, thick_radius: 0.5, thin_radius: 0.25}},\n"
      "     material: steel, fraction: 0.5}\n"
      "  - {name: C, shape: {spheres: [[0, 0.5], [0.6, 0.45], [1.2, 0.4], [1.8, 0.3]]},\n"
      "     count: 3, initial: {region: inside_trap, heading: toward_apex}}\n"
      "  - {name: D, shape: {preset: RnT, thin_radius: 0.25, step: 2.2, bend: 0.05,\n"
      "     bend_form: s}, count: 4, initial: {region: outside_trap, heading: 45}}\n"
      "  - {name: E, shape: {stepped: {length: 4.5, radii: [0.55, 0.4, 0.25], steps: [1.5, 3]}},\n"
      "     count: 2}\n"
      "  - {name: F, shape: {spheres: [[0, 0.5, 0.02], [0.6, 0.45], [1.2, 0.4, -0.03]]},\n"
      "     count: 2}\n"
      "materials:\n"
      "  steel-wall: {restitution: 0.5}\n"
      "  rod-steel: {friction: 0.2}\n"
      "run: {duration: 2, dt: 5.0e-5, turn_correction: full, contact_solver: exact}\n"
      "output: {bullet_snapshots: [1, 0.5], frame_interval: 0.05}\n"
      "metrics: {window: 0.1, stationary_threshold: 0.5}\n";
  const Scenario first = load_ok(yaml);
  const std::string resolved = resolved_yaml(first);
  INFO(resolved);
  const Scenario second = load_ok(resolved);
  check_same_model(first.model, second.model);
  CHECK(resolved_yaml(second) == resolved);
  CHECK(second.name == "roundtrip");
  CHECK(second.run.steps == first.run.steps);
  CHECK(second.output.snapshot_steps == std::vector<std::int64_t>{10000, 20000});
  CHECK(second.metrics.stationary_threshold == 0.5);
  const int steel = second.model.materials.index_of("steel");
  CHECK(second.model.materials.get(steel, engine::MaterialTable::kWall).restitution == 0.5);
  CHECK(second.model.materials.get(steel, second.model.materials.index_of("rod")).friction == 0.2);
  CHECK_THAT(resolved, Catch::Contains("derived:"));
  CHECK_THAT(resolved, Catch::Contains("gamma:"));
  // Offsets are written where a sphere has one, left out where it is 0.
  CHECK_THAT(resolved, Catch::Contains("- [0, 0.5, 0.02]\n"));
  CHECK_THAT(resolved, Catch::Contains("- [0.6, 0.45]\n"));
  CHECK_THAT(resolved, Catch::Contains("- [1.2, 0.4, -0.03]\n"));
}

TEST_CASE("a stepped rod of one step is the RnT preset", "[scenario]") {
  const Scenario scenario = load_ok(
      "species:\n"
      "  - {name: S, shape: {stepped: {length: 3.5, radii: [0.55, 0.3], steps: [1.75]}}, count: "
      "1}\n"
      "  - {name: RnT, shape: {preset: RnT}, count: 1}\n");
  const auto& stepped = scenario.model.species[0].shape;
  const auto& preset = scenario.model.species[1].shape;
  REQUIRE(stepped.spheres.size() == preset.spheres.size());
  for (std::size_t k = 0; k < preset.spheres.size(); ++k) {
    CHECK(stepped.spheres[k].axial == preset.spheres[k].axial);
    CHECK(stepped.spheres[k].radius == preset.spheres[k].radius);
  }
  CHECK(stepped.mass == preset.mass);
  CHECK(stepped.inertia_transverse == preset.inertia_transverse);
  // A stepped rod needs its radii, the right number of steps, and room in every section.
  CHECK_THAT(errors_of("species: [{shape: {stepped: {length: 4.5, radii: [0.55, 0.4]}}}]\n"),
             Catch::Contains("species[0].shape.stepped.steps: expected 1 step, one fewer than "
                             "the 2 radii, got 0"));
  CHECK_THAT(errors_of("species: [{shape: {stepped: {length: 4.5, radii: [0.55], steps: []}, "
                       "preset: A}}]\n"),
             Catch::Contains("give one of preset, taper, stepped or spheres, not several"));
}

TEST_CASE("the RnT step is checked against the thin radius and applies to RnT only", "[scenario]") {
  const std::string rnt =
      "species: [{shape: {preset: RnT, thin_radius: 0.3, step: 3.3}, count: 3}]\n";
  CHECK_THAT(
      errors_of(rnt),
      Catch::Contains("test.yaml:1:57: species[0].shape.step: must be "
                      "from 1.011 mm to 3.2 mm with thick_radius 0.55 mm and thin_radius 0.3 mm"));
  CHECK_THAT(errors_of(rnt, {"species[0].shape.step=1"}),
             Catch::Contains("species[0].shape.step: must be from 1.011 mm"));
  load_ok("species: [{shape: {preset: RnT, thin_radius: 0.3, step: 3.2}, count: 3}]\n");
  CHECK_THAT(errors_of("species: [{shape: {preset: A, step: 2}}]\n"),
             Catch::Contains("species[0].shape.step: applies to `preset: RnT` only"));
  const Scenario mid = load_ok("species: [{shape: {preset: RnT}, count: 3}]\n");
  CHECK_THAT(resolved_yaml(mid), Catch::Contains("step: 1.75"));
  CHECK_THAT(resolved_yaml(mid), Catch::Contains("thick_radius: 0.55"));
}

TEST_CASE("the RnT thick radius sets the thick part and bounds the thin one and the step",
          "[scenario]") {
  const std::string rnt = "species: [{shape: {preset: RnT, thick_radius: 0.5}, count: 3}]\n";
  const Scenario thinner = load_ok(rnt + "run: {dt: 1.25e-5}\n");
  const Scenario preset = load_ok("species: [{shape: {preset: RnT}, count: 3}]\n");
  // The thick spheres shrink, the thin ones stay; so the rod is lighter and the same length.
  const engine::RodShape& changed = thinner.model.species[0].shape;
  const engine::RodShape& kept = preset.model.species[0].shape;
  CHECK(changed.mass < kept.mass);
  CHECK(changed.length == Approx(kept.length).epsilon(1e-12));
  double widest = 0.0;
  for (const engine::Sphere& sphere : changed.spheres) widest = std::max(widest, sphere.radius);
  CHECK(widest == 0.5);
  CHECK_THAT(resolved_yaml(thinner), Catch::Contains("thick_radius: 0.5"));
  CHECK_THAT(errors_of("species: [{shape: {preset: RnT, thick_radius: 0.25}, count: 3}]\n"),
             Catch::Contains("species[0].shape.thin_radius: must be <= thick_radius (0.25 mm), "
                             "got 0.3 mm"));
  CHECK_THAT(errors_of("species: [{shape: {preset: RnT, thick_radius: 1.7}, count: 3}]\n"),
             Catch::Contains("species[0].shape.thick_radius: 1.7 mm leaves no room for a step"));
  const std::string early =
      errors_of("species: [{shape: {preset: RnT, thick_radius: 0.5, step: 0.8}}]\n");
  CHECK_THAT(early, Catch::Contains("species[0].shape.step: must be from 0.9"));
  CHECK_THAT(early, Catch::Contains("with thick_radius 0.5 mm and thin_radius 0.3 mm"));
  CHECK_THAT(errors_of("species: [{shape: {preset: A, thick_radius: 0.5}}]\n"),
             Catch::Contains("species[0].shape.thick_radius: applies to `preset: RnT` only"));
}

TEST_CASE("the resolved paper scenario states the derived values", "[scenario][resolved]") {
  const Scenario scenario = load_ok("trap: {angle: 120}\n");
  const std::string resolved = resolved_yaml(scenario);
  CHECK_THAT(resolved, Catch::Contains("count: " + std::to_string(scenario.model.rods.size())));
  CHECK_THAT(resolved, Catch::Contains("amplitude: 0.0434"));
  CHECK_THAT(resolved, Catch::Contains("trap_area: 876.8"));
  CHECK_THAT(resolved, Catch::Contains("count: auto"));
  check_same_model(scenario.model, load_ok(resolved).model);
}

TEST_CASE("intervals that are not a multiple of dt are warned about", "[scenario]") {
  const LoadResult result =
      load_scenario_text("trap: {angle: 120}\noutput: {frame_interval: 0.06996}\n", "w.yaml");
  REQUIRE(result.ok());
  REQUIRE(result.diagnostics.size() == 1);
  CHECK(result.diagnostics[0].severity == Severity::warning);
  CHECK_THAT(result.diagnostics[0].to_string(),
             Catch::Contains("w.yaml:2:26: warning: output.frame_interval: 0.06996 s is not a "
                             "multiple of run.dt = 1e-4 s; using 700 steps (0.07 s)"));
  CHECK(result.scenario->output.frame_steps == 700);
}

TEST_CASE("RnT rods with the collision kick at a large dt are warned about", "[scenario]") {
  const std::string species =
      "species: [{name: RnT, shape: {preset: RnT}, count: 10, noise: {kick_eps: 0.01}}]\n";
  const LoadResult coarse = load_scenario_text(species, "k.yaml");
  REQUIRE(coarse.ok());
  REQUIRE(coarse.diagnostics.size() == 1);
  CHECK(coarse.diagnostics[0].severity == Severity::warning);
  CHECK_THAT(coarse.diagnostics[0].to_string(),
             Catch::Contains("k.yaml:1:74: warning: species[0].noise.kick_eps: the collision "
                             "kick's rotational diffusion of RnT rods has not converged at "
                             "run.dt = 1e-4 s"));
  CHECK(load_scenario_text(species + "run: {dt: 2.5e-5}\n", "k.yaml").diagnostics.empty());
  // White noise instead of the kick, or rod A with the kick, is converged at the default dt.
  const std::string white =
      "species: [{name: RnT, shape: {preset: RnT}, count: 10, noise: {kick_eps: 0, white_Dr: "
      "1}}]\n";
  CHECK(load_scenario_text(white, "k.yaml").diagnostics.empty());
  CHECK(load_scenario_text("species: [{name: A, count: 10}]\n", "k.yaml").diagnostics.empty());
}

TEST_CASE("RnT outlines whose gait changes with dt are warned about at a large dt", "[scenario]") {
  const auto rnt = [](const std::string& shape) {
    return "species: [{name: R, shape: {preset: RnT" + shape +
           "}, count: 10, noise: {kick_eps: 0}}]\n";
  };
  const LoadResult coarse = load_scenario_text(rnt(", thin_radius: 0.4, step: 2.25"), "s.yaml");
  REQUIRE(coarse.ok());
  REQUIRE(coarse.diagnostics.size() == 1);
  CHECK(coarse.diagnostics[0].severity == Severity::warning);
  CHECK_THAT(
      coarse.diagnostics[0].to_string(),
      Catch::Contains("s.yaml:1:66: warning: species[0].shape.step: an RnT outline other than "
                      "the preset's (thick_radius 0.55 mm, thin_radius 0.4 mm, step 2.25 mm) may "
                      "change its gait with run.dt = 1e-4 s and 10 solver sweeps"));
  // Only the thin radius moved, the step left at mid-length: the warning names thin_radius.
  const LoadResult thin = load_scenario_text(rnt(", thin_radius: 0.2"), "s.yaml");
  REQUIRE(thin.diagnostics.size() == 1);
  CHECK_THAT(thin.diagnostics[0].to_string(), Catch::Contains("species[0].shape.thin_radius: "));
  // Only the thick radius: it names thick_radius.
  const LoadResult thick = load_scenario_text(rnt(", thick_radius: 0.5"), "s.yaml");
  REQUIRE(thick.diagnostics.size() == 1);
  CHECK_THAT(thick.diagnostics[0].to_string(),
             Catch::Contains("species[0].shape.thick_radius: an RnT outline other than the "
                             "preset's (thick_radius 0.5 mm, thin_radius 0.3 mm, step 1.75 mm)"));
  // Resolved at 6.25e-6 s with 30 sweeps or the exact solve, and neither at 1.25e-5 s nor with
  // ten sweeps; the preset's own outline, written out or not; a short thick part, which runs
  // steadily at every dt; a long one, which lies level and rattles.
  const std::string shuttling = rnt(", thin_radius: 0.4, step: 2.25");
  CHECK(load_scenario_text(shuttling + "run: {dt: 6.25e-6, solver_iterations: 30}\n", "s.yaml")
            .diagnostics.empty());
  // (the exact solve is warned of for ten rods, as for any crowd, but not for the outline)
  const LoadResult exact =
      load_scenario_text(shuttling + "run: {dt: 6.25e-6, contact_solver: exact}\n", "s.yaml");
  REQUIRE(exact.diagnostics.size() == 1);
  CHECK_THAT(exact.diagnostics[0].to_string(), Catch::Contains("run.contact_solver: exact"));
  CHECK(load_scenario_text(shuttling + "run: {dt: 6.25e-6}\n", "s.yaml").diagnostics.size() == 1);
  CHECK(load_scenario_text(shuttling + "run: {dt: 1.25e-5, solver_iterations: 100}\n", "s.yaml")
            .diagnostics.size() == 1);
  CHECK(load_scenario_text(rnt(""), "s.yaml").diagnostics.empty());
  CHECK(load_scenario_text(rnt(", thick_radius: 0.55, thin_radius: 0.3, step: 1.75"), "s.yaml")
            .diagnostics.empty());
  CHECK(load_scenario_text(rnt(", step: 1.5"), "s.yaml").diagnostics.empty());
  CHECK(load_scenario_text(rnt(", step: 3.0"), "s.yaml").diagnostics.empty());
  CHECK(load_scenario_text(rnt(", step: 2.99"), "s.yaml").diagnostics.size() == 1);
}

TEST_CASE("RnT rods with the turns corrected in full at a large dt are warned about",
          "[scenario]") {
  const std::string rnt =
      "species: [{name: R, shape: {preset: RnT}, count: 10, noise: {kick_eps: 0}}]\n";
  const LoadResult coarse = load_scenario_text(rnt + "run: {turn_correction: full}\n", "g.yaml");
  REQUIRE(coarse.ok());
  REQUIRE(coarse.diagnostics.size() == 1);
  CHECK(coarse.diagnostics[0].severity == Severity::warning);
  CHECK_THAT(coarse.diagnostics[0].to_string(),
             Catch::Contains("g.yaml:2:24: warning: run.turn_correction: full at run.dt = 1e-4 s "
                             "locks RnT rods (R) in a slow glide"));
  // At 1.25e-5 s the RnT runs again; by default (tenth) it runs at every dt; rod A never glides.
  CHECK(load_scenario_text(rnt + "run: {turn_correction: full, dt: 1.25e-5}\n", "g.yaml")
            .diagnostics.empty());
  CHECK(load_scenario_text(rnt, "g.yaml").diagnostics.empty());
  CHECK(load_scenario_text("species: [{name: A, count: 10}]\nrun: {turn_correction: full}\n",
                           "g.yaml")
            .diagnostics.empty());
}

TEST_CASE("run.contact_solver: exact solves lone rods exactly and warns for crowds", "[scenario]") {
  const Scenario sweeps = load_ok("species: [{name: A, count: 1}]\nbox: {size: 30}\n");
  CHECK_FALSE(sweeps.model.exact_contact_solver);
  CHECK(sweeps.model.constraint_force_mixing == 0.0);
  const Scenario exact =
      load_ok("species: [{name: A, count: 1}]\nbox: {size: 30}\nrun: {contact_solver: exact}\n");
  CHECK(exact.model.exact_contact_solver);
  CHECK(exact.model.constraint_force_mixing == engine::kExactSolverCompliance);
  const LoadResult crowd = load_scenario_text(
      "species: [{name: A, count: 9}]\nbox: {size: 30}\nrun: {contact_solver: exact}\n", "c.yaml");
  REQUIRE(crowd.ok());
  REQUIRE(crowd.diagnostics.size() == 1);
  CHECK_THAT(crowd.diagnostics[0].to_string(),
             Catch::Contains("c.yaml:3:23: warning: run.contact_solver: exact solves of 9 rods"));
  CHECK_THAT(errors_of("run: {contact_solver: dantzig}\n"),
             Catch::Contains("run.contact_solver: expected sweeps or exact, got dantzig"));
}

TEST_CASE("a missing file is an error, not an exception", "[scenario]") {
  const LoadResult result = load_scenario("no/such/file.yaml");
  CHECK_FALSE(result.ok());
  CHECK_THAT(format_diagnostics(result.diagnostics),
             Catch::Contains("no/such/file.yaml: cannot open the file"));
}

TEST_CASE("what is not a regular file of bounded size is refused without reading it",
          "[scenario]") {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / "rodsort-scenario-file-kinds";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  const auto message_of = [](const std::filesystem::path& path) {
    const LoadResult result = load_scenario(path);
    CHECK_FALSE(result.ok());
    return format_diagnostics(result.diagnostics);
  };
  CHECK_THAT(message_of(folder), Catch::Contains(": is a directory; expected a YAML file"));
  // A device that never ends, and a pipe that no one writes to, would hang a reader.
  CHECK_THAT(message_of("/dev/zero"), Catch::Contains("/dev/zero: is not a regular file"));
  const std::filesystem::path fifo = folder / "pipe.yaml";
  REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
  CHECK_THAT(message_of(fifo), Catch::Contains("pipe.yaml: is not a regular file"));
  // A file one byte beyond the bound; its content would be valid YAML.
  const std::filesystem::path large = folder / "large.yaml";
  {
    std::ofstream out(large);
    out << "name: large\n" << std::string(16'000'000, '#') << "\n";
  }
  CHECK_THAT(message_of(large), Catch::Contains("large.yaml: larger than 16 MB"));
  std::filesystem::remove_all(folder);
}

TEST_CASE("a bounded cell: the box around it, rods inside, its walls after the trap's",
          "[scenario][cell]") {
  const std::string yaml =
      "cell: {shape: flower, diameter: 80, petals: 12, petal_depth: 4}\n"
      "trap: {angle: 90, arm_length: 30}\n"
      "species: [{name: A, count: 100}]\n";
  const Scenario scenario = load_ok(yaml);
  REQUIRE(scenario.cell);
  const engine::Model& model = scenario.model;
  // 80 mm, two 1 mm walls and a rod's reach (2.6 mm) on each side, rounded up to a whole mm.
  CHECK(model.box_x == 88.0);
  CHECK(model.box_y == 88.0);
  CHECK(scenario.cell->centre() == Eigen::Vector2d(44.0, 44.0));
  CHECK(model.walls.size() == scenario.trap->walls().size() + scenario.cell->walls().size());
  CHECK(model.walls.front().center_x == scenario.trap->walls().front().center_x);
  CHECK(scenario.cell_area == Approx(scenario.cell->area()));
  REQUIRE(model.rods.size() == 100);
  for (const engine::RodInit& rod : model.rods) {
    CHECK(scenario.cell->contains({rod.x, rod.y}));
  }
  // The trap is centred in the cell: its apex and the middle of its opening lie on either side.
  const auto triangle = scenario.trap->outline();
  const Eigen::Vector2d middle =
      0.5 * (triangle[0] + 0.5 * (triangle[1] + triangle[2])) - scenario.cell->centre();
  CHECK(middle.norm() < 1e-9);

  const std::string resolved = resolved_yaml(scenario);
  INFO(resolved);
  CHECK_THAT(resolved, Catch::Contains("cell:\n  shape: flower\n  diameter: 80\n  petals: 12\n"
                                       "  petal_depth: 4\n  wall_thickness: 1\n"));
  const Scenario second = load_ok(resolved);
  check_same_model(model, second.model);
  CHECK(resolved_yaml(second) == resolved);

  // count: auto and area_fraction take the area inside the wall, not the box's.
  const Scenario by_fraction = load_ok(
      "cell: {shape: circle, diameter: 60}\ntrap: none\npopulation: {area_fraction: 0.1}\n");
  CHECK(by_fraction.cell_area == Approx(kPi * 30.0 * 30.0).epsilon(1e-3));
  CHECK(static_cast<double>(by_fraction.model.rods.size()) ==
        Approx(0.1 * by_fraction.cell_area / by_fraction.species[0].projected_area).margin(0.5));
}

TEST_CASE("a circle warns about a flower's keys, which a sweep over the shape may leave",
          "[scenario][cell]") {
  const LoadResult result =
      load_scenario_text("cell: {shape: circle, petals: 10}\ntrap: {angle: 100}\n", "test.yaml");
  REQUIRE(result.ok());
  CHECK_THAT(format_diagnostics(result.diagnostics),
             Catch::Contains("cell.petals: ignored: it is only for a flower wall"));
  CHECK(result.scenario->cell->petals() == 0);
  CHECK_THAT(errors_of("cell: {shape: circle, diameter: 30}\ntrap: {angle: 100}\n"),
             Catch::Contains("reaches outside the circular cell 30 mm across"));
}

TEST_CASE("output.rods_format chooses rods.csv, rods.h5 or both", "[scenario][output]") {
  const Scenario plain = load_ok("trap: {angle: 100}\n");
  CHECK(plain.output.rods_csv);
  CHECK_FALSE(plain.output.rods_h5md);
  const Scenario h5md =
      load_ok("trap: {angle: 100}\noutput: {rods_format: h5md, h5md_precision: double}\n");
  CHECK_FALSE(h5md.output.rods_csv);
  CHECK(h5md.output.rods_h5md);
  CHECK(h5md.output.h5md_double);
  CHECK_THAT(resolved_yaml(h5md), Catch::Contains("rods_format: h5md\n  h5md_precision: double\n"));
  const Scenario both = load_ok("trap: {angle: 100}\noutput: {rods_format: both}\n");
  CHECK(both.output.rods_csv);
  CHECK(both.output.rods_h5md);
  CHECK_FALSE(both.output.h5md_double);

  CHECK_THAT(errors_of("trap: {angle: 100}\noutput: {rods_format: hdf5}\n"),
             Catch::Contains("output.rods_format") && Catch::Contains("h5md"));
  const LoadResult ignored =
      load_scenario_text("trap: {angle: 100}\noutput: {h5md_precision: double}\n", "test.yaml");
  REQUIRE(ignored.ok());
  CHECK_THAT(format_diagnostics(ignored.diagnostics),
             Catch::Contains("output.h5md_precision: ignored: it is only for rods.h5"));
  // A resolved scenario names the default precision whatever the format; read back for a run
  // that writes rods.csv (every sweep point, every resume) it warns of nothing.
  const Scenario csv = load_ok("trap: {angle: 100}\n");
  REQUIRE_THAT(resolved_yaml(csv), Catch::Contains("h5md_precision: single\n"));
  const LoadResult reread = load_scenario_text(resolved_yaml(csv), "scenario.resolved.yaml");
  REQUIRE(reread.ok());
  CHECK(reread.diagnostics.empty());
}

TEST_CASE("an RnT whose thin part lies off its axis, or bent, is warned about at a large dt",
          "[scenario]") {
  const auto rnt = [](const std::string& shape, const std::string& run) {
    return "species: [{name: R, shape: {preset: RnT" + shape +
           "}, count: 10, noise: {kick_eps: 0}}]\n" + run;
  };
  const LoadResult coarse = load_scenario_text(rnt(", thin_offset: 0.05", ""), "o.yaml");
  REQUIRE(coarse.ok());
  REQUIRE(coarse.diagnostics.size() == 1);
  CHECK(coarse.diagnostics[0].severity == Severity::warning);
  CHECK_THAT(coarse.diagnostics[0].to_string(),
             Catch::Contains("o.yaml:1:55: warning: species[0].shape.thin_offset: an RnT whose "
                             "thin part lies off its axis may change its gait with run.dt = "
                             "1e-4 s"));
  // At the smallest step studied, or with the thin part on the axis, nothing is said.
  CHECK(load_scenario_text(rnt(", thin_offset: 0.05", "run: {dt: 1.25e-5}\n"), "o.yaml")
            .diagnostics.empty());
  CHECK(load_scenario_text(rnt(", thin_offset: 0", ""), "o.yaml").diagnostics.empty());
  // So is a bent one.
  const LoadResult bent = load_scenario_text(rnt(", bend: 0.1, bend_form: s", ""), "b.yaml");
  REQUIRE(bent.ok());
  REQUIRE(bent.diagnostics.size() == 1);
  CHECK_THAT(bent.diagnostics[0].to_string(),
             Catch::Contains("b.yaml:1:48: warning: species[0].shape.bend: a bent RnT may change "
                             "its gait with run.dt = 1e-4 s"));
  CHECK(
      load_scenario_text(rnt(", bend: 0.1", "run: {dt: 1.25e-5}\n"), "b.yaml").diagnostics.empty());
  CHECK(load_scenario_text(rnt(", bend: 0", ""), "b.yaml").diagnostics.empty());
}

TEST_CASE("restitutions of base and lid both above 0.65 are warned about at a large dt",
          "[scenario]") {
  const std::string rods = "species: [{name: A, count: 10}]\n";
  const auto lively = [&](const std::string& base, const std::string& lid, const std::string& run) {
    return rods + "materials:\n  rod-base: {restitution: " + base +
           "}\n  rod-lid: {restitution: " + lid + "}\n" + run;
  };
  const LoadResult coarse = load_scenario_text(lively("0.8", "0.7", ""), "e.yaml");
  REQUIRE(coarse.ok());
  REQUIRE(coarse.diagnostics.size() == 1);
  CHECK(coarse.diagnostics[0].severity == Severity::warning);
  // Named at the last plate pair given, the lid's.
  CHECK_THAT(coarse.diagnostics[0].to_string(),
             Catch::Contains("e.yaml:4:26: warning: materials.rod-lid.restitution: restitutions "
                             "of 0.8 with the base and 0.7 with the lid (rod material rod) make "
                             "rods rattle between the plates, and their gait changes with "
                             "run.dt = 1e-4 s"));
  // At 1.25e-5 s, at 0.65, or with one plate alone lively, nothing is said.
  CHECK(load_scenario_text(lively("0.8", "0.7", "run: {dt: 1.25e-5}\n"), "e.yaml")
            .diagnostics.empty());
  CHECK(load_scenario_text(lively("0.65", "0.65", ""), "e.yaml").diagnostics.empty());
  CHECK(load_scenario_text(lively("0.9", "0.1", ""), "e.yaml").diagnostics.empty());
  CHECK(load_scenario_text(lively("0.1", "0.9", ""), "e.yaml").diagnostics.empty());
}

TEST_CASE("explicit spheres carry their offsets from the axis into the rod", "[scenario]") {
  // The RnT preset with its thin part off the axis, written out sphere by sphere, is that rod.
  const engine::RodProfile profile = engine::preset_rnt_profile(0.3, 1.75, 0.55, 0.05);
  std::string list;
  char number[96];
  for (const engine::Sphere& sphere : profile.spheres) {
    std::snprintf(number, sizeof number, "[%.17g, %.17g, %.17g]", sphere.axial, sphere.radius,
                  sphere.lateral);
    list += (list.empty() ? "" : ", ") + std::string(number);
  }
  const Scenario preset = load_ok(
      "species: [{name: R, shape: {preset: RnT, thin_offset: 0.05}, count: 2}]\n"
      "run: {dt: 1.25e-5}\n");
  const Scenario spheres =
      load_ok("species: [{name: R, shape: {spheres: [" + list + "]}, count: 2}]\n");
  const engine::RodShape& a = preset.model.species[0].shape;
  const engine::RodShape& b = spheres.model.species[0].shape;
  CHECK(b.mass == a.mass);
  CHECK(b.inertia_axial == a.inertia_axial);
  CHECK(b.inertia_normal == a.inertia_normal);
  CHECK(b.axis_lean == a.axis_lean);
  CHECK(b.axis_lean > 0.02);  // the offset of 0.05 mm leans the axis (docs/model.md)
  CHECK(b.max_lateral == a.max_lateral);
  // Left out, the offset is 0: the same list without it is the straight preset.
  const Scenario straight = load_ok(
      "species: [{name: R, shape: {spheres: [[0, 0.55], [1, 0.55, 0], [2, 0.3]]}, count: 2}]\n");
  CHECK(engine::is_straight(straight.model.species[0].shape.spheres));
}
