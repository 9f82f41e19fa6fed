#pragma once
// What the model cannot simulate meaningfully, refused before a run starts. The schema's ranges
// refuse values that are wrong on their face (a negative gap); these checks refuse combinations
// that are legal one by one but outrun the time step: whatever moves a rod (the plates, the
// collision kick, white angular noise) may move none of its spheres by more than half the
// thinnest sphere's radius in one step, or contacts are missed and the run is nonsense (rods
// through the base, NaN). Each message names the bound, the value, and what to change.

#include <cstdint>

#include "engine/model.hpp"
#include "scenarios/diagnostic.hpp"
#include "scenarios/scenario_spec.hpp"

namespace rodsort::scenarios {

/// Largest travel of a rod's sphere in one step, as a fraction of the thinnest sphere's radius.
inline constexpr double kMaxStepTravel = 0.5;
/// Most time steps in one run (run.duration / run.dt): a single flat-plate rod costs ~1 us per
/// step (docs/performance.md), so 1e10 steps are some three CPU-hours per rod.
inline constexpr double kMaxSteps = 1.0e10;

/// Checks the drive and the species' noise of a compiled model against the time step.
void check_step_travel(const ScenarioSpec& spec, const engine::Model& model,
                       Diagnostics& diagnostics);

}  // namespace rodsort::scenarios
