// libFuzzer target: scenario text, as a user or a mutated file would give it, through the whole
// reading path (YAML, --set overrides, schema, compile, placement) and, when it is accepted, a few
// steps of the engine. What counts as a finding:
//   - a crash, an exception, a sanitizer report, a hang or runaway memory (libFuzzer's own checks);
//   - an accepted scenario that is absurd: a model that is not finite, or a run that the engine
//     stops because a rod left the space between base and lid.
// Lines of the input that start with "--set " are --set options, applied to the rest.
//
// Built and run by scripts/fuzz (clang, -DRODSORT_FUZZ=ON); README, "Tests, sanitizers and the
// fuzzer".

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "engine/simulation.hpp"
#include "scenarios/override.hpp"
#include "scenarios/scenario.hpp"

namespace {

using namespace rodsort;

/// The engine is stepped only for systems this small: enough to meet the plates and each other.
constexpr std::size_t kMaxSteppedRods = 400;
constexpr std::int64_t kSteps = 200;

[[noreturn]] void absurd(const std::string& what) {
  std::fprintf(stderr, "accepted an absurd scenario: %s\n", what.c_str());
  std::abort();
}

void check_finite(double value, const char* what) {
  if (!std::isfinite(value)) absurd(std::string(what) + " is not finite");
}

void check_model(const scenarios::Scenario& scenario) {
  const engine::Model& model = scenario.model;
  check_finite(model.box_x, "box_x");
  check_finite(model.box_y, "box_y");
  check_finite(model.dt, "dt");
  check_finite(model.drive.amplitude, "drive.amplitude");
  check_finite(model.drive.frequency, "drive.frequency");
  for (const engine::Species& species : model.species) {
    check_finite(species.shape.mass, "a species' mass");
    check_finite(species.shape.inertia_transverse, "a species' inertia");
    check_finite(species.shape.inertia_normal, "a species' inertia");
    check_finite(species.shape.axis_lean, "a species' axis lean");
    check_finite(species.noise.kick_eps, "kick_eps");
    check_finite(species.noise.white_Dr, "white_Dr");
  }
  for (const engine::RodInit& rod : model.rods) {
    check_finite(rod.x, "a rod's x");
    check_finite(rod.y, "a rod's y");
    check_finite(rod.heading, "a rod's heading");
    check_finite(rod.roll, "a rod's roll");
  }
  if (scenario.run.steps < 1) absurd("a run of fewer than one step");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  std::string yaml;
  std::vector<scenarios::Override> overrides;
  scenarios::Diagnostics option_diagnostics;
  std::size_t start = 0;
  while (start < input.size()) {
    std::size_t end = input.find('\n', start);
    if (end == std::string_view::npos) end = input.size();
    const std::string_view line = input.substr(start, end - start);
    if (line.rfind("--set ", 0) == 0) {
      if (auto parsed = scenarios::parse_set_option(line.substr(6), option_diagnostics)) {
        overrides.push_back(std::move(*parsed));
      }
    } else {
      yaml.append(line);
      yaml.push_back('\n');
    }
    start = end + 1;
  }
  if (option_diagnostics.has_errors()) return 0;

  const scenarios::LoadResult result = scenarios::load_scenario_text(yaml, "fuzz.yaml", overrides);
  for (const scenarios::Diagnostic& diagnostic : result.diagnostics) {
    if (diagnostic.message.empty()) absurd("a diagnostic without a message");
  }
  if (!result.scenario) return 0;
  const scenarios::Scenario& scenario = *result.scenario;
  check_model(scenario);
  if (scenario.model.rods.size() > kMaxSteppedRods) return 0;
  try {
    engine::Simulation simulation(scenario.model);
    simulation.advance(std::min<std::int64_t>(kSteps, scenario.run.steps));
  } catch (const std::runtime_error& error) {
    absurd(error.what());
  }
  return 0;
}
