#pragma once
// Trapping as the paper measures it: in every frame, count the rods "at zero velocity" (N0) and
// report the trapping efficiency eta = N0 a / A_t, where a is the area of a rod's projection on
// the plate and A_t the trap's area. A rod is at zero velocity when its speed over the window tau
// (the paper's frame interval, 0.07 s) is below a threshold: a rod locked in the trap still
// jiggles with the plates, so an exact zero never occurs. docs/metrics.md explains the default.
//
// For a mixture every stationary rod counts with its own species' area, so eta is the fraction
// of the trap's area covered by stationary rods whatever their kind. The metrics layer does not
// know the trap: it takes a flag per rod saying whether its (wrapped) centre lies inside.

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "engine/frame.hpp"

namespace rodsort::metrics {

/// Default window tau over which speeds are measured [s]: the paper's frame interval.
inline constexpr double kDefaultWindow = 0.07;
/// Default speed below which a rod counts as stationary [mm/s]; see docs/metrics.md.
inline constexpr double kDefaultStationarySpeed = 5.0;

/// Whether a point of the plane lies in the trap (a trap::Obstacle's contains(), for instance).
using InsidePredicate = std::function<bool(const Eigen::Vector2d&)>;

/// Per rod: speed < threshold [mm/s].
std::vector<bool> stationary_flags(const std::vector<double>& speeds, double threshold);
/// Per rod: inside(wrapped centre of mass).
std::vector<bool> inside_flags(const engine::Frame& frame, const InsidePredicate& inside);

/// Rod counts of one population (all rods, or one species).
struct Counts {
  int rods = 0;
  int stationary = 0;         ///< N0
  int inside = 0;             ///< centre inside the trap, whatever the speed
  int stationary_inside = 0;  ///< both
};

struct TrappingCounts {
  Counts all;
  std::vector<Counts> species;  ///< indexed by species
};

/// Counts of a frame given per-rod flags; species outside [0, species_count) are a broken
/// invariant.
TrappingCounts count_trapping(const engine::Frame& frame, const std::vector<bool>& stationary,
                              const std::vector<bool>& inside, int species_count);

struct Efficiency {
  double eta = 0.0;                 ///< sum over stationary rods of a_s, over A_t
  double eta_trap = 0.0;            ///< the same, stationary rods inside the trap only
  std::vector<double> eta_species;  ///< N0_s a_s / A_t
  std::vector<double> eta_trap_species;
};

/// species_area: projected area a_s of each species [mm^2]; trap_area: A_t [mm^2] (> 0).
Efficiency trapping_efficiency(const TrappingCounts& counts,
                               const std::vector<double>& species_area, double trap_area);

}  // namespace rodsort::metrics
