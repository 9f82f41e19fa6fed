#pragma once
// Initial placement of the rods: random sequential addition. Rods are drawn one at a time with a
// uniform centre in their region and a heading (isotropic, toward the trap's apex, or given), and
// kept when they overlap neither a rod already placed nor a wall; otherwise they are drawn again.
//
// Overlaps are tested in the plane on each rod's bounding capsule: the segment along the axis from
// (thick tip + R) to (thin tip - R), with R the largest sphere radius, swept by a disc of radius R.
// Every sphere of the rod lies inside it (a sphere at the end of the axis, of radius r <= R,
// reaches r past a point R - r beyond the segment's end), so capsules apart means rods apart, with
// a small clearance on top. The cell is periodic: distances use the nearest image.
//
// At the paper's densities (area fraction about 0.08 for 319 A rods in the 86.85 mm cell) a rod
// needs only a few draws; the draws come from one random stream of the scenario seed, so the same
// scenario gives the same rods, bit for bit.

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "engine/model.hpp"
#include "engine/rod_shape.hpp"

namespace rodsort::trap {
class Obstacle;
}

namespace rodsort::scenarios {

enum class PlacementRegion { anywhere, inside_trap, outside_trap };

struct PlacementHeading {
  enum class Kind { random, toward_apex, fixed };
  Kind kind = Kind::random;
  double angle = 0.0;  ///< for `fixed`: from +x, thick to thin end [rad]
};

/// The rods of one species to place.
struct SpeciesPlacement {
  int species = 0;  ///< index into Model::species
  int count = 0;
  engine::RodShape shape;
  PlacementRegion region = PlacementRegion::anywhere;
  PlacementHeading heading;
};

struct PlacementCell {
  double box_x = 0.0, box_y = 0.0;       ///< periodic cell [mm]
  std::vector<engine::Wall> walls;       ///< rods must not overlap these
  const trap::Obstacle* trap = nullptr;  ///< for the inside/outside regions; may be null
  std::optional<Eigen::Vector2d> apex;   ///< for headings toward the apex [mm]
  /// A bounded cell's wall: centres are drawn inside it (a rod across it overlaps its walls,
  /// which are among `walls`); null for the periodic cell.
  const trap::Obstacle* boundary = nullptr;
};

struct PlacementFailure {
  int species;  ///< index of the species that could not be placed
  int placed;   ///< rods of it placed before giving up
  int requested;
};

struct PlacementResult {
  std::vector<engine::RodInit> rods;  ///< grouped by species, in species order
  std::optional<PlacementFailure> failure;
};

/// Gap kept between the capsules of neighbouring rods, and between rods and walls [mm].
inline constexpr double kPlacementClearance = 0.05;
/// Draws tried for one rod before placement gives up.
inline constexpr int kPlacementAttempts = 20000;

/// Places every rod of every species; the species are interleaved in proportion to their counts,
/// so that a mixture starts homogeneous.
PlacementResult place_rods(const PlacementCell& cell, const std::vector<SpeciesPlacement>& species,
                           std::uint64_t seed);

/// Distance between two segments of the plane [mm].
double segment_distance(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1,
                        const Eigen::Vector2d& q0, const Eigen::Vector2d& q1);

}  // namespace rodsort::scenarios
