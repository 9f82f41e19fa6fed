#pragma once
// The state a trapping run spends its time in: the paper's system with its trap filled by the
// rods' own motion, not packed by hand. It is made once, by stepping the packed-trap system
// (319-full) for a fill time, and kept in a file, so that later measurements, and other builds
// compared before and after a change, start from the very same configuration.
//
// Its larger versions are copies of it side by side: k x k tiles in a cell k times wider, each
// tile with its own trap, 319 k^2 rods. Every tile holds the same local state, so the cost per
// rod across sizes measures the size alone (memory, the broadphase), not a different pile. The
// copies take the rods' positions, frames and velocities; their persistent plate and wall
// contacts are made again in the first steps of the benchmark's warm-up.

#include <cstdint>
#include <filesystem>
#include <iosfwd>

#include "engine/model.hpp"
#include "engine/state.hpp"

namespace rodsort::bench {

/// The simulated time the packed-trap system is stepped to fill its trap [s] (docs/performance.md,
/// section 1: after 30 s the packed and the dispersed starts cost the same).
inline constexpr double kDefaultFillTime = 30.0;

struct FillOptions {
  std::filesystem::path directory;  ///< where filled states are kept
  double dt = 1.0e-4;               ///< [s]
  std::uint64_t seed = 1;
  int solver_iterations = 10;
  double fill_time = kDefaultFillTime;  ///< [s]
};

/// The file that holds the filled state of `options` (its name carries seed, dt, solver iterations
/// and fill time).
std::filesystem::path filled_state_path(const FillOptions& options);

/// The filled paper system's state: read from filled_state_path(options) when it is there and
/// belongs to the paper's system, otherwise made (the fill, announced on `log` with its expected
/// cost) and written there (through a temporary file, so that an interrupted fill leaves nothing).
/// Throws std::runtime_error when the directory cannot be written.
engine::State filled_paper_state(const FillOptions& options, std::ostream& log);

/// `model` (one periodic cell) repeated `tiles` x `tiles` times: a cell `tiles` times wider, the
/// walls and rods of every tile shifted by whole cells; rods of tile t are rods t n .. t n + n - 1.
engine::Model tile_model(const engine::Model& model, int tiles);

/// The state of a tile_model of `one_cell_model` with every tile's rods as in `one_cell`, shifted
/// by whole cells. The first tile keeps `one_cell`'s random streams, the others take
/// `tiled_fresh`'s (the tiled model's own, one per rod); a single tile keeps `one_cell`'s contacts
/// too, and so continues it exactly.
engine::State tile_state(const engine::State& one_cell, const engine::Model& one_cell_model,
                         const engine::State& tiled_fresh, int tiles);

}  // namespace rodsort::bench
