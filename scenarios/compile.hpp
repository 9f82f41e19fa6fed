#pragma once
// compile(): ScenarioSpec -> Scenario. Builds the rod shapes, the drive, the trap, the pair table
// and the initial rods, and refuses setups that cannot work, each with its reason and the line
// that causes it:
//   - a rod thicker than the gap, or short enough to stand on end between base and lid;
//   - a trap that does not fit in the periodic cell (with a rod's reach of clearance);
//   - fewer than 20 time steps per drive period (the plates' motion would be sampled too coarsely
//     for the impacts that drive the rods);
//   - more rods than random placement can fit (area fraction above kMaxPlacementFraction);
//   - plates, kicks or white noise that move a sphere by more than half the thinnest radius in a
//     step, and runs of more than kMaxSteps steps (scenarios/plausibility.hpp);
//   - outputs that fall outside the run or between time steps.

#include <optional>

#include "scenarios/diagnostic.hpp"
#include "scenarios/scenario.hpp"
#include "scenarios/scenario_spec.hpp"

namespace rodsort::scenarios {

/// Fewest time steps per drive period accepted.
inline constexpr double kMinStepsPerDrivePeriod = 20.0;
/// Highest area fraction (projected rod area over free area) accepted for random placement.
inline constexpr double kMaxPlacementFraction = 0.4;

/// Compiles a spec read without errors; reports what cannot work and returns nothing then.
std::optional<Scenario> compile(const ScenarioSpec& spec, Diagnostics& diagnostics);

}  // namespace rodsort::scenarios
