// Rod A's single-rod figures against their reference (tests/golden/reference.yaml, made by
// scripts/single-rod-reference from rods the test does not use): the speed, the rotational
// diffusion, the collision rate and the restitution on the base of the default model, each within
// three standard errors of the difference, so that a change of the physics shows here even when it
// is a few percent (a few tenths of a percent for the restitution).
#include <yaml-cpp/yaml.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <string>

#include "bench/accuracy.hpp"

namespace {

struct Reference {
  double mean = 0.0;
  double standard_error = 0.0;
};

std::map<std::string, Reference> read_reference() {
  const YAML::Node section =
      YAML::LoadFile(RODSORT_SOURCE_DIR "/tests/golden/reference.yaml")["single_rod"];
  REQUIRE(section.IsMap());
  std::map<std::string, Reference> values;
  for (const auto& entry : section) {
    values[entry.first.as<std::string>()] = {entry.second["mean"].as<double>(),
                                             entry.second["standard_error"].as<double>()};
  }
  return values;
}

void check_against(const char* name, double measured, double measured_error,
                   const Reference& reference) {
  const double tolerance = 3.0 * std::hypot(measured_error, reference.standard_error);
  INFO(name << ": " << measured << " +- " << measured_error << ", reference " << reference.mean
            << " +- " << reference.standard_error << " (tolerance " << tolerance << ")");
  CHECK(std::abs(measured - reference.mean) <= tolerance);
}

}  // namespace

TEST_CASE("rod A moves and turns as its reference says", "[bench][physics][reference]") {
  const auto reference = read_reference();
  REQUIRE(reference.count("v0_mm_s") == 1);
  REQUIRE(reference.count("Dr_rad2_s") == 1);
  REQUIRE(reference.count("events_per_s") == 1);
  REQUIRE(reference.count("restitution_base") == 1);
  rodsort::bench::AccuracyOptions options;
  options.rods = 12;
  options.seconds = 20.0;
  options.cost_time = 0.0;
  options.seed = 1;  // the reference's rods start at seed 101
  const rodsort::bench::AccuracyResult result = rodsort::bench::measure_accuracy(1.0e-4, options);
  check_against("v0 [mm/s]", result.speed, result.speed_error, reference.at("v0_mm_s"));
  check_against("D_r [rad^2/s]", result.diffusion, result.diffusion_error,
                reference.at("Dr_rad2_s"));
  check_against("collisions per s", result.events_per_second, result.events_error,
                reference.at("events_per_s"));
  check_against("restitution on the base", result.restitution, result.restitution_error,
                reference.at("restitution_base"));
}
